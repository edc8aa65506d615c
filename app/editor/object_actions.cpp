// Object actions (see object_actions.h).
#include "editor/object_actions.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string>
#include <variant>

namespace glint {
namespace {

// How far to the right of the camera's target a new object appears [m].
constexpr float kNewObjectOffset = 1.2f;

glm::vec3& shapeCenter(Shape& shape) {
    return std::visit([](auto& concrete) -> glm::vec3& { return concrete.center; }, shape);
}

// "cube", "cube 2", "cube 3", ...: the first name no object has yet.
std::string uniqueObjectName(const Scene& scene, const std::string& base) {
    auto taken = [&](const std::string& name) {
        for (const SceneObject& object : scene.objects)
            if (object.name == name) return true;
        return false;
    };
    if (!taken(base)) return base;
    for (int suffix = 2;; ++suffix)
        if (const std::string name = base + " " + std::to_string(suffix); !taken(name)) return name;
}

Shape defaultShape(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Sphere: return SphereShape{};
        case ObjectKind::Plane: return PlaneShape{.center = {0.0f, 0.0f, 0.0f}, .normal = {0, 1, 0}, .size = {2, 2}};
        case ObjectKind::Cube: return CubeShape{};
        case ObjectKind::Torus: return TorusShape{};
    }
    return SphereShape{};
}

void selectNew(EditorState& state) { state.selectedObject = static_cast<int>(state.session.scene().objects.size()) - 1; }

}  // namespace

const char* objectKindLabel(ObjectKind kind) {
    switch (kind) {
        case ObjectKind::Sphere: return "Sphere";
        case ObjectKind::Plane: return "Plane";
        case ObjectKind::Cube: return "Cube";
        case ObjectKind::Torus: return "Torus";
    }
    return "?";
}

const char* shapeLabel(const Shape& shape) {
    constexpr const char* kLabels[] = {"Sphere", "Plane", "Cube", "Torus", "Mesh"};  // order of Shape
    static_assert(std::size(kLabels) == std::variant_size_v<Shape>);
    return kLabels[shape.index()];
}

void addObject(EditorState& state, ObjectKind kind) {
    std::string base = objectKindLabel(kind);
    base[0] = static_cast<char>(std::tolower(base[0]));
    addObjectWithShape(state, base, defaultShape(kind));
}

void addObjectWithShape(EditorState& state, const std::string& baseName, Shape shape, std::optional<Material> material) {
    const Camera& camera = state.session.scene().camera;
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    shapeCenter(shape) = camera.target + kNewObjectOffset * right;
    Scene& scene = state.session.change("Add " + baseName);
    const std::string name = uniqueObjectName(scene, baseName);
    scene.materials.push_back(material ? std::move(*material) : Material::withDefaults(name + " material", BrdfModel::Lambert));
    SceneObject object{name, std::move(shape), static_cast<int>(scene.materials.size()) - 1};
    object.interpolation = defaultInterpolation(object.shape);
    scene.objects.push_back(std::move(object));
    selectNew(state);
    state.statusMessage = "Added " + name;
}

bool duplicateObject(EditorState& state, int objectIndex) {
    if (objectIndex < 0 || objectIndex >= static_cast<int>(state.session.scene().objects.size())) return false;
    Scene& scene = state.session.change("Duplicate object");
    SceneObject copy = scene.objects[objectIndex];
    copy.name = uniqueObjectName(scene, copy.name);
    Material material = scene.materials.at(copy.materialIndex);
    material.name = copy.name + " material";
    scene.materials.push_back(std::move(material));
    copy.materialIndex = static_cast<int>(scene.materials.size()) - 1;
    shapeCenter(copy.shape).x += kNewObjectOffset;
    scene.objects.push_back(std::move(copy));
    selectNew(state);
    state.statusMessage = "Duplicated as " + scene.objects.back().name;
    return true;
}

void keepSelectionInScene(EditorState& state) {
    state.selectedObject = std::clamp(state.selectedObject, 0, std::max(0, static_cast<int>(state.session.scene().objects.size()) - 1));
}

bool removeObject(EditorState& state, int objectIndex) {
    if (objectIndex < 0 || objectIndex >= static_cast<int>(state.session.scene().objects.size())) return false;
    Scene& scene = state.session.change("Remove object");
    state.statusMessage = "Removed " + scene.objects[objectIndex].name;
    scene.objects.erase(scene.objects.begin() + objectIndex);
    state.selectedObject = std::max(0, std::min(objectIndex, static_cast<int>(scene.objects.size()) - 1));
    return true;
}

void toggleWireframe(EditorState& state) {
    OverlaySettings& overlays = state.session.change("Wireframe overlay").display.overlays;
    overlays.wireframe = !overlays.wireframe;
}

void toggleNormals(EditorState& state) {
    OverlaySettings& overlays = state.session.change("Normals overlay").display.overlays;
    overlays.normals = !overlays.normals;
}

}  // namespace glint
