// The CPU reference renderer: ray-casts the analytic scene (exact spheres and planes), one ray
// through each pixel centre, and evaluates the same BRDFs and lights as the GPU into linear
// radiance. It is the ground truth the GL renderer is tested against; it is not fast.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "image/image.h"
#include "render/transmission_backdrop.h"
#include "scene/scene.h"

namespace glint {

// The triangle a ray hit (render/triangle_scene.h): its corners in world space and the hit's
// barycentric weights, for Gouraud shading.
struct TriangleCorners {
    std::array<Vertex, 3> vertices;
    glm::vec3 barycentric;
    int index;  // the triangle's index within its object's mesh
};

struct SurfaceHit {
    float distance;       // along the ray [m]
    glm::vec3 position;
    glm::vec3 normal;     // unit, facing the ray's origin
    glm::vec3 tangent;    // unit, ⟂ normal: direction of increasing u (see surfaceTangent)
    int objectIndex;
    std::optional<TriangleCorners> triangle = std::nullopt;  // set for shapes drawn from triangles
};

// The shading tangent of a shape at a point, before any two-sided flip: for a sphere the
// direction of increasing u of its UV parametrisation (azimuth around +y, as makeUvSphere's
// vertex tangent), with a fixed tangent at the poles; for a plane its mesh tangent (makePlane).
// GLSL twin: sphereTangent in shaders/surface.frag (planes pass the mesh tangent).
glm::vec3 surfaceTangent(const Shape& shape, glm::vec3 outwardNormal);

// Nearest intersection of a ray with the scene's objects, if any.
std::optional<SurfaceHit> intersectScene(const Scene& scene, const Ray& ray);

// How the reference lights surfaces by the environment: by default with the GPU's own image-based
// lighting (environment/environment_lighting.h, so GPU and CPU agree per pixel); with
// `sampleEnvironment`, by Monte-Carlo sampling of the true integral (render/environment_sampling.h).
struct ReferenceOptions {
    bool sampleEnvironment = false;
    int environmentSamples = 512;  // per pixel, when sampling
    uint32_t environmentSeed = 0;  // another seed: another (independent, as deterministic) estimate
    // Called now and then from the calling thread with the fraction of rows done (0 … 1).
    std::function<void(float)> progress = nullptr;
    // What the transmitted rays of glass and openpbr see of the frame's opaque objects: the GPU's
    // opaque pass of the same frame (Renderer::readTransmissionBackdrop). None: they see the
    // environment or the background only, as rays that miss the scene.
    const TransmissionBackdrop* backdrop = nullptr;
};

// Outgoing radiance [W/(sr·m²)] at a hit towards `towardsViewer`: Σ f_r·E⊥·cos θ over the delta
// lights, plus k_a·L_a for the ambient lights, plus the model's traced delta lobes (mirror, glass)
// whose secondary rays see the environment or the background (transmitted ones the backdrop
// first), plus the environment's light.
// Twin of shadeSurface() in common/shading.glsl. `pixelSeed` seeds the environment sampling.
glm::vec3 shadeHit(const Scene& scene, const SurfaceHit& hit, glm::vec3 towardsViewer,
                   const ReferenceOptions& options = {}, uint32_t pixelSeed = 0);

// Renders the whole scene at width×height (the scene's own size when zero).
RadianceImage renderReference(const Scene& scene, int width = 0, int height = 0, const ReferenceOptions& options = {});

}  // namespace glint
