// The GLSL twin of every BRDF model against its C++ reference: each model with three parameter
// sets (plus exponent 0 where valid), on a sphere and a floor plane under a point, a directional,
// a spot and an ambient light (tests/scenes/sweep_lights.json), rendered headless at 96×96 and
// compared pixel by pixel on linear float output (silhouettes excluded).
#include <gtest/gtest.h>

#include <cstdio>
#include <utility>
#include <vector>

#include "gpu_test_support.h"
#include "test_support.h"

namespace glint {
namespace {

using Setting = std::pair<const char*, glm::vec3>;

struct SweepCase {
    const char* model;
    std::vector<Setting> settings;  // over the model's defaults
};

const SweepCase kSweep[] = {
    {"lambert", {{"albedo", {0.8f, 0.5f, 0.2f}}}},
    {"lambert", {{"albedo", {0.0f, 0.0f, 0.0f}}}},
    {"lambert", {{"albedo", {1.0f, 1.0f, 1.0f}}}},
    {"blinn_phong", {{"form", glm::vec3(0)}, {"exponent", glm::vec3(30)}}},
    {"blinn_phong", {{"form", glm::vec3(2)}, {"exponent", glm::vec3(300)}, {"specular", glm::vec3(0.5f)}}},
    {"blinn_phong", {{"form", glm::vec3(3)}, {"exponent", glm::vec3(4)}}},
    {"blinn_phong", {{"form", glm::vec3(1)}, {"exponent", glm::vec3(0)}}},  // x^0 = 1, also for x = 0
    {"oren_nayar", {{"roughness", glm::vec3(0)}}},
    {"oren_nayar", {{"roughness", glm::vec3(30)}, {"albedo", {0.7f, 0.4f, 0.3f}}}},
    {"oren_nayar", {{"roughness", glm::vec3(90)}}},
    {"phong", {{"form", glm::vec3(0)}, {"exponent", glm::vec3(20)}}},
    {"phong", {{"form", glm::vec3(1)}, {"exponent", glm::vec3(200)}, {"specular", glm::vec3(0.6f)}}},
    {"phong", {{"form", glm::vec3(3)}, {"exponent", glm::vec3(8)}}},
    {"phong", {{"form", glm::vec3(3)}, {"exponent", glm::vec3(0)}}},
    {"cook_torrance", {{"distribution", glm::vec3(1)}, {"geometry", glm::vec3(1)}, {"fresnel", glm::vec3(1)},
                       {"ior", {0.18299f, 0.42108f, 1.3734f}}, {"extinction", {3.4242f, 2.3459f, 1.7704f}},
                       {"roughness", glm::vec3(0.15f)}}},
    {"cook_torrance", {{"distribution", glm::vec3(0)}, {"geometry", glm::vec3(0)}, {"fresnel", glm::vec3(0)},
                       {"diffuse_albedo", {0.5f, 0.1f, 0.1f}}, {"roughness", glm::vec3(0.3f)}}},
    {"cook_torrance", {{"distribution", glm::vec3(0)}, {"geometry", glm::vec3(1)}, {"fresnel", glm::vec3(1)},
                       {"ior", glm::vec3(0.75f)}, {"roughness", glm::vec3(0.6f)}}},  // n < 1: total internal reflection
    {"ggx_anisotropic", {}},
    {"ggx_anisotropic", {{"roughness_x", glm::vec3(0.5f)}, {"roughness_y", glm::vec3(0.08f)}, {"fresnel", glm::vec3(0)}}},
    {"ggx_anisotropic", {{"roughness_x", glm::vec3(0.2f)}, {"roughness_y", glm::vec3(0.2f)}, {"diffuse_albedo", glm::vec3(0.3f)},
                         {"ior", glm::vec3(1.5f)}, {"extinction", glm::vec3(0)}}},
    {"ward", {}},
    {"ward", {{"normalization", glm::vec3(0)}, {"roughness_x", glm::vec3(0.3f)}, {"roughness_y", glm::vec3(0.05f)}}},
    {"ward", {{"roughness_x", glm::vec3(0.2f)}, {"roughness_y", glm::vec3(0.2f)}, {"specular", {0.9f, 0.6f, 0.3f}}}},
    {"retroreflective", {}},
    {"retroreflective", {{"limb_darkening", glm::vec3(0)}, {"minnaert_k", glm::vec3(0.6f)}, {"albedo", glm::vec3(0.5f)}}},
    {"retroreflective", {{"limb_darkening", glm::vec3(0)}, {"minnaert_k", glm::vec3(1.4f)},
                         {"retroreflection", {0.8f, 0.8f, 0.2f}}, {"retro_exponent", glm::vec3(20)}}},
    {"retroreflective", {{"retroreflection", glm::vec3(0.5f)}, {"retro_exponent", glm::vec3(0)}}},
    {"mirror", {}},
    {"mirror", {{"extinction", glm::vec3(0)}, {"ior", glm::vec3(1.5f)}, {"diffuse_albedo", {0.3f, 0.2f, 0.1f}}}},
    {"mirror", {{"ior", {0.18299f, 0.42108f, 1.3734f}}, {"extinction", {3.4242f, 2.3459f, 1.7704f}}}},
    {"glass", {}},
    {"glass", {{"ior", glm::vec3(1.33f)}, {"absorption", {0.1f, 0.6f, 1.2f}}}},
    {"glass", {{"transparency", glm::vec3(1)}, {"transmission", glm::vec3(0.7f)}, {"ior", glm::vec3(2.42f)}}},
    {"openpbr", {}},
    {"openpbr", {{"base_metalness", glm::vec3(1)}, {"base_color", {0.95f, 0.75f, 0.35f}}, {"specular_color", {1.0f, 0.9f, 0.7f}},
                 {"specular_roughness_anisotropy", glm::vec3(0.7f)}, {"geometry_tangent_rotation", glm::vec3(30)},
                 {"thin_film_weight", glm::vec3(0.5f)}}},
    {"openpbr", {{"base_color", {0.5f, 0.05f, 0.05f}}, {"base_diffuse_roughness", glm::vec3(0.7f)}, {"coat_weight", glm::vec3(1)},
                 {"coat_roughness", glm::vec3(0.15f)}, {"coat_color", {0.9f, 0.9f, 0.8f}}, {"fuzz_weight", glm::vec3(0.6f)},
                 {"fuzz_color", {0.3f, 0.3f, 0.9f}}, {"emission_luminance", glm::vec3(20)}, {"transmission_weight", glm::vec3(0.5f)}}},
};

Material sweepMaterial(const SweepCase& sweep) {
    const auto model = findModel(sweep.model);
    EXPECT_TRUE(model.has_value()) << sweep.model;
    Material material = Material::withDefaults(sweep.model, *model);
    const auto table = modelInfo(*model).params;
    for (const auto& [name, value] : sweep.settings) {
        const int index = findParam(table, name);
        EXPECT_GE(index, 0) << sweep.model << "." << name;
        for (int c = 0; c < componentCount(table[index].kind); ++c)
            material.analytic()->values[packedOffset(table, index) + c] = value[c];
    }
    return material;
}

TEST(BrdfGpuSweep, EveryModelMatchesItsCppTwin) {
    Scene scene = test::loadTestScene("scenes/sweep_lights.json");
    ASSERT_EQ(scene.lights.size(), 4u);
    EXPECT_EQ(scene.lights[0].type, LightType::Point);
    EXPECT_EQ(scene.lights[1].type, LightType::Directional);
    EXPECT_EQ(scene.lights[2].type, LightType::Spot);
    EXPECT_EQ(scene.lights[3].type, LightType::Ambient);  // each model's ambient hook, too
    std::vector<bool> modelSwept(allModels().size(), false);
    for (const SweepCase& sweep : kSweep) {
        const Material material = sweepMaterial(sweep);
        scene.materials = {material};
        for (SceneObject& object : scene.objects) object.materialIndex = 0;
        auto images = test::sharedHeadless().render(scene, 96, 96);
        ASSERT_TRUE(images.ok()) << images.error().format();
        const auto agreement = test::compareWithReference(scene, images->radiance);
        EXPECT_EQ(agreement.disagreeing, 0) << sweep.model << ": " << agreement.firstDisagreement
                                            << " (worst relative " << agreement.worstRelative << ")";
        EXPECT_GT(agreement.compared, 6000) << sweep.model;
        std::printf("%s: worst relative GPU-CPU difference %.2e\n", sweep.model, agreement.worstRelative);
        modelSwept[static_cast<size_t>(material.analytic()->model)] = true;
    }
    for (const ModelInfo& info : allModels())
        EXPECT_TRUE(modelSwept[static_cast<size_t>(info.model)]) << info.id << " is missing from the sweep";
}

}  // namespace
}  // namespace glint
