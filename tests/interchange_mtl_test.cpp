// Wavefront .mtl: statements map onto Glint's models, a Glint → MTL → Glint round trip keeps
// every parameter MTL holds, and malformed files give located errors (file:line).
#include <gtest/gtest.h>

#include "interchange/material_values.h"
#include "interchange/mtl.h"
#include "test_support.h"

namespace glint {
namespace {

ImportedFile parseMtlOk(const std::string& text) {
    auto parsed = parseMtl(text, "test.mtl");
    EXPECT_TRUE(parsed.ok()) << (parsed ? "" : parsed.error().format());
    return parsed ? *parsed : ImportedFile{};
}

bool hasWarning(const ImportedFile& file, const std::string& fragment) {
    for (const Diagnostic& warning : allWarnings(file))
        if (warning.format().find(fragment) != std::string::npos) return true;
    return false;
}

TEST(Mtl, Illum2IsLectureBlinnPhongWithEveryStatement) {
    const ImportedFile file = parseMtlOk(
        "# a comment\n"
        "newmtl red plastic\n"
        "Ka 0.5 0.1 0.1\nKd 0.5 0.1 0.1\nKs 0.25 0.25 0.25\nNs 96\nNi 1.45\nd 1\nillum 2\n"
        "map_Kd -s 2 2 1 -bm 0.5 textures/red diffuse.png\nmap_Ks spec.png\nmap_Ns gloss.png\nmap_d alpha.png\n"
        "map_bump -bm 2 bump.png\nbump bump2.png\n");
    ASSERT_EQ(file.materials.size(), 1u);
    const ImportedMaterial& imported = file.materials[0];
    EXPECT_EQ(imported.material.name, "red plastic");
    EXPECT_EQ(imported.material.analytic()->model, BrdfModel::BlinnPhong);
    EXPECT_EQ(paramValue(imported.material, "diffuse_albedo"), glm::vec3(0.5f, 0.1f, 0.1f));
    EXPECT_EQ(paramValue(imported.material, "specular"), glm::vec3(0.25f));
    EXPECT_EQ(paramScalar(imported.material, "exponent"), 96.0f);
    EXPECT_EQ(paramScalar(imported.material, "form"), 0.0f);  // lecture: Ks (N·H)^Ns
    ASSERT_EQ(imported.textures.size(), 6u);
    EXPECT_EQ(imported.textures[0].slot, "map_Kd");
    EXPECT_EQ(imported.textures[0].options, "-s 2 2 1 -bm 0.5");
    EXPECT_EQ(imported.textures[0].path, "textures/red diffuse.png");
    EXPECT_EQ(imported.textures[5].slot, "bump");
    EXPECT_TRUE(hasWarning(file, "not rendered"));
}

TEST(Mtl, IllumModelsMapToTheNearestGlintModel) {
    const ImportedFile file = parseMtlOk(
        "newmtl flat\nKd 0.2 0.3 0.4\nillum 0\n"
        "newmtl matte\nKd 0.6\nillum 1\n"
        "newmtl chrome\nKd 0 0 0\nKs 0.9 0.8 0.7\nillum 3\n"
        "newmtl window\nNi 1.5\nillum 7\n"
        "newmtl water\nNi 1.33\nTr 0.9\nillum 4\n");
    ASSERT_EQ(file.materials.size(), 5u);
    EXPECT_EQ(file.materials[0].material.analytic()->model, BrdfModel::Lambert);
    EXPECT_TRUE(hasWarning(file, "illum 0"));
    EXPECT_EQ(paramValue(file.materials[1].material, "albedo"), glm::vec3(0.6f));
    const Material& chrome = file.materials[2].material;
    EXPECT_EQ(chrome.analytic()->model, BrdfModel::Mirror);
    // κ for n = 1 gives back the reflectance: κ²/(4 + κ²) = Ks.
    const glm::vec3 kappa = paramValue(chrome, "extinction");
    EXPECT_NEAR(kappa.r * kappa.r / (4 + kappa.r * kappa.r), 0.9f, 1e-5f);
    EXPECT_NEAR(kappa.b * kappa.b / (4 + kappa.b * kappa.b), 0.7f, 1e-5f);
    EXPECT_EQ(file.materials[3].material.analytic()->model, BrdfModel::Glass);
    EXPECT_FLOAT_EQ(paramScalar(file.materials[3].material, "ior"), 1.5f);
    EXPECT_FLOAT_EQ(paramScalar(file.materials[4].material, "ior"), 1.33f);
    EXPECT_TRUE(hasWarning(file, "illum 4"));
}

// Found by fuzz_mtl: a line of only a form feed once indexed an empty word list.
TEST(Mtl, LinesOfOtherWhitespaceAreBlank) {
    const ImportedFile file = parseMtlOk("newmtl a\n\f\n\v \x0c\nKd 0.5\n");
    ASSERT_EQ(file.materials.size(), 1u);
    EXPECT_EQ(paramValue(file.materials[0].material, "diffuse_albedo"), glm::vec3(0.5f));
}

TEST(Mtl, ValidButUnusedStatementsWarnWithTheirLine) {
    const ImportedFile file = parseMtlOk("newmtl a\nKd 0.5\nKe 1 1 1\nTf 1 1 1\nsharpness 60\nPr 0.5\nd 0.5\n");
    EXPECT_TRUE(hasWarning(file, "test.mtl:3: warning: 'Ke'"));
    EXPECT_TRUE(hasWarning(file, "test.mtl:4: warning: 'Tf'"));
    EXPECT_TRUE(hasWarning(file, "dissolve"));
}

// Every parameter MTL can hold survives Glint → MTL → Glint for the models it maps exactly.
TEST(Mtl, RoundTripKeepsEveryParameterMtlHolds) {
    std::vector<ImportedMaterial> originals;
    Material blinn = test::materialWith("glossy red", BrdfModel::BlinnPhong,
        {{"diffuse_albedo", glm::vec3(0.7f, 0.123456f, 0.05f)}, {"specular", glm::vec3(0.3f, 0.2f, 0.1f)},
         {"exponent", 123.456f}, {"form", 0.0f}});
    originals.push_back({blinn, {{"map_Kd", "albedo map.png", "-s 2 2 1"}, {"bump", "n.png", ""}}});
    Material lambert = Material::withDefaults("chalk", BrdfModel::Lambert);
    setParam(lambert, "albedo", glm::vec3(0.9f, 0.8f, 0.7f));
    originals.push_back({lambert, {}});
    Material mirror = test::materialWith("steel", BrdfModel::Mirror,
        {{"ior", 1.0f}, {"extinction", glm::vec3(3.0f, 2.5f, 2.0f)},
         {"diffuse_albedo", glm::vec3(0.01f, 0.02f, 0.03f)}});
    originals.push_back({mirror, {}});
    Material glass = Material::withDefaults("crown glass", BrdfModel::Glass);
    setParam(glass, "ior", 1.523f);
    originals.push_back({glass, {}});

    const ExportedText written = writeMtl(originals);
    const ImportedFile read = parseMtlOk(written.text);
    ASSERT_EQ(read.materials.size(), originals.size()) << written.text;
    for (size_t i = 0; i < originals.size(); ++i) {
        const Material& before = originals[i].material;
        const Material& after = read.materials[i].material;
        EXPECT_EQ(after.name, before.name);
        ASSERT_EQ(after.analytic()->model, before.analytic()->model) << before.name;
        ASSERT_EQ(after.analytic()->values.size(), before.analytic()->values.size());
        for (size_t v = 0; v < before.analytic()->values.size(); ++v)
            EXPECT_NEAR(after.analytic()->values[v], before.analytic()->values[v], 1e-5f * std::max(1.0f, std::abs(before.analytic()->values[v])))
                << before.name << " value " << v << "\n" << written.text;
        ASSERT_EQ(read.materials[i].textures.size(), originals[i].textures.size());
        for (size_t t = 0; t < originals[i].textures.size(); ++t) {
            EXPECT_EQ(read.materials[i].textures[t].slot, originals[i].textures[t].slot);
            EXPECT_EQ(read.materials[i].textures[t].path, originals[i].textures[t].path);
            EXPECT_EQ(read.materials[i].textures[t].options, originals[i].textures[t].options);
        }
    }
}

TEST(Mtl, ExportWarnsAboutWhatMtlCannotHold) {
    std::vector<ImportedMaterial> materials{{Material::withDefaults("ct", BrdfModel::CookTorrance), {}},
                                            {Material::withDefaults("normalized", BrdfModel::BlinnPhong), {}}};
    const ExportedText written = writeMtl(materials);
    ASSERT_EQ(written.warnings.size(), 2u);
    EXPECT_NE(written.warnings[0].message.find("approximated by Blinn-Phong"), std::string::npos);
    EXPECT_NE(written.warnings[1].message.find("form is not kept"), std::string::npos);
    EXPECT_TRUE(parseMtl(written.text, "out.mtl").ok());
}

// The malformed corpus: each entry must give an error naming file:line and the cause.
// What other tools write and Wavefront readers skip: Latin-1 names and comments, `Ni 0`, 3ds
// Max's `Km`, Blender's empty `newmtl`. Each is a warning with its line; the file loads.
TEST(Mtl, OtherToolsQuirksAreWarningsWithLines) {
    const ImportedFile file = parseMtlOk(
        "# caf\xe9 \xa9 someone\n"
        "newmtl bl\xe5\n"
        "Kd 0.5 0.5 0.5\n"
        "Ni 0.000000\n"
        "Km 0.3\n"
        "newmtl\n"
        "Kd 0.1 0.2 0.3\n");
    ASSERT_EQ(file.materials.size(), 2u);
    EXPECT_EQ(file.materials[0].material.name, "bl\xc3\xa5");  // Latin-1 å as UTF-8
    EXPECT_EQ(file.materials[1].material.name, "unnamed (line 6)");
    EXPECT_TRUE(hasWarning(file, "test.mtl:1: warning: the line is not UTF-8; read as Latin-1"));
    EXPECT_TRUE(hasWarning(file, "test.mtl:2: warning: the line is not UTF-8"));
    EXPECT_TRUE(hasWarning(file, "test.mtl:4: warning: 'Ni 0.000000' is no index of refraction; read as 1"));
    EXPECT_TRUE(hasWarning(file, "test.mtl:5: warning: unknown statement 'Km'; ignored"));
    EXPECT_TRUE(hasWarning(file, "test.mtl:6: warning: 'newmtl' without a name"));
    // A material's warnings stay with it: choosing the second leaves the first's out.
    const std::vector<Diagnostic> second = warningsFor(file, 1);
    for (const Diagnostic& warning : second) EXPECT_EQ(warning.format().find("'Km'"), std::string::npos);
}

// `Ns 0` with a highlight colour, as Blender 4.x writes roughness 1 and MeshLab an unset
// shininess: no highlight (Lambert with Kd), with a warning. Ns 0 without Ks stays Blinn-Phong.
TEST(Mtl, NsZeroWithAHighlightColourIsReadAsNoHighlight) {
    const ImportedFile file = parseMtlOk(
        "newmtl blender_rough\nNs 0.000000\nKd 0.2 0.3 0.6\nKs 0.5 0.5 0.5\nillum 2\n"
        "newmtl meshlab\nKd 1 1 1\nKs 1 1 1\nillum 2\nNs 0.000000\n"
        "newmtl no_highlight\nKd 0.4 0.4 0.4\nKs 0 0 0\nNs 0\nillum 2\n");
    ASSERT_EQ(file.materials.size(), 3u);
    const Material& rough = file.materials[0].material;
    ASSERT_TRUE(rough.analytic());
    EXPECT_EQ(rough.analytic()->model, BrdfModel::Lambert);
    EXPECT_EQ(paramValue(rough, "albedo"), glm::vec3(0.2f, 0.3f, 0.6f));
    EXPECT_EQ(file.materials[1].material.analytic()->model, BrdfModel::Lambert);
    EXPECT_TRUE(hasWarning(file, "test.mtl:1: warning: 'blender_rough': 'Ns 0'"));
    EXPECT_TRUE(hasWarning(file, "test.mtl:6: warning: 'meshlab': 'Ns 0'"));
    EXPECT_EQ(file.materials[2].material.analytic()->model, BrdfModel::BlinnPhong);
    EXPECT_TRUE(file.materials[2].warnings.empty());
}

TEST(Mtl, MalformedFilesGiveLocatedErrors) {
    test::expectParseErrors(parseMtl, "test.mtl", {
        {"", "no material in the file"},
        {"# only a comment\n", "no material in the file"},
        {"Kd 1 1 1\n", "test.mtl:1: 'Kd' before the first 'newmtl'"},
        {"newmtl a\nKd 0.5 0.5\n", "test.mtl:2: 'Kd' takes one (grey) or three"},
        {"newmtl a\nKd 0.5 zero 0.5\n", "test.mtl:2: 'zero' is not a number"},
        {"newmtl a\nKd 0.5 nan 0.5\n", "test.mtl:2: 'nan' is not a finite number"},
        {"newmtl a\nNs 1e999\n", "test.mtl:2: '1e999' is out of range"},
        {"newmtl a\nKd 2 0 0\n", "must be in [0, 1]"},
        {"newmtl a\nNs -4\n", "test.mtl:2: 'Ns' must be at least 0"},
        {"newmtl a\nd 1.5\n", "'d' must be in [0, 1]"},
        {"newmtl a\nillum 11\n", "test.mtl:2: 'illum' must be an integer 0-10"},
        {"newmtl a\nillum 2.5\n", "'illum' must be an integer"},
        {"newmtl a\nmap_Kd\n", "'map_Kd' needs a file name"},
        {"newmtl a\nmap_Kd -s\n", "texture option '-s' needs 1 value(s)"},
        {"newmtl a\nmap_Kd -zoom 2 x.png\n", "unknown texture option '-zoom'"},
        {"newmtl a\nNi 9\nillum 7\n", "test.mtl:1: 'a': Ni = 9"},
        {"newmtl a\nKd 0.5 0.5 0.5 0.5\n", "'Kd' takes one (grey) or three"},
        {"newmtl a\nmap_Kd \x01 -bm 0,5 bump.png\n", "test.mtl:2: control character 0x01"},
        {std::string("newmtl a\nmap_Kd x\0y.png\n", 24), "test.mtl:2: control character 0x00"},
    });
}

}  // namespace
}  // namespace glint
