// Scene helpers and the default scene (see scene.h).
#include "scene/scene.h"

namespace glint {

Material Material::withDefaults(std::string name, BrdfModel model) {
    return Material{std::move(name), model, defaultValues(modelInfo(model).params)};
}

SurfaceInterpolation defaultInterpolation(const Shape& shape) {
    return std::holds_alternative<SphereShape>(shape) ? SurfaceInterpolation::Exact : SurfaceInterpolation::Phong;
}

bool drawnAsTriangles(const Shape& shape, SurfaceInterpolation interpolation) {
    return !(std::holds_alternative<SphereShape>(shape) && interpolation == SurfaceInterpolation::Exact);
}

Scene defaultScene() {
    Scene scene;
    scene.camera.position = {0.0f, 0.9f, 4.2f};
    scene.camera.target = {0.0f, -0.1f, 0.0f};
    scene.background.color = {0.02f, 0.022f, 0.026f};

    Material sphereMaterial = Material::withDefaults("red plastic", BrdfModel::BlinnPhong);
    Material floorMaterial = Material::withDefaults("grey floor", BrdfModel::Lambert);
    floorMaterial.values = {0.35f, 0.35f, 0.35f};
    scene.materials = {sphereMaterial, floorMaterial};

    scene.objects.push_back({"sphere", SphereShape{}, 0});
    scene.objects.push_back({"floor", PlaneShape{}, 1, SurfaceInterpolation::Phong});

    Light key;
    key.name = "key";
    key.type = LightType::Directional;
    key.direction = glm::normalize(glm::vec3(-0.5f, -1.0f, -0.6f));
    key.irradiance = 2.5f;
    Light fill;
    fill.name = "fill";
    fill.type = LightType::Point;
    fill.position = {2.5f, 1.5f, 2.0f};
    fill.power = 150.0f;
    fill.color = {0.8f, 0.9f, 1.0f};
    scene.lights = {key, fill};
    return scene;
}

}  // namespace glint
