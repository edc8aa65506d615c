// The editor's surface probe tool (see probe_panel.h).
// Sections: input · recomputation · the window · drawing.
#include "editor/probe_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <imgui.h>

#include "classroom/probe_overlay.h"
#include "classroom/probe_text.h"
#include "editor/window_placement.h"
#include "util/text.h"

namespace glint {
namespace {

// The tool's state; one editor window per process, like the camera drag (camera_actions.cpp).
struct ProbeTool {
    bool armed = false;     // the next left click on the viewport sets the point
    bool active = false;    // a point is set: arrows and window shown
    glm::vec2 point{0.5f};  // the point as a fraction of the viewport (0..1, y down)
    // The last computation and what it was computed for.
    std::uint64_t revision = ~0ull;
    glm::ivec2 size{0};
    glm::vec2 computedPoint{-1.0f};
    ProbeResult result;
};
ProbeTool gProbeTool;

bool probeInsideViewport(const ViewportRect& viewport, ImVec2 point) {
    return point.x >= viewport.x && point.y >= viewport.y && point.x < viewport.x + viewport.width &&
           point.y < viewport.y + viewport.height;
}

// --- recomputation: only when the scene's revision, the viewport's size or the point changed ---

const ProbeResult& currentProbe(ProbeTool& probe, const EditorState& state, const ViewportRect& viewport) {
    const glm::ivec2 size{std::max(1, static_cast<int>(std::lround(viewport.width))),
                          std::max(1, static_cast<int>(std::lround(viewport.height)))};
    if (probe.revision != state.session.revision() || probe.size != size || probe.computedPoint != probe.point) {
        const int x = std::clamp(static_cast<int>(probe.point.x * size.x), 0, size.x - 1);
        const int y = std::clamp(static_cast<int>(probe.point.y * size.y), 0, size.y - 1);
        probe.result = probeSurface(state.session.scene(), x, y, size.x, size.y);
        probe.revision = state.session.revision();
        probe.size = size;
        probe.computedPoint = probe.point;
    }
    return probe.result;
}

void probeRow(const char* quantity, const std::string& value) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(quantity);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(value.c_str());
}

std::string probeDegreesText(float degrees) { return formatNumber(degrees, "%.1f°"); }

std::string probeDirectionText(glm::vec3 v) {
    return "(" + formatProbeNumber(v.x) + ", " + formatProbeNumber(v.y) + ", " + formatProbeNumber(v.z) + ")";
}

// --- the window: per light, then the total and the display chain -------------------------------

void drawProbeLight(const ProbeLight& light) {
    const std::string title = "Light " + std::to_string(light.lightIndex + 1) + " \"" + light.name + "\"";
    if (!ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::PushID(light.lightIndex);
    if (ImGui::BeginTable("chain", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        probeRow(light.source.symbol, formatProbeNumber(light.source.amount) + " " + light.source.unit + "  (" +
                                          formatProbeNumber(light.source.photometric) + " " + light.source.photometricUnit + ")");
        if (std::isfinite(light.distance)) probeRow("distance d", formatProbeNumber(light.distance) + " m");
        probeRow("L", probeDirectionText(light.towardsLight));
        probeRow("H", probeDirectionText(light.halfVector));
        probeRow("R", probeDirectionText(light.mirror));
        if (light.transmitted)
            probeRow("T", light.transmitted->totalInternalReflection ? std::string("total internal reflection")
                                                                      : probeDirectionText(light.transmitted->direction) +
                                                                            "  θt " +
                                                                            probeDegreesText(light.transmitted->transmittedDegrees));
        probeRow("θi = ∠(N,L)", probeDegreesText(light.incidentDegrees));
        probeRow("θr = ∠(N,V)", probeDegreesText(light.reflectedDegrees));
        probeRow("∠(N,H)", probeDegreesText(light.halfDegrees));
        probeRow("∠(R,V)", probeDegreesText(light.mirrorViewDegrees));
        probeRow("cos θi", formatProbeNumber(light.cosTheta));
        probeRow("E⊥", formatProbeRgb(light.normalIrradiance) + " W/m²");
        probeRow("E", formatProbeRgb(light.irradiance) + " W/m²  (" + formatProbeNumber(light.illuminance) + " lx)" +
                          (light.shadowed ? "  in shadow" : "") + (light.behindSurface ? "  behind" : ""));
        probeRow("f_r", formatProbeRgb(light.brdf) + " 1/sr");
        probeRow("L_r", formatProbeRgb(light.radiance) + " W/(sr·m²)  (" + formatProbeNumber(light.luminance) + " nit)");
        ImGui::EndTable();
    }
    for (const std::string& line : probeLightEquation(light)) ImGui::TextWrapped("%s", line.c_str());
    ImGui::PopID();
}

void drawProbeWindow(ProbeTool& probe, const ProbeResult& result) {
    // The readout is reserved: other windows open beside it (editor/window_placement.h).
    bool open = true;
    if (beginPlacedWindow("Surface probe", &open, {ImVec2(30.0f, 16.0f), ImVec2(16.0f, 8.0f), ImVec2(0.45f, 0.4f)}, 0,
                          /*reserved=*/true)) {
        ImGui::Text("Pixel (%d, %d) of %d×%d", result.pixelX, result.pixelY, result.width, result.height);
        if (!result.hitSurface) {
            ImGui::TextUnformatted("No surface: the ray sees the background.");
        } else {
            ImGui::Text("%s — %s (%s)", result.objectName.c_str(), result.materialName.c_str(), result.modelLabel.c_str());
            ImGui::TextWrapped("point %s m, %s m along the ray", probeDirectionText(result.position).c_str(),
                               formatProbeNumber(result.hitDistance).c_str());
            ImGui::TextWrapped("N %s, V %s", probeDirectionText(result.normal).c_str(),
                               probeDirectionText(result.towardsViewer).c_str());
            if (result.gpuOnlyMaterial)
                ImGui::TextWrapped("A custom .brdf material runs on the GPU only: the probe cannot break it down.");
            if (result.viewTransmitted) {
                const ProbeRefraction& view = *result.viewTransmitted;
                std::string line = "View ray: η " + formatProbeNumber(view.etaIncident) + " → " +
                                   formatProbeNumber(view.etaTransmitted) + ", θi " + probeDegreesText(view.incidentDegrees);
                if (view.criticalDegrees) line += ", critical " + probeDegreesText(*view.criticalDegrees);
                line += view.totalInternalReflection ? ": total internal reflection"
                                                     : ", θt " + probeDegreesText(view.transmittedDegrees);
                ImGui::TextWrapped("%s", line.c_str());
            }
            if (result.gouraud)
                ImGui::TextWrapped("Gouraud surface: the terms are at the point; the pixel interpolates its triangle's corners.");
            for (const ProbeLight& light : result.lights) drawProbeLight(light);
            if (result.ambientRadiance != glm::vec3(0.0f))
                ImGui::Text("Ambient: k_a %s × L_a %s W/(sr·m²)", formatProbeRgb(result.ambientReflectance).c_str(),
                            formatProbeRgb(result.ambientRadiance).c_str());
            ImGui::TextUnformatted("Shadows: per light above (shadow rays of lights that cast shadows).");
        }
        if (const std::string line = probeEnvironmentLine(result); !line.empty()) ImGui::TextWrapped("%s", line.c_str());
        ImGui::Separator();
        ImGui::TextWrapped("%s", probeTotalEquation(result).c_str());
        ImGui::Text("Luminance %s nit", formatProbeNumber(result.luminance).c_str());
        ImGui::Separator();
        ImGui::TextUnformatted("Display chain");
        for (const std::string& line : probeDisplayEquation(result)) ImGui::TextWrapped("%s", line.c_str());
    }
    ImGui::End();
    if (!open) probe.active = probe.armed = false;
}

}  // namespace

// --- input ------------------------------------------------------------------------------------

void toggleProbeTool() {
    ProbeTool& probe = gProbeTool;
    if (probe.active || probe.armed) probe.active = probe.armed = false;
    else probe.armed = true;
}

void showProbeAt(glm::vec2 fractionOfViewport) {
    gProbeTool.point = glm::clamp(fractionOfViewport, glm::vec2(0.0f), glm::vec2(1.0f));
    gProbeTool.active = true;
    gProbeTool.armed = false;
}

bool probeToolOn() { return gProbeTool.active || gProbeTool.armed; }

std::optional<float> probedIncidenceDegrees() {
    if (!gProbeTool.active || !gProbeTool.result.hitSurface) return std::nullopt;
    for (const ProbeLight& light : gProbeTool.result.lights)
        if (!light.behindSurface) return light.incidentDegrees;
    return std::nullopt;
}

bool handleProbeClick(const ViewportRect& viewport) {
    ProbeTool& probe = gProbeTool;
    const ImGuiIO& io = ImGui::GetIO();
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left) || io.WantCaptureMouse) return false;
    if (!probeInsideViewport(viewport, io.MousePos) || !(io.KeyShift || probe.armed)) return false;
    probe.point = {(io.MousePos.x - viewport.x) / viewport.width, (io.MousePos.y - viewport.y) / viewport.height};
    probe.active = true;
    probe.armed = false;
    return true;
}

// --- drawing ----------------------------------------------------------------------------------

void drawProbe(const EditorState& state, const ViewportRect& viewport) {
    ProbeTool& probe = gProbeTool;
    if (!probe.active) return;
    const ProbeResult& result = currentProbe(probe, state, viewport);
    // The legend of angles bottom left, unless the lesson note took that corner (then top left).
    const float lines = ImGui::GetTextLineHeight() * static_cast<float>(result.lights.size() + 2);
    const ScreenRect legendBand{viewport.x, viewport.y + viewport.height - lines, viewport.width * 0.6f, lines};
    const ProbeLegendCorner corner =
        reservedAreaOf(legendBand, "lesson note") > 1.0f ? ProbeLegendCorner::TopLeft : ProbeLegendCorner::BottomLeft;
    const ProbeOverlayRects covered = drawProbeOverlay(ImGui::GetBackgroundDrawList(), result, state.session.scene().camera,
                                                       {viewport.x, viewport.y, viewport.width, viewport.height}, corner);
    const auto reserve = [](const char* what, const ProbeOverlayArea& r, bool hard) {
        if (r.width > 0.0f && r.height > 0.0f) reserveScreenRect(what, {r.x, r.y, r.width, r.height}, hard);
    };
    reserve("probe angles", covered.legend, true);
    reserve("probe arrows", covered.arrows, false);  // windows avoid them, but may cover them rather than shrink
    drawProbeWindow(probe, result);
}

}  // namespace glint
