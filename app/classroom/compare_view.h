// The editor's Compare window (View ▸ Compare materials… / Shading interpolation…): what each
// pane shows for the selected object (its current material, another material of the scene, a
// preset, or its material under another model; or flat, Gouraud and Phong with a tessellation
// slider), the rendered composite, and the split's divider dragged with the mouse. Rendering and
// compositing are compare_render.h; no layout maths here.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "classroom/compare_render.h"
#include "classroom/compare_scenes.h"

namespace glint {

struct EditorState;  // editor/editor_state.h

struct ComparePaneChoice {
    enum class Kind { Current, SceneMaterial, Preset, Model };
    Kind kind = Kind::Current;
    int index = 0;  // into the scene's materials, allPresets() or allModels()
};

struct CompareViewState {
    bool open = false;
    bool interpolation = false;  // the shading-interpolation lesson instead of materials
    CompareLayout layout = CompareLayout::Split;
    int paneCount = 2;  // split: 2; grid: 2..4
    std::array<ComparePaneChoice, 4> choices;
    float divider = 0.5f;
    Tessellation tessellation{12, 6};
    std::string message;  // why nothing could be rendered

    // What was rendered, so that a divider drag only composites again.
    bool renderWanted = true, compositeWanted = true;
    std::uint64_t renderedRevision = ~0ull;
    int width = 0, height = 0;  // composite size [pixels]
    std::vector<ComparePaneScene> panes;
    std::vector<RenderedImages> paneRenders;
    unsigned texture = 0;  // GL texture of the composite
};

// The window (when open); records what changed. Call between ImGui::NewFrame and ImGui::Render.
void drawCompareWindow(EditorState& state);
// Renders and composites what drawCompareWindow asked for, into the window's texture. Returns
// true when it used the renderer, whose viewport image must then be rendered again.
bool updateCompareView(EditorState& state, Renderer& renderer);
// The panes' scenes as chosen: the selected object (or the compare subject) wearing each pane's
// material, or drawn flat, Gouraud and Phong with the chosen tessellation.
Result<std::vector<ComparePaneScene>> compareViewPanes(const EditorState& state);
// Opens the window on one of its two lessons.
void openCompareView(EditorState& state, bool interpolation);

}  // namespace glint
