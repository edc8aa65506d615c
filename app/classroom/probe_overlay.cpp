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

// Sizes follow the font, so the overlay reads from the back of a lecture hall in presentation mode.
struct ProbeStroke {
    float scale;  // the font's height over the 17 px of the normal UI font
    float line() const { return 2.5f * scale; }
    float outline() const { return line() + 3.0f * scale; }
    float head() const { return 12.0f * scale; }
};

ImVec2 textSize(const std::string& text) { return ImGui::CalcTextSize(text.c_str()); }

bool rectsOverlap(const ImVec4& a, const ImVec4& b) { return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w; }

// Labels already drawn (and the legend): each new label takes the first spot near its arrow's tip
// that overlaps none of them.
struct ProbeLabels {
    std::vector<ImVec4> taken;  // x0, y0, x1, y1

    ImVec2 place(ImVec2 tip, float ux, float uy, ImVec2 size, float gap) {
        // Beyond the tip, then to either side of it, then further out.
        const ImVec2 centres[] = {{tip.x + ux * (gap + size.x * 0.5f), tip.y + uy * (gap + size.y * 0.5f)},
                                  {tip.x - uy * (gap + size.x * 0.5f), tip.y + ux * (gap + size.y * 0.5f)},
                                  {tip.x + uy * (gap + size.x * 0.5f), tip.y - ux * (gap + size.y * 0.5f)},
                                  {tip.x + ux * (gap * 2.0f + size.x), tip.y + uy * (gap * 2.0f + size.y)},
                                  {tip.x - uy * (gap * 2.0f + size.x), tip.y + ux * (gap * 2.0f + size.y)},
                                  {tip.x + uy * (gap * 2.0f + size.x), tip.y - ux * (gap * 2.0f + size.y)},
                                  {tip.x, tip.y - gap - size.y},
                                  {tip.x, tip.y + gap + size.y}};
        ImVec4 chosen;
        int fewest = 1 << 30;
        for (const ImVec2 centre : centres) {
            const ImVec4 rect(centre.x - size.x * 0.5f, centre.y - size.y * 0.5f, centre.x + size.x * 0.5f, centre.y + size.y * 0.5f);
            int overlaps = 0;
            for (const ImVec4& other : taken) overlaps += rectsOverlap(rect, other) ? 1 : 0;
            if (overlaps < fewest) {
                fewest = overlaps;
                chosen = rect;
            }
            if (overlaps == 0) break;
        }
        taken.push_back(chosen);
        return ImVec2(chosen.x, chosen.y);
    }
};

// Text on a dark box with a dark outline, so it reads over a white highlight and a black background alike.
void probeLabel(ImDrawList* drawList, ImVec2 at, ImU32 color, const std::string& text, const ProbeStroke& stroke) {
    const ImVec2 size = textSize(text);
    const float pad = 2.0f * stroke.scale;
    drawList->AddRectFilled(ImVec2(at.x - pad, at.y - pad), ImVec2(at.x + size.x + pad, at.y + size.y + pad),
                            IM_COL32(0, 0, 0, 150), 3.0f * stroke.scale);
    const float o = std::max(1.0f, std::round(1.5f * stroke.scale));
    for (const ImVec2 offset : {ImVec2(-o, 0), ImVec2(o, 0), ImVec2(0, -o), ImVec2(0, o), ImVec2(-o, -o), ImVec2(o, o),
                                ImVec2(-o, o), ImVec2(o, -o)})
        drawList->AddText(ImVec2(at.x + offset.x, at.y + offset.y), kProbeShadowColor, text.c_str());
    drawList->AddText(at, color, text.c_str());
}

// An arrow from the probed point along a unit direction, labelled near its tip.
void probeArrow(ImDrawList* drawList, const ProbeProjector& project, glm::vec3 origin, glm::vec3 direction, float length,
                ImU32 color, const std::string& label, const ProbeStroke& stroke, ProbeLabels& labels) {
    const auto start = project(origin), end = project(origin + direction * length);
    if (!start || !end) return;
    const float dx = end->x - start->x, dy = end->y - start->y;
    const float pixels = std::sqrt(dx * dx + dy * dy);
    drawList->AddLine(*start, *end, kProbeShadowColor, stroke.outline());
    drawList->AddLine(*start, *end, color, stroke.line());
    float ux = 0.0f, uy = -1.0f;  // straight at the viewer: the label goes above the point
    if (pixels > 4.0f) {  // a head, unless the arrow points straight at the viewer
        ux = dx / pixels;
        uy = dy / pixels;
        const float head = std::min(stroke.head(), 0.4f * pixels);
        const ImVec2 left(end->x - ux * head - uy * head * 0.55f, end->y - uy * head + ux * head * 0.55f);
        const ImVec2 right(end->x - ux * head + uy * head * 0.55f, end->y - uy * head - ux * head * 0.55f);
        drawList->AddTriangle(*end, left, right, kProbeShadowColor, stroke.outline() - stroke.line());
        drawList->AddTriangleFilled(*end, left, right, color);
    }
    const ImVec2 at = labels.place(*end, ux, uy, textSize(label), 4.0f * stroke.scale);
    probeLabel(drawList, at, color, label, stroke);
}

// One line of the legend: pieces of text, each in its vector's colour.
struct ProbeLegendPiece {
    ImU32 color;
    std::string text;
};
struct ProbeLegendLine {
    std::vector<ProbeLegendPiece> pieces;
};

ImVec2 probeLegendSize(const std::vector<ProbeLegendLine>& lines) {
    float width = 0.0f;
    for (const ProbeLegendLine& line : lines) {
        float lineWidth = 0.0f;
        for (const ProbeLegendPiece& piece : line.pieces) lineWidth += ImGui::CalcTextSize(piece.text.c_str()).x;
        width = std::max(width, lineWidth);
    }
    return ImVec2(width, ImGui::GetTextLineHeight() * static_cast<float>(lines.size()));
}

void probeLegend(ImDrawList* drawList, ImVec2 at, const std::vector<ProbeLegendLine>& lines) {
    const float lineHeight = ImGui::GetTextLineHeight();
    const ImVec2 size = probeLegendSize(lines);
    drawList->AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2), IM_COL32(0, 0, 0, 170), 3.0f);
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

// The probed pixel, crossed: the ray sees the background.
void drawMissedPixel(ImDrawList* drawList, const ProbeResult& probe, const ProbeOverlayArea& area, const ProbeStroke& stroke) {
    const float scaleX = area.width / static_cast<float>(probe.width), scaleY = area.height / static_cast<float>(probe.height);
    const ImVec2 at(area.x + (probe.pixelX + 0.5f) * scaleX, area.y + (probe.pixelY + 0.5f) * scaleY);
    const float arm = 6.0f * stroke.scale;
    drawList->AddLine(ImVec2(at.x - arm, at.y - arm), ImVec2(at.x + arm, at.y + arm), kProbeNormalColor, stroke.line());
    drawList->AddLine(ImVec2(at.x - arm, at.y + arm), ImVec2(at.x + arm, at.y - arm), kProbeNormalColor, stroke.line());
    probeLabel(drawList, ImVec2(at.x + arm * 1.5f, at.y - arm), kProbeNormalColor, "no surface", stroke);
}

// A light's arrows are numbered when there are several lights; a light that cannot reach the
// point is drawn dark.
std::string lightIndex(const ProbeResult& probe, const ProbeLight& light) {
    return probe.lights.size() > 1 ? std::to_string(light.lightIndex + 1) : "";
}
ImU32 lightColor(const ProbeLight& light) { return light.behindSurface || light.shadowed ? kProbeDarkLightColor : kProbeLightColor; }

// The angles, one line per light (the arrows carry only short names).
std::vector<ProbeLegendLine> probeLegendLines(const ProbeResult& probe) {
    std::vector<ProbeLegendLine> legend;
    const float viewDegrees = probe.lights.empty()
                                  ? glm::degrees(std::acos(std::clamp(glm::dot(probe.normal, probe.towardsViewer), -1.0f, 1.0f)))
                                  : probe.lights[0].reflectedDegrees;
    legend.push_back({{{kProbeViewColor, "V" + probeAngle("θr", viewDegrees)}}});
    for (const ProbeLight& light : probe.lights) {
        const std::string index = lightIndex(probe, light);
        ProbeLegendLine line;
        line.pieces.push_back({lightColor(light), "L" + index + probeAngle("θi", light.incidentDegrees) +
                                                      (light.shadowed ? " (shadow)" : "") + (light.behindSurface ? " (behind)" : "")});
        line.pieces.push_back({kProbeHalfColor, "  H" + index + probeAngle("∠NH", light.halfDegrees)});
        line.pieces.push_back({kProbeMirrorColor, "  R" + index + probeAngle("∠RV", light.mirrorViewDegrees)});
        if (light.transmitted && !light.transmitted->totalInternalReflection)
            line.pieces.push_back({kProbeTransmitColor, "  T" + index + probeAngle("θt", light.transmitted->transmittedDegrees)});
        legend.push_back(std::move(line));
    }
    if (probe.viewTransmitted) {
        const ProbeRefraction& view = *probe.viewTransmitted;
        legend.push_back({{{kProbeTransmitColor, view.totalInternalReflection
                                                     ? "view ray: total internal reflection" + probeAngle("θi", view.incidentDegrees)
                                                     : "T(V)" + probeAngle("θt", view.transmittedDegrees)}}});
    }
    return legend;
}

// N and V first: the labels placed first keep the spot beyond their tips. `length` [m].
void drawProbeArrows(ImDrawList* drawList, const ProbeResult& probe, const ProbeProjector& project, float length,
                     const ProbeStroke& stroke, ProbeLabels& labels) {
    const glm::vec3 point = probe.position;
    probeArrow(drawList, project, point, probe.normal, length, kProbeNormalColor, "N", stroke, labels);
    probeArrow(drawList, project, point, probe.towardsViewer, length * 0.6f, kProbeViewColor, "V", stroke, labels);
    for (const ProbeLight& light : probe.lights) {
        const std::string index = lightIndex(probe, light);
        probeArrow(drawList, project, point, light.towardsLight, length, lightColor(light), "L" + index, stroke, labels);
        probeArrow(drawList, project, point, light.halfVector, length * 0.8f, kProbeHalfColor, "H" + index, stroke, labels);
        probeArrow(drawList, project, point, light.mirror, length * 0.9f, kProbeMirrorColor, "R" + index, stroke, labels);
        if (light.transmitted && !light.transmitted->totalInternalReflection)
            probeArrow(drawList, project, point, light.transmitted->direction, length * 0.9f, kProbeTransmitColor, "T" + index,
                       stroke, labels);
    }
    if (!probe.viewTransmitted) return;
    const ProbeRefraction& view = *probe.viewTransmitted;
    if (view.totalInternalReflection)
        probeArrow(drawList, project, point, probe.viewMirror, length * 0.9f, kProbeTransmitColor, "TIR", stroke, labels);
    else probeArrow(drawList, project, point, view.direction, length, kProbeTransmitColor, "T(V)", stroke, labels);
}

// What the arrows and their labels cover (the legend, the first "taken" rectangle, aside), within the area.
ProbeOverlayArea arrowsRect(const ProbeLabels& labels, std::optional<ImVec2> point, const ProbeOverlayArea& area) {
    ImVec4 box(1e9f, 1e9f, -1e9f, -1e9f);
    for (size_t i = 1; i < labels.taken.size(); ++i) {
        const ImVec4& r = labels.taken[i];
        box = ImVec4(std::min(box.x, r.x), std::min(box.y, r.y), std::max(box.z, r.z), std::max(box.w, r.w));
    }
    if (point) box = ImVec4(std::min(box.x, point->x), std::min(box.y, point->y), std::max(box.z, point->x), std::max(box.w, point->y));
    if (box.z <= box.x) return {};
    box = ImVec4(std::max(box.x, area.x), std::max(box.y, area.y), std::min(box.z, area.x + area.width), std::min(box.w, area.y + area.height));
    return {box.x, box.y, std::max(0.0f, box.z - box.x), std::max(0.0f, box.w - box.y)};
}

}  // namespace

ProbeOverlayRects drawProbeOverlay(ImDrawList* drawList, const ProbeResult& probe, const Camera& camera,
                                   const ProbeOverlayArea& area, ProbeLegendCorner corner) {
    const ProbeProjector project{camera.viewProjection(area.width / area.height), area};
    const ProbeStroke stroke{ImGui::GetFontSize() / 17.0f};
    drawList->PushClipRect(ImVec2(area.x, area.y), ImVec2(area.x + area.width, area.y + area.height), true);
    if (!probe.hitSurface) {
        drawMissedPixel(drawList, probe, area, stroke);
        drawList->PopClipRect();
        return {};
    }
    // The legend first, so no arrow label lands on it.
    const std::vector<ProbeLegendLine> legend = probeLegendLines(probe);
    const ImVec2 legendSize = probeLegendSize(legend);
    const float margin = 6.0f * stroke.scale;
    const ImVec2 legendAt(area.x + margin, corner == ProbeLegendCorner::TopLeft ? area.y + margin : area.y + area.height - margin - legendSize.y);
    ProbeLabels labels;
    labels.taken.emplace_back(legendAt.x - 3, legendAt.y - 2, legendAt.x + legendSize.x + 3, legendAt.y + legendSize.y + 2);
    // Arrow length: a fixed fraction of the view's height at the point's depth [m].
    const float viewHeight = camera.projection == Projection::Orthographic
                                 ? camera.orthoHeight
                                 : 2.0f * probe.hitDistance * std::tan(glm::radians(0.5f * camera.verticalFovDegrees));
    drawProbeArrows(drawList, probe, project, kProbeArrowFraction * viewHeight, stroke, labels);
    probeLegend(drawList, legendAt, legend);
    const std::optional<ImVec2> point = project(probe.position);
    if (point) {
        drawList->AddCircleFilled(*point, 4.5f * stroke.scale, kProbeShadowColor);
        drawList->AddCircleFilled(*point, 3.0f * stroke.scale, kProbeNormalColor);
    }
    drawList->PopClipRect();
    ProbeOverlayRects rects;
    rects.legend = {legendAt.x - 3, legendAt.y - 2, legendSize.x + 6, legendSize.y + 4};
    rects.arrows = arrowsRect(labels, point, area);
    return rects;
}

}  // namespace glint
