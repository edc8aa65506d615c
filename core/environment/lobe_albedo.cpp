// Directional-albedo tables (see lobe_albedo.h), one table per thread, kept in the disk cache.
#include "environment/lobe_albedo.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <thread>

#include "brdf/blinn_phong.h"
#include "brdf/cook_torrance.h"
#include "brdf/microfacet.h"
#include "brdf/phong.h"
#include "brdf/ward.h"
#include "environment/ggx_sampling.h"
#include "environment/prefilter_kernel.h"
#include "math/constants.h"
#include "math/frame.h"
#include "util/disk_cache.h"

namespace glint {
namespace {

// The texel (r, cos θ_o) of a table; the view direction in the local frame (z the normal).
struct TableTexel {
    float alpha;
    glm::vec3 view;
};

void fillTable(LobeAlbedoTables& tables, int table, float minAlpha, const std::function<glm::vec2(const TableTexel&)>& texel) {
    for (int row = 0; row < kLobeAlbedoSize; ++row) {
        const float perceptual = static_cast<float>(row) / (kLobeAlbedoSize - 1);
        for (int column = 0; column < kLobeAlbedoSize; ++column) {
            const float cosOut = (column + 0.5f) / kLobeAlbedoSize;
            tables.texels[(table * kLobeAlbedoSize + row) * kLobeAlbedoSize + column] =
                texel({std::max(perceptual * perceptual, minAlpha), {std::sqrt(1.0f - cosOut * cosOut), 0.0f, cosOut}});
        }
    }
}

// cook_torrance's lobe (F = 1, brdf/cook_torrance.h) of a D × G pair (microfacetPair) at α.
CookTorranceParams microfacetLobe(int pair, float alpha) {
    return {.roughness = alpha, .distribution = static_cast<MicrofacetDistribution>(pair / 2),
            .geometry = static_cast<MicrofacetGeometry>(pair % 2)};
}

// A half vector of density D cos θ_h: GGX's, or Beckmann's (tan² θ_h = −α² ln(1 − u)).
glm::vec3 sampleHalfVector(MicrofacetDistribution distribution, glm::vec2 u, float alpha) {
    if (distribution == MicrofacetDistribution::Ggx) return sampleGgxHalfVector(u, alpha);
    const float cos2 = 1.0f / (1.0f - alpha * alpha * std::log(1.0f - u.x));
    const float cosTheta = std::sqrt(cos2), sinTheta = std::sqrt(std::max(0.0f, 1.0f - cos2));
    const float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// The mean of f_r cos θ_i / pdf = G (v·h) / (cos θ_o cos θ_h) over 1024 half vectors of density
// D cos θ_h (the pair's G: cookTorranceGeometry), each times `fresnelParts` of v·h.
glm::vec2 microfacetIntegral(const TableTexel& t, int pair, glm::vec2 (*fresnelParts)(float viewDotHalf)) {
    constexpr int kSamples = 1024;
    const CookTorranceParams lobe = microfacetLobe(pair, t.alpha);
    glm::vec2 sum(0.0f);
    for (int i = 0; i < kSamples; ++i) {
        const glm::vec3 halfway = sampleHalfVector(lobe.distribution, hammersley(i, kSamples), t.alpha);
        const float viewDotHalf = glm::dot(t.view, halfway);
        const glm::vec3 light = 2.0f * viewDotHalf * halfway - t.view;
        if (light.z <= 0.0f || viewDotHalf <= 0.0f) continue;
        const float geometry = cookTorranceGeometry(lobe, halfway.z, light.z, t.view.z, viewDotHalf);
        sum += fresnelParts(viewDotHalf) * (geometry * viewDotHalf / (t.view.z * halfway.z));
    }
    return sum / static_cast<float>(kSamples);
}

// The split sum's (A, B): Schlick's form split into 1 − (1 − v·h)⁵ and (1 − v·h)⁵.
glm::vec2 splitSumParts(float viewDotHalf) {
    const float schlick = std::pow(1.0f - viewDotHalf, 5.0f);
    return {1.0f - schlick, schlick};
}

// The share C of the F82 form's term a·μ(1 − μ)⁶ (fresnel.h), μ = v·h.
glm::vec2 f82Part(float viewDotHalf) { return {f82Weight(viewDotHalf), 0.0f}; }

// ∫ f_r cos θ_i dω_i of a lobe (ρ = 1) by multiple importance sampling (balance heuristic, Veach
// 1997) of three strategies in equal shares, so that narrow lobes and wide ones, cut by the
// horizon at grazing view, are both sampled well: GGX half vectors at α (density D cos θ_h /
// (4 v·h)), a Phong lobe of the equivalent exponent m = (2/α² − 2)/4 around the mirror direction
// ((m + 1)/(2π) cos^m δ) and the uniform hemisphere (1/(2π): bounded weights where the forms'
// 1/cos θ_i makes f_r cos θ_i flat up to the horizon).
// Returns (∫ f_r cos θ_i ω_i dω_i, ∫ f_r cos θ_i dω_i).
glm::vec4 lobeMoments(const TableTexel& t, const std::function<float(glm::vec3 light, glm::vec3 view, float alpha)>& brdf) {
    constexpr int kSamples = 256;  // per strategy
    const float m = (2.0f / (t.alpha * t.alpha) - 2.0f) / 4.0f;
    const glm::vec3 mirror{-t.view.x, -t.view.y, t.view.z};
    const ShadingFrame aroundMirror = ShadingFrame::fromNormal(mirror);
    const auto density = [&](glm::vec3 light) {
        const glm::vec3 halfway = glm::normalize(light + t.view);
        const float ggx = distributionGgx(halfway.z, std::max(0.0f, 1.0f - halfway.z * halfway.z), t.alpha) *
                          std::max(halfway.z, 0.0f) / (4.0f * std::max(glm::dot(t.view, halfway), 1e-6f));
        const float cosMirror = glm::dot(light, mirror);
        const float phong = cosMirror > 0.0f ? (m + 1.0f) / (2.0f * kPi) * std::pow(cosMirror, m) : 0.0f;
        return (ggx + phong + 0.5f * kInvPi) / 3.0f;
    };
    glm::dvec4 sum(0.0);
    for (int i = 0; i < kSamples; ++i) {
        const glm::vec2 u = hammersley(i, kSamples);
        const glm::vec3 halfway = sampleGgxHalfVector(u, t.alpha);
        const float cosMirror = std::pow(u.x, 1.0f / (m + 1.0f)), sinMirror = std::sqrt(std::max(0.0f, 1.0f - cosMirror * cosMirror));
        const float cosine = u.x, sine = std::sqrt(1.0f - u.x * u.x), phi = 2.0f * kPi * u.y;
        const glm::vec3 lights[3] = {
            2.0f * glm::dot(t.view, halfway) * halfway - t.view,
            aroundMirror.toWorld({sinMirror * std::cos(phi), sinMirror * std::sin(phi), cosMirror}),
            {sine * std::cos(phi), sine * std::sin(phi), cosine}};
        for (const glm::vec3& light : lights)
            if (light.z > 0.0f) sum += glm::dvec4(light, 1.0) * static_cast<double>(brdf(light, t.view, t.alpha) * light.z / density(light));
    }
    return glm::vec4(sum / (3.0 * kSamples));
}

// The mean cosine to R of the kernel the prefiltered level of perceptual roughness r = i/(size − 1)
// would hold (prefilter_kernel.h), i < size.
std::vector<float> levelKernelMeanCosines(int size) {
    std::vector<float> means(size);
    for (int i = 0; i < size; ++i) {
        const float r = std::max(static_cast<float>(i) / (size - 1), 1e-3f);
        means[i] = prefilterKernelMeanCosine(r * r);
    }
    return means;
}

// A lobe's GGX stand-in at a texel (lobe_albedo.h; Ward's, a microfacet pair's): the perceptual
// roughness whose kernel's mean cosine (falling with r, interpolated in `means`) is the lobe's
// |∫ f_r cos ω| / ∫ f_r cos, and the factor t with n + (R − n) t along the lobe's mean direction
// (q = its x/z, R = (−sin θ_o, 0, cos θ_o)).
glm::vec2 ggxStandIn(const TableTexel& t, const glm::vec4& moments, const std::vector<float>& means) {
    const float meanCosine = glm::length(glm::vec3(moments)) / moments.w;
    const auto past = std::find_if(means.begin(), means.end(), [&](float mean) { return mean < meanCosine; });
    float perceptual = 1.0f;
    if (past == means.begin()) perceptual = 0.0f;
    else if (past != means.end()) {
        const int i = static_cast<int>(past - means.begin());
        perceptual = (i - 1 + (means[i - 1] - meanCosine) / (means[i - 1] - means[i])) / (means.size() - 1.0f);
    }
    const float q = moments.x / moments.z, sinOut = t.view.x, cosOut = t.view.z;
    return {perceptual, -q / (sinOut + q * (cosOut - 1.0f))};
}

}  // namespace

const LobeAlbedoTables& lobeAlbedoTables() {
    static const LobeAlbedoTables tables{cachedValues<glm::vec2>("lobe-albedo", kLobeAlbedoTables * kLobeAlbedoSize * kLobeAlbedoSize, [] {
        LobeAlbedoTables result;
        result.texels.resize(kLobeAlbedoTables * kLobeAlbedoSize * kLobeAlbedoSize);
        const ShadingFrame frame = ShadingFrame::fromNormalAndTangent({0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f});
        const auto lobe = [](auto brdf) {
            return [brdf](const TableTexel& t) { return glm::vec2(lobeMoments(t, brdf).w, 0.0f); };
        };
        const std::vector<float> means = levelKernelMeanCosines(1024);  // the stand-ins'
        std::vector<std::function<void()>> jobs;
        for (int pair = 0; pair < 4; ++pair) {
            jobs.push_back([&, pair] {
                fillTable(result, kMicrofacetSplitSum + pair, 0.0f,
                          [pair](const TableTexel& t) { return microfacetIntegral(t, pair, splitSumParts); });
            });
            jobs.push_back([&, pair] {
                fillTable(result, kMicrofacetF82 + pair, 0.0f,
                          [pair](const TableTexel& t) { return microfacetIntegral(t, pair, f82Part); });
            });
        }
        for (int form = 0; form < 4; ++form) {
            // The lecture, max-cosine and half-vector forms × the normalised form's factor (lobe_albedo.h).
            jobs.push_back([&, form] {
                fillTable(result, kBlinnPhongAlbedo + form, kLobeAlbedoMinAlpha, lobe([&, form](glm::vec3 l, glm::vec3 v, float alpha) {
                    const float n = 2.0f / (alpha * alpha) - 2.0f;
                    const BlinnPhongParams p{glm::vec3(0.0f), glm::vec3(1.0f), n, static_cast<BlinnForm>(form)};
                    return (form == 3 ? 1.0f : (n + 8.0f) / (8.0f * kPi)) * evalBlinnPhong(p, l, v, frame).x;
                }));
            });
            jobs.push_back([&, form] {
                fillTable(result, kPhongAlbedo + form, kLobeAlbedoMinAlpha, lobe([&, form](glm::vec3 l, glm::vec3 v, float alpha) {
                    const float n = (2.0f / (alpha * alpha) - 2.0f) / 4.0f;
                    const PhongParams p{glm::vec3(0.0f), glm::vec3(1.0f), n, static_cast<PhongForm>(form)};
                    return (form == 3 ? 1.0f : (n + 2.0f) / (2.0f * kPi)) * evalPhong(p, l, v, frame).x;
                }));
            });
        }
        for (int normalization = 0; normalization < 2; ++normalization) {
            const auto ward = [&, normalization](glm::vec3 l, glm::vec3 v, float alpha) {
                const WardParams p{glm::vec3(0.0f), glm::vec3(1.0f), alpha, alpha, static_cast<WardNormalization>(normalization)};
                return wardSpecular(p, l, v, frame);
            };
            jobs.push_back([&, normalization, ward] { fillTable(result, kWardAlbedo + normalization, kLobeAlbedoMinAlpha, lobe(ward)); });
            jobs.push_back([&, normalization, ward] {
                fillTable(result, kWardStandIn + normalization, kLobeAlbedoMinAlpha,
                          [&](const TableTexel& t) { return ggxStandIn(t, lobeMoments(t, ward), means); });
            });
        }
        for (int pair = 0; pair < kGgxSmithPair; ++pair) {
            jobs.push_back([&, pair] {
                const auto microfacet = [&, pair](glm::vec3 l, glm::vec3 v, float alpha) {
                    return cookTorranceSpecular(microfacetLobe(pair, alpha), l, v, frame);
                };
                fillTable(result, kMicrofacetStandIn + pair, kLobeAlbedoMinAlpha,
                          [&](const TableTexel& t) { return ggxStandIn(t, lobeMoments(t, microfacet), means); });
            });
        }
        std::atomic<size_t> next{0};
        const auto work = [&] {
            for (size_t job = next++; job < jobs.size(); job = next++) jobs[job]();
        };
        std::vector<std::thread> threads(std::clamp(std::thread::hardware_concurrency(), 1u, 13u) - 1);
        for (std::thread& thread : threads) thread = std::thread(work);
        work();
        for (std::thread& thread : threads) thread.join();
        return result.texels;
    })};
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
