// Where floating windows (Plots, Lessons, Compare, Surface probe, help…) open: somewhere that
// covers nothing important. Each frame the editor names the usable screen and the reserved
// rectangles (the lesson note, the probe readout, the plot); a window is placed when it first
// appears in a layout (UI scale, presentation mode or screen size changed) or reappears over a
// reserved rectangle or off the screen, and is sized in font units so it scales with the UI.
// Positions are remembered between runs in ImGui's ini file beside settings.json.
// GLINT_LOG_LAYOUT=1 prints the screen's rectangles to stderr whenever they change (GUI tests).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include <imgui.h>

namespace glint {

struct ScreenRect {
    float x = 0, y = 0, width = 0, height = 0;  // ImGui pixels, y down
    float right() const { return x + width; }
    float bottom() const { return y + height; }
    float overlapArea(const ScreenRect& other) const;
    bool contains(const ScreenRect& other) const;  // with half a pixel of slack
};

// What a placement avoids: rectangles with a weight per covered pixel. A reserved one (the lesson
// note, the probe readout, the plot) is covered only when the window fits nowhere else.
struct PlacementObstacle {
    ScreenRect rect;
    float weight = 1.0f;
    bool reserved = false;
};

struct WindowPlacement {
    ImVec2 position, size;
};

// Where a window of `size` goes inside `bounds`: the spot that covers the least reserved area,
// then the least weighted area of the other obstacles; among equals the earliest candidate (the
// corners of `bounds` from the top right clockwise, then beside each obstacle, then a grid).
// When every spot covers something reserved, the window is tried smaller (down to `minimumSize`);
// a window larger than `bounds` is shrunk to fit it.
WindowPlacement placeWindow(ImVec2 size, ImVec2 minimumSize, const ScreenRect& bounds,
                            std::span<const PlacementObstacle> obstacles);

// --- per frame, in the editor ------------------------------------------------------------------

// Starts a frame: `usable` is the screen between the menu bar and the status bar, `viewport` the
// 3D view inside it; `layout` changes whenever windows should be sized and placed afresh.
void beginWindowLayoutFrame(const ScreenRect& usable, const ScreenRect& viewport, std::uint64_t layout);
// A rectangle nothing may open over this frame and the next (`what` names it in the log); a soft
// one (`hard` false: the probe's arrows) is avoided like a reserved one but covered rather than
// shrinking a window.
void reserveScreenRect(const std::string& what, const ScreenRect& rect, bool hard = true);
// How much of `rect` is taken, for a fixed overlay choosing between a few spots: each pixel of a
// reserved rectangle named in `heavy` counts 10, of any other reserved rectangle or floating
// window 1 (`self` excluded; this frame's and the last's).
float screenAreaTaken(const ScreenRect& rect, std::string_view self, std::span<const std::string_view> heavy);
// How much of `rect` the reserved rectangle named `name` covers (this frame's, else the last's).
float reservedAreaOf(const ScreenRect& rect, std::string_view name);
// A floating window's size in font heights, so it scales with the UI.
struct WindowSizing {
    ImVec2 fonts;                              // preferred
    ImVec2 minimumFonts{14.0f, 8.0f};          // the smallest it is shrunk to so as to cover nothing reserved
    ImVec2 maxScreenFraction{0.6f, 0.75f};     // of the usable screen
};

// ImGui::Begin for a floating window sized and placed as above; `reserved` makes the window
// itself one that others avoid. Call ImGui::End afterwards whatever it returns.
bool beginPlacedWindow(const char* name, bool* open, const WindowSizing& sizing, ImGuiWindowFlags flags = 0,
                       bool reserved = false);
// Ends the frame: with GLINT_LOG_LAYOUT set, prints the screen's rectangles when they changed.
void endWindowLayoutFrame();
// Where ImGui keeps window positions between runs: imgui.ini beside settings.json.
std::string windowLayoutFilePath();

}  // namespace glint
