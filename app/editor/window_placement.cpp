// Window placement (see window_placement.h).
// Sections: geometry · the frame's rectangles · placed windows · the layout log.
#include "editor/window_placement.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "editor/recovery.h"

namespace glint {

// --- geometry ----------------------------------------------------------------------------------

float ScreenRect::overlapArea(const ScreenRect& other) const {
    const float w = std::min(right(), other.right()) - std::max(x, other.x);
    const float h = std::min(bottom(), other.bottom()) - std::max(y, other.y);
    return w > 0.0f && h > 0.0f ? w * h : 0.0f;
}

bool ScreenRect::contains(const ScreenRect& other) const {
    constexpr float kSlack = 0.5f;
    return other.x >= x - kSlack && other.y >= y - kSlack && other.right() <= right() + kSlack &&
           other.bottom() <= bottom() + kSlack;
}

namespace {

struct Spot {
    ImVec2 position;
    float reservedArea = 0.0f;  // pixels of reserved obstacles covered
    float cost = 0.0f;          // weighted pixels of the others
    bool betterThan(const Spot& other) const {
        if (reservedArea != other.reservedArea) return reservedArea < other.reservedArea - 0.5f;
        return cost < other.cost - 0.5f;
    }
};

Spot bestSpot(ImVec2 size, const ScreenRect& bounds, std::span<const PlacementObstacle> obstacles) {
    std::vector<ImVec2> candidates = {{bounds.right() - size.x, bounds.y},
                                      {bounds.right() - size.x, bounds.bottom() - size.y},
                                      {bounds.x, bounds.bottom() - size.y},
                                      {bounds.x, bounds.y}};
    for (const PlacementObstacle& obstacle : obstacles) {
        const ScreenRect& o = obstacle.rect;
        for (const ImVec2 at : {ImVec2(o.right(), o.y), ImVec2(o.x - size.x, o.y), ImVec2(o.x, o.bottom()),
                                ImVec2(o.x, o.y - size.y), ImVec2(o.right(), o.bottom() - size.y),
                                ImVec2(o.x - size.x, o.bottom() - size.y), ImVec2(o.right() - size.x, o.bottom()),
                                ImVec2(o.right() - size.x, o.y - size.y)})
            candidates.push_back(at);
    }
    constexpr int kGrid = 12;
    for (int row = 0; row <= kGrid; ++row)
        for (int column = 0; column <= kGrid; ++column)
            candidates.emplace_back(bounds.x + (bounds.width - size.x) * column / kGrid,
                                    bounds.y + (bounds.height - size.y) * row / kGrid);
    Spot best{ImVec2(bounds.x, bounds.y), 1e30f, 1e30f};
    for (ImVec2 at : candidates) {
        at.x = std::clamp(at.x, bounds.x, bounds.right() - size.x);
        at.y = std::clamp(at.y, bounds.y, bounds.bottom() - size.y);
        const ScreenRect rect{at.x, at.y, size.x, size.y};
        Spot spot{at};
        for (const PlacementObstacle& obstacle : obstacles) {
            const float area = rect.overlapArea(obstacle.rect);
            if (obstacle.reserved) spot.reservedArea += area;
            else spot.cost += obstacle.weight * area;
        }
        if (spot.betterThan(best)) best = spot;
    }
    return best;
}

}  // namespace

WindowPlacement placeWindow(ImVec2 size, ImVec2 minimumSize, const ScreenRect& bounds,
                            std::span<const PlacementObstacle> obstacles) {
    size = ImVec2(std::min(size.x, bounds.width), std::min(size.y, bounds.height));
    WindowPlacement placement{bestSpot(size, bounds, obstacles).position, size};
    for (const float shrink : {1.0f, 0.85f, 0.7f, 0.55f, 0.4f}) {
        const ImVec2 tried(std::max(size.x * shrink, std::min(minimumSize.x, size.x)),
                           std::max(size.y * shrink, std::min(minimumSize.y, size.y)));
        const Spot spot = bestSpot(tried, bounds, obstacles);
        if (spot.reservedArea < 1.0f) return {spot.position, tried};
    }
    return placement;  // covers something reserved at every size: the full size where it covers least
}

namespace {

// --- the frame's rectangles --------------------------------------------------------------------

constexpr float kSoftReservedWeight = 20.0f;  // a reserved rectangle that may be covered (the probe's arrows)
constexpr float kWindowWeight = 10.0f;      // another floating window
constexpr float kMaterialColumnWeight = 8.0f;  // the material column: tweaked while a window shows the effect
constexpr float kSceneColumnWeight = 4.0f;     // the scene column
constexpr float kViewMiddleWeight = 1.0f;   // the middle of the 3D view, where the objects usually are

struct NamedRect {
    std::string name;
    ScreenRect rect;
    bool hard = true;  // a reserved rectangle no window may cover while it fits elsewhere
};

struct LayoutFrame {
    ScreenRect usable, viewport;
    std::uint64_t layout = 0;
    std::vector<NamedRect> reserved, previousReserved;
    std::vector<NamedRect> windows, previousWindows;  // placed windows, this frame and the last
    std::string lastLog;
};
LayoutFrame gFrame;

struct WindowRecord {
    std::uint64_t layout = ~0ull;  // the layout it was last placed for
    int settleFrames = 0;          // frames after a placement in which it may still grow (auto-fit)
    bool seen = false;             // shown before in this run
};
std::map<std::string, WindowRecord, std::less<>> gWindows;

bool overlapsReserved(const ScreenRect& rect, const std::string& self) {
    for (const auto* list : {&gFrame.reserved, &gFrame.previousReserved})
        for (const NamedRect& reserved : *list)
            if (reserved.hard && reserved.name != self && rect.overlapArea(reserved.rect) > 1.0f) return true;
    return false;
}

std::vector<PlacementObstacle> obstaclesFor(const std::string& self) {
    std::vector<PlacementObstacle> obstacles;
    for (const auto* list : {&gFrame.reserved, &gFrame.previousReserved})
        for (const NamedRect& reserved : *list)
            if (reserved.name != self)
                obstacles.push_back({reserved.rect, reserved.hard ? 1.0f : kSoftReservedWeight, reserved.hard});
    for (const NamedRect& window : gFrame.previousWindows)
        if (window.name != self) obstacles.push_back({window.rect, kWindowWeight});
    const ScreenRect& u = gFrame.usable;
    const ScreenRect& v = gFrame.viewport;
    obstacles.push_back({{u.x, u.y, v.x - u.x, u.height}, kSceneColumnWeight});
    obstacles.push_back({{v.right(), u.y, u.right() - v.right(), u.height}, kMaterialColumnWeight});
    obstacles.push_back({{v.x + v.width * 0.25f, v.y + v.height * 0.2f, v.width * 0.5f, v.height * 0.6f}, kViewMiddleWeight});
    return obstacles;
}

}  // namespace

void beginWindowLayoutFrame(const ScreenRect& usable, const ScreenRect& viewport, std::uint64_t layout) {
    gFrame.usable = usable;
    gFrame.viewport = viewport;
    gFrame.layout = layout;
    gFrame.previousReserved = std::move(gFrame.reserved);
    gFrame.reserved.clear();
    gFrame.previousWindows = std::move(gFrame.windows);
    gFrame.windows.clear();
}

void reserveScreenRect(const std::string& what, const ScreenRect& rect, bool hard) {
    gFrame.reserved.push_back({what, rect, hard});
}

float reservedAreaOf(const ScreenRect& rect, std::string_view name) {
    for (const auto* list : {&gFrame.reserved, &gFrame.previousReserved})
        for (const NamedRect& reserved : *list)
            if (reserved.name == name) return rect.overlapArea(reserved.rect);
    return 0.0f;
}

float screenAreaTaken(const ScreenRect& rect, std::string_view self, std::span<const std::string_view> heavy) {
    float area = 0.0f;
    for (const auto* list : {&gFrame.reserved, &gFrame.previousReserved, &gFrame.windows, &gFrame.previousWindows})
        for (const NamedRect& taken : *list) {
            if (taken.name == self) continue;
            const bool weighty = std::find(heavy.begin(), heavy.end(), taken.name) != heavy.end();
            area += (weighty ? 10.0f : 1.0f) * rect.overlapArea(taken.rect);
        }
    return area;
}

// --- placed windows ----------------------------------------------------------------------------

bool beginPlacedWindow(const char* name, bool* open, const WindowSizing& sizing, ImGuiWindowFlags flags, bool reserved) {
    WindowRecord& record = gWindows[name];
    const bool newLayout = record.layout != gFrame.layout;
    // A position from the last run (imgui.ini) is kept when it still covers nothing reserved.
    const bool remembered = !record.seen && ImGui::FindWindowSettings(ImHashStr(name)) != nullptr;
    const ScreenRect& usable = gFrame.usable;
    const float font = ImGui::GetFontSize();
    const ImVec2 size(std::min(sizing.fonts.x * font, usable.width * sizing.maxScreenFraction.x),
                      std::min(sizing.fonts.y * font, usable.height * sizing.maxScreenFraction.y));
    if (newLayout && !remembered) ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(font * 8.0f, usable.width), 0.0f), ImVec2(usable.width, usable.height));
    const bool shown = ImGui::Begin(name, open, flags);
    ScreenRect rect{ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowWidth(), ImGui::GetWindowHeight()};
    const bool misplaced = !usable.contains(rect) || overlapsReserved(rect, name);
    const bool place = (newLayout && !remembered) || ((newLayout || record.settleFrames > 0 || ImGui::IsWindowAppearing()) && misplaced);
    if (newLayout) record.settleFrames = 3;
    else if (record.settleFrames > 0) --record.settleFrames;
    if (place) {
        const std::vector<PlacementObstacle> obstacles = obstaclesFor(name);
        const WindowPlacement placement =
            placeWindow(ImVec2(rect.width, rect.height), ImVec2(sizing.minimumFonts.x * font, sizing.minimumFonts.y * font), usable,
                        obstacles);
        ImGui::SetWindowPos(placement.position);
        if (placement.size.x != rect.width || placement.size.y != rect.height) ImGui::SetWindowSize(placement.size);
        rect = {placement.position.x, placement.position.y, placement.size.x, placement.size.y};
    }
    record.layout = gFrame.layout;
    record.seen = true;
    gFrame.windows.push_back({name, rect});
    if (reserved) reserveScreenRect(name, rect);
    return shown;
}

// --- the layout log ----------------------------------------------------------------------------

void endWindowLayoutFrame() {
    static const bool log = std::getenv("GLINT_LOG_LAYOUT") != nullptr;
    if (!log) return;
    const auto line = [](const char* kind, const std::string& name, const ScreenRect& r) {
        char text[320];
        std::snprintf(text, sizeof text, "glint layout: %s \"%s\" %.0f %.0f %.0f %.0f\n", kind, name.c_str(), r.x, r.y, r.width,
                      r.height);
        return std::string(text);
    };
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    std::string text = line("screen", "screen", {0.0f, 0.0f, display.x, display.y});
    text += line("viewport", "viewport", gFrame.viewport);
    for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows)
        if (window->Active && !window->Hidden && !(window->Flags & ImGuiWindowFlags_ChildWindow) &&
            std::string_view(window->Name).rfind("Debug##", 0) != 0)  // ImGui's implicit window, never drawn
            text += line("window", window->Name, {window->Pos.x, window->Pos.y, window->Size.x, window->Size.y});
    for (const NamedRect& reserved : gFrame.reserved) text += line("reserved", reserved.name, reserved.rect);
    if (text == gFrame.lastLog) return;
    gFrame.lastLog = text;
    // One write for the whole block, so no other thread's output lands inside it.
    text += "glint layout: end\n";
    std::fflush(stderr);
    for (size_t written = 0; written < text.size();) {
        const ssize_t count = ::write(STDERR_FILENO, text.data() + written, text.size() - written);
        if (count <= 0) break;
        written += static_cast<size_t>(count);
    }
}

std::string windowLayoutFilePath() { return stateDirectory() + "/imgui.ini"; }

}  // namespace glint
