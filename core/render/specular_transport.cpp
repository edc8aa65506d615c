// Dispatch of the specular-transport hook over the models that have one (see
// specular_transport.h); the tracing itself lives in the header, beside its GLSL twin's layout.
#include "render/specular_transport.h"

#include "brdf/glass.h"
#include "brdf/mirror.h"
#include "render/openpbr_transport.h"

namespace glint {
namespace {

// The C++ twins of transport<Model> (shaders/brdf/<model>.glsl), one per model with delta lobes.
struct TracedRay {
    const MissRadiance& miss;
    const SphereGeometry* sphere;
    glm::vec3 position, normal, towardsViewer;
    float viewerDistance;
};

glm::vec3 traceDeltaLobes(const MirrorParams& mirror, const TracedRay& ray) {
    return traceMirror(mirror.ior, mirror.extinction, ray.miss, ray.normal, ray.towardsViewer);
}

glm::vec3 traceDeltaLobes(const GlassParams& glass, const TracedRay& ray) {
    return traceGlass(glassInterface(glass), glass.absorption, ray.miss, ray.sphere, ray.position, ray.normal,
                      ray.towardsViewer, ray.viewerDistance);
}

glm::vec3 traceDeltaLobes(const OpenPbrParams& p, const TracedRay& ray) {
    return transportOpenpbr(p, ray.miss, ray.sphere, ray.position, ray.normal, ray.towardsViewer);
}

}  // namespace

glm::vec3 traceSpecular(BrdfModel model, std::span<const float> values, const MissRadiance& miss,
                        const SphereGeometry* sphere, glm::vec3 position, glm::vec3 normal, glm::vec3 towardsViewer,
                        float viewerDistance) {
    const TracedRay ray{miss, sphere, position, normal, towardsViewer, viewerDistance};
    return dispatch(model, [&]<class M>(M) {
        constexpr bool twin = requires(const typename M::Params& p, const TracedRay& r) { traceDeltaLobes(p, r); };
        static_assert(twin == TracesDeltaLobes<M>, "a model that traces delta lobes needs its traceDeltaLobes here");
        if constexpr (twin) return traceDeltaLobes(unpack<M>(values.data()), ray);
        else return glm::vec3(0.0f);
    });
}

}  // namespace glint
