// Custom BRDFs from .brdf files written here render on the GPU and match their built-in twins
// (the CPU reference of the twin, per pixel, silhouettes excluded): Lambert, normalised
// Blinn-Phong and GGX/Smith/Schlick Cook-Torrance. GLSL errors name the .brdf line; the
// child-process probe times out on an endless loop instead of hanging.
#include <chrono>

#include <gtest/gtest.h>

#include "runtime/brdf_probe.h"
#include "gpu_test_support.h"
#include "interchange/custom_brdf.h"
#include "scene/preview_stage.h"
#include "twin_brdf_texts.h"

namespace glint {
namespace {

constexpr int kSize = 96;

std::shared_ptr<const CustomBrdf> parseCustom(const std::string& text, const std::string& name) {
    auto file = parseBrdfFile(text, name);
    if (!file) {
        ADD_FAILURE() << file.error().format();
        return nullptr;
    }
    return makeCustomBrdf(std::move(*file));
}

constexpr const char* kGgx = R"(analytic
::begin parameters
float roughness 0.001 1 0.3
float ior 1 3 1.5
color diffuse 0.1 0.1 0.1
bool specularOn 1
::end parameters
::begin shader
uniform float roughness;
uniform float ior;
const float PI = 3.14159265358979323846;
float smithLambda(float cosTheta, float alpha)
{
    float cos2 = cosTheta * cosTheta;
    float tan2 = max(1.0 - cos2, 0.0) / cos2;
    return 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * tan2));
}
vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)
{
    float NdotL = dot(N, L), NdotV = dot(N, V);
    if (NdotL <= 0.0 || NdotV <= 0.0) return vec3(0.0);
    vec3 H = normalize(L + V);
    vec3 c = cross(N, H);
    float scaled = roughness * dot(N, H);
    float k = roughness / (dot(c, c) + scaled * scaled);
    float D = k * k / PI;
    float G = 1.0 / (1.0 + smithLambda(NdotL, roughness) + smithLambda(NdotV, roughness));
    float f0 = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
    float m = clamp(1.0 - dot(V, H), 0.0, 1.0);
    float F = f0 + (1.0 - f0) * m * m * m * m * m;
    return diffuse / PI + vec3(specularOn ? D * G * F / (4.0 * NdotL * NdotV) : 0.0);
}
::end shader
)";

// Test files shared with brdf_cli_test.sh: glsl_error.brdf has its error on line 7 (a float
// assigned a vec3); endless.brdf loops forever.
std::shared_ptr<const CustomBrdf> loadTestBrdf(const std::string& name) {
    auto brdf = loadCustomBrdf(std::string(GLINT_TEST_DATA_DIR) + "/brdf_files/" + name);
    if (!brdf) {
        ADD_FAILURE() << brdf.error().format();
        return nullptr;
    }
    return *brdf;
}

// Renders `custom` with `values` on the preview stage and compares with the CPU reference of the
// same stage carrying `twin`.
void expectMatchesTwin(const std::shared_ptr<const CustomBrdf>& custom, const std::vector<float>& values,
                       const Material& twin) {
    ASSERT_TRUE(custom);
    Material material = customBrdfMaterial(custom);
    material.custom()->values = values;
    const Scene customStage = test::keyLitPreviewStage(material, kSize, kSize);
    auto images = test::sharedHeadless().render(customStage, kSize, kSize);
    ASSERT_TRUE(images) << images.error().format();
    const auto agreement = test::compareWithReference(test::keyLitPreviewStage(twin, kSize, kSize), images->radiance);
    EXPECT_GT(agreement.compared, kSize * kSize / 2);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative "
                                        << agreement.worstRelative << ")";
}

TEST(CustomBrdfGpu, LambertMatchesBuiltInLambert) {
    Material twin = Material::withDefaults("twin", BrdfModel::Lambert);
    twin.analytic()->values = {0.6f, 0.3f, 0.15f};
    expectMatchesTwin(parseCustom(test::kLambertTwinBrdf, "lambert.brdf"), {0.6f, 0.3f, 0.15f}, twin);
}

TEST(CustomBrdfGpu, BlinnPhongMatchesNormalisedBlinnPhong) {
    Material twin = Material::withDefaults("twin", BrdfModel::BlinnPhong);
    twin.analytic()->values = {0.4f, 0.2f, 0.1f, 0.3f, 0.3f, 0.3f, 40.0f, 3.0f};  // form 3: normalised
    expectMatchesTwin(parseCustom(test::kBlinnPhongTwinBrdf, "blinn_phong.brdf"), {0.4f, 0.2f, 0.1f, 0.3f, 40.0f}, twin);
}

TEST(CustomBrdfGpu, GgxMatchesCookTorranceGgxSmithSchlick) {
    Material twin = Material::withDefaults("twin", BrdfModel::CookTorrance);
    // diffuse, ior, extinction, roughness, GGX, Smith, Schlick
    twin.analytic()->values = {0.2f, 0.1f, 0.05f, 1.7f, 1.7f, 1.7f, 0, 0, 0, 0.45f, 1, 1, 0};
    expectMatchesTwin(parseCustom(kGgx, "ggx.brdf"), {0.45f, 1.7f, 0.2f, 0.1f, 0.05f, 1.0f}, twin);
    // The bool parameter reaches the shader: specular off leaves the Lambert term.
    Material lambert = Material::withDefaults("twin", BrdfModel::Lambert);
    lambert.analytic()->values = {0.2f, 0.1f, 0.05f};
    expectMatchesTwin(parseCustom(kGgx, "ggx.brdf"), {0.45f, 1.7f, 0.2f, 0.1f, 0.05f, 0.0f}, lambert);
}

TEST(CustomBrdfGpu, GlslErrorNamesTheBrdfLine) {
    auto custom = loadTestBrdf("glsl_error.brdf");
    ASSERT_TRUE(custom);
    const Scene stage = previewStage(customBrdfMaterial(custom), 32, 32);
    auto images = test::sharedHeadless().render(stage, 32, 32);
    ASSERT_FALSE(images);
    EXPECT_NE(images.error().message.find("glsl_error.brdf:7:"), std::string::npos) << images.error().message;
}

TEST(CustomBrdfGpu, ReferenceRefusesCustomBrdfs) {
    const Scene stage = previewStage(customBrdfMaterial(parseCustom(test::kLambertTwinBrdf, "lambert.brdf")), 32, 32);
    const Status refused = referenceCanRender(stage);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("only on the GPU preview"), std::string::npos);
}

TEST(CustomBrdfProbe, GoodShaderPassesAndErrorsComeBackWithLines) {
    setBrdfProbeExecutable(GLINT_EXECUTABLE);  // this test binary is not `glint`
    auto good = parseCustom(kGgx, "ggx.brdf");
    ASSERT_TRUE(good);
    EXPECT_TRUE(probeCustomBrdf(*good, defaultValues(good->table), 60.0));
    auto broken = loadTestBrdf("glsl_error.brdf");
    ASSERT_TRUE(broken);
    const Status probed = probeCustomBrdf(*broken, defaultValues(broken->table), 60.0);
    ASSERT_FALSE(probed);
    EXPECT_NE(probed.error().message.find("glsl_error.brdf:7:"), std::string::npos) << probed.error().message;
}

TEST(CustomBrdfProbe, EndlessLoopTimesOutWithoutHanging) {
    setBrdfProbeExecutable(GLINT_EXECUTABLE);
    auto endless = loadTestBrdf("endless.brdf");
    ASSERT_TRUE(endless);
    const auto start = std::chrono::steady_clock::now();
    const Status probed = probeCustomBrdf(*endless, {}, 3.0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(probed);
    EXPECT_NE(probed.error().format().find("endless.brdf:2:1: the shader did not finish in 3 s"), std::string::npos)
        << probed.error().format();
    // Killed at its deadline, not left to loop: a busy machine may take seconds more to start and
    // end the child (14 s was seen beside two busy loops), never a minute.
    EXPECT_LT(seconds, 60.0) << "the probe of an endless loop returned only after " << seconds << " s";
}

}  // namespace
}  // namespace glint
