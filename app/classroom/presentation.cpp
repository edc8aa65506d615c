// Presentation mode (presentation.h): the state logic (scale, which panels show), the
// high-contrast style and the large font. Drawing the panels it hides stays in editor/panels/.
#include "classroom/presentation.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "classroom/lessons_view.h"

namespace glint {
namespace {

// White on black with saturated yellow accents: legible on a washed-out projector.
void makeHighContrast(ImGuiStyle& style) {
    ImGui::StyleColorsDark(&style);
    ImVec4* colors = style.Colors;
    const ImVec4 black(0.0f, 0.0f, 0.0f, 1.0f), white(1.0f, 1.0f, 1.0f, 1.0f), yellow(1.0f, 0.85f, 0.0f, 1.0f);
    const ImVec4 darkGrey(0.15f, 0.15f, 0.15f, 1.0f), midGrey(0.3f, 0.3f, 0.3f, 1.0f);
    colors[ImGuiCol_Text] = white;
    colors[ImGuiCol_TextDisabled] = ImVec4(0.8f, 0.8f, 0.8f, 1.0f);
    colors[ImGuiCol_WindowBg] = black;
    colors[ImGuiCol_ChildBg] = black;
    colors[ImGuiCol_PopupBg] = black;
    colors[ImGuiCol_MenuBarBg] = black;
    colors[ImGuiCol_Border] = white;
    colors[ImGuiCol_FrameBg] = darkGrey;
    colors[ImGuiCol_FrameBgHovered] = midGrey;
    colors[ImGuiCol_FrameBgActive] = midGrey;
    colors[ImGuiCol_TitleBg] = black;
    colors[ImGuiCol_TitleBgActive] = darkGrey;
    colors[ImGuiCol_Header] = midGrey;
    colors[ImGuiCol_HeaderHovered] = ImVec4(0.45f, 0.4f, 0.0f, 1.0f);
    colors[ImGuiCol_HeaderActive] = ImVec4(0.6f, 0.5f, 0.0f, 1.0f);
    colors[ImGuiCol_Button] = midGrey;
    colors[ImGuiCol_ButtonHovered] = ImVec4(0.45f, 0.4f, 0.0f, 1.0f);
    colors[ImGuiCol_ButtonActive] = ImVec4(0.6f, 0.5f, 0.0f, 1.0f);
    colors[ImGuiCol_SliderGrab] = yellow;
    colors[ImGuiCol_SliderGrabActive] = white;
    colors[ImGuiCol_CheckMark] = yellow;
    colors[ImGuiCol_Separator] = white;
    style.FrameBorderSize = 1.0f;
    style.WindowBorderSize = 1.0f;
}

}  // namespace

float effectiveUiScale(const Settings& settings, float displayHeight) {
    if (!settings.presentationMode) return settings.uiScale;
    const float scale = std::clamp(settings.presentationScale, kPresentationScaleMin, kPresentationScaleMax);
    constexpr float kReferenceHeight = 1080.0f;  // the presentation scale is chosen for a 1080-pixel-high screen
    if (displayHeight <= 0.0f || displayHeight >= kReferenceHeight) return scale;
    return std::max(1.0f, scale * displayHeight / kReferenceHeight);
}

bool advancedPanelsVisible(const Settings& settings) { return !settings.presentationMode; }

void togglePresentationMode(EditorState& state) {
    state.settings.presentationMode = !state.settings.presentationMode;
    saveSettings(state.settings);
    state.statusMessage = state.settings.presentationMode ? "Presentation mode on (F11 to leave)" : "Presentation mode off";
}

void startPresentation(EditorState& state, const std::string& lessonListPath) {
    if (!state.settings.presentationMode) togglePresentationMode(state);  // as F11: kept until F11 leaves it
    state.classroom.lessonListPath = lessonListPath;
    openLesson(state, 0);
}

float columnWidthLimit(const Settings& settings) {
    return (settings.presentationMode ? kPresentationColumnFraction : 0.4f) * ImGui::GetIO().DisplaySize.x;
}

void keepPresentationColumns(EditorState& state) {
    static bool presenting = false, leftBefore = true, rightBefore = true, leftShown = false;
    if (state.settings.presentationMode != presenting) {
        presenting = state.settings.presentationMode;
        if (presenting) {
            leftBefore = state.showLeftPanel;
            rightBefore = state.showRightPanel;
            state.showLeftPanel = state.showRightPanel = false;
        } else {
            state.showLeftPanel = leftBefore;
            state.showRightPanel = rightBefore;
        }
    } else if (presenting && state.showLeftPanel && state.showRightPanel) {
        // The one opened last stays.
        if (leftShown) state.showLeftPanel = false;
        else state.showRightPanel = false;
    }
    leftShown = state.showLeftPanel;
}

float collapsedColumnStripWidth(const Settings& settings) {
    // Never narrower than ImGui's smallest window, which the strip would otherwise outgrow.
    return settings.presentationMode ? std::max(std::round(ImGui::GetFontSize() * 1.2f), ImGui::GetStyle().WindowMinSize.x) : 0.0f;
}

void drawCollapsedColumnStrips(EditorState& state, float top, float height, float windowWidth) {
    const float width = collapsedColumnStripWidth(state.settings);
    if (width <= 0.0f) return;
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    const auto strip = [&](const char* name, float x, const char* arrow, const char* tip, bool& show) {
        if (show) return;
        ImGui::SetNextWindowPos(ImVec2(x, top));
        ImGui::SetNextWindowSize(ImVec2(width, height));
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
        if (ImGui::Begin(name, nullptr, flags)) {
            if (ImGui::Button(arrow, ImVec2(width, height))) show = true;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
        }
        ImGui::End();
        ImGui::PopStyleVar();
    };
    strip("##scene strip", 0.0f, "›", "Show the scene column (lights, display, camera)", state.showLeftPanel);
    strip("##material strip", windowWidth - width, "‹", "Show the material column", state.showRightPanel);
}

void fitWindowToPresentation(GLFWwindow* window, bool presenting) {
    static bool fitted = false;
    static int savedX = 0, savedY = 0, savedWidth = 0, savedHeight = 0;
    if (presenting && !fitted) {
        GLFWmonitor* monitor = glfwGetPrimaryMonitor();
        if (!monitor) return;
        int x = 0, y = 0, width = 0, height = 0;
        glfwGetMonitorWorkarea(monitor, &x, &y, &width, &height);
        if (width <= 0 || height <= 0) return;
        glfwGetWindowPos(window, &savedX, &savedY);
        glfwGetWindowSize(window, &savedWidth, &savedHeight);
        glfwSetWindowPos(window, x, y);
        glfwSetWindowSize(window, width, height);
        fitted = true;
    } else if (!presenting && fitted) {
        glfwSetWindowSize(window, savedWidth, savedHeight);
        glfwSetWindowPos(window, savedX, savedY);
        fitted = false;
    }
}

std::uint64_t windowLayoutKey(float uiScale, bool presenting, bool leftColumn, bool rightColumn, float displayWidth,
                              float displayHeight) {
    std::uint64_t key = (presenting ? 1 : 0) | (leftColumn ? 2 : 0) | (rightColumn ? 4 : 0);
    for (const float value : {uiScale * 100.0f, displayWidth, displayHeight})
        key = key * 1'000'003ull + static_cast<std::uint64_t>(std::lround(value));
    return key;
}

ImFont* loadPresentationFont(float pixelSize) {
    std::error_code error;
    if (!std::filesystem::exists(kPresentationFontPath, error)) {
        std::fprintf(stderr, "glint: presentation mode: %s is missing (install Debian's fonts-dejavu-core); "
                             "the normal font is scaled instead\n", kPresentationFontPath);
        return nullptr;
    }
    static const ImWchar ranges[] = {0x0020, 0x017F, 0x0370, 0x03FF, 0x2000, 0x209F, 0x2190, 0x22FF, 0x25CF, 0x25CF, 0};
    return ImGui::GetIO().Fonts->AddFontFromFileTTF(kPresentationFontPath, pixelSize, nullptr, ranges);
}

void applyEditorLook(const Settings& settings, float displayHeight, const ImGuiStyle& baseStyle, ImFont* presentationFont,
                     float normalFontPixels, float presentationFontPixels) {
    const float scale = effectiveUiScale(settings, displayHeight);
    ImGuiStyle& style = ImGui::GetStyle();
    style = baseStyle;
    if (settings.presentationMode) makeHighContrast(style);
    style.ScaleAllSizes(scale);
    style.WindowMinSize = baseStyle.WindowMinSize;  // a scaled minimum made the status bar taller than its row
    ImGuiIO& io = ImGui::GetIO();
    if (settings.presentationMode && presentationFont) {
        io.FontDefault = presentationFont;  // rasterised large: crisp instead of a magnified small font
        io.FontGlobalScale = scale * normalFontPixels / presentationFontPixels;
    } else {
        io.FontDefault = nullptr;  // the atlas's first font
        io.FontGlobalScale = scale;
    }
}

}  // namespace glint
