// The surface probe's arrows (see probe_overlay.h).
#include "classroom/probe_overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>

namespace glint {
namespace {

constexpr float kProbeArrowFraction = 0.25f;  // arrow length as a fraction of the view's height at the point
constexpr ImU32 kProbeNormalColor = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kProbeViewColor = IM_COL32(110, 200, 255, 255);
constexpr ImU32 kProbeLightColor = IM_COL32(255, 214, 60, 255);
constexpr ImU32 kProbeHalfColor = IM_COL32(90, 230, 110, 255);
constexpr ImU32 kProbeMirrorColor = IM_COL32(255, 100, 220, 255);
constexpr ImU32 kProbeTransmitColor = IM_COL32(90, 140, 255, 255);
constexpr ImU32 kProbeDarkLightColor = IM_COL32(150, 150, 150, 255);  // behind the surface or shadowed
constexpr ImU32 kProbeShadowColor = IM_COL32(0, 0, 0, 200);

struct ProbeProjector {
    glm::mat4 viewProjection;
    ProbeOverlayArea area;

    std::optional<ImVec2> operator()(glm::vec3 world) const {
        const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
        if (clip.w <= 1e-6f) return std::nullopt;  // behind the camera
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        return ImVec2(area.x + (ndc.x * 0.5f + 0.5f) * area.width, area.y + (0.5f - ndc.y * 0.5f) * area.height);
    }
};

// Text with a dark outline so it reads over bright and dark pixels alike.
void probeLabel(ImDrawList* drawList, ImVec2 at, ImU32 color, const std::string& text) {
    for (const ImVec2 offset : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1)})
        drawList->AddText(ImVec2(at.x + offset.x, at.y + offset.y), kProbeShadowColor, text.c_str());
    drawList->AddText(at, color, text.c_str());
}

// An arrow from the probed point along a unit direction, labelled at its tip.
void probeArrow(ImDrawList* drawList, const ProbeProjector& project, glm::vec3 origin, glm::vec3 direction, float length,
                ImU32 color, const std::string& label) {
    const auto start = project(origin), end = project(origin + direction * length);
    if (!start || !end) return;
    const float dx = end->x - start->x, dy = end->y - start->y;
    const float pixels = std::sqrt(dx * dx + dy * dy);
    drawList->AddLine(*start, *end, kProbeShadowColor, 4.0f);
    drawList->AddLine(*start, *end, color, 2.0f);
    if (pixels > 4.0f) {  // a head, unless the arrow points straight at the viewer
        const float ux = dx / pixels, uy = dy / pixels, head = std::min(9.0f, 0.4f * pixels);
        drawList->AddTriangleFilled(*end, ImVec2(end->x - ux * head - uy * head * 0.5f, end->y - uy * head + ux * head * 0.5f),
                                    ImVec2(end->x - ux * head + uy * head * 0.5f, end->y - uy * head - ux * head * 0.5f),
                                    color);
    }
    const float away = pixels > 1.0f ? 6.0f / pixels : 0.0f;  // the label just beyond the tip
    probeLabel(drawList, ImVec2(end->x + dx * away - 4.0f, end->y + dy * away - 7.0f), color, label);
}

// One line of the legend: pieces of text, each in its vector's colour.
struct ProbeLegendPiece {
    ImU32 color;
    std::string text;
};
struct ProbeLegendLine {
    std::vector<ProbeLegendPiece> pieces;
};

void probeLegend(ImDrawList* drawList, ImVec2 at, const std::vector<ProbeLegendLine>& lines) {
    const float lineHeight = ImGui::GetTextLineHeight();
    float width = 0.0f;
    for (const ProbeLegendLine& line : lines) {
        float lineWidth = 0.0f;
        for (const ProbeLegendPiece& piece : line.pieces) lineWidth += ImGui::CalcTextSize(piece.text.c_str()).x;
        width = std::max(width, lineWidth);
    }
    drawList->AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + width + 3, at.y + lineHeight * lines.size() + 2),
                            IM_COL32(0, 0, 0, 150), 3.0f);
    for (size_t row = 0; row < lines.size(); ++row) {
        float x = at.x;
        for (const ProbeLegendPiece& piece : lines[row].pieces) {
            drawList->AddText(ImVec2(x, at.y + lineHeight * row), piece.color, piece.text.c_str());
            x += ImGui::CalcTextSize(piece.text.c_str()).x;
        }
    }
}

std::string probeAngle(const char* name, float degrees) {
    char text[48];
    std::snprintf(text, sizeof text, " %s %.1f°", name, degrees);
    return text;
}

}  // namespace

void drawProbeOverlay(ImDrawList* drawList, const ProbeResult& probe, const Camera& camera, const ProbeOverlayArea& area) {
    const ProbeProjector project{camera.viewProjection(area.width / area.height), area};
    drawList->PushClipRect(ImVec2(area.x, area.y), ImVec2(area.x + area.width, area.y + area.height), true);
    if (!probe.hitSurface) {
        // The probed pixel, crossed: the ray sees the background.
        const float scaleX = area.width / static_cast<float>(probe.width), scaleY = area.height / static_cast<float>(probe.height);
        const ImVec2 at(area.x + (probe.pixelX + 0.5f) * scaleX, area.y + (probe.pixelY + 0.5f) * scaleY);
        drawList->AddLine(ImVec2(at.x - 6, at.y - 6), ImVec2(at.x + 6, at.y + 6), kProbeNormalColor, 2.0f);
        drawList->AddLine(ImVec2(at.x - 6, at.y + 6), ImVec2(at.x + 6, at.y - 6), kProbeNormalColor, 2.0f);
        probeLabel(drawList, ImVec2(at.x + 9, at.y - 7), kProbeNormalColor, "no surface");
        drawList->PopClipRect();
        return;
    }
    // Arrow length: a fixed fraction of the view's height at the point's depth [m].
    const float viewHeight = camera.projection == Projection::Orthographic
                                 ? camera.orthoHeight
                                 : 2.0f * probe.hitDistance * std::tan(glm::radians(0.5f * camera.verticalFovDegrees));
    const float length = kProbeArrowFraction * viewHeight;
    const glm::vec3 point = probe.position;
    // Arrows carry short names; the angles go into a legend in the corner, one line per light.
    std::vector<ProbeLegendLine> legend;
    legend.push_back({{{kProbeViewColor, "V" + probeAngle("θr", probe.lights.empty() ? glm::degrees(std::acos(std::clamp(
                                             glm::dot(probe.normal, probe.towardsViewer), -1.0f, 1.0f)))
                                                                               : probe.lights[0].reflectedDegrees)}}});
    const bool severalLights = probe.lights.size() > 1;
    for (const ProbeLight& light : probe.lights) {
        const std::string index = severalLights ? std::to_string(light.lightIndex + 1) : "";
        const bool dark = light.behindSurface || light.shadowed;
        const ImU32 lightColor = dark ? kProbeDarkLightColor : kProbeLightColor;
        ProbeLegendLine line;
        line.pieces.push_back({lightColor, "L" + index + probeAngle("θi", light.incidentDegrees) +
                                               (light.shadowed ? " (shadow)" : "") + (light.behindSurface ? " (behind)" : "")});
        line.pieces.push_back({kProbeHalfColor, "  H" + index + probeAngle("∠NH", light.halfDegrees)});
        line.pieces.push_back({kProbeMirrorColor, "  R" + index + probeAngle("∠RV", light.mirrorViewDegrees)});
        probeArrow(drawList, project, point, light.towardsLight, length, lightColor, "L" + index);
        probeArrow(drawList, project, point, light.halfVector, length * 0.8f, kProbeHalfColor, "H" + index);
        probeArrow(drawList, project, point, light.mirror, length * 0.9f, kProbeMirrorColor, "R" + index);
        if (light.transmitted && !light.transmitted->totalInternalReflection) {
            probeArrow(drawList, project, point, light.transmitted->direction, length * 0.9f, kProbeTransmitColor, "T" + index);
            line.pieces.push_back({kProbeTransmitColor, "  T" + index + probeAngle("θt", light.transmitted->transmittedDegrees)});
        }
        legend.push_back(std::move(line));
    }
    if (probe.viewTransmitted) {
        const ProbeRefraction& view = *probe.viewTransmitted;
        if (view.totalInternalReflection) {
            probeArrow(drawList, project, point, probe.viewMirror, length * 0.9f, kProbeTransmitColor, "TIR");
            legend.push_back({{{kProbeTransmitColor, "view ray: total internal reflection" + probeAngle("θi", view.incidentDegrees)}}});
        } else {
            probeArrow(drawList, project, point, view.direction, length, kProbeTransmitColor, "T(V)");
            legend.push_back({{{kProbeTransmitColor, "T(V)" + probeAngle("θt", view.transmittedDegrees)}}});
        }
    }
    probeArrow(drawList, project, point, probe.towardsViewer, length * 0.6f, kProbeViewColor, "V");
    probeArrow(drawList, project, point, probe.normal, length, kProbeNormalColor, "N");
    probeLegend(drawList, ImVec2(area.x + 6.0f, area.y + 6.0f), legend);
    if (const auto at = project(point)) {
        drawList->AddCircleFilled(*at, 4.0f, kProbeShadowColor);
        drawList->AddCircleFilled(*at, 2.5f, kProbeNormalColor);
    }
    drawList->PopClipRect();
}

}  // namespace glint
