// Presentation mode (View ▸ Presentation mode, F11): for a lecture-hall projector — a UI scale of
// 1.5–3× with DejaVu Sans rasterised at that size, a high-contrast style, and the advanced panels
// hidden (shadow-map settings, the environment light section, BRDF Explorer file actions).
// The choice and its scale persist in settings.json. Lessons live in lessons_view.h.
#pragma once

#include <string>

#include "editor/editor_state.h"

struct ImFont;
struct ImGuiStyle;

namespace glint {

inline constexpr float kPresentationScaleMin = 1.5f;
inline constexpr float kPresentationScaleMax = 3.0f;
inline constexpr const char* kPresentationFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

// The UI scale in effect: the presentation scale while presentation mode is on, else the normal one.
float effectiveUiScale(const Settings& settings);
// False while presentation mode hides the advanced panels.
bool advancedPanelsVisible(const Settings& settings);
// F11 / the View menu: flips the mode, saves the settings and says so in the status bar.
void togglePresentationMode(EditorState& state);

// Loads the presentation font at `pixelSize` into ImGui's atlas (before the atlas is built);
// nullptr and a message on stderr when the file is missing (the normal font is then scaled).
ImFont* loadPresentationFont(float pixelSize);
// Applies the look for `settings`: style (dark or high contrast) scaled by the effective UI
// scale, and the font (the presentation font at its native size when there is one).
void applyEditorLook(const Settings& settings, const ImGuiStyle& baseStyle, ImFont* presentationFont,
                     float normalFontPixels, float presentationFontPixels);

}  // namespace glint
