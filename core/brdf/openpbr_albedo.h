// Directional-albedo tables of the OpenPBR model's lobes, precomputed once on the CPU (kept in the
// disk cache, util/disk_cache.h) and handed
// to the GLSL twin as constant arrays (openPbrAlbedoGlsl), so that both twins interpolate the same
// numbers: the GGX lobe with height-correlated Smith masking split by Fresnel term (A, B, C) and
// the Charlie sheen with Neubelt's visibility. They drive the energy
// compensation (Turquin 2019) and the albedo scaling of the layers. No BRDF here: openpbr.h.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace glint {

// Columns at cos θ_o = (i + ½)/size, rows at perceptual roughness r = j/(size − 1) (α = r²).
inline constexpr int kOpenPbrAlbedoSize = 32;

struct OpenPbrAlbedoTables {
    // Per (row, column): ∫ D·G2/(4 cos θ_i cos θ_o) · w(ω_o·h) cos θ_i dω_i for the Fresnel weights
    // w = 1 − (1 − c)^5 (A), (1 − c)^5 (B) and c(1 − c)^6 (C, the F82 correction), so that a lobe
    // with F = F0 + (F90 − F0)(1 − c)^5 − a·c(1 − c)^6 reflects F0·A + F90·B − a·C.
    std::vector<glm::vec3> ggx;
    // Per (row, column): the albedo of the Charlie sheen D·V (Estevez & Kulla 2017; Neubelt &
    // Pettineo 2013) at fuzz roughness r (α = r²).
    std::vector<float> sheen;
};

const OpenPbrAlbedoTables& openPbrAlbedoTables();

// Bilinear lookups (clamped at the edges), twins of the GLSL functions of the same names.
glm::vec3 ggxAlbedoTerms(float cosOut, float perceptualRoughness);
float sheenAlbedo(float cosOut, float perceptualRoughness);

// The tables as GLSL constant arrays (printed to float precision) for shaders/brdf/openpbr_albedo.glsl.
std::string openPbrAlbedoGlsl();

}  // namespace glint
