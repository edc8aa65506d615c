// Scene helpers and the default scene (see scene.h).
#include "scene/scene.h"

#include "scene/preview_stage.h"

namespace glint {

SurfaceInterpolation defaultInterpolation(const Shape& shape) {
    return std::holds_alternative<SphereShape>(shape) ? SurfaceInterpolation::Exact : SurfaceInterpolation::Phong;
}

bool drawnAsTriangles(const Shape& shape, SurfaceInterpolation interpolation) {
    return !(std::holds_alternative<SphereShape>(shape) && interpolation == SurfaceInterpolation::Exact);
}

Scene defaultScene() {
    return previewStage(Material::withDefaults("red plastic", BrdfModel::BlinnPhong), 960, 720);
}

}  // namespace glint
