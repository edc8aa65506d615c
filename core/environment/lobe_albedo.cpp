// Directional-albedo tables (see lobe_albedo.h): Monte-Carlo over GGX half vectors (Hammersley
// points), once per process.
#include "environment/lobe_albedo.h"

#include <algorithm>
#include <cmath>

#include "brdf/blinn_phong.h"
#include "brdf/microfacet.h"
#include "brdf/phong.h"
#include "brdf/ward.h"
#include "environment/ggx_sampling.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint {
namespace {

constexpr int kSamples = 1024;

// Fills one table: at each (r, cos θ_o) the mean over GGX half vectors of roughness α = r² of
// `weight(light, view, α, f_r cos θ_i / pdf)` for the pdf D cos θ_h / (4 v·h) (local frame, z the normal).
template <class Weight>
void fillTable(LobeAlbedoTables& tables, int table, float minAlpha, Weight&& weight) {
    for (int row = 0; row < kLobeAlbedoSize; ++row) {
        const float perceptual = static_cast<float>(row) / (kLobeAlbedoSize - 1);
        const float alpha = std::max(perceptual * perceptual, minAlpha);
        for (int column = 0; column < kLobeAlbedoSize; ++column) {
            const float cosOut = (column + 0.5f) / kLobeAlbedoSize;
            const glm::vec3 view{std::sqrt(1.0f - cosOut * cosOut), 0.0f, cosOut};
            glm::vec2 sum(0.0f);
            for (int i = 0; i < kSamples; ++i) {
                const glm::vec3 halfway = sampleGgxHalfVector(hammersley(i, kSamples), alpha);
                const float viewDotHalf = glm::dot(view, halfway);
                const glm::vec3 light = 2.0f * viewDotHalf * halfway - view;
                if (light.z <= 0.0f || viewDotHalf <= 0.0f) continue;
                sum += weight(light, view, halfway, alpha);
            }
            tables.texels[(table * kLobeAlbedoSize + row) * kLobeAlbedoSize + column] = sum / static_cast<float>(kSamples);
        }
    }
}

// f_r cos θ_i / pdf for a lobe's f_r (ρ = 1) and the GGX half-vector pdf at α.
float lobeWeight(float brdf, glm::vec3 light, glm::vec3 view, glm::vec3 halfway, float alpha) {
    const float pdf = distributionGgx(halfway.z, std::max(0.0f, 1.0f - halfway.z * halfway.z), alpha) * halfway.z /
                      (4.0f * glm::dot(view, halfway));
    return brdf * light.z / pdf;
}

}  // namespace

const LobeAlbedoTables& lobeAlbedoTables() {
    static const LobeAlbedoTables tables = [] {
        LobeAlbedoTables result;
        result.texels.resize(kLobeAlbedoTables * kLobeAlbedoSize * kLobeAlbedoSize);
        // GGX: f_r cos θ_i / pdf = G2 (v·h) / (cos θ_o cos θ_h), split by Schlick's (1 − v·h)⁵.
        fillTable(result, kGgxSplitSum, 0.0f, [](glm::vec3 light, glm::vec3 view, glm::vec3 halfway, float alpha) {
            const float viewDotHalf = glm::dot(view, halfway);
            const float geometry = smithHeightCorrelated(lambdaGgx(light.z, alpha), lambdaGgx(view.z, alpha));
            const float weight = geometry * viewDotHalf / (view.z * halfway.z);
            const float schlick = std::pow(1.0f - viewDotHalf, 5.0f);
            return glm::vec2((1.0f - schlick) * weight, schlick * weight);
        });
        const ShadingFrame frame = ShadingFrame::fromNormalAndTangent({0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f});
        for (int form = 0; form < 4; ++form) {
            fillTable(result, kBlinnPhongAlbedo + form, kLobeAlbedoMinAlpha, [&](glm::vec3 l, glm::vec3 v, glm::vec3 h, float alpha) {
                const float exponent = 2.0f / (alpha * alpha) - 2.0f;
                const BlinnPhongParams p{glm::vec3(0.0f), glm::vec3(1.0f), exponent, static_cast<BlinnForm>(form)};
                const float factor = form == 3 ? 1.0f : (exponent + 8.0f) / (8.0f * kPi);  // see lobe_albedo.h
                return glm::vec2(lobeWeight(factor * evalBlinnPhong(p, l, v, frame).x, l, v, h, alpha), 0.0f);
            });
            fillTable(result, kPhongAlbedo + form, kLobeAlbedoMinAlpha, [&](glm::vec3 l, glm::vec3 v, glm::vec3 h, float alpha) {
                const float exponent = (2.0f / (alpha * alpha) - 2.0f) / 4.0f;
                const PhongParams p{glm::vec3(0.0f), glm::vec3(1.0f), exponent, static_cast<PhongForm>(form)};
                const float factor = form == 3 ? 1.0f : (exponent + 2.0f) / (2.0f * kPi);
                return glm::vec2(lobeWeight(factor * evalPhong(p, l, v, frame).x, l, v, h, alpha), 0.0f);
            });
        }
        for (int normalization = 0; normalization < 2; ++normalization)
            fillTable(result, kWardAlbedo + normalization, kLobeAlbedoMinAlpha, [&](glm::vec3 l, glm::vec3 v, glm::vec3 h, float alpha) {
                const WardParams p{glm::vec3(0.0f), glm::vec3(1.0f), alpha, alpha, static_cast<WardNormalization>(normalization)};
                return glm::vec2(lobeWeight(wardSpecular(p, l, v, frame), l, v, h, alpha), 0.0f);
            });
        return result;
    }();
    return tables;
}

glm::vec2 sampleLobeAlbedo(int table, float cosOut, float perceptualRoughness) {
    const float last = kLobeAlbedoSize - 1.0f;
    const float x = std::clamp(cosOut * kLobeAlbedoSize - 0.5f, 0.0f, last);
    const float y = std::clamp(perceptualRoughness * last, 0.0f, last);
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const int x1 = std::min(x0 + 1, kLobeAlbedoSize - 1), y1 = std::min(y0 + 1, kLobeAlbedoSize - 1);
    const float fx = x - x0, fy = y - y0;
    const auto at = [&](int column, int row) {
        return lobeAlbedoTables().texels[(table * kLobeAlbedoSize + row) * kLobeAlbedoSize + column];
    };
    const glm::vec2 top = at(x0, y0) * (1.0f - fx) + at(x1, y0) * fx;
    const glm::vec2 bottom = at(x0, y1) * (1.0f - fx) + at(x1, y1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

}  // namespace glint
