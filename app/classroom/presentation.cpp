// Presentation mode (presentation.h): the state logic (scale, which panels show), the
// high-contrast style and the large font. Drawing the panels it hides stays in editor/panels/.
#include "classroom/presentation.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

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

float effectiveUiScale(const Settings& settings) {
    return settings.presentationMode ? std::clamp(settings.presentationScale, kPresentationScaleMin, kPresentationScaleMax)
                                     : settings.uiScale;
}

bool advancedPanelsVisible(const Settings& settings) { return !settings.presentationMode; }

void togglePresentationMode(EditorState& state) {
    state.settings.presentationMode = !state.settings.presentationMode;
    saveSettings(state.settings);
    state.statusMessage = state.settings.presentationMode ? "Presentation mode on (F11 to leave)" : "Presentation mode off";
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

void applyEditorLook(const Settings& settings, const ImGuiStyle& baseStyle, ImFont* presentationFont,
                     float normalFontPixels, float presentationFontPixels) {
    const float scale = effectiveUiScale(settings);
    ImGuiStyle& style = ImGui::GetStyle();
    style = baseStyle;
    if (settings.presentationMode) makeHighContrast(style);
    style.ScaleAllSizes(scale);
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
