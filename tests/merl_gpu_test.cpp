// MERL measured materials on the GPU (OSMesa) against the CPU reference, per pixel, silhouettes
// excluded: a synthetic glossy table (a lobe in θ_h with θ_d and φ_d variation, so that every
// axis and the φ_d wrap are exercised) under the preview stage's lights plus an ambient light and
// under the Studio environment; and a constant (Lambertian) table against the Lambert model.
#include <cmath>

#include <gtest/gtest.h>

#include "environment_test_support.h"
#include "gpu_test_support.h"
#include "interchange/measured_brdf.h"
#include "math/constants.h"
#include "scene/preview_stage.h"

namespace glint {
namespace {

constexpr int kMerlGpuSize = 96;

// f_r at each sample's own angles: sample (i, j, k) sits at θ_h = (i/90)²·π/2, θ_d = j/90·π/2,
// φ_d = k/180·π (merlBinCoordinates inverted).
std::shared_ptr<const MeasuredBrdf> merlGpuGlossyTable() {
    MerlTable table;
    table.reflectance.resize(3 * kMerlSamplesPerChannel);
    const glm::vec3 diffuse(0.10f, 0.07f, 0.04f), lobe(2.0f, 1.6f, 1.1f);
    for (int i = 0; i < kMerlThetaHalfBins; ++i)
        for (int j = 0; j < kMerlThetaDifferenceBins; ++j)
            for (int k = 0; k < kMerlPhiDifferenceBins; ++k) {
                const float u = float(i) / kMerlThetaHalfBins;
                const float thetaHalf = u * u * kPi / 2, thetaDifference = j * kPi / 2 / kMerlThetaDifferenceBins;
                const float phiDifference = k * kPi / kMerlPhiDifferenceBins;
                const float shape = std::exp(-thetaHalf * thetaHalf / 0.04f) * (1.0f + 0.5f * std::pow(std::sin(thetaDifference), 4.0f)) *
                                    (1.0f + 0.3f * std::cos(2.0f * phiDifference));
                const size_t index = (size_t(i) * kMerlThetaDifferenceBins + j) * kMerlPhiDifferenceBins + k;
                for (int c = 0; c < 3; ++c) table.reflectance[c * kMerlSamplesPerChannel + index] = diffuse[c] + lobe[c] * shape;
            }
    return makeMeasuredBrdf(std::move(table), "glossy.binary");
}

void expectMerlGpuAgrees(const Scene& scene, float relativeTolerance) {
    const RadianceImage gpu = test::renderGpu(scene, kMerlGpuSize, kMerlGpuSize);
    const auto agreement = test::compareWithReference(scene, gpu, relativeTolerance);
    EXPECT_GT(agreement.compared, kMerlGpuSize * kMerlGpuSize / 2);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative " << agreement.worstRelative << ")";
    std::printf("[ measured ] worst relative GPU-CPU difference %.3g over %ld pixels\n", agreement.worstRelative,
                agreement.compared);
}

TEST(MerlGpu, GlossyTableMatchesTheCpuReferenceUnderLightsAndAmbient) {
    Scene scene = test::keyLitPreviewStage(measuredBrdfMaterial(merlGpuGlossyTable()), kMerlGpuSize, kMerlGpuSize);
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambientRadiance = 0.3f;
    scene.lights.push_back(ambient);
    expectMerlGpuAgrees(scene, 1e-3f);
}

TEST(MerlGpu, GlossyTableMatchesTheCpuReferenceUnderAnEnvironment) {
    expectMerlGpuAgrees(test::sphereUnderEnvironment(measuredBrdfMaterial(merlGpuGlossyTable()), EnvironmentKind::Studio), 1e-3f);
}

TEST(MerlGpu, ConstantTableRendersAsTheLambertModel) {
    const glm::vec3 albedo(0.7f, 0.45f, 0.2f);
    auto table = parseMerl(makeConstantMerl(albedo / kPi), "lambert.binary");
    ASSERT_TRUE(table.ok()) << table.error().format();
    const Scene measured = test::keyLitPreviewStage(measuredBrdfMaterial(makeMeasuredBrdf(std::move(*table), "lambert.binary")),
                                        kMerlGpuSize, kMerlGpuSize);
    Material lambert = Material::withDefaults("lambert", BrdfModel::Lambert);
    lambert.analytic()->values = {albedo.r, albedo.g, albedo.b};
    const RadianceImage gpu = test::renderGpu(measured, kMerlGpuSize, kMerlGpuSize);
    const auto agreement = test::compareWithReference(test::keyLitPreviewStage(lambert, kMerlGpuSize, kMerlGpuSize), gpu);
    EXPECT_GT(agreement.compared, kMerlGpuSize * kMerlGpuSize / 2);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative " << agreement.worstRelative << ")";
}

}  // namespace
}  // namespace glint
