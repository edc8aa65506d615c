// Measured (MERL) materials: the directional albedo table, material JSON with "merl_file"
// (relative paths, round trip, refused references with their key), the .binary row of the
// import table, and the CPU reference of a constant table against the Lambert model.
#include <filesystem>

#include <gtest/gtest.h>

#include "interchange/import_formats.h"
#include "interchange/measured_brdf.h"
#include "math/constants.h"
#include "render/reference_renderer.h"
#include "scene/preview_stage.h"
#include "scene/scene_json.h"
#include "test_support.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"

namespace glint {
namespace {

const glm::vec3 kMeasuredTestAlbedo(0.7f, 0.45f, 0.2f);

// A constant (Lambertian) .binary in the test output folder, written once.
std::string measuredTestFile() {
    static const std::string path = [] {
        const std::string file = test::outputDirectory("measured_material") + "/lambert.binary";
        EXPECT_TRUE(writeFileAtomically(file, makeConstantMerl(kMeasuredTestAlbedo / kPi)).ok());
        return file;
    }();
    return path;
}

TEST(MeasuredMaterial, ConstantTableHasItsAlbedoAtEveryAngle) {
    auto brdf = loadMeasuredBrdf(measuredTestFile());
    ASSERT_TRUE(brdf.ok()) << brdf.error().format();
    EXPECT_EQ((*brdf)->displayName, "lambert.binary");
    for (float cosThetaOut : {0.0f, 0.01f, 0.3f, 0.77f, 1.0f})
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(measuredDirectionalAlbedo(**brdf, cosThetaOut)[c], kMeasuredTestAlbedo[c], 1e-5f);
    const Material material = measuredBrdfMaterial(*brdf);
    EXPECT_EQ(material.name, "lambert");
    ASSERT_TRUE(material.measured());
    EXPECT_EQ(material.measured()->brdf, *brdf);
    EXPECT_TRUE(paramTable(material).empty());  // the table is all there is: no stand-in parameters
}

TEST(MeasuredMaterial, JsonReadsTheFileRelativeToItselfAndWritesItBack) {
    measuredTestFile();
    const std::string folder = test::outputDirectory("measured_material");
    const std::string text = R"({"format": "glint-material", "version": 1, "name": "plaster", "model": "merl", "merl_file": "lambert.binary"})";
    auto material = parseMaterial(text, folder + "/plaster.json");
    ASSERT_TRUE(material.ok()) << material.error().format();
    ASSERT_TRUE(material->measured());
    EXPECT_EQ(material->name, "plaster");
    const nlohmann::json written = materialToJson(*material, folder + "/sub/again.json");
    EXPECT_EQ(written["model"], "merl");
    EXPECT_EQ(written["merl_file"], "../lambert.binary");
    // Outside the folder of again.json: refused unless allowed (util/reference_confinement.h).
    auto refused = parseMaterial(written.dump(), folder + "/sub/again.json");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("refused '../lambert.binary'"), std::string::npos) << refused.error().format();
    const OutsideReferencesAllowance allowed;
    auto again = parseMaterial(written.dump(), folder + "/sub/again.json");
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(again->measured()->brdf->table.reflectance, material->measured()->brdf->table.reflectance);
}

TEST(MeasuredMaterial, JsonRefusesBadReferencesAtTheKey) {
    const std::string folder = test::outputDirectory("measured_material");
    measuredTestFile();
    ASSERT_TRUE(writeFileAtomically(folder + "/short.binary", std::string(100, '\0')).ok());
    struct Case {
        const char* body;
        const char* expected;
    };
    const Case cases[] = {
        {R"("model": "merl", "merl_file": "missing.binary")", "not a readable MERL .binary file"},
        {R"("model": "lambert", "merl_file": "lambert.binary")", "\"model\": \"merl\""},
        {R"("model": "merl", "merl_file": "short.binary")", "not a MERL BRDF"},
        {R"("model": "merl", "merl_file": "lambert.binary", "albedo": 0.5)", "albedo"},
    };
    for (const Case& testCase : cases) {
        const std::string text = std::string("{\"format\": \"glint-material\", \"version\": 1,\n  ") + testCase.body + "}";
        auto material = parseMaterial(text, folder + "/bad.json");
        ASSERT_FALSE(material.ok()) << testCase.body;
        EXPECT_NE(material.error().message.find(testCase.expected), std::string::npos) << material.error().format();
        EXPECT_EQ(material.error().where.line, 2) << material.error().format();
    }
}

TEST(MeasuredMaterial, BinaryFilesOpenThroughTheImportTable) {
    const ImportFormat* format = findImportFormat("/some/where/BRASS.BINARY");
    ASSERT_NE(format, nullptr);
    auto imported = format->load(measuredTestFile());
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    ASSERT_EQ(imported->materials.size(), 1u);
    EXPECT_TRUE(imported->materials[0].material.measured());
    EXPECT_TRUE(allWarnings(*imported).empty());
}

TEST(MeasuredMaterial, CpuReferenceOfAConstantTableIsTheLambertModel) {
    auto brdf = loadMeasuredBrdf(measuredTestFile());
    ASSERT_TRUE(brdf.ok()) << brdf.error().format();
    Scene measured = previewStage(measuredBrdfMaterial(*brdf), 48, 48);
    Material lambert = Material::withDefaults("lambert", BrdfModel::Lambert);
    lambert.analytic()->values = {kMeasuredTestAlbedo.r, kMeasuredTestAlbedo.g, kMeasuredTestAlbedo.b};
    Scene analytic = previewStage(lambert, 48, 48);
    Light ambient;
    ambient.type = LightType::Ambient;
    measured.lights.push_back(ambient);
    analytic.lights.push_back(ambient);
    const RadianceImage fromTable = renderReference(measured, 48, 48), fromModel = renderReference(analytic, 48, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(fromTable.at(x, y)[c], fromModel.at(x, y)[c], 1e-5f + 1e-5f * fromModel.at(x, y)[c]) << x << "," << y;
}

}  // namespace
}  // namespace glint
