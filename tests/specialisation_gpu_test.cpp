// Specialised programs (gl/shader_specialisation.h) draw the same pictures as the generic ones:
// for every light kind (directional, point, spot, classic attenuation), each kind of shadow map, a sky
// and a constant background (a clear), the fused display's choices and a material's enum choices,
// and OpenPBR's layers weighted zero, the radiance agrees to float rounding and the 8-bit display
// image byte for byte.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "brdf/model_registry.h"
#include "brdf/param_table.h"
#include "gl/frame_uniforms.h"
#include "gl/shader_specialisation.h"
#include "gpu_test_support.h"

namespace glint {
namespace {

// The default stage (sphere on a floor) without its environment and MSAA, lit by one light of
// each kind; the key, fill and spot lights cast shadows (an orthographic, a cube and a perspective
// map, in three slots).
Scene everyLightKind() {
    Scene scene = defaultScene();
    scene.environment = Environment{};
    scene.msaaSamples = 1;
    scene.lights.resize(1);
    scene.lights[0].castsShadows = true;
    Light fill;
    fill.name = "fill";
    fill.type = LightType::Point;
    fill.position = {-2.0f, 1.5f, 2.0f};
    fill.castsShadows = true;
    Light spot;
    spot.name = "spot";
    spot.type = LightType::Spot;
    spot.position = {-1.5f, 2.5f, 1.5f};
    spot.direction = glm::normalize(glm::vec3(1.5f, -2.5f, -1.5f));
    spot.falloffExponent = 2.0f;
    spot.castsShadows = true;
    Light classic;
    classic.name = "classic";
    classic.type = LightType::Point;
    classic.position = {0.0f, 1.0f, 3.0f};
    classic.attenuation.enabled = true;
    classic.attenuation.coefficients = {1.0f, 0.2f, 0.05f};
    scene.lights.push_back(fill);
    scene.lights.push_back(spot);
    scene.lights.push_back(classic);
    return scene;
}

struct Rendered {
    RadianceImage radiance;
    DisplayImage display;
};

Rendered renderWith(const Scene& scene, bool specialised) {
    Renderer& renderer = test::sharedHeadless().renderer();
    renderer.options().specialisePrograms = specialised;
    auto images = test::sharedHeadless().render(scene, 96, 72);
    renderer.options().specialisePrograms = true;
    EXPECT_TRUE(images.ok()) << images.error().format();
    if (!images.ok()) return {RadianceImage(96, 72), DisplayImage(96, 72)};
    return {std::move(images->radiance), std::move(images->display)};
}

void expectSamePictures(const Scene& scene, const std::string& what) {
    const Rendered generic = renderWith(scene, false), specialised = renderWith(scene, true);
    ASSERT_EQ(generic.radiance.pixels.size(), specialised.radiance.pixels.size());
    float worst = 0.0f;
    for (size_t i = 0; i < generic.radiance.pixels.size(); ++i) {
        const float a = generic.radiance.pixels[i], b = specialised.radiance.pixels[i];
        worst = std::max(worst, std::abs(a - b) / std::max(std::abs(a), 1e-3f));
    }
    EXPECT_LT(worst, 1e-5f) << what << ": worst relative radiance difference";
    EXPECT_EQ(generic.display.pixels, specialised.display.pixels) << what;
}

TEST(Specialisation, EveryLightKindAndAShadowDrawTheGenericPicture) {
    expectSamePictures(everyLightKind(), "constant background");
    Scene sky = everyLightKind();
    sky.background.kind = BackgroundKind::Sky;
    expectSamePictures(sky, "sky");
}

TEST(Specialisation, ManyLightsOfEveryKindDrawTheGenericPicture) {
    // 30 lights of the four kinds, two of them shadowed (unrolled among the looped ones): interleaved
    // (loops of any kind between the unrolled lights), then grouped by kind (a loop per kind's run).
    const Scene kinds = everyLightKind();
    Scene scene = kinds;
    scene.lights.clear();
    for (int i = 0; i < 30; ++i) {
        Light light = kinds.lights[i % kinds.lights.size()];
        light.position += glm::vec3(0.1f * (i % 5), 0.0f, -0.1f * (i % 3));
        light.power /= 8.0f;
        light.irradiance /= 8.0f;
        light.castsShadows = i == 0 || i == 9;
        scene.lights.push_back(light);
    }
    expectSamePictures(scene, "30 lights, kinds interleaved");
    const auto kindOrder = [](const Light& light) { return 2 * static_cast<int>(light.type) + light.attenuation.enabled; };
    std::stable_sort(scene.lights.begin(), scene.lights.end(),
                     [&](const Light& a, const Light& b) { return kindOrder(a) < kindOrder(b); });
    expectSamePictures(scene, "30 lights, grouped by kind");
}

TEST(Specialisation, DisplayChoicesDrawTheGenericPicture) {
    Scene scene = everyLightKind();
    scene.display = {1.0f, Transfer::Gamma, 1.8f, ToneMap::Reinhard};
    scene.display.levels = 8;
    scene.display.dither = Dither::Bayer4;  // a dithered background is drawn, not cleared
    expectSamePictures(scene, "gamma, Reinhard, 8 levels, Bayer 4x4");
    scene.display.dither = Dither::None;
    scene.display.toneMap = ToneMap::AcesFilmic;
    expectSamePictures(scene, "ACES, 8 levels");
}

TEST(Specialisation, MaterialChoicesDrawTheGenericPicture) {
    Scene scene = everyLightKind();
    Material& material = scene.materials[0];
    material = Material::withDefaults("metal", BrdfModel::CookTorrance);
    const auto table = modelInfo(BrdfModel::CookTorrance).params;
    for (int distribution : {0, 1})
        for (int geometry : {0, 1})
            for (int fresnel : {0, 1}) {
                material.analytic()->values[packedOffset(table, findParam(table, "distribution"))] = static_cast<float>(distribution);
                material.analytic()->values[packedOffset(table, findParam(table, "geometry"))] = static_cast<float>(geometry);
                material.analytic()->values[packedOffset(table, findParam(table, "fresnel"))] = static_cast<float>(fresnel);
                expectSamePictures(scene, "cook_torrance " + std::to_string(distribution) + std::to_string(geometry) +
                                              std::to_string(fresnel));
            }
}

TEST(Specialisation, LayersWeightedZeroAreCompiledOutAndDrawTheGenericPicture) {
    Scene scene = everyLightKind();
    Material& material = scene.materials[0];
    material = Material::withDefaults("openpbr", BrdfModel::OpenPbr);
    const auto table = modelInfo(BrdfModel::OpenPbr).params;
    const auto weight = [&](const char* name) -> float& { return material.analytic()->values[packedOffset(table, findParam(table, name))]; };
    weight("coat_weight") = 0.0f;
    weight("fuzz_weight") = 0.0f;
    const std::string defines = materialSpecialisation(*material.analytic());
    EXPECT_NE(defines.find("#define GLINT_PARAM_coat_weight 0.0"), std::string::npos) << defines;
    EXPECT_NE(defines.find("#define GLINT_PARAM_fuzz_weight 0.0"), std::string::npos) << defines;
    expectSamePictures(scene, "openpbr, no coat or fuzz");
    weight("coat_weight") = 0.7f;
    EXPECT_EQ(materialSpecialisation(*material.analytic()).find("GLINT_PARAM_coat_weight"), std::string::npos);
}

TEST(Specialisation, TheFramesChoicesBecomeConstants) {
    const Scene scene = everyLightKind();
    ShadowBlockStd140 shadows{};
    for (glm::ivec4& entry : shadows.mapOfLight) entry = glm::ivec4(-1);
    shadows.mapOfLight[0][0] = 0;  // the key light has map 0 (orthographic)
    shadows.mapOfLight[0][1] = 2;  // the point light has map 2, a cube map
    shadows.origin[2].w = static_cast<float>(ShadowMapKind::Cube);
    const std::string text = frameSpecialisation(packFrameUniforms(scene, 64, 64), shadows, scene.environment, scene.display);
    EXPECT_NE(text.find("#define GLINT_LIGHT_SUM(term) (term(0, LIGHT_DIRECTIONAL, 0, 0) + term(1, LIGHT_POINT, 2, 2) + "
                        "term(2, LIGHT_ANY, -1, 0) + term(3, LIGHT_ANY, -1, 0))\n"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find("GLINT_LOOPED"), std::string::npos) << "4 lights are all unrolled";
    // Beyond kMaxUnrolledLights, the lights without a map are looped over, a loop per run of one kind.
    const Light& point = scene.lights[1];
    const Light& classic = scene.lights[3];
    Scene runs = scene;
    runs.lights.insert(runs.lights.end(), 7, point);
    runs.lights.insert(runs.lights.end(), 2, classic);
    runs.lights.push_back(scene.lights[0]);  // directional
    const std::string runsText = frameSpecialisation(packFrameUniforms(runs, 64, 64), shadows, runs.environment, runs.display);
    EXPECT_NE(runsText.find("#define GLINT_LOOPED_LIGHT_SUM(run) (run(8, 11, LIGHT_POINT) + run(11, 13, LIGHT_ANY) + "
                            "run(13, 14, LIGHT_DIRECTIONAL))\n"),
              std::string::npos)
        << runsText;
    // Kinds alternating into more than kMaxLightRuns runs: a loop of any kind on each side of light
    // 10, which has a map and is unrolled.
    Scene alternating = scene;
    alternating.lights.insert(alternating.lights.end(), 4, point);
    for (int i = 0; i < 8; ++i) alternating.lights.push_back(i % 2 ? classic : point);
    shadows.mapOfLight[2][2] = 1;  // light 10: map 1, orthographic
    const std::string alternatingText =
        frameSpecialisation(packFrameUniforms(alternating, 64, 64), shadows, alternating.environment, alternating.display);
    EXPECT_NE(alternatingText.find("term(10, LIGHT_POINT, 1, 0))\n#define GLINT_LOOPED_LIGHT_SUM(run) (run(8, 10, LIGHT_ANY) + "
                                   "run(11, 16, LIGHT_ANY))\n"),
              std::string::npos)
        << alternatingText;
    EXPECT_NE(text.find("#define GLINT_FUSED_DISPLAY 1"), std::string::npos);
    EXPECT_NE(text.find("#define GLINT_ENVIRONMENT_ENABLED 0"), std::string::npos);
    EXPECT_NE(materialSpecialisation(*Material::withDefaults("plastic", BrdfModel::BlinnPhong).analytic()).find("#define GLINT_PARAM_form "),
              std::string::npos);
}

}  // namespace
}  // namespace glint
