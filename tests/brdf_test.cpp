// Property tests for every BRDF model, after pbrt-v4's bsdfs_test.cpp: f_r ≥ 0, reciprocity
// where the model claims it (and its absence where the lectures say so), directional albedo
// ≤ 1 for energy-conserving models, and the registry's tables being self-consistent.
#include <gtest/gtest.h>

#include <random>

#include "brdf/blinn_phong.h"
#include "brdf/lambert.h"
#include "brdf/model_registry.h"

namespace glint {
namespace {

glm::vec3 uniformHemisphere(std::mt19937& random) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float z = unit(random), phi = 2.0f * kPi * unit(random);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Random packed values within each parameter's slider range (log-uniform where the table says log).
std::vector<float> randomValues(const ModelInfo& info, std::mt19937& random) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<float> values;
    for (const ParamSpec& spec : info.params) {
        for (int c = 0; c < componentCount(spec.kind); ++c) {
            float value;
            if (spec.kind == ParamKind::Enum) value = std::floor(unit(random) * (spec.options.size() - 0.001f));
            else if (spec.kind == ParamKind::Bool) value = unit(random) < 0.5f ? 0.0f : 1.0f;
            else if (spec.scale == ParamScale::Log)
                value = spec.sliderMin * std::pow(spec.sliderMax / spec.sliderMin, unit(random));
            else value = spec.sliderMin + (spec.sliderMax - spec.sliderMin) * unit(random);
            values.push_back(value);
        }
    }
    return values;
}

// ∫ f_r(wi, wo) cos θ_i dω_i by stratified sampling over the hemisphere (per channel).
glm::vec3 directionalAlbedo(const ModelInfo& info, const std::vector<float>& values, glm::vec3 wo) {
    const ShadingFrame frame;
    const int thetaSteps = 256, phiSteps = 512;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < thetaSteps; ++i) {
        const double cosTheta = (i + 0.5) / thetaSteps;  // uniform in cos θ: dω = d(cos θ) dφ
        const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = 2.0 * M_PI * (j + 0.5) / phiSteps;
            const glm::vec3 wi(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
            sum += glm::dvec3(evalBrdf(info.model, values, wi, wo, frame)) * cosTheta;
        }
    }
    return glm::vec3(sum * (2.0 * M_PI / (double(thetaSteps) * phiSteps)));
}

TEST(BrdfRegistry, TablesAreConsistent) {
    for (const ModelInfo& info : allModels()) {
        SCOPED_TRACE(info.id);
        EXPECT_EQ(findModel(info.id), info.model);
        EXPECT_LE(packedSize(info.params), 32) << "MaterialBlock holds 32 floats";
        for (const ParamSpec& spec : info.params) {
            SCOPED_TRACE(spec.name);
            EXPECT_LE(spec.validMin, spec.sliderMin);
            EXPECT_GE(spec.validMax, spec.sliderMax);
            EXPECT_LT(spec.sliderMin, spec.sliderMax);
            if (spec.scale == ParamScale::Log) EXPECT_GT(spec.sliderMin, 0.0f);
            if (spec.kind == ParamKind::Enum) EXPECT_EQ(spec.sliderMax + 1, static_cast<float>(spec.options.size()));
            for (int c = 0; c < componentCount(spec.kind); ++c) {
                EXPECT_GE(spec.defaultValue[c], spec.validMin);
                EXPECT_LE(spec.defaultValue[c], spec.validMax);
            }
        }
    }
    EXPECT_FALSE(findModel("no_such_model").has_value());
}

TEST(BrdfProperties, NonNegativeEverywhere) {
    std::mt19937 random(1);
    const ShadingFrame frame;
    for (const ModelInfo& info : allModels()) {
        for (int trial = 0; trial < 2000; ++trial) {
            const auto values = randomValues(info, random);
            const glm::vec3 f = evalBrdf(info.model, values, uniformHemisphere(random), uniformHemisphere(random), frame);
            ASSERT_TRUE(f.r >= 0 && f.g >= 0 && f.b >= 0 && std::isfinite(f.r + f.g + f.b)) << info.id;
        }
    }
}

TEST(BrdfProperties, ReciprocalWhereClaimed) {
    std::mt19937 random(2);
    const ShadingFrame frame;
    for (const ModelInfo& info : allModels()) {
        for (int trial = 0; trial < 2000; ++trial) {
            const auto values = randomValues(info, random);
            if (!isReciprocal(info.model, values)) continue;
            const glm::vec3 a = uniformHemisphere(random), b = uniformHemisphere(random);
            const glm::vec3 forward = evalBrdf(info.model, values, a, b, frame);
            const glm::vec3 backward = evalBrdf(info.model, values, b, a, frame);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(forward[c], backward[c], 1e-4f * std::max(1.0f, forward[c])) << info.id;
        }
    }
}

TEST(BrdfProperties, LectureBlinnPhongIsNotReciprocal) {
    // The lecture form k_s cos^n δ / cos θ' divides by the cosine to the light only.
    BlinnPhongParams params{{0, 0, 0}, {1, 1, 1}, 10.0f, BlinnForm::Lecture};
    std::vector<float> values = defaultValues(kBlinnPhongTable);
    values[7] = static_cast<float>(BlinnForm::Lecture);
    EXPECT_FALSE(isReciprocal(BrdfModel::BlinnPhong, values));
    const ShadingFrame frame;
    const glm::vec3 steep = glm::normalize(glm::vec3(0.1f, 0.0f, 1.0f));
    const glm::vec3 grazing = glm::normalize(glm::vec3(-1.0f, 0.0f, 0.3f));
    const float forward = evalBlinnPhong(params, steep, grazing, frame).r;
    const float backward = evalBlinnPhong(params, grazing, steep, frame).r;
    EXPECT_GT(std::abs(forward - backward), 0.1f * forward);
}

TEST(BrdfProperties, LambertAlbedoIsRho) {
    const ModelInfo& info = modelInfo(BrdfModel::Lambert);
    const std::vector<float> values = {0.2f, 0.5f, 1.0f};
    for (float theta : {0.0f, 0.7f, 1.4f}) {
        const glm::vec3 albedo = directionalAlbedo(info, values, {std::sin(theta), 0.0f, std::cos(theta)});
        EXPECT_NEAR(albedo.r, 0.2f, 1e-4f);
        EXPECT_NEAR(albedo.g, 0.5f, 1e-4f);
        EXPECT_NEAR(albedo.b, 1.0f, 1e-4f);
    }
    EXPECT_FLOAT_EQ(evalLambert({{0.5f, 0.5f, 0.5f}}, {0, 0, 1}, {0, 0, 1}, {}).r, 0.5f / kPi);
}

TEST(BrdfProperties, EnergyConservingModelsReflectAtMostOne) {
    std::mt19937 random(3);
    for (const ModelInfo& info : allModels()) {
        if (!info.energyConserving) continue;
        for (int trial = 0; trial < 8; ++trial) {
            auto values = randomValues(info, random);
            // The extremes of the valid range, too: the claim holds over all of it.
            if (trial == 0) for (float& v : values) v = 1.0f;
            const float theta = 1.5f * trial / 8.0f;
            const glm::vec3 albedo = directionalAlbedo(info, values, {std::sin(theta), 0.0f, std::cos(theta)});
            EXPECT_LE(std::max({albedo.r, albedo.g, albedo.b}), 1.0f + 1e-3f) << info.id;
        }
    }
}

TEST(BrdfProperties, NormalizedBlinnPhongLobeIntegratesNearItsWeight) {
    // (n+8)/8π makes the lobe's albedo at normal incidence close to k_s (Akenine-Möller et al.,
    // Real-Time Rendering): within a few percent for moderate exponents.
    const ModelInfo& info = modelInfo(BrdfModel::BlinnPhong);
    for (float exponent : {16.0f, 64.0f, 256.0f}) {
        std::vector<float> values = {0, 0, 0, 1, 1, 1, exponent, static_cast<float>(BlinnForm::Normalized)};
        const glm::vec3 albedo = directionalAlbedo(info, values, {0, 0, 1});
        EXPECT_NEAR(albedo.r, 1.0f, 0.08f) << "n = " << exponent;
    }
}

TEST(BrdfProperties, BelowTheHorizonIsBlack) {
    std::vector<float> values = defaultValues(kBlinnPhongTable);
    const glm::vec3 below{0.0f, 0.6f, -0.8f}, above{0.0f, 0.0f, 1.0f};
    EXPECT_EQ(evalBrdf(BrdfModel::BlinnPhong, values, below, above, {}), glm::vec3(0.0f));
    EXPECT_EQ(evalBrdf(BrdfModel::BlinnPhong, values, above, below, {}), glm::vec3(0.0f));
}

}  // namespace
}  // namespace glint
