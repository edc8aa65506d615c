// The editor's Compare window (see compare_view.h).
// Sections: pane choices · window · pane scenes and rendering.
#include "classroom/compare_view.h"

#include <glad/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "brdf/model_registry.h"
#include "brdf/presets.h"
#include "editor/editor_state.h"
#include "editor/window_placement.h"
#include "gl/display_texture.h"

namespace glint {
namespace {

// --- pane choices -------------------------------------------------------------------------------

// The selected object, or the compare subject when nothing valid is selected.
Result<size_t> compareViewSubject(const EditorState& state) {
    const Scene& scene = state.session.scene();
    if (state.selectedObject >= 0 && static_cast<size_t>(state.selectedObject) < scene.objects.size())
        return static_cast<size_t>(state.selectedObject);
    return compareSubject(scene);
}

// The material a choice puts on the subject, and its label.
std::pair<Material, std::string> chosenMaterial(const Scene& scene, const Material& own, const ComparePaneChoice& choice) {
    switch (choice.kind) {
        case ComparePaneChoice::Kind::Current: return {own, own.name};
        case ComparePaneChoice::Kind::SceneMaterial: {
            const Material& other = scene.materials.at(std::min<size_t>(choice.index, scene.materials.size() - 1));
            return {other, other.name};
        }
        case ComparePaneChoice::Kind::Preset: {
            const Preset& preset = allPresets()[std::min<size_t>(choice.index, allPresets().size() - 1)];
            return {preset.material(), preset.name};
        }
        case ComparePaneChoice::Kind::Model: {
            const ModelInfo& info = allModels()[std::min<size_t>(choice.index, allModels().size() - 1)];
            return {withModel(own, info.model), std::string(own.name) + " as " + info.label};
        }
    }
    return {own, own.name};
}

// --- window -------------------------------------------------------------------------------------

std::string choiceLabel(const Scene& scene, const ComparePaneChoice& choice) {
    switch (choice.kind) {
        case ComparePaneChoice::Kind::Current: return "current material";
        case ComparePaneChoice::Kind::SceneMaterial:
            return "scene: " + (static_cast<size_t>(choice.index) < scene.materials.size() ? scene.materials[choice.index].name : "?");
        case ComparePaneChoice::Kind::Preset: return std::string("preset: ") + allPresets()[choice.index].name;
        case ComparePaneChoice::Kind::Model: return std::string("model: ") + allModels()[choice.index].label;
    }
    return "";
}

// One pane's combo; true when the choice changed.
bool drawPaneChoice(const Scene& scene, int pane, ComparePaneChoice& choice) {
    bool changed = false;
    const std::string label = "Pane " + std::to_string(pane + 1);
    if (!ImGui::BeginCombo(label.c_str(), choiceLabel(scene, choice).c_str())) return false;
    auto option = [&](ComparePaneChoice candidate) {
        const bool selected = candidate.kind == choice.kind && candidate.index == choice.index;
        if (ImGui::Selectable(choiceLabel(scene, candidate).c_str(), selected) && !selected) choice = candidate, changed = true;
    };
    option({ComparePaneChoice::Kind::Current, 0});
    for (size_t i = 0; i < scene.materials.size(); ++i) option({ComparePaneChoice::Kind::SceneMaterial, static_cast<int>(i)});
    for (size_t i = 0; i < allPresets().size(); ++i) option({ComparePaneChoice::Kind::Preset, static_cast<int>(i)});
    for (size_t i = 0; i < allModels().size(); ++i) option({ComparePaneChoice::Kind::Model, static_cast<int>(i)});
    ImGui::EndCombo();
    return changed;
}

void drawCompareControls(EditorState& state) {
    CompareViewState& view = state.compare;
    const Scene& scene = state.session.scene();
    bool changed = false;
    if (view.interpolation) {
        // A typed value outside the scene file's limits (shape_json.cpp) is refused.
        auto tessellationSlider = [&](const char* label, int& value, int sliderMax, int valid) {
            int typed = value;
            if (!ImGui::SliderInt(label, &typed, 3, sliderMax)) return;
            if (typed >= 3 && typed <= valid) value = typed, changed = true, view.message.clear();
            else view.message = std::string(label) + ": " + std::to_string(typed) + " refused; it must lie in [3, " + std::to_string(valid) + "]";
        };
        tessellationSlider("Segments", view.tessellation.segments, 128, 1024);
        tessellationSlider("Rings", view.tessellation.rings, 64, 512);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Tessellation of the selected sphere or torus in the three panes");
    } else {
        int layout = view.layout == CompareLayout::Split ? 0 : 1;
        if (ImGui::Combo("Layout", &layout, "split (2 panes, divider)\0grid (2x2)\0")) {
            view.layout = layout == 0 ? CompareLayout::Split : CompareLayout::Grid;
            view.paneCount = layout == 0 ? 2 : 4;
            changed = true;
        }
        for (int i = 0; i < view.paneCount; ++i) changed |= drawPaneChoice(scene, i, view.choices[i]);
        if (view.layout == CompareLayout::Split && ImGui::SliderFloat("Divider", &view.divider, 0.0f, 1.0f, "%.2f"))
            view.compositeWanted = true;
    }
    view.renderWanted |= changed;
}

// The composite, with the divider dragged by the mouse anywhere over it (split only).
void drawCompareImage(CompareViewState& view) {
    const ImVec2 available = ImGui::GetContentRegionAvail();
    const int width = std::clamp(static_cast<int>(available.x), 16, 2048);
    const int height = std::clamp(static_cast<int>(available.y), 16, 2048);
    if (width != view.width || height != view.height) view.width = width, view.height = height, view.renderWanted = true;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    if (view.texture) ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(view.texture)), ImVec2(float(width), float(height)));
    ImGui::SetCursorScreenPos(origin);
    ImGui::InvisibleButton("compare divider", ImVec2(float(width), float(height)));
    if (view.interpolation || view.layout != CompareLayout::Split) return;
    if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    if (ImGui::IsItemActive()) {
        const float divider = std::clamp((ImGui::GetIO().MousePos.x - origin.x) / float(width), 0.0f, 1.0f);
        if (divider != view.divider) view.divider = divider, view.compositeWanted = true;
    }
}

}  // namespace

void openCompareView(EditorState& state, bool interpolation) {
    if (!state.compare.open && !interpolation)  // first opening: the current material against three presets
        for (int i = 1; i < 4; ++i) state.compare.choices[i] = {ComparePaneChoice::Kind::Preset, (i - 1) % static_cast<int>(allPresets().size())};
    state.compare.open = true;
    state.compare.interpolation = interpolation;
    state.compare.renderWanted = true;
}

void drawCompareWindow(EditorState& state) {
    CompareViewState& view = state.compare;
    if (!view.open) return;
    const char* title = view.interpolation ? "Compare: shading interpolation###compare" : "Compare: materials###compare";
    if (beginPlacedWindow(title, &view.open, {ImVec2(33.0f, 30.0f), ImVec2(22.0f, 20.0f)})) {
        drawCompareControls(state);
        if (!view.message.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", view.message.c_str());
        drawCompareImage(view);
    }
    ImGui::End();
    if (state.session.revision() != view.renderedRevision) view.renderWanted = true;
}

// --- pane scenes and rendering -------------------------------------------------------------

Result<std::vector<ComparePaneScene>> compareViewPanes(const EditorState& state) {
    const CompareViewState& view = state.compare;
    const Scene& scene = state.session.scene();
    auto subject = compareViewSubject(state);
    if (!subject) return subject.error();
    std::vector<ComparePaneScene> panes;
    if (view.interpolation) {
        const char* labels[3] = {"flat", "Gouraud", "Phong"};
        for (int i = 0; i < 3; ++i)
            panes.push_back({withSubjectInterpolation(scene, *subject, kInterpolationLesson[i], view.tessellation), labels[i]});
        return panes;
    }
    const Material& own = scene.materials.at(scene.objects[*subject].materialIndex);
    for (int i = 0; i < view.paneCount; ++i) {
        auto [material, label] = chosenMaterial(scene, own, view.choices[i]);
        panes.push_back({withSubjectMaterial(scene, *subject, material), label});
    }
    return panes;
}

bool updateCompareView(EditorState& state, Renderer& renderer) {
    CompareViewState& view = state.compare;
    if (!view.open || view.width == 0 || (!view.renderWanted && !view.compositeWanted)) return false;
    const CompareLayout layout = view.interpolation ? CompareLayout::Row : view.layout;
    const int paneCount = view.interpolation ? 3 : view.paneCount;
    const bool rendering = view.renderWanted;
    if (rendering) {
        view.renderWanted = false;
        view.renderedRevision = state.session.revision();
        view.paneRenders.clear();
        auto panes = compareViewPanes(state);
        if (!panes) return view.message = panes.error().format(), false;
        view.panes = std::move(*panes);
        // Rendered with the divider in the middle, so that every split pane is whole and a drag composites only.
        auto rendered = renderComparePanes(renderer, view.panes, compareGeometry(layout, paneCount, view.width, view.height, 0.5f));
        if (!rendered) return view.message = rendered.error().format(), true;
        view.paneRenders = std::move(*rendered);
    }
    view.compositeWanted = false;
    if (view.paneRenders.size() != view.panes.size()) return rendering;
    auto composite = compositeCompare(view.paneRenders, view.panes, compareGeometry(layout, paneCount, view.width, view.height, view.divider),
                                      view.width, view.height);
    if (!composite) return view.message = composite.error().format(), rendering;
    view.message.clear();
    view.texture = uploadDisplayTexture(composite->display, GL_NEAREST, view.texture);
    return rendering;
}

}  // namespace glint
