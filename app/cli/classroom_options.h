// The classroom's options of `glint render`: the display lessons (--levels, --dither, --transfer,
// --gamma, --levels-ramp) and the compare views (--compare, --layout, --divider,
// --compare-interpolation, --tessellation). Parsing, checking and applying them to a loaded
// scene; the rendering itself is app/classroom/compare_render.h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "classroom/compare_layout.h"
#include "classroom/compare_render.h"
#include "classroom/compare_scenes.h"

namespace glint {

inline constexpr const char* kClassroomUsage =
    "  --transfer srgb|gamma|linear  the display encoding (linear: gamma off)\n"
    "  --gamma G          encode with value^(1/G), G in [0.1, 10] (sets --transfer gamma)\n"
    "  --levels N         quantise each channel to N intensity levels, 2..256 (256: plain 8-bit)\n"
    "  --dither none|bayer2|bayer4|halftone  ordered dither before quantising to the levels\n"
    "  --levels-ramp      draw a grey radiance ramp 0..1 through the display chain along the bottom\n"
    "  --compare A,B[,C,D]  panes of the same scene whose subject (first non-plane object) wears the\n"
    "                     material file A, B, ... or preset:NAME (see glint presets) or model:ID\n"
    "                     (the subject's own material under another model)\n"
    "  --layout split|grid  split: two panes and a divider (default for 2); grid: 2x2 (default for 3, 4)\n"
    "  --divider F        the split's divider as a fraction of the width, in [0, 1] (default 0.5)\n"
    "  --compare-interpolation  flat, Gouraud and Phong side by side on the subject\n"
    "  --tessellation SxR  the subject's segments x rings for --compare-interpolation (sphere or torus)\n";

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

    enum class Parsed { NotClassroom, Taken, Refused };
    // Takes arguments[i] (and its value, advancing i) when it is one of these options; a bad
    // value is Refused with `error` set.
    Parsed parse(const std::vector<std::string>& arguments, size_t& i, std::string& error);
    // Options that contradict each other; "" when they fit together.
    std::string check() const;
    bool comparing() const { return !compare.empty() || compareInterpolation; }
    void applyDisplay(Scene& scene) const;
    // The panes of --compare or --compare-interpolation on `scene` (display options applied).
    Result<std::vector<ComparePaneScene>> paneScenes(const Scene& scene) const;
    CompareLayout chosenLayout() const;
};

}  // namespace glint
