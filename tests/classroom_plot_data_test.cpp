// The classroom plots' numbers (core/classroom): directional albedo of known BRDFs, the warning
// for the lecture-form Phong, the polar plot and lobe against evalBrdf, the glass delta lobes, and
// the Fresnel curves' known values (glass 0.04, Brewster, critical angle, Schlick at 0°); a MERL
// table plotted from its lookup, and a sampler's batches. (.brdf on the GPU: plot_sampling_gpu_test.)
#include <gtest/gtest.h>

#include <cmath>

#include "brdf/fresnel.h"
#include "classroom/brdf_plot_data.h"
#include "classroom/fresnel_curves.h"
#include "interchange/measured_brdf.h"
#include "math/constants.h"

namespace glint {
namespace {

PlotMaterial plotDataMaterial(BrdfModel model, std::vector<float> values = {}) {
    PlotMaterial material{Material::withDefaults(modelInfo(model).id, model), {}};
    if (!values.empty()) material.analytic()->values = std::move(values);
    return material;
}

TEST(ClassroomPlotData, LambertAlbedoIsRhoAtEveryAngle) {
    const PlotMaterial lambert = plotDataMaterial(BrdfModel::Lambert, {0.8f, 0.5f, 0.2f});
    const AlbedoCurve curve = albedoCurve(lambert);
    ASSERT_EQ(curve.albedo.size(), 31u);
    for (const glm::vec3& albedo : curve.albedo) {
        EXPECT_NEAR(albedo.r, 0.8f, 1e-4f);
        EXPECT_NEAR(albedo.g, 0.5f, 1e-4f);
        EXPECT_NEAR(albedo.b, 0.2f, 1e-4f);
    }
    EXPECT_FALSE(curve.exceedsOne);
    EXPECT_FALSE(albedoCurve(plotDataMaterial(BrdfModel::Lambert, {1, 1, 1})).exceedsOne);  // white: exactly 1
}

TEST(ClassroomPlotData, NormalisedBlinnPhongConservesEnergy) {
    // The energy-normalised form (n+8)/(8π) with ρ_d + k_s = 0.9: never more out than in.
    for (float exponent : {4.0f, 32.0f, 200.0f}) {
        const AlbedoCurve curve = albedoCurve(plotDataMaterial(BrdfModel::BlinnPhong, {0.5f, 0.5f, 0.5f, 0.4f, 0.4f, 0.4f, exponent, 3}));
        EXPECT_LE(curve.largestAlbedo, 1.0f) << "n = " << exponent;
        EXPECT_FALSE(curve.exceedsOne) << "n = " << exponent;
        EXPECT_GT(curve.albedo.front().r, 0.85f) << "n = " << exponent;  // and not far below at normal incidence
    }
    // (n+8)/(8π) is an approximation: a white lobe (k_s = 1) with a low exponent overshoots by a
    // few per cent at normal incidence, and the plot flags it.
    const AlbedoCurve white = albedoCurve(plotDataMaterial(BrdfModel::BlinnPhong, {0, 0, 0, 1, 1, 1, 4, 3}));
    EXPECT_GT(white.albedo.front().r, 1.0f);
    EXPECT_LT(white.albedo.front().r, 1.1f);
    EXPECT_TRUE(white.exceedsOne);
}

TEST(ClassroomPlotData, LecturePhongExceedsOneAtGrazingAndIsFlagged) {
    // k_s cos^n δ / cos θ': bounded at normal incidence (2π/(n+2) ≈ 0.52 for n = 10), unbounded at grazing.
    const AlbedoCurve curve = albedoCurve(plotDataMaterial(BrdfModel::Phong, {0, 0, 0, 1, 1, 1, 10, 0}));
    EXPECT_NEAR(curve.albedo.front().r, 2.0f * kPi / 12.0f, 0.01f);
    EXPECT_GT(curve.albedo.back().r, 1.0f);
    EXPECT_TRUE(curve.exceedsOne);
    EXPECT_GT(curve.largestAlbedo, 1.0f);
}

TEST(ClassroomPlotData, PolarPlotAndLobeFollowEvalBrdf) {
    const PlotMaterial blinn = plotDataMaterial(BrdfModel::BlinnPhong);
    const PolarPlotData polar = polarPlotData(blinn, 30.0f, 181);
    ASSERT_EQ(polar.outgoingDegrees.size(), 181u);
    EXPECT_FLOAT_EQ(polar.outgoingDegrees.front(), -90.0f);
    EXPECT_FLOAT_EQ(polar.outgoingDegrees.back(), 90.0f);
    // f_r peaks in the mirror direction, θ_o = +30°; f_r·cos θ_o a little towards the normal.
    size_t peak = 0, weightedPeak = 0;
    for (size_t i = 0; i < polar.reflectance.size(); ++i) {
        if (polar.reflectance[i].r > polar.reflectance[peak].r) peak = i;
        if (polar.cosineWeighted[i].r > polar.cosineWeighted[weightedPeak].r) weightedPeak = i;
    }
    EXPECT_NEAR(polar.outgoingDegrees[peak], 30.0f, 1.0f);
    EXPECT_GT(polar.outgoingDegrees[weightedPeak], 20.0f);
    EXPECT_LT(polar.outgoingDegrees[weightedPeak], 30.0f);
    const glm::vec3 expected = evalBrdf(blinn.analytic()->model, blinn.analytic()->values, plotIncidentDirection(30.0f * kPi / 180.0f),
                                        plotOutgoingDirection(0.0f), ShadingFrame{});
    EXPECT_NEAR(polar.reflectance[90].r, expected.r, 1e-6f);
    EXPECT_NEAR(polar.cosineWeighted[90].r, expected.r, 1e-6f);  // cos 0° = 1

    const LobeMesh lobe = lobeMesh(blinn, 30.0f, 12, 24);
    ASSERT_EQ(lobe.points.size(), 13u * 24u);
    EXPECT_GT(lobe.largestRadius, 0.0f);
    // The top point (θ_o = 0) has radius f_r·cos 0 = f_r (luminance).
    EXPECT_NEAR(glm::length(lobe.point(0, 0)), plotLuminance(expected), 1e-5f);
}

TEST(ClassroomPlotData, GlassTransmitsBySnellWithFresnelWeights) {
    const DeltaLobes lobes = deltaLobes(plotDataMaterial(BrdfModel::Glass), 45.0f);  // η = 1.5
    ASSERT_TRUE(lobes.hasTransmission);
    const float expectedSin = std::sin(45.0f * kPi / 180.0f) / 1.5f;
    EXPECT_NEAR(lobes.transmittedDirection.x, expectedSin, 1e-5f);
    EXPECT_LT(lobes.transmittedDirection.z, 0.0f);
    EXPECT_NEAR(lobes.transmittedDegrees, std::asin(expectedSin) * 180.0f / kPi, 1e-3f);
    const float reflected = fresnelDielectric(std::cos(45.0f * kPi / 180.0f), 1.5f);
    EXPECT_NEAR(lobes.reflectedWeight.r, reflected, 1e-6f);
    EXPECT_NEAR(lobes.transmittedWeight.r, 1.0f - reflected, 1e-6f);
    EXPECT_FALSE(deltaLobes(plotDataMaterial(BrdfModel::Lambert), 45.0f).hasReflection);
}

TEST(ClassroomFresnelCurves, GlassKnownValues) {
    const FresnelCurves outside = fresnelCurves({glm::vec3(1.5f), glm::vec3(0.0f)}, false, 181);
    const FresnelChannelCurves& red = outside.channels[0];
    EXPECT_NEAR(red.unpolarised.front(), 0.04f, 1e-6f);
    EXPECT_NEAR(red.schlick.front(), red.unpolarised.front(), 1e-6f);  // Schlick is exact at 0°
    EXPECT_NEAR(red.brewsterDegrees, std::atan(1.5f) * 180.0f / kPi, 1e-4f);
    const float brewsterCos = std::cos(red.brewsterDegrees * kPi / 180.0f);
    EXPECT_NEAR(fresnelDielectricPolarised(brewsterCos, 1.5f).p, 0.0f, 1e-7f);
    const size_t at56 = 112;  // 56.0°, the sample nearest Brewster (56.31°)
    EXPECT_LT(red.p[at56], 1e-4f);
    EXPECT_LT(red.criticalDegrees, 0.0f);  // no critical angle from outside

    const FresnelCurves inside = fresnelCurves({glm::vec3(1.5f), glm::vec3(0.0f)}, true, 181);
    EXPECT_NEAR(inside.channels[1].criticalDegrees, std::asin(1.0f / 1.5f) * 180.0f / kPi, 1e-4f);
    EXPECT_FLOAT_EQ(inside.channels[1].unpolarised[90], 1.0f);  // 45° > 41.8°: total internal reflection
    EXPECT_NEAR(inside.channels[1].unpolarised.front(), 0.04f, 1e-6f);
}

TEST(ClassroomFresnelCurves, ConductorIndexFromTheMaterial) {
    const auto index = materialComplexIndex(plotDataMaterial(BrdfModel::Mirror));
    ASSERT_TRUE(index.has_value());
    EXPECT_GT(index->k.r, 0.0f);
    const FresnelCurves curves = fresnelCurves(*index);
    EXPECT_LT(curves.channels[0].brewsterDegrees, 0.0f);  // conductors: no Brewster angle marked
    EXPECT_NEAR(curves.channels[0].unpolarised.front(), fresnelF0(index->n, index->k).r, 1e-5f);
    EXPECT_NEAR(materialComplexIndex(plotDataMaterial(BrdfModel::Glass))->n.g, 1.5f, 1e-6f);
    EXPECT_FALSE(materialComplexIndex(plotDataMaterial(BrdfModel::Lambert)).has_value());
}

// A constant MERL table of ρ/π plots as Lambert: f_r·cos θ_o = ρ/π·cos θ_o in the plane, ρ at
// every incidence, no delta lobes, no Fresnel index.
TEST(ClassroomPlotData, ConstantMerlTablePlotsAsLambert) {
    const glm::vec3 albedo(0.6f, 0.4f, 0.2f);
    auto table = parseMerl(makeConstantMerl(albedo / kPi), "synthetic.binary");
    ASSERT_TRUE(table) << table.error().format();
    const Material measured = measuredBrdfMaterial(makeMeasuredBrdf(std::move(*table), "synthetic.binary"));
    const std::optional<PlotMaterial> material = plotMaterialFrom(measured);
    ASSERT_TRUE(material.has_value());
    ASSERT_TRUE(material->measured());
    const PolarPlotData polar = polarPlotData(*material, 30.0f, 37);
    for (size_t i = 0; i < polar.outgoingDegrees.size(); ++i) {
        const float cosOutgoing = std::max(std::cos(polar.outgoingDegrees[i] * kPi / 180.0f), 0.0f);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(polar.cosineWeighted[i][c], albedo[c] / kPi * cosOutgoing, 1e-5f) << polar.outgoingDegrees[i] << "°";
    }
    const AlbedoCurve curve = albedoCurve(*material, 4, 16, 32);
    for (const glm::vec3& value : curve.albedo) EXPECT_NEAR(value.r, albedo.r, 1e-4f);
    EXPECT_FALSE(deltaLobes(*material, 30.0f).hasReflection);
    EXPECT_FALSE(materialComplexIndex(*material).has_value());  // a table has no n to plot
}

// A sampler gets each plot's directions as one batch and its values are what the plot shows.
TEST(ClassroomPlotData, SampledMaterialUsesItsSamplerInOneBatchPerPlot) {
    int batches = 0;
    PlotMaterial sampled{Material{"sampled", {}}, {}};
    sampled.sampler = [&batches](std::span<const glm::vec3> incident, std::span<const glm::vec3> outgoing) {
        ++batches;
        std::vector<glm::vec3> values;
        for (size_t k = 0; k < incident.size(); ++k) values.push_back(glm::vec3(outgoing[k].z));  // f_r = cos θ_o
        return values;
    };
    const PolarPlotData polar = polarPlotData(sampled, 20.0f, 19);
    EXPECT_NEAR(polar.reflectance[9].r, 1.0f, 1e-6f);  // θ_o = 0
    // ∫ cos θ_o · cos θ_o dω = 2π/3.
    EXPECT_NEAR(albedoCurve(sampled, 5, 32, 16).albedo.front().g, 2.0f * kPi / 3.0f, 2e-3f);
    EXPECT_EQ(batches, 2);
    EXPECT_FALSE(materialComplexIndex(sampled).has_value());
}

}  // namespace
}  // namespace glint
