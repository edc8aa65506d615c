// Material presets: every preset is a valid material that survives a file round trip, names a
// source, the metals' complex indices give the published normal-incidence reflectance F0, and the
// clear dielectrics refract.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "brdf/cook_torrance.h"
#include "brdf/fresnel.h"
#include "brdf/glass.h"
#include "brdf/presets.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

TEST(Presets, EveryPresetIsAValidMaterialWithASource) {
    std::set<std::string> names;
    for (const Preset& preset : allPresets()) {
        SCOPED_TRACE(preset.name);
        EXPECT_TRUE(names.insert(preset.name).second) << "duplicate name";
        EXPECT_GT(std::string(preset.source).size(), 10u);
        EXPECT_EQ(findPreset(preset.name), &preset);
        const Material material = preset.material();
        // Through a file, as `glint presets NAME -o FILE` writes it: the reader checks every range.
        const std::string path = test::outputDirectory("presets") + "/" + preset.name + ".json";
        ASSERT_TRUE(saveMaterial(material, path).ok());
        auto loaded = loadMaterial(path);
        ASSERT_TRUE(loaded.ok()) << loaded.error().format();
        EXPECT_EQ(loaded->analytic()->values, material.analytic()->values);
        EXPECT_EQ(loaded->analytic()->model, preset.model);
    }
    EXPECT_EQ(findPreset("unobtainium"), nullptr);
}

glm::vec3 presetF0(const char* name) {
    const Preset* preset = findPreset(name);
    EXPECT_NE(preset, nullptr) << name;
    const CookTorranceParams params = unpack<CookTorrance>(preset->material().analytic()->values.data());
    return fresnelF0(params.ior, params.extinction);
}

TEST(Presets, MetalF0MatchesPublishedValues) {
    // Published F0 (linear sRGB) of Akenine-Möller et al., Real-Time Rendering 4th ed. (2018),
    // Table 9.2: integrated over the visible spectrum and clipped to [0, 1] (gold's red). The presets'
    // F0 is the same integration of measured spectra (D65, CIE 1931; metal_spectra.h,
    // exact to float precision: tests/metal_spectra_test.cpp). All within 0.01 but iron, measured
    // (+0.0125, +0.0022, -0.0154) off with Querry's data, the closest we found (Johnson & Christy
    // 1974: -0.084 in blue; Werner 2009: +0.33).
    struct Published {
        const char* name;
        glm::vec3 f0;
        glm::vec3 measuredDeviation;  // zero: within 0.01; else the deviation asserted (± 0.001)
    };
    const Published published[] = {
        {"gold", {1.000f, 0.782f, 0.344f}, glm::vec3(0.0f)},
        {"silver", {0.972f, 0.960f, 0.915f}, glm::vec3(0.0f)},
        {"copper", {0.955f, 0.638f, 0.538f}, glm::vec3(0.0f)},
        {"aluminium", {0.913f, 0.922f, 0.924f}, glm::vec3(0.0f)},
        {"iron", {0.562f, 0.565f, 0.578f}, {0.0125f, 0.0022f, -0.0154f}},
        {"chromium", {0.549f, 0.556f, 0.554f}, glm::vec3(0.0f)},
    };
    std::printf("%-10s %-21s %-21s %s\n", "metal", "RTR4 Table 9.2", "preset F0", "deviation");
    for (const Published& metal : published) {
        const glm::vec3 f0 = presetF0(metal.name);
        const glm::vec3 deviation = f0 - metal.f0;
        std::printf("%-10s (%.3f, %.3f, %.3f) (%.4f, %.4f, %.4f) (%+.4f, %+.4f, %+.4f)\n", metal.name, metal.f0.r,
                    metal.f0.g, metal.f0.b, f0.r, f0.g, f0.b, deviation.r, deviation.g, deviation.b);
        for (int c = 0; c < 3; ++c) {
            if (metal.measuredDeviation == glm::vec3(0.0f)) EXPECT_NEAR(f0[c], metal.f0[c], 0.01f) << metal.name << " channel " << c;
            else EXPECT_NEAR(deviation[c], metal.measuredDeviation[c], 0.001f) << metal.name << " channel " << c;
        }
    }
    // Gold's colour: red reflects most, blue least.
    const glm::vec3 gold = presetF0("gold");
    EXPECT_GT(gold.r, gold.g);
    EXPECT_GT(gold.g, gold.b);
}

TEST(Presets, ClearDielectricsRefractWithTheirIndex) {
    // Glass, water, diamond and ice are the refracting `glass` model (clear: no absorption, exact
    // Fresnel), so they read as transparent on the preview stage; F0 follows from n alone.
    for (const auto& [name, ior] : {std::pair{"glass", 1.5f}, {"water", 1.333f}, {"diamond", 2.42f}, {"ice", 1.31f}}) {
        const Preset* preset = findPreset(name);
        ASSERT_NE(preset, nullptr) << name;
        EXPECT_EQ(preset->model, BrdfModel::Glass) << name;
        const GlassParams params = unpack<Glass>(preset->material().analytic()->values.data());
        EXPECT_EQ(params.ior, ior) << name;
        EXPECT_EQ(params.absorption, glm::vec3(0.0f)) << name << " is clear";
        EXPECT_EQ(params.transparency, GlassTransparency::Fresnel) << name << " uses the exact Fresnel equations";
        const glm::vec3 f0 = fresnelF0(glm::vec3(params.ior), glm::vec3(0.0f));
        EXPECT_NEAR(f0.r, (ior - 1) * (ior - 1) / ((ior + 1) * (ior + 1)), 1e-6f) << name;
    }
    const float glassIor = unpack<Glass>(findPreset("glass")->material().analytic()->values.data()).ior;
    EXPECT_NEAR(fresnelF0(glm::vec3(glassIor), glm::vec3(0.0f)).r, 0.04f, 1e-6f);
}

TEST(Presets, PlasticsHaveAWhiteSpecularWithTheirIndex) {
    for (const auto& [name, ior] : {std::pair{"red_acrylic", 1.49f}, {"white_polystyrene", 1.59f}}) {
        const glm::vec3 f0 = presetF0(name);
        EXPECT_NEAR(f0.r, (ior - 1) * (ior - 1) / ((ior + 1) * (ior + 1)), 1e-6f) << name;
        EXPECT_EQ(f0.r, f0.b) << name << " has a white specular";
    }
}

}  // namespace
}  // namespace glint
