// The OpenPBR albedo tables (see openpbr_albedo.h): GGX by visible-normal sampling on Hammersley
// points, the sheen by the midpoint rule over the hemisphere; both deterministic.
#include "brdf/openpbr_albedo.h"

#include <algorithm>
#include <cmath>

#include "brdf/microfacet.h"
#include "brdf/openpbr_lobes.h"
#include "environment/ggx_sampling.h"
#include "math/constants.h"
#include "util/disk_cache.h"
#include "util/text.h"

namespace glint {
namespace {

constexpr int kSize = kOpenPbrAlbedoSize;

float columnCosine(int column) { return (column + 0.5f) / kSize; }
float rowRoughness(int row) { return static_cast<float>(row) / (kSize - 1); }

// With visible normals as the density, f·cos θ_i / pdf = G2/G1(ω_o) (Heitz 2018, eq. 19).
glm::vec3 ggxTerms(float cosOut, float alpha) {
    constexpr int kSamples = 4096;
    const glm::vec3 view{std::sqrt(1.0f - cosOut * cosOut), 0.0f, cosOut};
    const float lambdaView = lambdaGgx(cosOut, alpha);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < kSamples; ++i) {
        const glm::vec3 halfway = sampleGgxVisibleNormal(view, hammersley(i, kSamples), alpha);
        const float viewDotHalf = glm::dot(view, halfway);
        const glm::vec3 light = 2.0f * viewDotHalf * halfway - view;
        if (light.z <= 0.0f || viewDotHalf <= 0.0f) continue;
        const double weight = (1.0 + lambdaView) / (1.0 + lambdaView + lambdaGgx(light.z, alpha));
        const double c = viewDotHalf, schlick = std::pow(1.0 - c, 5.0);
        sum += weight * glm::dvec3(1.0 - schlick, schlick, c * std::pow(1.0 - c, 6.0));
    }
    return glm::vec3(sum / static_cast<double>(kSamples));
}

// ∫ f_sheen cos θ_i dω_i by the midpoint rule in (cos θ_i, φ), using the lobe's symmetry in φ.
float sheenTerm(float cosOut, float perceptualRoughness) {
    constexpr int kCosines = 96, kAngles = 96;
    const glm::vec3 view{std::sqrt(1.0f - cosOut * cosOut), 0.0f, cosOut};
    double sum = 0.0;
    for (int i = 0; i < kCosines; ++i) {
        const float cosIn = (i + 0.5f) / kCosines, sinIn = std::sqrt(1.0f - cosIn * cosIn);
        for (int j = 0; j < kAngles; ++j) {
            const float phi = kPi * (j + 0.5f) / kAngles;
            const glm::vec3 light{sinIn * std::cos(phi), sinIn * std::sin(phi), cosIn};
            sum += sheenLobe(light, view, perceptualRoughness) * cosIn;
        }
    }
    return static_cast<float>(sum * 2.0 * kPi / (kCosines * kAngles));  // dω = d(cos θ) dφ, φ over 2π
}

template <typename T>
T bilinear(const std::vector<T>& table, float cosOut, float perceptualRoughness) {
    const float x = std::clamp(cosOut * kSize - 0.5f, 0.0f, kSize - 1.0f);
    const float y = std::clamp(perceptualRoughness * (kSize - 1), 0.0f, kSize - 1.0f);
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const int x1 = std::min(x0 + 1, kSize - 1), y1 = std::min(y0 + 1, kSize - 1);
    const float fx = x - x0, fy = y - y0;
    auto at = [&](int column, int row) { return table[row * kSize + column]; };
    const T top = at(x0, y0) * (1.0f - fx) + at(x1, y0) * fx;
    const T bottom = at(x0, y1) * (1.0f - fx) + at(x1, y1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

std::string glslFloat(float value) { return formatNumber(value, "%.8e"); }

}  // namespace

const OpenPbrAlbedoTables& openPbrAlbedoTables() {
    static const OpenPbrAlbedoTables tables = [] {
        const auto table = [](auto term) {  // term(cos θ_o, perceptual roughness) at every texel
            std::vector<decltype(term(0.0f, 0.0f))> values(kSize * kSize);
            for (int row = 0; row < kSize; ++row)
                for (int column = 0; column < kSize; ++column) values[row * kSize + column] = term(columnCosine(column), rowRoughness(row));
            return values;
        };
        OpenPbrAlbedoTables t;
        t.ggx = cachedValues<glm::vec3>("openpbr-ggx-albedo", kSize * kSize, [&] {
            return table([](float cosOut, float roughness) { return ggxTerms(cosOut, roughness * roughness); });
        });
        t.sheen = cachedValues<float>("openpbr-sheen-albedo", kSize * kSize, [&] { return table(sheenTerm); });
        return t;
    }();
    return tables;
}

glm::vec3 ggxAlbedoTerms(float cosOut, float perceptualRoughness) {
    return bilinear(openPbrAlbedoTables().ggx, cosOut, perceptualRoughness);
}

float sheenAlbedo(float cosOut, float perceptualRoughness) {
    return bilinear(openPbrAlbedoTables().sheen, cosOut, perceptualRoughness);
}

std::string openPbrAlbedoGlsl() {
    const OpenPbrAlbedoTables& t = openPbrAlbedoTables();
    const std::string count = std::to_string(kSize * kSize);
    std::string glsl = "const int OPENPBR_ALBEDO_SIZE = " + std::to_string(kSize) + ";  // kOpenPbrAlbedoSize\n";
    glsl += "const vec3 OPENPBR_GGX_ALBEDO[" + count + "] = vec3[](";
    for (size_t i = 0; i < t.ggx.size(); ++i)
        glsl += (i ? ",vec3(" : "vec3(") + glslFloat(t.ggx[i].x) + "," + glslFloat(t.ggx[i].y) + "," +
                glslFloat(t.ggx[i].z) + ")";
    glsl += ");\nconst float OPENPBR_SHEEN_ALBEDO[" + count + "] = float[](";
    for (size_t i = 0; i < t.sheen.size(); ++i) glsl += (i ? "," : "") + glslFloat(t.sheen[i]);
    return glsl + ");\n";
}

}  // namespace glint
