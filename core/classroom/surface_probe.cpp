// The classroom surface probe (see surface_probe.h). The shading terms come from the reference
// renderer's own shadingBreakdown(); this file adds the geometry a lecture names (H, R, T, the
// angles), the sources' quantities and the display chain.
#include "classroom/surface_probe.h"

#include <algorithm>
#include <cmath>

#include "brdf/model_traits.h"
#include "display/display_chain.h"
#include "light/photometry.h"
#include "environment/environment_lighting.h"
#include "render/environment_sampling.h"
#include "render/miss_radiance.h"
#include "render/reference_renderer.h"
#include "render/shading_breakdown.h"
#include "render/specular_transport.h"

namespace glint {
namespace {

float probeAngleDegrees(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)));
}

// Mirror direction of a unit vector d (pointing away from the surface) about N: 2(N·d)N − d.
glm::vec3 probeMirror(glm::vec3 direction, glm::vec3 normal) { return reflectDirection(-direction, normal); }

// Snell's law for the ray travelling along -awayFromSurface (towards the surface, on N's side),
// from a medium of index etaIncident into etaTransmitted (Hecht, Optics, §4.4).
ProbeRefraction probeRefraction(glm::vec3 awayFromSurface, glm::vec3 normal, float etaIncident, float etaTransmitted) {
    ProbeRefraction refraction;
    refraction.etaIncident = etaIncident;
    refraction.etaTransmitted = etaTransmitted;
    const float cosIncident = std::clamp(glm::dot(awayFromSurface, normal), 0.0f, 1.0f);
    refraction.incidentDegrees = glm::degrees(std::acos(cosIncident));
    if (etaIncident > etaTransmitted) refraction.criticalDegrees = glm::degrees(std::asin(etaTransmitted / etaIncident));
    const float etaRatio = etaIncident / etaTransmitted;
    const float sinTransmitted = etaRatio * std::sqrt(std::max(0.0f, 1.0f - cosIncident * cosIncident));
    if (sinTransmitted > 1.0f) {
        refraction.totalInternalReflection = true;
        return refraction;
    }
    refraction.transmittedDegrees = glm::degrees(std::asin(sinTransmitted));
    refraction.direction = glm::normalize(refractDirection(-awayFromSurface, normal, etaRatio));
    return refraction;
}

ProbeSource probeSource(const Light& light) {
    const LightPhotometry photometry = lightPhotometry(light);
    if (light.type == LightType::Directional)
        return {"M", "W/m²", light.irradiance, light.color, photometry.lux, "lx"};
    return {"Φ", "W", light.power, light.color, photometry.lumens, "lm"};
}

}  // namespace

ProbeDisplayChannel traceDisplayChannel(glm::vec3 radiance, int c, const DisplaySettings& display) {
    ProbeDisplayChannel channel;
    channel.radiance = radiance[c];
    const glm::vec3 exposed = glm::max(radiance * std::exp2(display.exposureStops), 0.0f);
    channel.exposed = exposed[c];
    channel.toneMapped = applyToneMap(exposed, display.toneMap)[c];
    channel.clamped = std::clamp(channel.toneMapped, 0.0f, 1.0f);
    channel.encoded = encodeForDisplay(radiance, display)[c];
    channel.value8 = quantize8(channel.encoded);
    return channel;
}

namespace {

using Etas = std::pair<float, float>;  // η on the viewer's side, η beyond

// One light's chain to the point: its arrival, the angles, the factors and what it adds.
ProbeLight probeLight(const Light& light, const DirectLightTerm& term, glm::vec3 normal, glm::vec3 towardsViewer,
                      std::optional<Etas> etas) {
    ProbeLight probe{.lightIndex = term.lightIndex, .name = light.name, .type = light.type,
                     .source = probeSource(light), .towardsLight = term.arrival.towardsLight,
                     .halfVector = glm::normalize(term.arrival.towardsLight + towardsViewer),
                     .mirror = probeMirror(term.arrival.towardsLight, normal),
                     .distance = term.arrival.distance, .cosTheta = term.cosTheta};
    if (etas) probe.transmitted = probeRefraction(term.arrival.towardsLight, normal, etas->first, etas->second);
    if (light.type != LightType::Directional) {
        probe.distanceFactor = distanceFactor(light.attenuation, term.arrival.distance);
        probe.classicAttenuation = light.attenuation.enabled;
    }
    if (light.type == LightType::Spot)
        probe.spotFactor = spotFactor(glm::dot(-term.arrival.towardsLight, glm::normalize(light.direction)),
                                      spotCosOuter(light), spotCosInner(light), light.falloffExponent);
    probe.incidentDegrees = probeAngleDegrees(normal, probe.towardsLight);
    probe.reflectedDegrees = probeAngleDegrees(normal, towardsViewer);
    probe.halfDegrees = probeAngleDegrees(normal, probe.halfVector);
    probe.mirrorViewDegrees = probeAngleDegrees(probe.mirror, towardsViewer);
    probe.behindSurface = term.cosTheta <= 0.0f;
    probe.shadowed = !probe.behindSurface && term.visibility == 0.0f;
    probe.normalIrradiance = term.arrival.normalIrradiance;
    probe.irradiance = term.arrival.normalIrradiance * std::max(term.cosTheta, 0.0f) * term.visibility;
    probe.illuminance = illuminance(probe.irradiance);
    probe.brdf = term.brdf;
    probe.radiance = term.radiance;
    probe.luminance = luminance(probe.radiance);
    return probe;
}

// Refraction (glass): the indices either side; the viewer is outside unless the ray hit an exact
// sphere from inside. None for a material that does not refract.
std::optional<Etas> refractionIndices(const AnalyticMaterial* analytic, const ShadingBreakdown& breakdown, const SceneObject& object,
                                      const SurfaceHit& hit) {
    const auto lobes = analytic ? deltaLobeWeights(analytic->model, breakdown.values, 1.0f) : std::nullopt;
    if (!lobes || !lobes->refractiveIndex) return std::nullopt;
    const float ior = *lobes->refractiveIndex;
    const auto* sphere = std::get_if<SphereShape>(&object.shape);
    const bool inside = sphere && !hit.triangle && glm::dot(hit.normal, hit.position - sphere->center) < 0.0f;
    return inside ? Etas{ior, 1.0f} : Etas{1.0f, ior};
}

// The chain at a surface the ray hit: the material, each light's term, ambient and environment.
void probeHit(const Scene& scene, const SurfaceHit& hit, glm::vec3 towardsViewer, uint32_t pixelSeed, ProbeResult& result) {
    const SceneObject& object = scene.objects.at(hit.objectIndex);
    const Material& material = scene.materials.at(object.materialIndex);
    result.hitSurface = true;
    result.position = hit.position;
    result.hitDistance = hit.distance;
    result.objectIndex = hit.objectIndex;
    result.materialIndex = object.materialIndex;
    result.objectName = object.name;
    result.materialName = material.name;
    result.towardsViewer = towardsViewer;
    result.normal = hit.normal;
    if (material.custom()) {
        result.gpuOnlyMaterial = true;
        result.modelLabel = "custom .brdf";
        return;
    }
    const ShadingBreakdown breakdown = shadingBreakdown(scene, hit, towardsViewer, {}, pixelSeed);
    const AnalyticMaterial* analytic = material.analytic();  // else a measured table
    result.modelLabel = analytic ? modelInfo(analytic->model).label : "measured (MERL)";
    result.gouraud = hit.triangle && object.interpolation == SurfaceInterpolation::Gouraud;
    const glm::vec3 normal = breakdown.frame.normal;
    result.normal = normal;
    result.viewMirror = probeMirror(towardsViewer, normal);
    const std::optional<Etas> etas = refractionIndices(analytic, breakdown, object, hit);
    if (etas) result.viewTransmitted = probeRefraction(towardsViewer, normal, etas->first, etas->second);
    for (const DirectLightTerm& term : breakdown.lights)
        result.lights.push_back(probeLight(scene.lights.at(term.lightIndex), term, normal, towardsViewer, etas));
    result.ambientReflectance = breakdown.ambientReflectance;
    result.ambientRadiance = breakdown.ambientRadiance;
    result.environment = breakdown.environment;
    if (scene.environment.enabled() && analytic && modelInfo(analytic->model).glslEnvironment) {
        result.environmentMethod = environmentApproximation(analytic->model, breakdown.values, scene.environment);
        result.environmentTruth = sampleEnvironmentLighting(analytic->model, breakdown.values, towardsViewer, breakdown.frame,
                                                            scene.environment, pixelSeed, kProbeEnvironmentSamples);
    }
    result.specular = breakdown.specular;
    result.radiance = result.gouraud ? shadeHit(scene, hit, towardsViewer, {}, pixelSeed) : breakdown.total;
}

}  // namespace

ProbeResult probeSurface(const Scene& scene, int x, int y, int width, int height) {
    ProbeResult result;
    result.pixelX = x, result.pixelY = y, result.width = width, result.height = height;
    result.displaySettings = scene.display;
    const glm::mat4 inverseViewProjection =
        glm::inverse(scene.camera.viewProjection(static_cast<float>(width) / static_cast<float>(height)));
    const Ray ray = primaryRay(inverseViewProjection, x + 0.5f, y + 0.5f, width, height);
    result.rayOrigin = ray.origin, result.rayDirection = ray.direction;
    const std::optional<SurfaceHit> hit = intersectScene(scene, ray);
    const uint32_t pixelSeed = static_cast<uint32_t>(y) * static_cast<uint32_t>(width) + static_cast<uint32_t>(x);
    if (hit) probeHit(scene, *hit, -ray.direction, pixelSeed, result);
    else result.radiance = MissRadiance(scene.background, &scene.environment).primary(ray.direction);
    // A custom .brdf's radiance is the GPU's alone: the probe shows it as black.
    result.luminance = luminance(result.radiance);
    for (int c = 0; c < 3; ++c) result.display[c] = traceDisplayChannel(result.radiance, c, scene.display);
    return result;
}

}  // namespace glint
