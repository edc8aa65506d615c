// Environment maps on the CPU: HDR files and their bad inputs, the scene-file keys, the
// precomputed lighting (SH9, prefiltering), the white-out and the GGX white furnace through the
// CPU reference, both its GPU twin and its Monte-Carlo sampling.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "brdf/cook_torrance.h"
#include "environment/environment_lighting.h"
#include "environment/environment_map.h"
#include "environment_test_support.h"
#include "render/reference_renderer.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

// --- HDR files ------------------------------------------------------------------------------

TEST(EnvironmentFile, ReadsAnHdrFileItWrote) {
    const std::string path = test::outputDirectory("environment") + "/sky.hdr";
    test::writeTestHdr(path, 64);
    auto image = readEquirectFile(path);
    ASSERT_TRUE(image.ok()) << image.error().format();
    EXPECT_EQ(image->width, 64);
    EXPECT_EQ(image->height, 32);
}

Diagnostic expectRefused(const std::string& path) {
    auto image = readEquirectFile(path);
    EXPECT_FALSE(image.ok()) << path;
    if (image.ok()) return {};
    EXPECT_EQ(image.error().where.file, path);
    return image.error();
}

TEST(EnvironmentFile, RefusesATruncatedFile) {
    const std::string directory = test::outputDirectory("environment");
    test::writeTestHdr(directory + "/whole.hdr", 64);
    std::ifstream in(directory + "/whole.hdr", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(directory + "/truncated.hdr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    expectRefused(directory + "/truncated.hdr");
}

TEST(EnvironmentFile, RefusesAWrongMagicNumber) {
    const std::string path = test::outputDirectory("environment") + "/not_radiance.hdr";
    std::ofstream(path) << "#?NOTRADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\nrubbish";
    expectRefused(path);
}

TEST(EnvironmentFile, RefusesNanAndNegativeTexelsNamingThem) {
    const std::string directory = test::outputDirectory("environment");
    test::writeTestHdr(directory + "/nan.exr", 16, std::nanf(""), true);
    EXPECT_NE(expectRefused(directory + "/nan.exr").message.find("texel (3, 4)"), std::string::npos);
    test::writeTestHdr(directory + "/negative.exr", 16, -1.0f, true);
    EXPECT_NE(expectRefused(directory + "/negative.exr").message.find("non-negative"), std::string::npos);
}

TEST(EnvironmentFile, RefusesAMapThatIsNotTwoToOne) {
    const std::string path = test::outputDirectory("environment") + "/square.exr";
    std::vector<float> texels(8 * 8 * 3, 1.0f);
    auto output = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(output->open(path, OIIO::ImageSpec(8, 8, 3, OIIO::TypeDesc::FLOAT)));
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, texels.data()));
    output->close();
    EXPECT_NE(expectRefused(path).message.find("twice as wide"), std::string::npos);
}

TEST(EnvironmentFile, AFailedLoadLeavesTheEnvironmentAsItWas) {
    Environment environment;
    environment.kind = EnvironmentKind::Studio;
    ASSERT_TRUE(loadEnvironment(environment).ok());
    Environment attempt = environment;
    attempt.kind = EnvironmentKind::File;
    attempt.file = "/nonexistent/sky.hdr";
    EXPECT_FALSE(loadEnvironment(attempt).ok());
    EXPECT_EQ(attempt.map, environment.map);
    EXPECT_EQ(attempt.file, "/nonexistent/sky.hdr");
}

// --- scene files ----------------------------------------------------------------------------

std::string sceneWithEnvironment(const std::string& environmentJson) {
    return R"({"format": "glint-scene", "version": 1,
  "environment": )" + environmentJson + R"(,
  "materials": [{"name": "m", "model": "lambert"}],
  "objects": [{"shape": "sphere", "material": "m"}]
})";
}

TEST(EnvironmentJson, RoundTripsThroughSaveAndLoad) {
    auto scene = parseScene(sceneWithEnvironment(R"({"type": "studio", "rotation_degrees": 30, "intensity": 2.5,
        "show_as_background": false})"), "env.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    EXPECT_EQ(scene->environment.kind, EnvironmentKind::Studio);
    ASSERT_TRUE(scene->environment.enabled());
    const std::string path = test::outputDirectory("environment") + "/saved.json";
    ASSERT_TRUE(saveScene(*scene, path).ok());
    auto again = loadScene(path);
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(again->environment.kind, EnvironmentKind::Studio);
    EXPECT_FLOAT_EQ(again->environment.rotationDegrees, 30.0f);
    EXPECT_FLOAT_EQ(again->environment.intensity, 2.5f);
    EXPECT_FALSE(again->environment.showAsBackground);
    EXPECT_EQ(sceneToJson(*again), sceneToJson(*scene));
}

TEST(EnvironmentJson, AFileIsFoundBesideTheSceneAndRoundTrips) {
    const std::string directory = test::outputDirectory("environment_json");
    test::writeTestHdr(directory + "/sky.exr", 32);
    std::ofstream(directory + "/scene.json") << sceneWithEnvironment(R"({"type": "file", "file": "sky.exr"})");
    auto scene = loadScene(directory + "/scene.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    ASSERT_TRUE(scene->environment.enabled());
    EXPECT_EQ(scene->environment.map->radiance.width, 32);
    ASSERT_TRUE(saveScene(*scene, directory + "/again.json").ok());
    auto again = loadScene(directory + "/again.json");
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(again->environment.map->radiance.texels, scene->environment.map->radiance.texels);
}

TEST(EnvironmentJson, MistakesAreLocated) {
    const struct {
        const char* json;
        const char* says;
    } cases[] = {
        {R"({"type": "studio", "intensity": -1})", "'intensity'"},
        {R"({"type": "studio", "rotation_degrees": 720})", "'rotation_degrees'"},
        {R"({"type": "sunset"})", "'type'"},
        {R"({"type": "file"})", "'file'"},
        {R"({"type": "file", "file": "missing.hdr"})", "cannot read the environment image"},
        {R"({"type": "white", "brightness": 2})", "brightness"},
    };
    for (const auto& c : cases) {
        auto scene = parseScene(sceneWithEnvironment(c.json), "bad.json");
        ASSERT_FALSE(scene.ok()) << c.json;
        EXPECT_EQ(scene.error().where.file, "bad.json") << c.json;
        EXPECT_EQ(scene.error().where.line, 2) << c.json << ": " << scene.error().format();
        EXPECT_NE(scene.error().message.find(c.says), std::string::npos) << scene.error().format();
    }
}

// --- precomputed lighting -------------------------------------------------------------------

TEST(EnvironmentMap, UniformWhiteIsUniformAtEveryLevel) {
    auto map = loadEnvironmentMap(EnvironmentKind::White, "");
    ASSERT_TRUE(map.ok());
    for (glm::vec3 d : {glm::vec3(0, 1, 0), glm::vec3(0.6f, -0.8f, 0), glm::vec3(0, 0, -1)}) {
        EXPECT_NEAR(shIrradiance((*map)->irradianceSh, d).g, kPi, 2e-4f * kPi);
        for (float r : {0.0f, 0.1f, 0.5f, 0.93f, 1.0f}) EXPECT_NEAR(prefilteredRadiance(**map, d, r).b, 1.0f, 1e-5f);
    }
}

TEST(EnvironmentMap, ShIrradianceOfTheSkyMatchesQuadrature) {
    auto map = loadEnvironmentMap(EnvironmentKind::Sky, "");
    ASSERT_TRUE(map.ok());
    // E(n) = ∫ L cos⁺ dω by brute force over the base texels, against the SH9 reconstruction: a
    // smooth sky is almost all in l ≤ 2 (Ramamoorthi & Hanrahan: within a few percent).
    const EquirectImage& radiance = (*map)->radiance;
    for (glm::vec3 normal : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(0, -1, 0)}) {
        glm::vec3 irradiance(0.0f);
        for (int y = 0; y < radiance.height; ++y)
            for (int x = 0; x < radiance.width; ++x) {
                const glm::vec3 d = equirectDirection({(x + 0.5f) / radiance.width, (y + 0.5f) / radiance.height});
                irradiance += radiance.at(x, y) * std::max(0.0f, glm::dot(d, normal)) * texelSolidAngle(y, radiance.width, radiance.height);
            }
        const glm::vec3 sh = shIrradiance((*map)->irradianceSh, normal);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh[c], irradiance[c], 0.03f * irradiance[c]) << c;
    }
}

TEST(EnvironmentMap, RotationTurnsTheMapAboutY) {
    Environment environment;
    environment.kind = EnvironmentKind::Studio;
    ASSERT_TRUE(loadEnvironment(environment).ok());
    const glm::vec3 seen = environmentRadiance(environment, {1, 0, 0});
    environment.rotationDegrees = 90.0f;
    // Turned by 90°, what was seen along +x is seen along −z... (x' = x cos − z sin).
    const glm::vec3 turned = environmentRadiance(environment, {0, 0, -1});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(turned[c], seen[c], 1e-4f);
}

// --- white-out and white furnace (CPU) -------------------------------------------------------

// Pixels well inside the unit sphere's disc of the 2.2-high orthographic view, with μ = cos θ_o.
template <class Check>
void forDiscPixels(const RadianceImage& image, float minCosine, Check check) {
    const float pixelSize = 2.2f / image.height;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float px = -1.1f + (x + 0.5f) * pixelSize, py = 1.1f - (y + 0.5f) * pixelSize;
            const float r2 = px * px + py * py;
            if (r2 >= 1.0f) continue;
            const float cosine = std::sqrt(1.0f - r2);
            if (cosine >= minCosine) check(x, y, cosine);
        }
}

Material lambert(float albedo) {
    Material material = Material::withDefaults("white-out", BrdfModel::Lambert);
    std::fill(material.values.begin(), material.values.end(), albedo);
    return material;
}

TEST(WhiteOut, LambertUnderUniformWhiteIsAFlatDiscOnTheCpu) {
    Scene scene = test::sphereUnderEnvironment(lambert(0.6f), EnvironmentKind::White);
    scene.environment.intensity = 2.0f;  // L = 2 W/(sr·m²): ρ·L = 1.2 everywhere on the disc
    for (bool sampled : {false, true}) {
        const RadianceImage image = renderReference(scene, 48, 48, {sampled, 64});
        forDiscPixels(image, 0.0f, [&](int x, int y, float) {
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], 1.2f, 1.2f * 2e-4f) << x << "," << y;
        });
    }
}

// A conductor with F = 1 (Schlick, F0 = 1 from κ = 10⁴): the specular lobe alone.
Material perfectConductor(float roughness) {
    Material material = Material::withDefaults("furnace", BrdfModel::CookTorrance);
    CookTorranceParams params = unpackCookTorrance(material.values.data());
    material.values = {0, 0, 0, 1, 1, 1, 1e4f, 1e4f, 1e4f, roughness, 1, 1, 0};
    EXPECT_EQ(unpackCookTorrance(material.values.data()).fresnel, FresnelMode::Schlick);
    (void)params;
    return material;
}

TEST(WhiteFurnace, GgxConductorUnderUniformWhiteReflectsLOnTheCpu) {
    // Smooth GGX loses little to single scattering: L·E(μ) ≈ L where μ = cos θ_o ≥ 0.7 (E = 0.988
    // at μ = 1, 0.981 at μ = 0.7 for α = 0.1, by quadrature; E falls to 0.957 at μ = 0.4 as the
    // lobe dips below the horizon). The sampled reference (512 samples per pixel) is within 2.5%.
    const Scene scene = test::sphereUnderEnvironment(perfectConductor(0.1f), EnvironmentKind::White);
    const RadianceImage image = renderReference(scene, 32, 32, {true, 512});
    forDiscPixels(image, 0.7f, [&](int x, int y, float) {
        ASSERT_NEAR(image.at(x, y).g, 1.0f, 0.025f) << x << "," << y;
    });
}

}  // namespace
}  // namespace glint
