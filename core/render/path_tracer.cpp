// The CPU path tracer (see path_tracer.h).
// Sections: the material at a vertex; light at a vertex (next-event estimation); the next
// direction; one path; passes.
#include "render/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <thread>

#include "environment/environment_lighting.h"
#include "environment/environment_map.h"
#include "interchange/measured_brdf.h"
#include "render/cosine_sampling.h"
#include "render/delta_lobes.h"
#include "render/hit_texture_point.h"
#include "render/miss_radiance.h"
#include "render/random_stream.h"
#include "render/reference_renderer.h"
#include "render/shadow_rays.h"
#include "render/specular_transport.h"
#include "scene/plane_edge_fade.h"
#include "texture/texture_eval.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

// ---- The material at a vertex ----

// A hit's material: f_r through the model's eval (textures and normal map applied) or the
// measured table, in its shading frame; and what of it is sampled as delta lobes.
struct VertexMaterial {
    ShadingFrame frame;
    const MeasuredBrdf* measured = nullptr;  // set for a MERL table, else the analytic model below
    BrdfModel model = BrdfModel::Lambert;
    std::vector<float> values;
    std::optional<SphereGeometry> sphere;  // an exact sphere: glass refracts through it

    glm::vec3 brdf(glm::vec3 towardsLight, glm::vec3 towardsViewer) const {
        return measured ? evalMeasuredBrdf(*measured, towardsLight, towardsViewer, frame)
                        : evalBrdf(model, values, towardsLight, towardsViewer, frame);
    }
    bool hasDeltaLobe() const { return !measured && samplesDeltaLobe(model); }
    // Traced lobes the tracer does not sample yet (openpbr's transmission, its emission).
    bool tracesOtherLobes() const { return !measured && !samplesDeltaLobe(model) && modelInfo(model).glslTransport != nullptr;
    }
};

VertexMaterial materialAt(const Scene& scene, const SurfaceHit& hit) {
    const SceneObject& object = scene.objects.at(hit.objectIndex);
    const TexturePoint texturePoint = hitTexturePoint(scene, hit);
    const ShadingFrame unmapped = ShadingFrame::fromNormalAndTangent(hit.normal, hit.tangent);
    VertexMaterial material;
    const auto* sphere = std::get_if<SphereShape>(&object.shape);
    if (sphere && !drawnAsTriangles(object.shape, object.interpolation))
        material.sphere = SphereGeometry{sphere->center, sphere->radius};
    const auto& kind = scene.materials.at(object.materialIndex).kind;
    if (const auto* analytic = std::get_if<AnalyticMaterial>(&kind)) {
        material.model = analytic->model;
        material.values = texturedValues(*analytic, texturePoint);
        material.frame = normalMappedFrame(*analytic, texturePoint, unmapped);
    } else {
        const auto* measured = std::get_if<MeasuredMaterial>(&kind);
        GLINT_CHECK(measured && "a .brdf material reached the path tracer (referenceCanRender refuses it)");
        material.measured = measured->brdf.get();
        material.frame = unmapped;
    }
    return material;
}

// ---- Light at a vertex ----

// A ray leaving `hit` along `direction`, its origin lifted off the surface as the shadow rays' are.
Ray rayLeaving(const SurfaceHit& hit, glm::vec3 direction) {
    const float offset = std::copysign(rayOriginOffset(hit.position), glm::dot(direction, hit.normal));
    return {hit.position + offset * hit.normal, direction};
}

// The environment's density of drawing a world direction [1/sr].
float environmentPdf(const Environment& environment, glm::vec3 direction) {
    return environment.map->distribution.pdf(environmentMapDirection(environment, direction));
}

// Next-event estimation at a vertex: Σ f_r·E⊥·cos θ·V over the delta lights (as the reference),
// and one environment sample drawn from the map, weighted against cosine sampling (balance).
glm::vec3 directLight(const Scene& scene, const SurfaceHit& hit, const VertexMaterial& material, glm::vec3 towardsViewer,
                      RandomStream& random) {
    glm::vec3 radiance(0.0f);
    for (const Light& light : scene.lights) {
        if (!light.enabled || light.type == LightType::Ambient) continue;  // ambient: seen by escaping rays
        const LightArrival arrival = lightArrival(light, hit.position);
        const float cosTheta = material.frame.cosTheta(arrival.towardsLight);
        if (cosTheta <= 0.0f || lightVisibility(scene, light, hit, arrival) == 0.0f) continue;
        radiance += material.brdf(arrival.towardsLight, towardsViewer) * arrival.normalIrradiance * cosTheta;
    }
    const Environment& environment = scene.environment;
    if (!environment.enabled()) return radiance;
    const EnvironmentDirectionSample drawn = environment.map->distribution.sample(random.uniform2());
    const glm::vec3 towardsLight = environmentWorldDirection(environment, drawn.direction);
    const float cosTheta = material.frame.cosTheta(towardsLight);
    if (cosTheta <= 0.0f || !(drawn.pdf > 0.0f) || intersectScene(scene, rayLeaving(hit, towardsLight))) return radiance;
    const float weight = drawn.pdf / (drawn.pdf + cosineDirectionPdf(cosTheta));
    return radiance + material.brdf(towardsLight, towardsViewer) * environmentRadiance(environment, towardsLight) *
                          (weight * cosTheta / drawn.pdf);
}

// ---- The next direction ----

struct Continuation {
    glm::vec3 direction;
    glm::vec3 weight;        // f·cos/p, divided by the probability of choosing this lobe
    bool delta;              // from a delta lobe: no MIS, and escaping it sees MissRadiance
    std::optional<glm::vec3> mediumAbsorption;  // as DeltaLobeSample's
};

float largestComponent(glm::vec3 value) { return std::max({value.r, value.g, value.b}); }

// A cosine-weighted direction, and where the material has a delta lobe, a sample of it: one of
// the two is followed, chosen in proportion to its weight and divided by that chance, so that
// the choice itself adds no bias. None when neither carries light.
std::optional<Continuation> nextDirection(const SurfaceHit& hit, const VertexMaterial& material, glm::vec3 towardsViewer,
                                          RandomStream& random) {
    const glm::vec3 cosineSampled = material.frame.toWorld(cosineDirection(random.uniform2()));
    const float lobeChoice = random.uniform(), deltaChoice = random.uniform();
    glm::vec3 cosineWeight(0.0f);
    if (glm::dot(cosineSampled, hit.normal) > 0.0f)  // not below the geometric surface
        cosineWeight = material.brdf(cosineSampled, towardsViewer) * kPi;  // f·cos θ / (cos θ/π)
    const Continuation diffuse{cosineSampled, cosineWeight, false, std::nullopt};
    if (!material.hasDeltaLobe()) return largestComponent(cosineWeight) > 0.0f ? std::optional(diffuse) : std::nullopt;
    const DeltaLobeSite site{hit.position, material.frame.normal, towardsViewer, material.sphere ? &*material.sphere : nullptr};
    const DeltaLobeSample delta = *sampleDeltaLobe(material.model, material.values, site, deltaChoice);
    const float deltaShare = largestComponent(delta.weight), diffuseShare = largestComponent(cosineWeight);
    if (!(deltaShare + diffuseShare > 0.0f)) return std::nullopt;
    const float deltaProbability = deltaShare / (deltaShare + diffuseShare);
    if (lobeChoice < deltaProbability)
        return Continuation{delta.direction, delta.weight / deltaProbability, true, delta.mediumAbsorption};
    return Continuation{diffuse.direction, diffuse.weight / (1.0f - deltaProbability), false, std::nullopt};
}

// ---- One path ----

class PathSampler {
public:
    PathSampler(const Scene& scene, const PathTraceSettings& settings)
        : scene_(scene), settings_(settings), miss_(scene.background, &scene.environment) {
        for (const Light& light : scene.lights) ambient_ += ambientRadiance(light);
    }

    // The radiance one path brings along the primary ray.
    glm::vec3 trace(Ray ray, RandomStream& random) const {
        const glm::vec3 primaryDirection = ray.direction;
        glm::vec3 radiance(0.0f), throughput(1.0f), absorption(0.0f);
        bool afterDelta = false;
        float lastCosinePdf = 0.0f;  // of the last diffuse bounce's direction
        std::optional<float> edgeFade;  // a primary hit on a plane: its fade into the background
        for (int bounce = 0;; ++bounce) {
            const auto hit = intersectScene(scene_, ray);
            if (!hit) {
                if (bounce == 0) return miss_.primary(ray.direction);
                radiance += throughput * escapedRadiance(ray.direction, afterDelta, lastCosinePdf);
                break;
            }
            if (bounce == settings_.maxBounces) break;
            throughput *= glm::exp(-absorption * hit->distance);  // Beer-Lambert inside glass
            if (const auto* plane = std::get_if<PlaneShape>(&scene_.objects.at(hit->objectIndex).shape); plane && bounce == 0)
                edgeFade = planeEdgeFade(plane->center, planeEdgeFadeRadii(*plane), hit->position);
            const glm::vec3 towardsViewer = -ray.direction;
            const VertexMaterial material = materialAt(scene_, *hit);
            radiance += throughput * directLight(scene_, *hit, material, towardsViewer, random);
            if (material.tracesOtherLobes())
                radiance += throughput * traceSpecular(material.model, material.values, miss_,
                                                       material.sphere ? &*material.sphere : nullptr, hit->position,
                                                       material.frame.normal, towardsViewer, hit->distance);
            const auto next = nextDirection(*hit, material, towardsViewer, random);
            if (!next) break;
            throughput *= next->weight;
            if (bounce + 1 >= settings_.russianRouletteAfter) {
                const float survival = std::min(0.95f, largestComponent(throughput));
                if (random.uniform() >= survival) break;
                throughput /= survival;
            }
            afterDelta = next->delta;
            lastCosinePdf = cosineDirectionPdf(material.frame.cosTheta(next->direction));
            if (next->mediumAbsorption) absorption = *next->mediumAbsorption;
            ray = rayLeaving(*hit, next->direction);
        }
        return edgeFade ? glm::mix(radiance, miss_.primary(primaryDirection), *edgeFade) : radiance;
    }

private:
    // What a ray leaving the scene brings (see path_tracer.h): after a delta lobe, what the
    // reference's mirrors see; after a diffuse bounce, the environment weighted against its own
    // next-event sample, and the ambient lights' uniform radiance.
    glm::vec3 escapedRadiance(glm::vec3 direction, bool afterDelta, float cosinePdf) const {
        if (afterDelta) return miss_(direction);
        const Environment& environment = scene_.environment;
        if (!environment.enabled()) return ambient_;
        const float weight = cosinePdf / (cosinePdf + environmentPdf(environment, direction));
        return ambient_ + weight * environmentRadiance(environment, direction);
    }

    const Scene& scene_;
    PathTraceSettings settings_;
    MissRadiance miss_;
    glm::vec3 ambient_{0.0f};
};

}  // namespace

// ---- Passes ----

PathTracer::PathTracer(const Scene& scene, int width, int height, PathTraceSettings settings)
    : scene_(scene), width_(width), height_(height), settings_(settings), sum_(static_cast<size_t>(width) * height * 3, 0.0) {}

void PathTracer::addPass() {
    const glm::mat4 inverseViewProjection = glm::inverse(scene_.camera.viewProjection(static_cast<float>(width_) / height_));
    const PathSampler sampler(scene_, settings_);
    const uint64_t passSeed = (static_cast<uint64_t>(settings_.seed) << 32u) | static_cast<uint32_t>(passes_);
    auto traceRows = [&](int firstRow, int rowStep) {
        for (int y = firstRow; y < height_; y += rowStep)
            for (int x = 0; x < width_; ++x) {
                const uint64_t pixel = static_cast<uint64_t>(y) * width_ + x;
                RandomStream random(passSeed, pixel);
                const glm::vec2 jitter = random.uniform2();  // a box filter over the pixel
                const Ray ray = primaryRay(inverseViewProjection, x + jitter.x, y + jitter.y, width_, height_);
                const glm::vec3 radiance = sampler.trace(ray, random);
                if (!std::isfinite(radiance.r + radiance.g + radiance.b)) continue;  // a degenerate path adds nothing
                for (int c = 0; c < 3; ++c) sum_[pixel * 3 + c] += radiance[c];
            }
    };
    const int threadCount = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    std::vector<std::thread> threads;
    for (int t = 1; t < threadCount; ++t) threads.emplace_back(traceRows, t, threadCount);
    traceRows(0, threadCount);
    for (std::thread& thread : threads) thread.join();
    ++passes_;
}

RadianceImage PathTracer::radiance() const {
    RadianceImage image(width_, height_);
    if (passes_ == 0) return image;
    for (size_t i = 0; i < sum_.size(); ++i) image.pixels[i] = static_cast<float>(sum_[i] / passes_);
    return image;
}

RadianceImage renderPathTraced(const Scene& scene, int samplesPerPixel, int width, int height,
                               const PathTraceSettings& settings, const std::function<void(float)>& progress) {
    if (width <= 0 || height <= 0) width = scene.width, height = scene.height;
    PathTracer tracer(scene, width, height, settings);
    for (int pass = 0; pass < samplesPerPixel; ++pass) {
        tracer.addPass();
        if (progress) progress(static_cast<float>(pass + 1) / samplesPerPixel);
    }
    return tracer.radiance();
}

}  // namespace glint
