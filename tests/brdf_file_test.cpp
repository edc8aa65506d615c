// The BRDF Explorer .brdf reader and .bparam files: good files parse into parameters and shader
// names; a corpus of malformed files each gets one located message (file:line:column).
#include <gtest/gtest.h>

#include "interchange/bparam_file.h"
#include "interchange/brdf_file.h"
#include "interchange/custom_brdf.h"
#include "test_support.h"

namespace glint {
namespace {

constexpr const char* kGood =
    "analytic\n"
    "# a comment\n"
    "::begin parameters\n"
    "float roughness 0.01 1 .25   # trailing comment\n"
    "bool useFresnel 1\n"
    "color tint 1 0.5 0.25\n"
    "::end parameters\n"
    "\n"
    "::begin shader\n"
    "uniform float roughness;\n"
    "const float PI = 3.14159265358979323846;\n"
    "float sqr(float x) { return x * x; }\n"
    "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\n"
    "{\n"
    "    float local = sqr(roughness);\n"
    "    return tint * local / PI;\n"
    "}\n"
    "::end shader\n";

TEST(BrdfFile, ParsesParametersShaderAndTopLevelNames) {
    auto file = parseBrdfFile(kGood, "good.brdf");
    ASSERT_TRUE(file) << file.error().format();
    ASSERT_EQ(file->params.size(), 3u);
    EXPECT_EQ(file->params[0].name, "roughness");
    EXPECT_EQ(file->params[0].kind, ParamKind::Scalar);
    EXPECT_FLOAT_EQ(file->params[0].min, 0.01f);
    EXPECT_FLOAT_EQ(file->params[0].max, 1.0f);
    EXPECT_FLOAT_EQ(file->params[0].defaultValue[0], 0.25f);
    EXPECT_EQ(file->params[1].kind, ParamKind::Bool);
    EXPECT_EQ(file->params[1].defaultValue[0], 1.0f);
    EXPECT_EQ(file->params[2].kind, ParamKind::Color);
    EXPECT_FLOAT_EQ(file->params[2].defaultValue[2], 0.25f);
    EXPECT_EQ(file->shaderLine, 9);
    const std::vector<std::string> expected = {"BRDF", "PI", "roughness", "sqr"};
    EXPECT_EQ(file->topLevelNames, expected);  // not `local` (inside a body), not `x` (a parameter)
    EXPECT_EQ(file->declaredUniforms, std::vector<std::string>{"roughness"});
    // Line N of the shader text is line N of the file.
    int line = 1;
    size_t at = 0;
    while (line < 13) at = file->shaderText.find('\n', at) + 1, ++line;
    EXPECT_EQ(file->shaderText.substr(at, 9), "vec3 BRDF");
    EXPECT_EQ(file->shaderText.find("::begin"), std::string::npos);
}

TEST(BrdfFile, ExamplesParse) {
    for (const char* name : {"lambert", "blinn_phong", "ggx_smith", "ashikhmin_shirley"}) {
        auto file = loadBrdfFile(std::string(GLINT_TEST_DATA_DIR) + "/../examples/brdf/" + name + ".brdf");
        EXPECT_TRUE(file) << name << ": " << file.error().format();
    }
}

TEST(BrdfFile, CustomBrdfTableFollowsTheFile) {
    auto file = parseBrdfFile(kGood, "good.brdf");
    ASSERT_TRUE(file);
    auto brdf = makeCustomBrdf(std::move(*file));
    ASSERT_EQ(brdf->table.size(), 3u);
    EXPECT_STREQ(brdf->table[0].name, "roughness");
    EXPECT_FLOAT_EQ(brdf->table[0].sliderMin, 0.01f);
    EXPECT_FLOAT_EQ(brdf->table[0].validMax, 1.0f);
    EXPECT_EQ(packedSize(brdf->table), 5);
    EXPECT_EQ(defaultValues(brdf->table), (std::vector<float>{0.25f, 1.0f, 1.0f, 0.5f, 0.25f}));
}

struct Malformed {
    const char* what;
    std::string text;
    const char* location;  // "file:line:column"
    const char* message;   // a part of the message
};

std::string withShader(const std::string& parameters, const std::string& shader = "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(0.0); }\n") {
    return "analytic\n::begin parameters\n" + parameters + "::end parameters\n::begin shader\n" + shader + "::end shader\n";
}

TEST(BrdfFile, MalformedCorpusGetsLocatedMessages) {
    const std::vector<Malformed> corpus = {
        {"empty file", "", "bad.brdf:1:1", "must start with the line 'analytic'"},
        {"wrong header", "measured\n", "bad.brdf:1:1", "only analytic"},
        {"text outside", "analytic\nfloat a 0 1 0\n", "bad.brdf:2:1", "text outside a block"},
        {"unterminated parameters", "analytic\n::begin parameters\nfloat a 0 1 0\n", "bad.brdf:2:1",
         "unterminated block"},
        {"unterminated shader", "analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {}\n",
         "bad.brdf:2:1", "unterminated block"},
        {"unterminated unknown section", "analytic\n::begin textures\n", "bad.brdf:2:1", "unterminated block: '::begin textures'"},
        {"mismatched end", "analytic\n::begin isFunc\n::end shader\n", "bad.brdf:3:1", "'::end shader' without"},
        {"end without begin", "analytic\n::end shader\n", "bad.brdf:2:1", "without '::begin shader'"},
        {"nested", "analytic\n::begin parameters\n::begin shader\n", "bad.brdf:3:1", "inside the block opened at line 2"},
        {"second shader", withShader("") + "::begin shader\n::end shader\n", "bad.brdf:7:1", "a second"},
        {"no shader", "analytic\n::begin parameters\n::end parameters\n", "bad.brdf:3:1", "no '::begin shader'"},
        {"no BRDF", withShader("", "vec3 brdf(vec3 L) { return L; }\n"), "bad.brdf:4:1", "defines no 'vec3 BRDF"},
        {"bad number", withShader("float a 0 1 0.5x\n"), "bad.brdf:3:13", "'0.5x' is not a number"},
        {"nan", withShader("float a 0 1 nan\n"), "bad.brdf:3:13", "not a number"},
        {"hex", withShader("float a 0 1 0x1\n"), "bad.brdf:3:13", "not a number"},
        {"huge", withShader("float a 0 1e300 1\n"), "bad.brdf:3:11", "too large"},
        {"huge float", withShader("float a 0 2e30 1\n"), "bad.brdf:3:11", "too large"},
        {"min above max", withShader("float a 2 1 1.5\n"), "bad.brdf:3:9", "min 2 is greater than max 1"},
        {"default outside", withShader("float a 0 1 3\n"), "bad.brdf:3:13", "default 3 lies outside [0, 1]"},
        {"duplicate", withShader("float a 0 1 0\ncolor a 1 1 1\n"), "bad.brdf:4:7", "declared twice (first at line 3)"},
        {"unknown type", withShader("int a 0 1 0\n"), "bad.brdf:3:1", "unknown parameter type 'int'"},
        {"missing number", withShader("float a 0 1\n"), "bad.brdf:3:12", "incomplete float parameter"},
        {"extra token", withShader("bool a 1 0\n"), "bad.brdf:3:10", "extra text after bool"},
        {"bool not 0/1", withShader("bool a 2\n"), "bad.brdf:3:8", "a bool is 0 or 1"},
        {"negative colour", withShader("color c 1 -1 0\n"), "bad.brdf:3:11", "at least 0"},
        {"bad name", withShader("float 9a 0 1 0\n"), "bad.brdf:3:7", "not a GLSL identifier"},
        {"reserved name", withShader("float gl_x 0 1 0\n"), "bad.brdf:3:7", "not a GLSL identifier"},
        {"uniform of another type", withShader("float a 0 1 0\n", "uniform vec3 a;\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return a; }\n"),
         "bad.brdf:6:14", "does not match the parameter declared at line 3"},
        {"non-UTF-8", "analytic\n# caf\xe9\n", "bad.brdf:2:6", "not UTF-8"},
        {"NUL byte", std::string("analytic\n\0\n", 11), "bad.brdf:2:1", "NUL"},
        {"bad directive", "analytic\n::begin\n", "bad.brdf:2:1", "expected '::begin SECTION'"},
    };
    for (const Malformed& bad : corpus) {
        auto file = parseBrdfFile(bad.text, "bad.brdf");
        ASSERT_FALSE(file) << bad.what;
        const std::string formatted = file.error().format();
        EXPECT_EQ(formatted.rfind(bad.location, 0), 0u) << bad.what << ": " << formatted;
        EXPECT_NE(formatted.find(bad.message), std::string::npos) << bad.what << ": " << formatted;
    }
}

TEST(BrdfFile, TooLargeFileIsRefused) {
    const std::string big = "analytic\n" + std::string(kMaxBrdfFileBytes, '#');
    auto file = parseBrdfFile(big, "big.brdf");
    ASSERT_FALSE(file);
    EXPECT_NE(file.error().message.find("at most 1 MiB"), std::string::npos);
}

// BRDF Explorer reads a header line's first word and warns about sections it does not know
// (BRDFBase::loadBRDF); an `isFunc` section (importance sampling) is skipped with a located warning.
TEST(BrdfFile, ReadsWhatBrdfExplorerReads) {
    std::string text = kGood;
    text.replace(0, 8, "analytic  # written by hand");
    text += "::begin isFunc\nvec3 sample(float u, float v) { return vec3(0); }\n::end isFunc\n";
    auto file = parseBrdfFile(text, "wild.brdf");
    ASSERT_TRUE(file) << file.error().format();
    ASSERT_EQ(file->warnings.size(), 1u);
    EXPECT_EQ(file->warnings[0].format().rfind("wild.brdf:19:9: warning: section 'isFunc' is skipped", 0), 0u)
        << file->warnings[0].format();
    EXPECT_EQ(file->shaderText.find("sample("), std::string::npos);  // not part of the shader
}

TEST(Bparam, RoundTripsEveryKind) {
    auto file = parseBrdfFile(kGood, "good.brdf");
    ASSERT_TRUE(file);
    auto brdf = makeCustomBrdf(std::move(*file));
    const std::vector<float> values = {0.625f, 0.0f, 0.1f, 0.2f, 0.3f};
    const std::string path = test::outputDirectory("bparam") + "/saved.bparam";
    ASSERT_TRUE(saveBparam(path, *brdf, values));
    // What BRDF Explorer reads: the first line names the .brdf (createBRDFFromFile opens it).
    const std::string text = formatBparam(*brdf, values);
    EXPECT_EQ(text.rfind("bparam /", 0), 0u) << text;
    EXPECT_NE(text.find("good.brdf\n\n::begin parameters\n"), std::string::npos) << text;
    std::vector<Diagnostic> warnings;
    auto loaded = loadBparam(path, *brdf, defaultValues(brdf->table), warnings);
    ASSERT_TRUE(loaded) << loaded.error().format();
    EXPECT_EQ(*loaded, values);
    EXPECT_TRUE(warnings.empty());
}

// A file as BRDF Explorer's saveParamsFile writes it (printf's %f), with a section it only warns about.
TEST(Bparam, ReadsWhatBrdfExplorerWrites) {
    auto file = parseBrdfFile(kGood, "good.brdf");
    ASSERT_TRUE(file);
    auto brdf = makeCustomBrdf(std::move(*file));
    const std::string written =
        "bparam /home/someone/brdfs/good.brdf\n\n"
        "::begin parameters\n"
        "float roughness 0.010000 1.000000 0.300000\n"
        "bool useFresnel 0\n"
        "color tint 0.100000 0.200000 0.300000\n"
        "::end parameters\n"
        "::begin isFunc\n"
        "anything at all\n"
        "::end isFunc\n";
    auto parsed = parseBparamFile(written, "explorer.bparam");
    ASSERT_TRUE(parsed) << parsed.error().format();
    EXPECT_EQ(parsed->brdfPath, "/home/someone/brdfs/good.brdf");
    std::vector<Diagnostic> warnings;
    auto values = parseBparam(written, "explorer.bparam", *brdf, defaultValues(brdf->table), warnings);
    ASSERT_TRUE(values) << values.error().format();
    EXPECT_EQ(*values, (std::vector<float>{0.3f, 0.0f, 0.1f, 0.2f, 0.3f}));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].format().rfind("explorer.bparam:8:1: warning: section 'isFunc' is skipped", 0), 0u)
        << warnings[0].format();
    // A .brdf file read as a .bparam (BRDF Explorer accepts an `analytic` header) gives its defaults.
    auto analytic = parseBparam(std::string(kGood).replace(0, 8, "analytic # comment"), "a.bparam", *brdf,
                                defaultValues(brdf->table), warnings);
    ASSERT_TRUE(analytic) << analytic.error().format();
    EXPECT_EQ(*analytic, defaultValues(brdf->table));
}

TEST(Bparam, PartialFileKeepsOtherValuesAndBadOnesAreLocated) {
    auto file = parseBrdfFile(kGood, "good.brdf");
    ASSERT_TRUE(file);
    auto brdf = makeCustomBrdf(std::move(*file));
    std::vector<Diagnostic> warnings;
    auto partial = parseBparam("::begin parameters\nbool useFresnel 0\n::end parameters\n", "p.bparam", *brdf,
                               defaultValues(brdf->table), warnings);
    ASSERT_TRUE(partial) << partial.error().format();
    EXPECT_EQ(*partial, (std::vector<float>{0.25f, 0.0f, 1.0f, 0.5f, 0.25f}));
    // What BRDF Explorer skips silently is a located warning; the rest of the file is read.
    const std::vector<std::pair<std::string, std::string>> skipped = {
        {"::begin parameters\nfloat shininess 0 1 0.5\n::end parameters\n", "p.bparam:2:1: warning: 'shininess' is not a parameter"},
        {"::begin parameters\ncolor roughness 1 1 1\n::end parameters\n", "p.bparam:2:1: warning: 'roughness' has another type"},
        {"::begin parameters\nfloat roughness 0 5 4\n::end parameters\n", "p.bparam:2:1: warning: roughness = 4 lies outside"},
    };
    for (const auto& [text, expected] : skipped) {
        warnings.clear();
        auto values = parseBparam(text, "p.bparam", *brdf, defaultValues(brdf->table), warnings);
        ASSERT_TRUE(values) << values.error().format();
        ASSERT_EQ(warnings.size(), 1u) << text;
        EXPECT_EQ(warnings[0].format().rfind(expected, 0), 0u) << warnings[0].format();
    }
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"::begin parameters\nbool useFresnel 1\n", "p.bparam:1:1: unterminated section"},
        {"float roughness 0 1 0.5\n", "p.bparam:1:1: text outside a section"},
        {"bparam x.brdf\n::begin parameters\n::begin shader\n", "p.bparam:3:1: '::begin shader' inside the section"},
        {"bparam x.brdf\n::begin parameters\n::end shader\n", "p.bparam:3:1: '::end shader' without"},
        {"::begin parameters\nfloat roughness 0 1\n::end parameters\n", "p.bparam:2:"},
        {"", "p.bparam:1:1: no '::begin parameters' block"},
    };
    for (const auto& [text, expected] : bad) {
        auto values = parseBparam(text, "p.bparam", *brdf, defaultValues(brdf->table), warnings);
        ASSERT_FALSE(values) << text;
        EXPECT_EQ(values.error().format().rfind(expected, 0), 0u) << values.error().format();
    }
}

}  // namespace
}  // namespace glint
