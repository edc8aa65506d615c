// The standard preview stage (see preview_stage.h). Light levels keep a white Lambert sphere
// (albedo 1) below 1 W/(sr·m²), so nothing clips at exposure 0: L = ρ/π·ΣE ≤ (1.6 + 0.58 + 0.8)/π ≈ 0.95.
#include "scene/preview_stage.h"

namespace glint {

Scene previewStage(const Material& material, int width, int height) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.camera.projection = Projection::Perspective;
    scene.camera.position = {0.0f, 0.8f, 4.3f};
    scene.camera.target = {0.0f, -0.12f, 0.0f};
    scene.camera.verticalFovDegrees = 36.0f;
    scene.background.color = {0.18f, 0.18f, 0.18f};  // neutral mid grey (sRGB ≈ 118/255)

    Material floor = Material::withDefaults("preview floor", BrdfModel::Lambert);
    floor.values = {0.3f, 0.3f, 0.3f};
    Material shown = material;
    if (shown.name == floor.name) shown.name += " (material)";
    scene.materials = {shown, floor};
    scene.objects.push_back({"preview sphere", SphereShape{{0.0f, 0.0f, 0.0f}, 1.0f}, 0});
    scene.objects.push_back({"preview floor", PlaneShape{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {30.0f, 30.0f}}, 1});

    Light key;  // from the upper left, in front: M = 1.6 W/m²
    key.name = "key";
    key.type = LightType::Directional;
    key.direction = glm::normalize(glm::vec3(0.6f, -1.0f, -0.7f));
    key.irradiance = 1.6f;
    Light fill;  // a point light on the right: Φ = 40 W gives E⊥ = Φ/(4πd²) ≈ 0.3 W/m² at the centre (d ≈ 3.35 m), ≤ 0.58 on the sphere
    fill.name = "fill";
    fill.type = LightType::Point;
    fill.position = {2.4f, 0.8f, 2.2f};
    fill.power = 40.0f;
    fill.color = {0.85f, 0.9f, 1.0f};
    Light rim;  // from behind, to separate the silhouette from the background
    rim.name = "rim";
    rim.type = LightType::Directional;
    rim.direction = glm::normalize(glm::vec3(-0.3f, -0.4f, 1.0f));
    rim.irradiance = 0.8f;
    rim.color = {1.0f, 0.95f, 0.9f};
    scene.lights = {key, fill, rim};
    return scene;
}

}  // namespace glint
