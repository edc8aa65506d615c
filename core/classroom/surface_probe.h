// The classroom surface probe: for one pixel of a W×H image, the CPU reference's primary ray,
// its hit and the whole chain from each light to the 8-bit pixel value (L, H, R, T and their
// angles, Φ or M, distance, cos θ, E, f_r, L, photometric equivalents, the display chain).
// It computes numbers only: the text is classroom/probe_text.h, the drawing app/classroom/.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace glint {

// A refraction by Snell's law η_i sin θ_i = η_t sin θ_t at the probed point (refractive materials).
struct ProbeRefraction {
    float etaIncident = 1.0f;     // η on the side the ray comes from
    float etaTransmitted = 1.0f;  // η on the other side
    float incidentDegrees = 0.0f;     // θ_i from the normal
    float transmittedDegrees = 0.0f;  // θ_t; meaningless under total internal reflection
    bool totalInternalReflection = false;  // sin θ_t = (η_i/η_t) sin θ_i > 1: no T
    std::optional<float> criticalDegrees;  // arcsin(η_t/η_i) when η_i > η_t
    glm::vec3 direction{0.0f};             // T, unit, into the far side (zero under TIR)
};

// What a source delivers, in its own quantity: Φ [W] (point, spot), M [W/m²] (directional).
struct ProbeSource {
    const char* symbol;       // "Φ" or "M"
    const char* unit;         // "W" or "W/m²"
    float amount;             // Φ or M as set on the light (before its colour filter)
    glm::vec3 color;          // the light's linear-RGB filter
    float photometric;        // lm (point, spot) or lx (directional), 683 lm/W weighted by Y
    const char* photometricUnit;
};

struct ProbeLight {
    int lightIndex;
    std::string name;
    LightType type;
    ProbeSource source;
    glm::vec3 towardsLight;   // L, unit
    glm::vec3 halfVector;     // H = (L + V)/|L + V|, unit
    glm::vec3 mirror;         // R = 2(N·L)N − L: L's mirror direction about N
    std::optional<ProbeRefraction> transmitted;  // -L refracted through the surface (refractive materials)
    float distance;           // [m]; infinity for directional lights
    float distanceFactor = 1.0f;  // point, spot: 1/d² or the classic 1/(a0 + a1·d + a2·d²) [1/m²]
    bool classicAttenuation = false;
    float spotFactor = 1.0f;  // spot lights: cos^a α × smooth edge (1 for the others)
    float cosTheta;           // N·L
    float incidentDegrees;    // θ_i = angle(N, L)
    float reflectedDegrees;   // θ_r = angle(N, V)
    float halfDegrees;        // angle(N, H), the Blinn-Phong angle
    float mirrorViewDegrees;  // angle(R, V), the Phong angle
    bool behindSurface;       // N·L ≤ 0: no light arrives
    bool shadowed;            // a shadow ray hit an object (only for lights that cast shadows)
    glm::vec3 normalIrradiance;  // E⊥ [W/m²] on a surface facing the light
    glm::vec3 irradiance;        // E = E⊥·cos θ·visibility [W/m²]
    float illuminance;           // lx
    glm::vec3 brdf;              // f_r(L, V) [1/sr]
    glm::vec3 radiance;          // f_r·E [W/(sr·m²)]
    float luminance;             // nit = cd/m²
};

// One channel through the display chain (core/display/display_chain.h).
struct ProbeDisplayChannel {
    float radiance;    // [W/(sr·m²)]
    float exposed;     // ×2^EV
    float toneMapped;  // after the tone curve
    float clamped;     // into [0, 1]
    float encoded;     // sRGB or 1/γ
    int value8;        // 0..255
};

struct ProbeResult {
    int pixelX = 0, pixelY = 0, width = 0, height = 0;
    bool hitSurface = false;     // false: the ray saw the background ("no surface")
    glm::vec3 rayOrigin{0.0f}, rayDirection{0.0f};
    // Set when hitSurface:
    glm::vec3 position{0.0f};    // [m]
    float hitDistance = 0.0f;    // along the primary ray [m]
    int objectIndex = -1, materialIndex = -1;
    std::string objectName, materialName, modelLabel;
    bool gpuOnlyMaterial = false;  // a custom .brdf material: the CPU cannot evaluate it, no terms
    bool gouraud = false;        // the pixel interpolates its corners' radiance: terms are at the point
    glm::vec3 normal{0.0f};      // N (shading normal, after normal mapping), unit, facing the viewer
    glm::vec3 towardsViewer{0.0f};  // V, unit
    glm::vec3 viewMirror{0.0f};     // R_V = 2(N·V)N − V, the direction a mirror reflects V into
    std::optional<ProbeRefraction> viewTransmitted;  // the primary ray refracted (refractive materials)
    std::vector<ProbeLight> lights;  // enabled delta lights
    glm::vec3 ambientReflectance{0.0f}, ambientRadiance{0.0f};  // k_a, Σ L_a
    glm::vec3 environment{0.0f};     // environment light reflected [W/(sr·m²)]: the preview's approximation
    std::string environmentMethod;   // how the preview computes it (environmentApproximation); empty: no environment term
    glm::vec3 environmentTruth{0.0f};  // the same by Monte-Carlo (kProbeEnvironmentSamples samples)
    glm::vec3 specular{0.0f};        // traced delta lobes (mirror, glass) [W/(sr·m²)]
    // Always set:
    glm::vec3 radiance{0.0f};        // the pixel's reference radiance (background when missed)
    float luminance = 0.0f;          // nit
    std::array<ProbeDisplayChannel, 3> display{};
    DisplaySettings displaySettings;
};

// Samples of the Monte-Carlo environment integral the probe measures the preview's error against.
inline constexpr int kProbeEnvironmentSamples = 4096;

// Probes pixel (x, y) (y down, pixel centres at +0.5, the reference renderer's rays) of a
// width×height image of the scene. Pixels outside the image are refused by the caller.
ProbeResult probeSurface(const Scene& scene, int x, int y, int width, int height);

// One channel through the display chain, step by step.
ProbeDisplayChannel traceDisplayChannel(glm::vec3 radiance, int channel, const DisplaySettings& display);

}  // namespace glint
