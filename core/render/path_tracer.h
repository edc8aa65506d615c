// The CPU path tracer: the scene's ground truth with light bouncing between surfaces.
// Unidirectional; next-event estimation of the delta lights (point, spot, directional) and of the
// environment map, whose light a BSDF-sampled ray also finds, combined by multiple importance
// sampling (balance heuristic, Veach 1997 §9.2); cosine-weighted continuation (no model has its own
// sampler yet), mirror and glass as sampled delta lobes (render/delta_lobes.h), Russian roulette.
// Progressive: each pass adds one jittered sample per pixel, on every core; the same seed gives
// the same picture whatever the thread count. Radiance in W/(sr·m²), as the reference renderer's.
// What light reaches a path, after the reference's conventions (so that one bounce agrees with
// it): rays leaving the scene after a diffuse or glossy bounce see the environment and the
// ambient lights' uniform radiance; after a delta lobe they see what the reference's mirrors
// see (the environment, else the background); primary rays see the background as it does.
// Not yet: openpbr's transmission and emission (added as the reference traces them, seeing the
// environment), Gouraud interpolation (shaded per hit), textures' ambient occlusion (the tracer
// finds the occlusion itself).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "scene/scene.h"

namespace glint {

struct PathTraceSettings {
    int maxBounces = 64;            // surface interactions per path; 1: direct light only
    int russianRouletteAfter = 3;   // bounces before paths may be ended at random
    uint32_t seed = 0;              // another seed: another independent estimate, as deterministic
};

// An accumulating path-traced picture of a scene, which must outlive it.
class PathTracer {
public:
    PathTracer(const Scene& scene, int width, int height, PathTraceSettings settings = {});

    // Adds one sample per pixel, on every core.
    void addPass();
    int samplesPerPixel() const { return passes_; }
    // The mean of the samples so far (black before the first pass).
    RadianceImage radiance() const;

private:
    const Scene& scene_;
    int width_, height_;
    PathTraceSettings settings_;
    int passes_ = 0;
    std::vector<double> sum_;  // RGB per pixel, row-major: double, so that thousands of passes add exactly enough
};

// `samplesPerPixel` passes of a PathTracer at width×height (the scene's size when zero);
// `progress`, when given, is called after each pass with the fraction done.
RadianceImage renderPathTraced(const Scene& scene, int samplesPerPixel, int width = 0, int height = 0,
                               const PathTraceSettings& settings = {},
                               const std::function<void(float)>& progress = nullptr);

}  // namespace glint
