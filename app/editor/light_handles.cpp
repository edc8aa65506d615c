// Light handles (see light_handles.h): project with the scene camera's view-projection, move by
// unprojecting the mouse at the handle's depth, test occlusion with the CPU reference's rays.
// Sections: projection · occlusion · drawing · input.
#include "editor/light_handles.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

#include "classroom/presentation.h"
#include "light/light_type_name.h"
#include "render/reference_renderer.h"

namespace glint {
namespace {

constexpr float kDirectionalHandleDistance = 1.5f;  // [m] from the camera target
constexpr float kGrabRadiusPixels = 10.0f;  // at UI scale 1, as the dots' sizes below
int gDraggedLight = -1;

glm::vec3 handlePosition(const Light& light, const Camera& camera) {
    return light.type == LightType::Directional
               ? camera.target - glm::normalize(light.direction) * kDirectionalHandleDistance
               : light.position;
}

// --- projection -------------------------------------------------------------------------

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

// --- occlusion (hiddenFromCamera is below, with the other public functions) -----------------

// Occlusion per light, computed again only when no widget is held: a field dragged on a large
// mesh would otherwise rebuild its ray-tracing hierarchy every frame.
const std::vector<bool>& occludedHandles(const Scene& scene) {
    static std::vector<bool> occluded;
    if (ImGui::IsAnyItemActive() && occluded.size() == scene.lights.size()) return occluded;
    occluded.assign(scene.lights.size(), false);
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].type != LightType::Ambient)
            occluded[i] = hiddenFromCamera(scene, handlePosition(scene.lights[i], scene.camera));
    return occluded;
}

// --- drawing ----------------------------------------------------------------------------------

ImU32 withAlpha(ImU32 colour, float alpha) {
    const auto a = static_cast<ImU32>(((colour >> IM_COL32_A_SHIFT) & 0xFF) * alpha);
    return (colour & ~IM_COL32_A_MASK) | (a << IM_COL32_A_SHIFT);
}

// A world-space line drawn in `pieces`, each faint where an object hides it from the camera
// (tested only while no widget is held, as occludedHandles()).
void drawDepthAwareLine(ImDrawList* drawList, const Scene& scene, const glm::mat4& viewProjection, const ViewportRect& viewport,
                        glm::vec3 from, glm::vec3 to, ImU32 colour, float thickness, int pieces) {
    const bool testDepth = !ImGui::IsAnyItemActive();
    for (int k = 0; k < pieces; ++k) {
        const glm::vec3 a = glm::mix(from, to, static_cast<float>(k) / pieces);
        const glm::vec3 b = glm::mix(from, to, static_cast<float>(k + 1) / pieces);
        const auto start = project(viewProjection, a, viewport);
        const auto end = project(viewProjection, b, viewport);
        if (!start || !end) continue;  // behind the camera
        const bool hidden = testDepth && hiddenFromCamera(scene, 0.5f * (a + b));
        drawList->AddLine(start->pixel, end->pixel, hidden ? withAlpha(colour, 0.3f) : colour, thickness);
    }
}

// A spot light's aim line (to the camera target's distance along its axis) and its cone: the rim
// at that distance (half angle θ_c) and four lines from the light to it.
void drawSpotCone(ImDrawList* drawList, const Scene& scene, const Light& light, const glm::mat4& viewProjection,
                  const ViewportRect& viewport, ImU32 colour) {
    const glm::vec3 axis = glm::normalize(light.direction);
    const float length = std::max(0.5f, glm::dot(scene.camera.target - light.position, axis));
    const glm::vec3 centre = light.position + axis * length;
    drawDepthAwareLine(drawList, scene, viewProjection, viewport, light.position, centre, colour, 2.0f, 16);
    const glm::vec3 side = glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    const glm::vec3 other = glm::cross(axis, side);
    const float radius = length * std::tan(glm::radians(std::min(light.coneHalfAngleDegrees, 85.0f)));
    constexpr int kRimPoints = 48;
    const auto rimPoint = [&](int k) {
        const float angle = 2.0f * 3.14159265f * static_cast<float>(k) / kRimPoints;
        return centre + radius * (std::cos(angle) * side + std::sin(angle) * other);
    };
    for (int k = 0; k < kRimPoints; ++k)
        drawDepthAwareLine(drawList, scene, viewProjection, viewport, rimPoint(k), rimPoint(k + 1), colour, 1.5f, 1);
    for (int k = 0; k < kRimPoints; k += kRimPoints / 4)
        drawDepthAwareLine(drawList, scene, viewProjection, viewport, light.position, rimPoint(k), colour, 1.0f, 12);
}

// The light's name and kind beside its dot: to the right, or to the left near the viewport's edge.
void drawLabel(ImDrawList* drawList, ImVec2 dot, const Light& light, bool selected, float alpha, const ViewportRect& viewport) {
    const std::string label = light.name + " (" + lightTypeName(light.type) + ")";
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    const float gap = ImGui::GetFontSize() * 0.8f;
    const bool left = dot.x + gap + size.x + 4.0f > viewport.x + viewport.width;
    const ImVec2 corner(left ? dot.x - gap - size.x : dot.x + gap, dot.y - size.y * 0.5f);
    const ImVec2 padding(4.0f, 1.0f);
    const ImU32 back = selected ? IM_COL32(70, 60, 20, 220) : IM_COL32(0, 0, 0, 150);
    drawList->AddRectFilled(ImVec2(corner.x - padding.x, corner.y - padding.y),
                            ImVec2(corner.x + size.x + padding.x, corner.y + size.y + padding.y), withAlpha(back, alpha), 3.0f);
    const ImU32 text = selected ? IM_COL32(255, 240, 190, 255) : IM_COL32(230, 230, 230, 255);
    drawList->AddText(corner, withAlpha(text, alpha), label.c_str());
}

void drawHandle(ImDrawList* drawList, const Scene& scene, size_t index, bool selected, bool hidden, ImVec2 dot,
                const glm::mat4& viewProjection, const ViewportRect& viewport, float uiScale) {
    const Light& light = scene.lights[index];
    const float alpha = hidden ? 0.35f : 1.0f;
    const ImU32 fill = withAlpha(light.enabled ? IM_COL32(255, 220, 90, 255) : IM_COL32(120, 120, 120, 255), alpha);
    if (light.type == LightType::Spot)
        drawSpotCone(drawList, scene, light, viewProjection, viewport, withAlpha(fill, selected ? 0.9f : 0.6f));
    if (light.type == LightType::Directional) {
        // A short stroke along the light's direction of travel.
        const glm::vec3 from = handlePosition(light, scene.camera);
        drawDepthAwareLine(drawList, scene, viewProjection, viewport, from, from + glm::normalize(light.direction) * 0.3f, fill, 2.0f, 1);
    }
    const float radius = (selected ? 7.0f : 5.0f) * uiScale;
    if (hidden) drawList->AddCircle(dot, radius, fill, 0, 2.0f * uiScale);  // behind an object: hollow and faint
    else drawList->AddCircleFilled(dot, radius, fill);
    drawList->AddCircle(dot, radius + 2.0f * uiScale, withAlpha(IM_COL32(0, 0, 0, 200), alpha), 0, 2.0f * uiScale);
    if (selected) drawList->AddCircle(dot, radius + 5.0f * uiScale, withAlpha(IM_COL32(255, 255, 255, 230), alpha), 0, 2.0f * uiScale);
    drawLabel(drawList, dot, light, selected, alpha, viewport);
}

}  // namespace

bool hiddenFromCamera(const Scene& scene, glm::vec3 point) {
    const glm::vec3 towardsViewer = towardsViewerFrom(scene.camera, point);
    const float distance = viewerDistance(scene.camera, point);
    const Ray ray{point + towardsViewer * distance, -towardsViewer};
    const auto hit = intersectScene(scene, ray);
    return hit && hit->distance < distance - 1e-3f;
}

glm::vec3 newLightPosition(const Camera& camera) {
    // The camera's own axes in world space (its view matrix inverted), as the picture is drawn.
    const glm::mat4 cameraToWorld = glm::inverse(camera.view());
    const glm::vec3 right = glm::normalize(glm::vec3(cameraToWorld[0]));
    const glm::vec3 up = glm::normalize(glm::vec3(cameraToWorld[1]));
    const glm::vec3 backwards = glm::normalize(glm::vec3(cameraToWorld[2]));
    // 40 % of the way from the target to the camera, at 45 % of the half-height to the right and
    // 55 % of it up (the half-width is at least the half-height).
    const float distance = glm::length(camera.position - camera.target);
    const float depth = 0.6f * distance;  // from the camera
    const float halfHeight = camera.projection == Projection::Perspective
                                 ? depth * std::tan(glm::radians(camera.verticalFovDegrees) * 0.5f)
                                 : camera.orthoHeight * 0.5f;
    return camera.target + backwards * (0.4f * distance) + right * (0.45f * halfHeight) + up * (0.55f * halfHeight);
}

// --- input ------------------------------------------------------------------------------------

bool handleLightHandles(EditorState& state, const ViewportRect& viewport) {
    const Scene& scene = state.session.scene();
    const glm::mat4 viewProjection = scene.camera.viewProjection(viewport.width / viewport.height);
    const ImGuiIO& io = ImGui::GetIO();
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left) || gDraggedLight >= static_cast<int>(scene.lights.size()))
        gDraggedLight = -1;

    const std::vector<bool>& occluded = occludedHandles(scene);
    const float uiScale = effectiveUiScale(state.settings);
    ImDrawList* drawList = ImGui::GetBackgroundDrawList();
    drawList->PushClipRect(ImVec2(viewport.x, viewport.y), ImVec2(viewport.x + viewport.width, viewport.y + viewport.height));
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (light.type == LightType::Ambient) continue;  // it comes from everywhere: no handle
        const auto screen = project(viewProjection, handlePosition(light, scene.camera), viewport);
        if (!screen) continue;
        const bool selected = state.selectedLight == static_cast<int>(i);
        drawHandle(drawList, scene, i, selected, occluded[i], screen->pixel, viewProjection, viewport, uiScale);
        const float dx = io.MousePos.x - screen->pixel.x, dy = io.MousePos.y - screen->pixel.y;
        if (gDraggedLight < 0 && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !io.WantCaptureMouse &&
            dx * dx + dy * dy <= (kGrabRadiusPixels * uiScale) * (kGrabRadiusPixels * uiScale)) {
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
