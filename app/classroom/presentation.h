// Presentation mode (View ▸ Presentation mode, F11; `glint present LIST.json`): for a lecture-hall
// projector — the window fills the screen, a UI scale of 1.5–3× with DejaVu Sans rasterised at
// that size, a high-contrast style, the advanced panels hidden (shadow-map settings, the
// environment light section, BRDF Explorer file actions) and the viewport first: the side
// columns start collapsed to narrow strips, one opens at a time and takes at most 26 % of the
// width. The choice and its scale persist in settings.json. Lessons live in lessons_view.h.
#pragma once

#include <cstdint>
#include <string>

#include "editor/editor_state.h"

struct GLFWwindow;
struct ImFont;
struct ImGuiStyle;

namespace glint {

inline constexpr float kPresentationScaleMin = 1.5f;
inline constexpr float kPresentationScaleMax = 3.0f;
inline constexpr float kPresentationColumnFraction = 0.26f;  // of the window's width, the one open column
inline constexpr const char* kPresentationFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

// The UI scale in effect: the normal one, or while presenting the presentation scale for a
// 1080-pixel-high screen, in proportion to `displayHeight` (text keeps its share of a projected
// picture, so 1024×768 gets 1.42× where 1920×1080 gets 2×), never below 1; 0: height unknown.
float effectiveUiScale(const Settings& settings, float displayHeight = 0.0f);
// False while presentation mode hides the advanced panels.
bool advancedPanelsVisible(const Settings& settings);
// F11 / the View menu: flips the mode, saves the settings and says so in the status bar.
void togglePresentationMode(EditorState& state);
// `glint present LIST.json`: presentation mode (saved, as F11 does) on the list's first lesson.
void startPresentation(EditorState& state, const std::string& lessonListPath);
// The widest a side column may be shown [ImGui px]: 40 % of the window, 26 % while presenting.
float columnWidthLimit(const Settings& settings);
// Once per frame: entering presentation mode collapses both columns (leaving restores them), and
// while presenting, opening one column collapses the other.
void keepPresentationColumns(EditorState& state);
// A hidden side column leaves a strip this wide while presenting (a button brings it back); 0 otherwise.
float collapsedColumnStripWidth(const Settings& settings);
void drawCollapsedColumnStrips(EditorState& state, float top, float height, float windowWidth);
// Entering presentation mode fills the screen (the monitor's work area); leaving restores the window.
void fitWindowToPresentation(GLFWwindow* window, bool presenting);
// Changes whenever floating windows should be sized and placed afresh (editor/window_placement.h):
// the UI scale, the mode or the screen changed, or a side column opened or closed (not while a
// column's edge is dragged: windows do not jump under the pointer).
std::uint64_t windowLayoutKey(float uiScale, bool presenting, bool leftColumn, bool rightColumn, float displayWidth,
                              float displayHeight);

// Loads the presentation font at `pixelSize` into ImGui's atlas (before the atlas is built);
// nullptr and a message on stderr when the file is missing (the normal font is then scaled).
ImFont* loadPresentationFont(float pixelSize);
// Applies the look for `settings`: style (dark or high contrast) scaled by the effective UI
// scale, and the font (the presentation font at its native size when there is one).
void applyEditorLook(const Settings& settings, float displayHeight, const ImGuiStyle& baseStyle, ImFont* presentationFont,
                     float normalFontPixels, float presentationFontPixels);

}  // namespace glint
