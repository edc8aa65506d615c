// What a model gives the exporters that write it in a simpler format: a Wavefront .mtl block
// (interchange/mtl.cpp) and a glTF metallic-roughness material (interchange/gltf_export.cpp).
// A model declares `mtlForm(Params)` and `gltfForm(Params)` when it has them (model.h); each form
// says in words what it does not keep. Plain data and the shared ways of building it; no file format.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "brdf/fresnel.h"
#include "brdf/microfacet.h"

namespace glint {

// One newmtl block: illum 1 (Lambert), 2 (Blinn-Phong highlight), 3 (mirror) or 7 (glass).
struct MtlForm {
    int illum = 1;
    glm::vec3 diffuse{0.0f}, specular{0.0f};  // Kd (written as Ka too), Ks
    float exponent = 0.0f, ior = 1.0f;        // Ns, Ni
    std::vector<std::string> lost;
};

// A glTF 2.0 material: metallic-roughness with KHR_materials_ior, _transmission and _volume.
struct GltfForm {
    enum class Kind { Dielectric, Metal, Glass };
    Kind kind = Kind::Dielectric;
    glm::vec3 baseColor{1.0f};   // a dielectric's diffuse albedo; a metal's F0
    float ior = 1.5f;            // dielectric and glass (KHR_materials_ior)
    float alpha = 1.0f;          // GGX α; glTF's roughnessFactor is √α
    glm::vec3 absorption{0.0f};  // glass: σ [1/m] (KHR_materials_volume)
    std::vector<std::string> lost;
};

// A microfacet lobe of index n + iκ in MTL: Ks = F0, Ns = 2/α² − 2 (Walter et al. 2007, eq. 33).
inline MtlForm mtlMicrofacet(glm::vec3 diffuse, glm::vec3 ior, glm::vec3 extinction, float alpha) {
    return {.illum = 2, .diffuse = diffuse, .specular = fresnelF0(ior, extinction),
            .exponent = std::max(blinnPhongExponentFromAlpha(alpha), 0.0f),
            .lost = {"the microfacet lobe is approximated by Blinn-Phong (Ks = F(0°), Ns = 2/α² − 2)"}};
}

// glTF has one real index: a per-channel one is written as its green channel.
inline GltfForm gltfDielectric(glm::vec3 diffuse, glm::vec3 ior, float alpha, std::vector<std::string> lost = {}) {
    if (ior.r != ior.g || ior.g != ior.b) lost.push_back("a per-channel index is written as its green channel " + std::to_string(ior.g));
    return {GltfForm::Kind::Dielectric, diffuse, ior.g, alpha, glm::vec3(0.0f), std::move(lost)};
}
// A conductor: glTF's metal has base colour F0 of n + iκ and no diffuse part.
inline GltfForm gltfMetal(glm::vec3 diffuse, glm::vec3 ior, glm::vec3 extinction, float alpha, std::vector<std::string> lost = {}) {
    if (diffuse != glm::vec3(0.0f)) lost.push_back("a metal's diffuse albedo is not kept");
    if (ior != glm::vec3(1.0f)) lost.push_back("n + iκ is written as its normal-incidence reflectance (imported back with n = 1)");
    return {GltfForm::Kind::Metal, fresnelF0(ior, extinction), 1.5f, alpha, glm::vec3(0.0f), std::move(lost)};
}
// Cook-Torrance-like: κ = 0 is a dielectric (base colour ρ_d, ior n), κ > 0 a metal.
inline GltfForm gltfMicrofacet(glm::vec3 diffuse, glm::vec3 ior, glm::vec3 extinction, float alpha, std::vector<std::string> lost = {}) {
    if (extinction == glm::vec3(0.0f)) return gltfDielectric(diffuse, ior, alpha, std::move(lost));
    return gltfMetal(diffuse, ior, extinction, alpha, std::move(lost));
}
// A diffuse model: a rough dielectric (roughness 1) with base colour = albedo.
inline GltfForm gltfRoughDielectric(glm::vec3 albedo) {
    return gltfDielectric(albedo, glm::vec3(1.5f), 1.0f, {"written as a rough dielectric (roughness 1) with base colour = albedo"});
}
// A Blinn-Phong-like lobe of exponent n: a GGX dielectric with α = √(2/(n + 2)) (Walter et al. 2007, eq. 33).
inline GltfForm gltfFromExponent(glm::vec3 diffuse, float exponent) {
    return gltfDielectric(diffuse, glm::vec3(1.5f), std::clamp(alphaFromBlinnPhongExponent(exponent), 0.001f, 1.0f),
                          {"written as a GGX dielectric (ior 1.5, α = √(2/(n + 2))); k_s is not kept"});
}

}  // namespace glint
