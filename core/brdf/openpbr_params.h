// The parameters of OpenPBR Surface 1.1 (ASWF / MaterialX `open_pbr_surface`): names, defaults
// and ranges as the specification's node definition, so that a file from another tool means the
// same here. Only the table and the struct it unpacks to (in table order); the model is
// core/brdf/openpbr.h.
// Left out (Glint has no subsurface or volume scattering, dispersion or cut-outs): subsurface_*,
// transmission_scatter*, transmission_dispersion_*, geometry_opacity, and the normal/tangent
// inputs (Glint's shading frame and normal maps give them). Added: geometry_tangent_rotation, the
// anisotropy direction's angle in the tangent plane (glTF's anisotropyRotation), and
// geometry_thickness, the path length through the volume of a shape that has no chord of its own
// (glTF's thicknessFactor × thicknessTexture).
#pragma once

#include <glm/glm.hpp>

#include "brdf/param_table.h"

namespace glint {

struct OpenPbrParams {
    float baseWeight;
    glm::vec3 baseColor;           // linear RGB reflectance
    float baseMetalness;
    float baseDiffuseRoughness;    // Oren-Nayar σ-like roughness in [0, 1]
    float specularWeight;
    glm::vec3 specularColor;       // dielectric tint; the metal's F82 edge tint
    float specularRoughness;       // perceptual: α = r²
    float specularAnisotropy;
    float specularIor;
    float transmissionWeight;
    glm::vec3 transmissionColor;
    float transmissionDepth;       // m: the distance after which light is exactly transmission_color
    float fuzzWeight;
    glm::vec3 fuzzColor;
    float fuzzRoughness;
    float coatWeight;
    glm::vec3 coatColor;
    float coatRoughness;           // perceptual
    float coatAnisotropy;
    float coatIor;
    float coatDarkening;
    float thinFilmWeight;
    float thinFilmThickness;       // µm
    float thinFilmIor;
    float emissionLuminance;       // nits (cd/m²)
    glm::vec3 emissionColor;
    bool thinWalled;
    float tangentRotation;         // degrees, counter-clockwise from the tangent towards the bitangent
    float thickness;               // m: the volume's path length on a plane or mesh (0: a tint only)
};

inline constexpr ParamSpec kOpenPbrTable[] = {
    // Base
    layerWeight(fractionParam("base_weight", "Base weight", 1.0f, "Multiplier on the diffuse and metallic base")),
    colorParam("base_color", "Base colour", {0.8f, 0.8f, 0.8f},
        "Albedo of the diffuse base; a metal's reflectance at normal incidence (F0)"),
    fractionParam("base_metalness", "Base metalness", 0.0f, "Mix from a dielectric base (0) to a metal (1)"),
    fractionParam("base_diffuse_roughness", "Base diffuse roughness", 0.0f,
        "Roughness of the diffuse base (0: Lambert; towards 1: flatter, Oren-Nayar)"),
    // Specular
    {.name = "specular_weight", .label = "Specular weight", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = kUnbounded, .defaultValue = {1.0f, 0, 0},
     .help = "Multiplies the dielectric's F0 (capped at 1)", .layerWeight = true},
    colorParam("specular_color", "Specular colour", {1.0f, 1.0f, 1.0f},
        "Tint of the dielectric reflection; the metal's edge tint (F82)"),
    fractionParam("specular_roughness", "Specular roughness", 0.3f, "Perceptual roughness r of the specular lobe (GGX α = r²)"),
    fractionParam("specular_roughness_anisotropy", "Specular anisotropy", 0.0f,
        "Stretches the highlight along the tangent (0: isotropic)"),
    {.name = "specular_ior", .label = "Specular IOR", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 1, .sliderMax = 3, .validMin = 1, .validMax = kUnbounded, .defaultValue = {1.5f, 0, 0},
     .help = "Index of refraction of the dielectric base (glass 1.5, water 1.33)"},
    // Transmission
    layerWeight(fractionParam("transmission_weight", "Transmission weight", 0.0f,
        "Mix from an opaque dielectric base (0) to a transparent one (1)")),
    colorParam("transmission_color", "Transmission colour", {1.0f, 1.0f, 1.0f},
        "Colour after transmission_depth inside (Beer-Lambert); a plain tint when the depth is 0"),
    {.name = "transmission_depth", .label = "Transmission depth", .unit = "m", .kind = ParamKind::Scalar,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = kUnbounded, .defaultValue = {0.0f, 0, 0},
     .help = "Distance inside after which the light is exactly transmission_color"},
    // Fuzz
    layerWeight(fractionParam("fuzz_weight", "Fuzz weight", 0.0f, "Presence of a fuzz (sheen) layer on top: velvet, satin, dust")),
    colorParam("fuzz_color", "Fuzz colour", {1.0f, 1.0f, 1.0f}, "Colour of the fuzz layer"),
    fractionParam("fuzz_roughness", "Fuzz roughness", 0.5f, "Roughness of the fuzz fibres (Charlie sheen α = r²)"),
    // Coat
    layerWeight(fractionParam("coat_weight", "Coat weight", 0.0f, "Presence of a clear coat on top: car paint, lacquer, an oily film")),
    colorParam("coat_color", "Coat colour", {1.0f, 1.0f, 1.0f},
        "Transmittance of the coat at normal incidence (absorption in the coat)"),
    fractionParam("coat_roughness", "Coat roughness", 0.0f, "Perceptual roughness of the coat's reflection (GGX α = r²)"),
    fractionParam("coat_roughness_anisotropy", "Coat anisotropy", 0.0f, "Stretches the coat's highlight along the tangent"),
    {.name = "coat_ior", .label = "Coat IOR", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 1, .sliderMax = 3, .validMin = 1, .validMax = kUnbounded, .defaultValue = {1.6f, 0, 0},
     .help = "Index of refraction of the coat"},
    fractionParam("coat_darkening", "Coat darkening", 1.0f,
        "How much light trapped under the coat darkens and saturates the base (1: physical)"),
    // Thin film
    layerWeight(fractionParam("thin_film_weight", "Thin-film weight", 0.0f,
        "Coverage of an iridescent thin film on the base: soap bubbles, oil, anodised metal")),
    {.name = "thin_film_thickness", .label = "Thin-film thickness", .unit = "µm", .kind = ParamKind::Scalar,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = kUnbounded, .defaultValue = {0.5f, 0, 0},
     .help = "Thickness of the film in micrometres"},
    {.name = "thin_film_ior", .label = "Thin-film IOR", .unit = "", .kind = ParamKind::Scalar,
     .sliderMin = 1, .sliderMax = 3, .validMin = 1, .validMax = kUnbounded, .defaultValue = {1.4f, 0, 0},
     .help = "Index of refraction of the film"},
    // Emission
    {.name = "emission_luminance", .label = "Emission luminance", .unit = "nit", .kind = ParamKind::Scalar,
     .sliderMin = 0, .sliderMax = 1000, .validMin = 0, .validMax = kUnbounded, .defaultValue = {0.0f, 0, 0},
     .help = "Emitted luminance in cd/m² (radiance = nits / 683 lm/W, for a colour of luminance 1)"},
    colorParam("emission_color", "Emission colour", {1.0f, 1.0f, 1.0f}, "Colour of the emitted light"),
    // Geometry
    {.name = "geometry_thin_walled", .label = "Thin walled", .unit = "", .kind = ParamKind::Bool,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = 1, .defaultValue = {0.0f, 0, 0},
     .help = "An infinitesimally thin shell (a bubble, a leaf): light passes without refracting"},
    {.name = "geometry_tangent_rotation", .label = "Tangent rotation", .unit = "deg", .kind = ParamKind::Scalar,
     .sliderMin = 0, .sliderMax = 360, .validMin = -kUnbounded, .validMax = kUnbounded, .defaultValue = {0.0f, 0, 0},
     .help = "Turns the anisotropy direction from the tangent towards the bitangent (Glint addition; glTF's anisotropyRotation)"},
    {.name = "geometry_thickness", .label = "Thickness", .unit = "m", .kind = ParamKind::Scalar,
     .sliderMin = 0, .sliderMax = 1, .validMin = 0, .validMax = kUnbounded, .defaultValue = {0.0f, 0, 0},
     .help = "Path length through the volume of a plane or mesh, for its absorption and refraction offset (Glint addition; "
             "glTF's thicknessFactor); 0 tints by transmission_color only; a sphere uses its exact chord"},
};

}  // namespace glint
