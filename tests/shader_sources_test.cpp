// The shader #include preprocessor, #line bookkeeping, error-log mapping and the GLSL generated
// from a parameter table. No GL context needed.
#include <gtest/gtest.h>

#include <fstream>

#include "gl/material_glsl.h"
#include "gl/shader_sources.h"
#include "gl/uniform_blocks.h"
#include "test_support.h"

namespace glint {
namespace {

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(ShaderSources, IncludesOnceAndKeepsLineNumbers) {
    const std::string directory = test::outputDirectory("shader_sources");
    std::filesystem::create_directories(directory + "/common");
    writeFile(directory + "/main.frag", "#version 410 core\n#include \"common/a.glsl\"\n#include \"common/a.glsl\"\nvoid main() {}\n");
    writeFile(directory + "/common/a.glsl", "float a() { return 1.0; }\n");
    auto assembled = assembleShader(ShaderSources(directory), "main.frag", "#define X 1\n");
    ASSERT_TRUE(assembled.ok()) << assembled.error().format();
    EXPECT_EQ(assembled->files, (std::vector<std::string>{"main.frag", "<generated prelude>", "common/a.glsl"}));
    EXPECT_EQ(assembled->text, "#version 410 core\n#define X 1\nfloat a() { return 1.0; }\nvoid main() {}\n");
    const std::vector<std::pair<int, int>> expected = {{0, 1}, {1, 1}, {2, 1}, {0, 4}};
    ASSERT_EQ(assembled->lineOrigins.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(assembled->lineOrigins[i].file, expected[i].first) << "line " << i + 1;
        EXPECT_EQ(assembled->lineOrigins[i].line, expected[i].second) << "line " << i + 1;
    }
}

TEST(ShaderSources, MissingIncludeNamesTheIncludingLine) {
    const std::string directory = test::outputDirectory("shader_sources_missing");
    writeFile(directory + "/main.frag", "#version 410 core\n\n#include \"nope.glsl\"\n");
    auto assembled = assembleShader(ShaderSources(directory), "main.frag");
    ASSERT_FALSE(assembled.ok());
    EXPECT_EQ(assembled.error().where.file, "main.frag");
    EXPECT_EQ(assembled.error().where.line, 3);
}

TEST(ShaderSources, GeneratedFilesAreIncludable) {
    auto assembled = assembleShader(ShaderSources(), "surface.frag", "",
                                    {{"generated/material.glsl", generateMaterialGlsl(modelInfo(BrdfModel::Lambert))}});
    ASSERT_TRUE(assembled.ok()) << assembled.error().format();
    EXPECT_NE(assembled->text.find("vec3 evalLambert"), std::string::npos);
    EXPECT_NE(assembled->text.find("#define GLINT_EVAL_BRDF evalLambert"), std::string::npos);
}

TEST(ShaderSources, EmbeddedCopiesMatchTheSourceTree) {
    for (const EmbeddedShader& shader : embeddedShaders()) {
        auto onDisk = ShaderSources(std::string(GLINT_TEST_DATA_DIR) + "/../shaders").read(shader.path);
        ASSERT_TRUE(onDisk.ok()) << shader.path;
        EXPECT_EQ(*onDisk, shader.source) << shader.path;
    }
    EXPECT_GE(embeddedShaders().size(), 8u);
}

TEST(ShaderSources, MapsMesaAndNvidiaLogsThroughTheAssembledLines) {
    // Line 3 of the text is line 7 of the included file, whatever source-string number the driver names.
    AssembledShader shader;
    shader.files = {"surface.frag", "brdf/lambert.glsl"};
    shader.lineOrigins = {{0, 1}, {0, 2}, {1, 7}, {0, 3}};
    EXPECT_EQ(mapCompileLog("0:3(12): error: `foo' undeclared\n", shader), "brdf/lambert.glsl:7:12: error: `foo' undeclared\n");
    EXPECT_EQ(mapCompileLog("0(4) : error C1008: undefined variable\n", shader), "surface.frag:3: error C1008: undefined variable\n");
    EXPECT_EQ(mapCompileLog("0:99(1): error: past the end\n", shader), "<line 99>:1: error: past the end\n");
}

TEST(MaterialGlsl, FollowsTheParameterTable) {
    const std::string glsl = generateMaterialGlsl(modelInfo(BrdfModel::BlinnPhong));
    EXPECT_NE(glsl.find("vec3 diffuse_albedo;"), std::string::npos);
    EXPECT_NE(glsl.find("p.specular = vec3(materialValue(3), materialValue(4), materialValue(5));"), std::string::npos);
    EXPECT_NE(glsl.find("p.exponent = materialValue(6);"), std::string::npos);
    EXPECT_NE(glsl.find("p.form = int(materialValue(7) + 0.5);"), std::string::npos);
}

TEST(MaterialGlsl, PerChannelQuantitiesAreVec3) {
    const std::string glsl = generateMaterialGlsl(modelInfo(BrdfModel::Mirror));
    EXPECT_NE(glsl.find("p.ior = vec3(materialValue(0), materialValue(1), materialValue(2));"), std::string::npos);
    EXPECT_NE(glsl.find("p.extinction = vec3(materialValue(3), materialValue(4), materialValue(5));"), std::string::npos);
}

TEST(MaterialGlsl, HooksForAmbientAndSpecularTransport) {
    const std::string lambert = generateMaterialGlsl(modelInfo(BrdfModel::Lambert));
    EXPECT_NE(lambert.find("#define GLINT_AMBIENT_REFLECTANCE ambientReflectanceLambert"), std::string::npos);
    EXPECT_EQ(lambert.find("GLINT_SPECULAR_TRANSPORT"), std::string::npos);
    const std::string glass = generateMaterialGlsl(modelInfo(BrdfModel::Glass));
    EXPECT_NE(glass.find("#define GLINT_AMBIENT_REFLECTANCE noAmbientReflectance"), std::string::npos);
    EXPECT_NE(glass.find("#define GLINT_SPECULAR_TRANSPORT transportGlass"), std::string::npos);
}

TEST(UniformBlocks, GlslLightCountMatchesTheCppMirror) {
    auto uniforms = ShaderSources(std::string(GLINT_TEST_DATA_DIR) + "/../shaders").read("common/uniforms.glsl");
    ASSERT_TRUE(uniforms.ok());
    EXPECT_NE(uniforms->find("const int MAX_LIGHTS = " + std::to_string(kMaxLights) + ";"), std::string::npos);
}

}  // namespace
}  // namespace glint
