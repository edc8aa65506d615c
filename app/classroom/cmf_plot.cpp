// CIE 1931 matching-function plot (cmf_plot.h): axes and ticks, a spectrum strip coloured through
// the matching functions themselves, and x̄ (red), ȳ (green), z̄ (blue) as polylines.
#include "classroom/cmf_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "colour/cie_cmf.h"
#include "colour/spectral_render.h"
#include "display/display_chain.h"
#include "editor/window_placement.h"

namespace glint {
namespace {

constexpr float kCmfPlotMaxValue = 1.9f;  // z̄ peaks at about 1.78 near 445 nm

ImU32 cmfPlotDisplayColour(glm::vec3 linear) {
    const glm::vec3 clipped = glm::clamp(linear, glm::vec3(0.0f), glm::vec3(1.0f));
    return IM_COL32(static_cast<int>(encodeSrgb(clipped.r) * 255.0f + 0.5f), static_cast<int>(encodeSrgb(clipped.g) * 255.0f + 0.5f),
                    static_cast<int>(encodeSrgb(clipped.b) * 255.0f + 0.5f), 255);
}

// The plot area inside the rectangle: room for the value labels left, the title above, and the
// spectrum strip and wavelength labels below.
struct CmfPlotArea {
    float left, right, top, bottom;
};

CmfPlotArea cmfPlotArea(ImVec2 topLeft, ImVec2 size, float fontSize) {
    return {topLeft.x + fontSize * 2.6f, topLeft.x + size.x - fontSize * 0.8f, topLeft.y + fontSize * 1.6f,
            topLeft.y + size.y - fontSize * 3.4f};
}

}  // namespace

ImVec2 cmfPlotPoint(ImVec2 topLeft, ImVec2 size, float fontSize, float wavelength, float value) {
    const CmfPlotArea area = cmfPlotArea(topLeft, size, fontSize);
    return {area.left + (wavelength - kVisibleMinNanometres) / (kVisibleMaxNanometres - kVisibleMinNanometres) * (area.right - area.left),
            area.bottom - value / kCmfPlotMaxValue * (area.bottom - area.top)};
}

void drawCmfPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 size, float fontSize) {
    const auto [left, right, top, bottom] = cmfPlotArea(topLeft, size, fontSize);
    const float stripHeight = fontSize * 0.6f;
    const ImU32 axisColour = IM_COL32(200, 200, 200, 255), gridColour = IM_COL32(90, 90, 90, 255);
    drawList->AddRectFilled(topLeft, ImVec2(topLeft.x + size.x, topLeft.y + size.y), IM_COL32(20, 20, 22, 255));
    const auto toX = [&](float wavelength) { return cmfPlotPoint(topLeft, size, fontSize, wavelength, 0.0f).x; };
    const auto toY = [&](float value) { return cmfPlotPoint(topLeft, size, fontSize, kVisibleMinNanometres, value).y; };
    char label[32];
    for (float value = 0.0f; value <= 1.81f; value += 0.5f) {  // value grid
        drawList->AddLine(ImVec2(left, toY(value)), ImVec2(right, toY(value)), gridColour);
        std::snprintf(label, sizeof label, "%.1f", value);
        drawList->AddText(nullptr, fontSize, ImVec2(topLeft.x + fontSize * 0.3f, toY(value) - fontSize * 0.5f), axisColour, label);
    }
    for (int wavelength = 400; wavelength <= 750; wavelength += 50) {  // wavelength ticks
        const float x = toX(static_cast<float>(wavelength));
        drawList->AddLine(ImVec2(x, bottom), ImVec2(x, bottom + fontSize * 0.3f), axisColour);
        std::snprintf(label, sizeof label, "%d", wavelength);
        drawList->AddText(nullptr, fontSize, ImVec2(x - fontSize, bottom + stripHeight + fontSize * 0.35f), axisColour, label);
    }
    // The spectrum strip: each wavelength's own colour (its matching functions through sRGB,
    // scaled so the brightest channel is 1; out-of-gamut negatives clipped for display).
    for (float x = left; x < right; x += 1.0f) {
        const float wavelength = kVisibleMinNanometres + (x - left) / (right - left) * (kVisibleMaxNanometres - kVisibleMinNanometres);
        glm::vec3 rgb = glm::max(spectralXyzToRgb(cieColourMatching(wavelength)), glm::vec3(0.0f));
        const float brightest = std::max({rgb.r, rgb.g, rgb.b, 1e-6f});
        const float fade = std::min(1.0f, cieColourMatching(wavelength).y * 8.0f);  // dim at the ends
        rgb *= fade / brightest;
        drawList->AddRectFilled(ImVec2(x, bottom + 1.0f), ImVec2(x + 1.0f, bottom + stripHeight), cmfPlotDisplayColour(rgb));
    }
    drawList->AddLine(ImVec2(left, top), ImVec2(left, bottom), axisColour);
    drawList->AddLine(ImVec2(left, bottom), ImVec2(right, bottom), axisColour);
    const ImU32 curveColours[3] = {IM_COL32(255, 80, 80, 255), IM_COL32(80, 230, 80, 255), IM_COL32(90, 140, 255, 255)};
    const char* const names[3] = {"x", "y", "z"};  // with a bar drawn above (the font has no combining macron)
    constexpr int kCmfPlotSteps = 200;
    for (int channel = 0; channel < 3; ++channel) {
        ImVec2 points[kCmfPlotSteps + 1];
        for (int step = 0; step <= kCmfPlotSteps; ++step) {
            const float wavelength = kVisibleMinNanometres + (kVisibleMaxNanometres - kVisibleMinNanometres) * step / kCmfPlotSteps;
            points[step] = ImVec2(toX(wavelength), toY(cieColourMatching(wavelength)[channel]));
        }
        drawList->AddPolyline(points, kCmfPlotSteps + 1, curveColours[channel], 0, std::max(1.5f, fontSize * 0.12f));
        const ImVec2 namePosition(right - fontSize * (6.0f - 2.0f * channel), top - fontSize * 1.4f);
        drawList->AddText(nullptr, fontSize * 1.1f, namePosition, curveColours[channel], names[channel]);
        drawList->AddLine(ImVec2(namePosition.x, namePosition.y + fontSize * 0.15f),
                          ImVec2(namePosition.x + fontSize * 0.55f, namePosition.y + fontSize * 0.15f), curveColours[channel]);
    }
    drawList->AddText(nullptr, fontSize, ImVec2(left, top - fontSize * 1.4f), axisColour, "CIE 1931 2°");
    drawList->AddText(nullptr, fontSize, ImVec2((left + right) * 0.5f - fontSize * 4.0f, topLeft.y + size.y - fontSize * 1.15f),
                      axisColour, "wavelength λ [nm]");
}

void drawCmfWindow(bool& open) {
    if (!open) return;
    const float fontSize = ImGui::GetFontSize();
    if (beginPlacedWindow("Colour matching functions", &open, {ImVec2(32.0f, 22.0f), ImVec2(24.0f, 16.0f)})) {
        const ImVec2 origin = ImGui::GetCursorScreenPos();
        ImVec2 available = ImGui::GetContentRegionAvail();
        available.y -= ImGui::GetTextLineHeightWithSpacing() * 2.0f;
        if (available.x > fontSize * 8.0f && available.y > fontSize * 6.0f) {
            drawCmfPlot(ImGui::GetWindowDrawList(), origin, available, fontSize);
            ImGui::Dummy(available);
        }
        ImGui::TextWrapped("Analytic multi-lobe fit of Wyman, Sloan & Shirley (JCGT 2013) to the CIE 1931 2° observer; "
                           "the green curve (y-bar) is the luminous efficiency V(λ), 683 lm/W at 555 nm.");
    }
    ImGui::End();
}

}  // namespace glint
