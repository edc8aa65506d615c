// The classroom's options of `glint render`: the display lessons (--levels, --dither, --transfer,
// --gamma, --levels-ramp) and the compare views (--compare, --layout, --divider,
// --compare-interpolation, --tessellation). Declaring, checking and applying them to a loaded
// scene; the rendering itself is app/classroom/compare_render.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "classroom/compare_layout.h"
#include "classroom/compare_render.h"
#include "classroom/compare_scenes.h"

namespace CLI {
class App;
}

namespace glint {

struct ClassroomOptions {
    std::optional<Transfer> transfer;
    std::optional<float> gamma;
    std::optional<int> levels;
    std::optional<Dither> dither;
    bool levelsRamp = false;
    std::vector<std::string> compare;  // pane sources as typed
    std::optional<CompareLayout> layout;
    std::optional<float> divider;
    bool compareInterpolation = false;
    std::optional<Tessellation> tessellation;

    // Adds these options to `command` (`glint render`), into this object, which must outlive the parse.
    void addTo(CLI::App& command);
    // Options that contradict each other; "" when they fit together.
    std::string check() const;
    bool comparing() const { return !compare.empty() || compareInterpolation; }
    void applyDisplay(Scene& scene) const;
    // The panes of --compare or --compare-interpolation on `scene` (display options applied).
    Result<std::vector<ComparePaneScene>> paneScenes(const Scene& scene) const;
    CompareLayout chosenLayout() const;
};

}  // namespace glint
