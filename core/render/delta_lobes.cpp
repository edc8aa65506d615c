// Sampled delta lobes of mirror and glass (see delta_lobes.h).
#include "render/delta_lobes.h"

#include "brdf/fresnel.h"
#include "brdf/glass.h"
#include "brdf/mirror.h"

namespace glint {
namespace {

// Ideal conductor mirror: the reflection, weighted by F(θ_o; n + iκ).
DeltaLobeSample sampleLobe(const MirrorParams& mirror, const DeltaLobeSite& site, float) {
    const float cosOut = glm::dot(site.normal, site.towardsViewer);
    return {reflectDirection(-site.towardsViewer, site.normal), fresnelConductor(cosOut, mirror.ior, mirror.extinction),
            std::nullopt};
}

// Glass: reflection with probability R (Fresnel or 1 − k_t), else transmission, each with weight 1.
// Through a sphere the ray refracts (Snell) and travels in the glass's absorption until it leaves;
// through a thin pane it passes unbent with (1 − R)² of the light (probability 1 − R, weight 1 − R),
// as traceGlass. The (η_t/η_i)² radiance factors of entering and leaving cancel on every path
// that starts and ends in air, so neither is applied.
DeltaLobeSample sampleLobe(const GlassParams& glass, const DeltaLobeSite& site, float u) {
    const GlassInterface interface = glassInterface(glass);
    const glm::vec3 incoming = -site.towardsViewer;
    const float cosIncident = glm::dot(site.normal, site.towardsViewer);
    const glm::vec3 reflected = reflectDirection(incoming, site.normal);
    if (!site.sphere) {
        const float reflectance = glassReflectance(interface, cosIncident, glass.ior);
        if (u < reflectance) return {reflected, glm::vec3(1.0f), std::nullopt};
        return {incoming, glm::vec3(1.0f - reflectance), std::nullopt};
    }
    const bool leaving = glm::dot(site.normal, site.position - site.sphere->center) < 0.0f;  // normal points inwards
    const float eta = leaving ? 1.0f / glass.ior : glass.ior;                                   // η_t / η_i
    const float reflectance = glassReflectance(interface, cosIncident, eta);
    if (u < reflectance) return {reflected, glm::vec3(1.0f), std::nullopt};
    return {refractDirection(incoming, site.normal, 1.0f / eta), glm::vec3(1.0f),
            leaving ? glm::vec3(0.0f) : glass.absorption};
}

template <class Params>
concept HasSampledLobe = requires(const Params& p, const DeltaLobeSite& site) { sampleLobe(p, site, 0.0f); };

}  // namespace

std::optional<DeltaLobeSample> sampleDeltaLobe(BrdfModel model, std::span<const float> values, const DeltaLobeSite& site,
                                               float u) {
    return dispatch(model, [&]<class M>(M) -> std::optional<DeltaLobeSample> {
        if constexpr (HasSampledLobe<typename M::Params>) return sampleLobe(unpack<M>(values.data()), site, u);
        else return std::nullopt;
    });
}

bool samplesDeltaLobe(BrdfModel model) {
    return dispatch(model, []<class M>(M) { return HasSampledLobe<typename M::Params>; });
}

}  // namespace glint
