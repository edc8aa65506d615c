// Numbers behind the classroom BRDF plots (issue 7): the polar plot in the plane of incidence, the
// 3D lobe over the hemisphere, the delta lobes of mirror and glass, and directional albedo against
// incidence angle. f_r comes from evalBrdf or the MERL table lookup (the functions the renderers
// use), or from a sampler the caller hands in (a .brdf shader evaluated on the GPU,
// core/gl/brdf_sampler.h). Draws nothing (app/classroom).
// Section index: plot material · polar plot · 3D lobe · delta lobes · directional albedo.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "brdf/model_registry.h"
#include "scene/scene.h"

namespace glint {

// ---- plot material -------------------------------------------------------------------------
// f_r [1/sr] per channel at each pair (incident[k], outgoing[k]), all in the local frame; returns
// one value per pair. For a BRDF the CPU cannot evaluate (a .brdf shader).
using PlotBrdfSampler = std::function<std::vector<glm::vec3>(std::span<const glm::vec3> incident,
                                                             std::span<const glm::vec3> outgoing)>;

// A material as the plots see it: f_r is its model's, its MERL table's (trilinear, as the
// renderers), or, when set, the sampler's (a .brdf material: its values are what was sampled).
// Local frame throughout: z is the normal, the plane of incidence is xz, the light comes from −x.
struct PlotMaterial : Material {
    PlotBrdfSampler sampler;
};

// A scene material for the plots; nullopt for a BRDF Explorer .brdf material (its GLSL cannot
// run on the CPU: the caller makes its sampler, app/classroom/plot_materials.h). Textures are not
// applied: the plots use the material's own values.
std::optional<PlotMaterial> plotMaterialFrom(const Material& material);
// Same material, same values, same table or shader: the plots would not change.
bool samePlotMaterial(const PlotMaterial& a, const PlotMaterial& b);

// ω_i for incidence angle θ_i [rad] (towards the light, on the −x side) and ω_o for a signed
// angle θ_o [rad] in the plane of incidence (positive: the mirror side, +x).
glm::vec3 plotIncidentDirection(float incidenceRadians);
glm::vec3 plotOutgoingDirection(float outgoingRadians);

// Photometric weight of an RGB triple (Rec. 709 luminance) used as the radius of single curves.
float plotLuminance(glm::vec3 rgb);

// ---- environment -------------------------------------------------------------------------
// The plotted material's environment term as the preview computes it, how (environmentApproximation)
// and its Monte-Carlo integral (kProbeEnvironmentSamples samples): for a surface facing up (+y),
// seen from θ_o = θ_i towards +z (the default camera's side). Nullopt without an environment, for a
// measured or sampled material, or a model with no environment hook.
struct PlotEnvironmentAccuracy {
    std::string method;
    glm::vec3 preview{0.0f}, truth{0.0f};  // [W/(sr·m²)]
};
std::optional<PlotEnvironmentAccuracy> plotEnvironmentAccuracy(const PlotMaterial& material, const Environment& environment,
                                                               float incidenceDegrees);

// ---- polar plot ----------------------------------------------------------------------------
// f_r and f_r·cos θ_o [1/sr] for θ_o from −90° to +90° in the plane of incidence.
struct PolarPlotData {
    float incidenceDegrees = 0.0f;
    std::vector<float> outgoingDegrees;          // −90 … +90
    std::vector<glm::vec3> reflectance;          // f_r [1/sr] per channel
    std::vector<glm::vec3> cosineWeighted;       // f_r·cos θ_o [1/sr]: what the plot draws
};
PolarPlotData polarPlotData(const PlotMaterial& material, float incidenceDegrees, int sampleCount = 181);

// ---- 3D lobe -------------------------------------------------------------------------------
// f_r·cos θ_o (luminance) as the radius over the hemisphere of outgoing directions, as in
// Disney's BRDF Explorer: rows of constant θ_o (0 … 90°), columns of constant φ_o (0 … 360°).
struct LobeMesh {
    float incidenceDegrees = 0.0f;
    int thetaSteps = 0, phiSteps = 0;   // points: (thetaSteps + 1) × phiSteps, row by row
    std::vector<glm::vec3> points;      // radius · ω_o in the local frame
    float largestRadius = 0.0f;         // [1/sr]
    glm::vec3 point(int thetaIndex, int phiIndex) const { return points[thetaIndex * phiSteps + phiIndex]; }
};
LobeMesh lobeMesh(const PlotMaterial& material, float incidenceDegrees, int thetaSteps = 24, int phiSteps = 48);

// ---- delta lobes ---------------------------------------------------------------------------
// The ideal lobes f_r cannot hold (mirror, glass; none for a measured or sampled material), drawn as arrows with their weights: the mirror
// direction with the Fresnel reflectance, and for glass the refracted direction below the surface
// by Snell's law (sin θ_t = sin θ_i / η) with the transmitted fraction of the power, 1 − F
// (or the classic k_t). Light arrives from the air side.
struct DeltaLobes {
    bool hasReflection = false, hasTransmission = false;
    glm::vec3 reflectedDirection{0.0f}, transmittedDirection{0.0f};  // local frame; transmitted has z < 0
    glm::vec3 reflectedWeight{0.0f}, transmittedWeight{0.0f};        // fractions of the incident power
    float transmittedDegrees = 0.0f;                                  // θ_t from −N
};
DeltaLobes deltaLobes(const PlotMaterial& material, float incidenceDegrees);

// ---- directional albedo --------------------------------------------------------------------
// ρ(θ_i) = ∫ f_r(ω_i, ω_o) cos θ_o dω_o over the hemisphere: a deterministic midpoint rule on
// (u = sin²θ_o, φ_o), where cos θ_o dω_o = ½ du dφ (cosine-weighted strata; exact for Lambert).
// Lobes narrower than the strata (a few degrees; Phong exponents above ~1000) are under-resolved.
// Delta lobes (mirror, glass) are not in f_r and so not in ρ.
glm::vec3 directionalAlbedo(const PlotMaterial& material, float incidenceDegrees, int thetaSteps = 64, int phiSteps = 128);

struct AlbedoCurve {
    std::vector<float> incidenceDegrees;  // 0 … 90 (the last just short of grazing: 89.5°)
    std::vector<glm::vec3> albedo;        // ρ per channel
    float largestAlbedo = 0.0f;           // over all angles and channels
    bool exceedsOne = false;              // reflects more than arrives: not energy conserving
};
AlbedoCurve albedoCurve(const PlotMaterial& material, int angleCount = 31, int thetaSteps = 64, int phiSteps = 128);

}  // namespace glint
