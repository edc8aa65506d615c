// Light handles (see light_handles.h): project with the scene camera's view-projection, move by
// unprojecting the mouse at the handle's depth.
#include "editor/light_handles.h"

#include <optional>

#include <imgui.h>

namespace glint {
namespace {

constexpr float kDirectionalHandleDistance = 1.5f;  // [m] from the camera target
constexpr float kGrabRadiusPixels = 10.0f;
int gDraggedLight = -1;

glm::vec3 handlePosition(const Light& light, const Camera& camera) {
    return light.type == LightType::Directional
               ? camera.target - glm::normalize(light.direction) * kDirectionalHandleDistance
               : light.position;
}

struct ScreenPoint {
    ImVec2 pixel;
    float ndcDepth;
};

std::optional<ScreenPoint> project(const glm::mat4& viewProjection, glm::vec3 world, const ViewportRect& viewport) {
    const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
    if (clip.w <= 1e-6f) return std::nullopt;  // behind the camera
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return ScreenPoint{ImVec2(viewport.x + (ndc.x * 0.5f + 0.5f) * viewport.width,
                              viewport.y + (0.5f - ndc.y * 0.5f) * viewport.height),
                       ndc.z};
}

glm::vec3 unproject(const glm::mat4& viewProjection, ImVec2 pixel, float ndcDepth, const ViewportRect& viewport) {
    const glm::vec4 ndc{(pixel.x - viewport.x) / viewport.width * 2.0f - 1.0f,
                        1.0f - (pixel.y - viewport.y) / viewport.height * 2.0f, ndcDepth, 1.0f};
    const glm::vec4 world = glm::inverse(viewProjection) * ndc;
    return glm::vec3(world) / world.w;
}

}  // namespace

bool handleLightHandles(EditorState& state, const ViewportRect& viewport) {
    const Scene& scene = state.session.scene();
    const glm::mat4 viewProjection = scene.camera.viewProjection(viewport.width / viewport.height);
    const ImGuiIO& io = ImGui::GetIO();
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left) || gDraggedLight >= static_cast<int>(scene.lights.size()))
        gDraggedLight = -1;

    ImDrawList* drawList = ImGui::GetBackgroundDrawList();
    drawList->PushClipRect(ImVec2(viewport.x, viewport.y), ImVec2(viewport.x + viewport.width, viewport.y + viewport.height));
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (light.type == LightType::Ambient) continue;  // it comes from everywhere: no handle
        const auto screen = project(viewProjection, handlePosition(light, scene.camera), viewport);
        if (!screen) continue;
        const bool selected = state.selectedLight == static_cast<int>(i);
        const ImU32 fill = light.enabled ? IM_COL32(255, 220, 90, 255) : IM_COL32(120, 120, 120, 255);
        drawList->AddCircleFilled(screen->pixel, selected ? 7.0f : 5.0f, fill);
        drawList->AddCircle(screen->pixel, selected ? 9.0f : 7.0f, IM_COL32(0, 0, 0, 200), 0, 2.0f);
        if (light.type == LightType::Directional) {
            // A short stroke along the light's direction of travel.
            if (const auto tip = project(viewProjection, handlePosition(light, scene.camera) + glm::normalize(light.direction) * 0.3f, viewport))
                drawList->AddLine(screen->pixel, tip->pixel, fill, 2.0f);
        }
        const float dx = io.MousePos.x - screen->pixel.x, dy = io.MousePos.y - screen->pixel.y;
        if (gDraggedLight < 0 && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.WantCaptureMouse &&
            dx * dx + dy * dy <= kGrabRadiusPixels * kGrabRadiusPixels) {
            gDraggedLight = static_cast<int>(i);
            state.selectedLight = static_cast<int>(i);
        }
    }
    drawList->PopClipRect();

    if (gDraggedLight < 0) return false;
    if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) {
        const Light& light = scene.lights[gDraggedLight];
        const auto screen = project(viewProjection, handlePosition(light, scene.camera), viewport);
        if (screen) {
            const glm::vec3 moved = unproject(viewProjection, io.MousePos, screen->ndcDepth, viewport);
            const glm::vec3 fromTarget = moved - scene.camera.target;
            if (light.type != LightType::Directional) {
                state.session.change("Move light").lights[gDraggedLight].position = moved;
            } else if (glm::length(fromTarget) > 1e-4f) {
                state.session.change("Turn light").lights[gDraggedLight].direction = -glm::normalize(fromTarget);
            }
        }
    }
    return true;
}

}  // namespace glint
