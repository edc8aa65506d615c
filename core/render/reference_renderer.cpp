// CPU reference renderer (see reference_renderer.h).
#include "render/reference_renderer.h"
#include "render/shading_breakdown.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <thread>
#include <vector>

#include "math/frame.h"
#include "environment/environment_lighting.h"
#include "render/environment_sampling.h"
#include "render/hit_texture_point.h"
#include "render/sphere_occlusion.h"
#include "scene/plane_edge_fade.h"
#include "render/measured_shading.h"
#include "render/shadow_rays.h"
#include "render/specular_transport.h"
#include "texture/texture_eval.h"
#include "render/triangle_scene.h"

namespace glint {
namespace {

// Ray-sphere: |o + t·d - c|² = r² with |d| = 1; the nearest t > 0. The discriminant is taken
// as r² − |l|², l the offset's part perpendicular to the ray, and the near root as c/q: the
// stable forms of Haines et al., "Precision Improvements for Ray/Sphere Intersection", Ray
// Tracing Gems, 2019, ch. 7 (near grazing, b² − c cancels and GPU and CPU would disagree).
std::optional<float> intersectSphere(const SphereShape& sphere, const Ray& ray) {
    const glm::vec3 offset = ray.origin - sphere.center;
    const float b = glm::dot(offset, ray.direction);
    const glm::vec3 perpendicular = offset - b * ray.direction;
    const float discriminant = sphere.radius * sphere.radius - glm::dot(perpendicular, perpendicular);
    if (discriminant < 0.0f) return std::nullopt;
    const float c = glm::dot(offset, offset) - sphere.radius * sphere.radius;
    const float q = -b - std::copysign(std::sqrt(discriminant), b);
    const float nearT = std::min(c / q, q), farT = std::max(c / q, q);
    if (nearT > 0.0f) return nearT;
    if (farT > 0.0f) return farT;
    return std::nullopt;
}

// Ray-rectangle: the plane through the centre, then the rectangle's extent in its own frame.
std::optional<float> intersectPlane(const PlaneShape& plane, const Ray& ray) {
    const float denominator = glm::dot(plane.normal, ray.direction);
    if (std::abs(denominator) < 1e-8f) return std::nullopt;
    const float t = glm::dot(plane.center - ray.origin, plane.normal) / denominator;
    if (t <= 0.0f) return std::nullopt;
    const ShadingFrame frame = ShadingFrame::fromNormal(plane.normal);
    const glm::vec3 local = frame.toLocal(ray.origin + t * ray.direction - plane.center);
    if (std::abs(local.x) > 0.5f * plane.size.x || std::abs(local.y) > 0.5f * plane.size.y) return std::nullopt;
    return t;
}

}  // namespace

glm::vec3 surfaceTangent(const Shape& shape, glm::vec3 outwardNormal) {
    if (std::holds_alternative<SphereShape>(shape)) {
        // ∂position/∂u ∝ (+y) × n; its length is sin(polar angle), zero at the poles, where
        // the tangent of the u = 0 meridian is used.
        const glm::vec3 alongU{outwardNormal.z, 0.0f, -outwardNormal.x};
        const float length = glm::length(alongU);
        return length > 1e-6f ? alongU / length : glm::vec3(0.0f, 0.0f, -1.0f);
    }
    return ShadingFrame::fromNormal(glm::normalize(std::get<PlaneShape>(shape).normal)).tangent;
}

std::optional<SurfaceHit> intersectScene(const Scene& scene, const Ray& ray) {
    std::optional<SurfaceHit> nearest;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (tracedAsTriangles(scene.objects[i])) continue;  // below, through the BVH
        const Shape& shape = scene.objects[i].shape;
        std::optional<float> t;
        if (const auto* sphere = std::get_if<SphereShape>(&shape)) t = intersectSphere(*sphere, ray);
        else t = intersectPlane(std::get<PlaneShape>(shape), ray);
        if (!t || (nearest && *t >= nearest->distance)) continue;
        const glm::vec3 position = ray.origin + *t * ray.direction;
        glm::vec3 normal;
        if (const auto* sphere = std::get_if<SphereShape>(&shape)) normal = (position - sphere->center) / sphere->radius;
        else normal = std::get<PlaneShape>(shape).normal;
        const glm::vec3 tangent = surfaceTangent(shape, normal);
        if (glm::dot(normal, ray.direction) > 0.0f) normal = -normal;  // surfaces are two-sided
        nearest = SurfaceHit{*t, position, glm::normalize(normal), tangent, static_cast<int>(i)};
    }
    // Meshes, cubes, tori and tessellated spheres (render/triangle_scene.h).
    const float limit = nearest ? nearest->distance : std::numeric_limits<float>::infinity();
    if (auto triangleHit = triangleSceneFor(scene)->intersect(scene, ray, limit)) nearest = std::move(triangleHit);
    return nearest;
}

namespace {

// A material's response at one hit: its textured values and normal-mapped frame, f_r for each
// light, and its ambient, environment and traced delta-lobe terms.
struct HitResponse {
    std::vector<float> values;  // packed per the model's table, textures applied (none for a table)
    ShadingFrame frame;
    std::function<glm::vec3(glm::vec3 towardsLight)> brdf;
    glm::vec3 ambientReflectance;
    float occlusion;  // the occlusion map (glTF's occlusionTexture): scales ambient and environment light only
    glm::vec3 environment;  // before occlusion
    glm::vec3 specular;
};

// How the hit's material responds there: its values and frame after textures, f_r, and the
// ambient, environment and traced delta-lobe terms.
HitResponse responseAt(const Scene& scene, const SurfaceHit& hit, glm::vec3 towardsViewer, const ReferenceOptions& options,
                       uint32_t pixelSeed) {
    const SceneObject& object = scene.objects.at(hit.objectIndex);
    // Textures (texture/texture_eval.h): the parameter values and the normal at this point.
    const TexturePoint texturePoint = hitTexturePoint(scene, hit);
    const ShadingFrame unmapped = ShadingFrame::fromNormalAndTangent(hit.normal, hit.tangent);
    // The delta lobes (mirror, glass) are traced against the environment or the background.
    std::optional<SphereGeometry> sphere;
    const auto* sphereShape = std::get_if<SphereShape>(&object.shape);
    if (sphereShape && !drawnAsTriangles(object.shape, object.interpolation))
        sphere = SphereGeometry{sphereShape->center, sphereShape->radius};
    return std::visit(
        Overloaded{
            [&](const AnalyticMaterial& analytic) {
                const BrdfModel model = analytic.model;
                std::vector<float> values = texturedValues(analytic, texturePoint);
                const ShadingFrame frame = normalMappedFrame(analytic, texturePoint, unmapped);
                // Environment light: the GPU's image-based lighting, or sampled.
                const glm::vec3 environment =
                    options.sampleEnvironment ? sampleEnvironmentLighting(model, values, towardsViewer, frame, scene.environment,
                                                                          pixelSeed, options.environmentSamples)
                                              : environmentLighting(model, values, towardsViewer, frame, scene.environment);
                const glm::vec3 specular =
                    traceSpecular(model, values, MissRadiance(scene.background, &scene.environment, options.backdrop),
                                  sphere ? &*sphere : nullptr, hit.position, frame.normal, towardsViewer, hit.distance);
                const glm::vec3 ambient = ambientReflectance(model, values, towardsViewer, frame);
                auto brdf = [=](glm::vec3 towardsLight) { return evalBrdf(model, values, towardsLight, towardsViewer, frame); };
                return HitResponse{std::move(values), frame, brdf, ambient, ambientOcclusion(analytic, texturePoint),
                                   environment, specular};
            },
            // A MERL table (measured_shading.h) has no delta lobes, and its ambient and environment
            // terms come from its measured directional albedo.
            [&](const MeasuredMaterial& measured) {
                const MeasuredBrdf& table = *measured.brdf;
                auto brdf = [&table, towardsViewer, unmapped](glm::vec3 towardsLight) {
                    return evalMeasuredBrdf(table, towardsLight, towardsViewer, unmapped);
                };
                return HitResponse{{}, unmapped, brdf, measuredAmbientReflectance(table, towardsViewer, unmapped), 1.0f,
                                   measuredEnvironmentLighting(table, towardsViewer, unmapped, scene.environment), glm::vec3(0.0f)};
            },
            [](const CustomMaterial&) -> HitResponse {
                GLINT_CHECK(!"a .brdf material reached the CPU reference (referenceCanRender refuses it)");
                return {};
            }},
        scene.materials.at(object.materialIndex).kind);
}

// The delta lights' sum: L_o = Σ f_r(ω_i, ω_o) · E⊥ · cos θ_i · V (V: a shadow ray). With a
// breakdown, every light's term, those that add nothing too.
glm::vec3 directLight(const Scene& scene, const SurfaceHit& hit, const HitResponse& response, ShadingBreakdown* breakdown) {
    glm::vec3 radiance(0.0f);
    for (size_t lightIndex = 0; lightIndex < scene.lights.size(); ++lightIndex) {
        const Light& light = scene.lights[lightIndex];
        if (!light.enabled || light.type == LightType::Ambient) continue;  // ambient: apart
        const LightArrival arrival = lightArrival(light, hit.position);
        const float cosTheta = response.frame.cosTheta(arrival.towardsLight);
        if (cosTheta <= 0.0f && !breakdown) continue;
        const float visibility = cosTheta <= 0.0f ? 0.0f : lightVisibility(scene, light, hit, arrival);
        if (visibility == 0.0f && !breakdown) continue;
        const glm::vec3 brdf = response.brdf(arrival.towardsLight);
        const glm::vec3 reflected = visibility == 0.0f ? glm::vec3(0.0f) : brdf * arrival.normalIrradiance * cosTheta;
        radiance += reflected;
        if (breakdown) breakdown->lights.push_back({static_cast<int>(lightIndex), arrival, cosTheta, visibility, brdf, reflected});
    }
    return radiance;
}

// shadeHit's terms at the hit itself; `breakdown`, when given, receives each term (the surface
// probe's hook), else only the sum is returned.
glm::vec3 shadeAtHit(const Scene& scene, const SurfaceHit& hit, glm::vec3 towardsViewer, const ReferenceOptions& options,
                     uint32_t pixelSeed, ShadingBreakdown* breakdown) {
    const HitResponse response = responseAt(scene, hit, towardsViewer, options, pixelSeed);
    const ShadingFrame& frame = response.frame;
    glm::vec3 radiance = directLight(scene, hit, response, breakdown);
    // Ambient: uniform radiance L_a from every direction reflects as k_a·L_a.
    glm::vec3 ambient(0.0f);
    for (const Light& light : scene.lights) ambient += ambientRadiance(light);
    radiance += response.occlusion * response.ambientReflectance * ambient;
    // The environment, less what the scene's spheres cover (sphere_occlusion.h).
    const glm::vec3 environment = response.occlusion * response.environment *
                                  environmentVisibility(occludingSpheres(scene), hit.position, frame.normal);
    radiance += environment;
    radiance += response.specular;
    if (breakdown) {
        breakdown->frame = frame;
        breakdown->values = response.values;
        breakdown->ambientReflectance = response.ambientReflectance;
        breakdown->ambientRadiance = ambient;
        breakdown->environment = environment;
        breakdown->specular = response.specular;
        breakdown->total = radiance;
    }
    return radiance;
}

}  // namespace

glm::vec3 shadeHit(const Scene& scene, const SurfaceHit& hit, glm::vec3 towardsViewer, const ReferenceOptions& options,
                   uint32_t pixelSeed) {
    if (hit.triangle && scene.objects.at(hit.objectIndex).interpolation == SurfaceInterpolation::Gouraud) {
        // Gouraud: shade the corners, interpolate the radiance (render/triangle_scene.h).
        glm::vec3 radiance(0.0f);
        const auto corners = gouraudCorners(scene, hit);
        for (int k = 0; k < 3; ++k)
            radiance += hit.triangle->barycentric[k] * shadeHit(scene, corners[k].first, corners[k].second, options, pixelSeed);
        return radiance;
    }
    return shadeAtHit(scene, hit, towardsViewer, options, pixelSeed, nullptr);
}

ShadingBreakdown shadingBreakdown(const Scene& scene, const SurfaceHit& hit, glm::vec3 towardsViewer,
                                  const ReferenceOptions& options, uint32_t pixelSeed) {
    ShadingBreakdown breakdown;
    shadeAtHit(scene, hit, towardsViewer, options, pixelSeed, &breakdown);
    return breakdown;
}

RadianceImage renderReference(const Scene& scene, int width, int height, const ReferenceOptions& options) {
    if (width <= 0 || height <= 0) width = scene.width, height = scene.height;
    RadianceImage image(width, height);
    const glm::mat4 inverseViewProjection =
        glm::inverse(scene.camera.viewProjection(static_cast<float>(width) / height));
    const MissRadiance miss(scene.background, &scene.environment);
    std::atomic<int> rowsDone{0};
    auto renderRows = [&](int firstRow, int rowStep) {
        for (int y = firstRow; y < height; y += rowStep) {
            if (options.progress && firstRow == 0) options.progress(static_cast<float>(rowsDone.load()) / height);
            for (int x = 0; x < width; ++x) {
                const Ray ray = primaryRay(inverseViewProjection, x + 0.5f, y + 0.5f, width, height);
                const auto hit = intersectScene(scene, ray);
                const uint32_t pixelSeed = static_cast<uint32_t>(y) * static_cast<uint32_t>(width) + static_cast<uint32_t>(x) +
                                         options.environmentSeed * 0x9E3779B9u;
                if (!hit) {
                    image.set(x, y, miss.primary(ray.direction));
                    continue;
                }
                glm::vec3 radiance = shadeHit(scene, *hit, -ray.direction, options, pixelSeed);
                if (const auto* plane = std::get_if<PlaneShape>(&scene.objects.at(hit->objectIndex).shape))
                    radiance = glm::mix(radiance, miss.primary(ray.direction),
                                        planeEdgeFade(plane->center, planeEdgeFadeRadii(*plane), hit->position));
                image.set(x, y, radiance);
            }
            ++rowsDone;
        }
    };
    const int threadCount = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
    std::vector<std::thread> threads;
    for (int t = 1; t < threadCount; ++t) threads.emplace_back(renderRows, t, threadCount);
    renderRows(0, threadCount);
    for (std::thread& thread : threads) thread.join();
    if (options.progress) options.progress(1.0f);
    return image;
}

}  // namespace glint
