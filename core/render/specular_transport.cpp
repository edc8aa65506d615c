// Dispatch of the specular-transport hook over the models that have one (see
// specular_transport.h); the tracing itself lives in the header, beside its GLSL twin's layout.
#include "render/specular_transport.h"

#include "brdf/glass.h"
#include "brdf/mirror.h"
#include "render/openpbr_transport.h"

namespace glint {

glm::vec3 traceSpecular(BrdfModel model, std::span<const float> values, const MissRadiance& miss,
                        const SphereGeometry* sphere, glm::vec3 position, glm::vec3 normal, glm::vec3 towardsViewer,
                        float viewerDistance) {
    switch (model) {
        case BrdfModel::Mirror: {
            const MirrorParams mirror = unpackMirror(values.data());
            return traceMirror(mirror.ior, mirror.extinction, miss, normal, towardsViewer);
        }
        case BrdfModel::Glass: {
            const GlassParams glass = unpackGlass(values.data());
            const GlassInterface glassInterface{glass.ior, glass.transparency == GlassTransparency::Classic, glass.transmission};
            return traceGlass(glassInterface, glass.absorption, miss, sphere, position, normal, towardsViewer,
                              viewerDistance);
        }
        case BrdfModel::OpenPbr:
            return transportOpenPbr(unpackOpenPbr(values.data()), miss, sphere, position, normal, towardsViewer);
        default: return glm::vec3(0.0f);  // no delta lobes (ModelInfo::glslTransport == nullptr)
    }
}

}  // namespace glint
