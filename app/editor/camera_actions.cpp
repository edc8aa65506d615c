// Camera actions (see camera_actions.h).
#include "editor/camera_actions.h"

#include <cmath>
#include <variant>

#include <imgui.h>

#include "camera/orbit.h"
#include "math/constants.h"

namespace glint {
namespace {

bool gDragging = false;  // a drag that started over the viewport

bool inside(const ViewportRect& rect, ImVec2 point) {
    return point.x >= rect.x && point.y >= rect.y && point.x < rect.x + rect.width && point.y < rect.y + rect.height;
}

// Bounding sphere of an object: centre and radius [m].
void boundsOf(const Shape& shape, glm::vec3& centre, float& radius) {
    if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
        centre = sphere->center;
        radius = sphere->radius;
    } else if (const auto* plane = std::get_if<PlaneShape>(&shape)) {
        centre = plane->center;
        radius = 0.5f * glm::length(plane->size);
    }
}

}  // namespace

bool handleViewportInput(EditorState& state, const ViewportRect& viewport) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool anyButton = ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
                           ImGui::IsMouseDown(ImGuiMouseButton_Middle);
    if (!anyButton) gDragging = false;
    const bool clicked = ImGui::IsMouseClicked(ImGuiMouseButton_Left) || ImGui::IsMouseClicked(ImGuiMouseButton_Right) ||
                         ImGui::IsMouseClicked(ImGuiMouseButton_Middle);
    if (clicked && !io.WantCaptureMouse && inside(viewport, io.MousePos)) gDragging = true;

    const float scale = 1.0f / std::max(viewport.height, 1.0f);
    const ImVec2 delta = io.MouseDelta;
    const bool moved = delta.x != 0 || delta.y != 0;
    const bool wheel = io.MouseWheel != 0.0f && !io.WantCaptureMouse && inside(viewport, io.MousePos);
    if (!(gDragging && moved) && !wheel) return gDragging;

    OrbitController orbit = OrbitController::fromCamera(state.session.scene().camera);
    if (gDragging && moved && ImGui::IsMouseDown(ImGuiMouseButton_Left)) orbit.orbit(-delta.x * scale * 3.0f, delta.y * scale * 3.0f);
    else if (gDragging && moved) orbit.pan(-delta.x * scale, delta.y * scale);
    Camera& camera = state.session.change(wheel ? "Zoom" : "Move camera").camera;
    if (wheel) {
        const float factor = std::pow(0.9f, io.MouseWheel);
        orbit.zoom(factor);
        camera.orthoHeight = std::clamp(camera.orthoHeight * factor, 0.01f, 1000.0f);
    }
    orbit.applyTo(camera);
    return gDragging;
}

void frameSelected(EditorState& state) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) return;
    glm::vec3 centre{0.0f};
    float radius = 1.0f;
    boundsOf(scene.objects[state.selectedObject].shape, centre, radius);
    OrbitController orbit = OrbitController::fromCamera(scene.camera);
    orbit.target = centre;
    // The bounding sphere fills the vertical field of view with a 10 % margin: d = r / sin(fov/2).
    const float halfFov = 0.5f * scene.camera.verticalFovDegrees * kPi / 180.0f;
    orbit.distance = 1.1f * radius / std::sin(halfFov);
    Camera& camera = state.session.change("Frame selected").camera;
    camera.orthoHeight = 2.2f * radius;
    orbit.applyTo(camera);
    state.session.settle(false);
}

void resetView(EditorState& state) {
    const Camera reset = defaultScene().camera;
    Camera& camera = state.session.change("Reset view").camera;
    const Projection projection = camera.projection;
    camera = reset;
    camera.projection = projection;
    state.session.settle(false);
}

void toggleProjection(EditorState& state) {
    Camera& camera = state.session.change("Switch projection").camera;
    camera.projection = camera.projection == Projection::Perspective ? Projection::Orthographic : Projection::Perspective;
    if (camera.projection == Projection::Orthographic) {
        // Keep the target's apparent size: the ortho height equals the frustum height at the target.
        const float distance = glm::length(camera.position - camera.target);
        camera.orthoHeight = 2.0f * distance * std::tan(0.5f * camera.verticalFovDegrees * kPi / 180.0f);
    }
    state.session.settle(false);
}

}  // namespace glint
