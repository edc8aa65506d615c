// Directional-albedo tables of the glossy lobes the environment prefilters (the split sum of Karis,
// "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course, for every lobe): at (cos θ_o,
// perceptual roughness r = √α) each table holds ∫ f_r cos θ_i dω_i of the lobe itself, computed
// once from the model's own BRDF, so that the prefiltered radiance × the table is exact under a
// uniform map. Stacked in one texture (shaders/common/environment.glsl reads it, texel for texel
// the same as sampleLobeAlbedo). Rows at r = i/(size − 1), so that r = 1 is a row; columns at
// cos θ_o = (i + ½)/size.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "brdf/cook_torrance.h"

namespace glint {

inline constexpr int kLobeAlbedoSize = 32;

// The tables, each kLobeAlbedoSize rows: per microfacet D × G pair (cook_torrance's options, as
// microfacetPair) scale A and bias B of ∫ f_r cos θ_i dω_i = F0·A + B under Schlick's Fresnel (− a·C
// with the F82 form's term a·μ(1 − μ)⁶, brdf/fresnel.h: C in x of the F82 tables, one per pair);
// then one albedo (in x) per Blinn-Phong and Phong form (0-3, as BlinnForm and PhongForm; the
// lecture, max-cosine and half-vector forms × the normalised form's factor (n + c)/(cπ), c = 8 and
// 2, so that the table stays near 1/cos θ_o: the hooks divide by it) at n = 2/α² − 2 and
// (2/α² − 2)/4, and per Ward normalisation (0-1, as WardNormalization) at α_x = α_y = α; then per
// Ward normalisation the GGX stand-in for its lobe on a smooth map (x: the perceptual roughness
// √α' of the prefiltered level whose kernel (n = v = R; by the stand-ins' measure,
// prefilter_kernel.h) has the lobe's mean cosine to its mean direction, y: that direction as the
// factor t of n + (R − n) t); then the F82 shares; last the same stand-in for each microfacet pair
// but GGX with Smith (whose lobe the levels hold). Lobes take α ≥ kLobeAlbedoMinAlpha. Computed
// on first use, a thread per table, and kept in the disk cache (util/disk_cache.h).
enum LobeAlbedoTable { kMicrofacetSplitSum = 0, kBlinnPhongAlbedo = 4, kPhongAlbedo = 8, kWardAlbedo = 12, kWardStandIn = 14,
                       kMicrofacetF82 = 16, kMicrofacetStandIn = 20, kLobeAlbedoTables = 23 };
// A microfacet D × G pair's offset in kMicrofacetSplitSum, kMicrofacetF82 and (but GGX with Smith) kMicrofacetStandIn.
inline constexpr int microfacetPair(MicrofacetDistribution distribution, MicrofacetGeometry geometry) {
    return 2 * static_cast<int>(distribution) + static_cast<int>(geometry);
}
inline constexpr int kGgxSmithPair = microfacetPair(MicrofacetDistribution::Ggx, MicrofacetGeometry::Smith);  // the last
inline constexpr float kLobeAlbedoMinAlpha = 0.01f;

struct LobeAlbedoTables {
    std::vector<glm::vec2> texels;  // row = table × size + roughness index, column = cos θ_o index
};
const LobeAlbedoTables& lobeAlbedoTables();

// Bilinear lookup in table `table` (+ the form or normalisation), edges clamped.
glm::vec2 sampleLobeAlbedo(int table, float cosOut, float perceptualRoughness);

}  // namespace glint
