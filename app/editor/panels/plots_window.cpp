// The Plots window (see plots_window.h): the incidence slider, pinned materials, and the four
// plots in a 2×2 grid; the lobe turns when dragged. .brdf materials are sampled on the GPU and
// MERL materials read from their table (app/classroom/plot_materials.h), each with a note.
#include "editor/panels/plots_window.h"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "classroom/plot_materials.h"
#include "classroom/probe_text.h"
#include "editor/editor_state.h"
#include "editor/probe_panel.h"
#include "editor/window_placement.h"

namespace glint {
namespace {

// The selected object's material first, then the pinned ones (each once); a .brdf material whose
// shader does not compile for sampling is left out, with its error in `leftOut`.
std::vector<PlotMaterial> plotsWindowMaterials(const EditorState& state, BrdfSampler& sampler, std::vector<std::string>& leftOut) {
    const Scene& scene = state.session.scene();
    std::vector<int> indices;
    if (state.selectedObject >= 0 && state.selectedObject < static_cast<int>(scene.objects.size()))
        indices.push_back(scene.objects[state.selectedObject].materialIndex);
    for (int pinned : state.plots.pinnedMaterials)
        if (std::find(indices.begin(), indices.end(), pinned) == indices.end()) indices.push_back(pinned);
    std::vector<PlotMaterial> materials;
    for (int index : indices) {
        if (index < 0 || index >= static_cast<int>(scene.materials.size())) continue;
        if (auto material = plotMaterialFor(scene.materials[index], sampler)) materials.push_back(std::move(*material));
        else leftOut.push_back(scene.materials[index].name + " is not plotted: " + material.error().format());
    }
    return materials;
}

bool samePlotMaterials(const std::vector<PlotMaterial>& a, const std::vector<PlotMaterial>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), samePlotMaterial);
}

// Why the Fresnel cell is empty: a measured table or a shader has no index to plot.
std::string noFresnelText(const std::vector<PlottedMaterial>& plotted) {
    for (const PlottedMaterial& entry : plotted)
        if (const std::string kind = kindWithoutIndex(entry.material); !kind.empty())
            return "Fresnel: " + entry.material.name + " is " + kind + ": it has no index n + iκ to plot";
    return "Fresnel: no plotted material has an index n (+ iκ)";
}

bool sameEnvironment(const Environment& a, const Environment& b) {
    return a.map == b.map && a.rotationDegrees == b.rotationDegrees && a.intensity == b.intensity;
}

void refreshPlotsCache(PlotsWindowState& plots, std::vector<PlotMaterial> materials, const Environment& environment) {
    if (plots.cachedIncidence == plots.incidenceDegrees && plots.cachedFromInside == plots.fresnelFromInside &&
        samePlotMaterials(plots.cachedMaterials, materials) && sameEnvironment(plots.cachedEnvironment, environment))
        return;
    plots.plotted.clear();
    plots.fresnel.reset();
    plots.environmentNotes.clear();
    for (size_t i = 0; i < materials.size(); ++i) {
        plots.plotted.push_back(computePlottedMaterial(materials[i], plotSeriesColour(static_cast<int>(i)), plots.incidenceDegrees));
        if (auto accuracy = plotEnvironmentAccuracy(materials[i], environment, plots.incidenceDegrees))
            plots.environmentNotes.push_back(materials[i].name + ", facing up, seen from θ_o = θ_i: " +
                                             environmentAccuracyText(accuracy->method, accuracy->preview, accuracy->truth));
        if (!plots.fresnel)
            if (auto index = materialComplexIndex(materials[i])) {
                plots.fresnel = fresnelCurves(*index, plots.fresnelFromInside);
                plots.fresnelName = materials[i].name;
            }
    }
    plots.cachedMaterials = std::move(materials);
    plots.cachedIncidence = plots.incidenceDegrees;
    plots.cachedFromInside = plots.fresnelFromInside;
    plots.cachedEnvironment = environment;
}

void drawPlotsPinning(EditorState& state) {
    const Scene& scene = state.session.scene();
    std::vector<int>& pinned = state.plots.pinnedMaterials;
    pinned.erase(std::remove_if(pinned.begin(), pinned.end(),
                                [&](int index) { return index < 0 || index >= static_cast<int>(scene.materials.size()); }),
                 pinned.end());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 10.0f);
    if (ImGui::BeginCombo("##pin", "Pin a material…")) {
        for (int index = 0; index < static_cast<int>(scene.materials.size()); ++index) {
            const bool isPinned = std::find(pinned.begin(), pinned.end(), index) != pinned.end();
            if (ImGui::Selectable(scene.materials[index].name.c_str(), isPinned)) {
                if (isPinned) pinned.erase(std::find(pinned.begin(), pinned.end(), index));
                else pinned.push_back(index);
            }
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Overlay other materials of the scene (click again to unpin)");
}

std::string gPlotsIncidenceRefusal;  // why a typed incidence angle was refused (one Plots window)
bool gPlotsFollowProbe = true;       // θ_i from the surface probe's point when it shows one

}  // namespace

void drawPlotsWindow(EditorState& state, BrdfSampler& sampler) {
    PlotsWindowState& plots = state.plots;
    if (!plots.open) return;
    // The plot is reserved: other windows open beside it (editor/window_placement.h).
    if (!beginPlacedWindow("BRDF and Fresnel plots", &plots.open, {ImVec2(44.0f, 34.0f), ImVec2(20.0f, 16.0f)}, 0,
                           /*reserved=*/true)) {
        ImGui::End();
        return;
    }
    const std::optional<float> probed = probedIncidenceDegrees();
    if (probed) {  // the probed point's first light: its θ_i, or the slider's when unticked
        ImGui::Checkbox("θ_i from the probe", &gPlotsFollowProbe);
        if (gPlotsFollowProbe) plots.incidenceDegrees = std::clamp(*probed, 0.0f, 90.0f);
        ImGui::SameLine();
    }
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.0f);
    float typedIncidence = plots.incidenceDegrees;
    ImGui::BeginDisabled(probed && gPlotsFollowProbe);
    ImGui::SliderFloat("Incidence θ_i", &typedIncidence, 0.0f, 90.0f, "%.0f°");
    ImGui::EndDisabled();
    if (typedIncidence >= 0.0f && typedIncidence <= 90.0f) {
        if (typedIncidence != plots.incidenceDegrees) gPlotsIncidenceRefusal.clear();
        plots.incidenceDegrees = typedIncidence;
    } else {  // a typed NaN or 120°: refused, and said why
        gPlotsIncidenceRefusal = "Incidence θ_i must be between 0° and 90°; kept " + std::to_string(static_cast<int>(plots.incidenceDegrees)) + "°";
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Angle of the light from the normal, 0–90° (Ctrl+click to type)");
    drawPlotsPinning(state);
    ImGui::SameLine();
    ImGui::Checkbox("Fresnel from inside", &plots.fresnelFromInside);
    if (!gPlotsIncidenceRefusal.empty()) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", gPlotsIncidenceRefusal.c_str());
    std::vector<std::string> leftOut;
    refreshPlotsCache(plots, plotsWindowMaterials(state, sampler, leftOut), state.session.scene().environment);
    for (const std::string& reason : leftOut) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "%s", reason.c_str());
    for (const PlotMaterial& material : plots.cachedMaterials)
        if (const std::string note = plotSourceNote(material); !note.empty()) ImGui::TextDisabled("%s", note.c_str());
    for (const std::string& note : plots.environmentNotes) ImGui::TextWrapped("%s", note.c_str());

    const ImVec2 available = ImGui::GetContentRegionAvail();
    const ImVec2 cell(std::max(available.x * 0.5f - 4.0f, 60.0f), std::max(available.y * 0.5f - 4.0f, 60.0f));
    // Axis labels keep apart in a small window (a large UI font on a small screen): the plots'
    // text shrinks until a cell is about 11 lines tall and 22 wide, to no less than 55 %.
    const float font = ImGui::GetFontSize();
    ImGui::SetWindowFontScale(std::clamp(std::min(cell.y / (11.0f * font), cell.x / (22.0f * font)), 0.55f, 1.0f));
    ImDrawList* drawList = ImGui::GetWindowDrawList();
    auto nextCell = [&](const char* id, bool sameLine) {
        if (sameLine) ImGui::SameLine();
        const ImVec2 topLeft = ImGui::GetCursorScreenPos();
        ImGui::InvisibleButton(id, cell);
        return topLeft;
    };
    ImVec2 at = nextCell("polar", false);
    drawPolarPlot(drawList, at, ImVec2(at.x + cell.x, at.y + cell.y), plots.plotted);
    at = nextCell("lobe", true);
    if (ImGui::IsItemActive()) {  // drag to turn the lobe
        const ImVec2 delta = ImGui::GetIO().MouseDelta;
        plots.lobeYaw += delta.x * 0.01f;
        plots.lobePitch = std::clamp(plots.lobePitch + delta.y * 0.01f, -1.5f, 1.5f);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Drag to turn the lobe");
    drawLobePlot(drawList, at, ImVec2(at.x + cell.x, at.y + cell.y), plots.plotted, plots.lobeYaw, plots.lobePitch);
    at = nextCell("albedo", false);
    drawAlbedoPlot(drawList, at, ImVec2(at.x + cell.x, at.y + cell.y), plots.plotted);
    at = nextCell("fresnel", true);
    if (plots.fresnel) {
        drawFresnelPlot(drawList, at, ImVec2(at.x + cell.x, at.y + cell.y), *plots.fresnel, plots.fresnelName);
    } else {
        drawList->AddRectFilled(at, ImVec2(at.x + cell.x, at.y + cell.y), IM_COL32(18, 20, 26, 235), 4.0f);
        const std::string why = noFresnelText(plots.plotted);
        drawList->PushClipRect(at, ImVec2(at.x + cell.x, at.y + cell.y), true);
        drawList->AddText(nullptr, 0.0f, ImVec2(at.x + 6, at.y + 4), IM_COL32(225, 228, 235, 255), why.c_str(), nullptr,
                          cell.x - 12.0f);  // wrapped to the cell
        drawList->PopClipRect();
    }
    ImGui::SetWindowFontScale(1.0f);
    ImGui::End();
}

}  // namespace glint
