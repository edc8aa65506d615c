// The delta lobes of mirror and glass as the path tracer samples them: one direction per call,
// chosen by Fresnel between reflection and refraction, with the weight f·cos/p that goes with it.
// The same optics as the reference's analytic tree of rays (render/specular_transport.h): exact
// Fresnel (or the classic k_t), Snell refraction into and out of an exact sphere, a plane or a
// mesh as a thin pane. It does not trace rays; the path tracer follows the direction it gives.
#pragma once

#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "brdf/model_registry.h"
#include "render/specular_transport.h"

namespace glint {

// Where a delta lobe is sampled: the shading normal faces the viewer; `sphere` is set when the
// surface is an exact sphere (glass refracts through it), null for a thin pane.
struct DeltaLobeSite {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 towardsViewer;
    const SphereGeometry* sphere;
};

struct DeltaLobeSample {
    glm::vec3 direction;  // unit, away from the surface (into it for refraction)
    glm::vec3 weight;     // the path's throughput factor: (f·cos / p) of the chosen lobe
    // The Beer-Lambert coefficient σ [1/m] of the medium the ray travels in from here when it
    // crossed an interface (0 on leaving glass); none when it stays on its side.
    std::optional<glm::vec3> mediumAbsorption;
};

// The sampled delta lobe of `model` for the uniform number u ∈ [0,1), or none when the model has
// no delta lobe the path tracer samples (openpbr's transmission is still traced as the reference
// traces it: traceSpecular).
std::optional<DeltaLobeSample> sampleDeltaLobe(BrdfModel model, std::span<const float> values, const DeltaLobeSite& site,
                                               float u);

// Whether sampleDeltaLobe gives a lobe for `model` (mirror and glass).
bool samplesDeltaLobe(BrdfModel model);

}  // namespace glint
