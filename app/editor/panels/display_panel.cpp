// The display section: exposure (stops), tone map (none, Reinhard, ACES filmic, PBR Neutral), the
// transfer function (sRGB, a pure gamma, or none), the classroom's intensity levels, ordered
// dither and levels ramp (core/display/quantisation.h), MSAA samples, and the background (a constant radiance or the sky
// gradient), then the Environment section (environment_section.cpp). Each change goes through
// the edit API.
#include <imgui.h>

#include "classroom/presentation.h"

#include "editor/panels/panels.h"
#include "editor/panels/typed_numbers.h"
#include "editor/panels/widgets.h"

namespace glint {
namespace {

// Levels, dither and the ramp strip (the classroom's display lessons); true when one changed.
bool drawQuantisationWidgets(DisplaySettings& display, std::string& refusal) {
    bool changed = false;
    int levels = display.levels;
    if (ImGui::SliderInt("Levels", &levels, 2, 256)) {
        if (levels >= 2 && levels <= 256) display.levels = levels, changed = true, refusal.clear();
        else refusal = "Levels: " + std::to_string(levels) + " refused; it must lie in [2, 256]";
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Intensity levels per channel after encoding (256: ordinary 8-bit output)");
    int dither = static_cast<int>(display.dither);
    if (comboBox("Dither", &dither, "none\0Bayer 2x2\0Bayer 4x4\0halftone (clustered dot)\0")) {
        display.dither = static_cast<Dither>(dither);
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Ordered dither added before quantising to the levels (Bayer 1973; clustered-dot screen)");
    changed |= ImGui::Checkbox("Levels ramp", &display.levelsRamp);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Bottom eighth of the image: a grey radiance ramp 0..1 through the same chain");
    return changed;
}

}  // namespace

void drawDisplaySection(EditorState& state) {
    const Scene& scene = state.session.scene();
    DisplaySettings display = scene.display;
    bool changed = false;
    changed |= editNumbers("Exposure", &display.exposureStops, 1, [](float* typed) { return ImGui::SliderFloat("Exposure", typed, -10.0f, 10.0f, "%+.2f EV"); });
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Radiance is multiplied by 2^EV before encoding");
    int toneMap = static_cast<int>(display.toneMap);
    if (comboBox("Tone map", &toneMap, "none (clip)\0Reinhard\0ACES filmic\0PBR Neutral\0")) {
        display.toneMap = static_cast<ToneMap>(toneMap);
        changed = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("none: values above 1 clip · Reinhard: x/(1+x) · ACES filmic: Narkowicz's 2015 fit · "
                          "PBR Neutral: Khronos, keeps hue and saturation");
    int transfer = static_cast<int>(display.transfer);
    if (comboBox("Encoding", &transfer, "sRGB\0gamma\0linear (gamma off)\0")) {
        display.transfer = static_cast<Transfer>(transfer);
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("sRGB: IEC 61966-2-1 · gamma: value^(1/γ) · linear: no encoding");
    if (display.transfer == Transfer::Gamma)
        changed |= boundedDrag("Gamma", display.gamma, 0.1f, 10.0f, "%.2f", state.displayPanelMessage.text(), "γ: the encoded value is value^(1/γ)");
    changed |= drawQuantisationWidgets(display, state.displayPanelMessage.text());
    if (!state.displayPanelMessage.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", state.displayPanelMessage.c_str());
    if (changed) state.session.change("Edit display").display = display;

    Background background = scene.background;
    bool backgroundChanged = false;
    int kind = background.kind == BackgroundKind::Constant ? 0 : 1;
    if (comboBox("Background", &kind, "constant\0sky gradient\0")) {
        background.kind = kind == 0 ? BackgroundKind::Constant : BackgroundKind::Sky;
        backgroundChanged = true;
    }
    if (background.kind == BackgroundKind::Constant) {
        backgroundChanged |= linearColorEdit("Radiance", background.color, "Radiance seen where no object is hit (shown sRGB-encoded)");
    } else {
        backgroundChanged |= linearColorEdit("Zenith", background.zenith, "Sky radiance straight up (+y)");
        backgroundChanged |= linearColorEdit("Horizon", background.horizon, "Sky radiance at the horizon");
        backgroundChanged |= linearColorEdit("Ground", background.ground, "Radiance straight down");
    }
    if (backgroundChanged) state.session.change("Edit background").background = background;
    if (advancedPanelsVisible(state.settings)) drawEnvironmentSection(state);  // hidden in presentation mode
    // Anti-aliasing: the scene's MSAA samples; a count this OpenGL lacks renders with the most it has.
    static constexpr int kSampleCounts[] = {1, 2, 4, 8, 16};
    int sampleChoice = 0;
    while (sampleChoice < 4 && kSampleCounts[sampleChoice] < scene.msaaSamples) ++sampleChoice;
    if (comboBox("Anti-aliasing", &sampleChoice, "off\0MSAA 2x\0MSAA 4x\0MSAA 8x\0MSAA 16x\0"))
        state.session.change("Edit anti-aliasing").msaaSamples = kSampleCounts[sampleChoice];
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Multisample anti-aliasing; the exact sphere's edge is covered analytically per sample");
    if (!state.samplesNote.empty()) ImGui::TextDisabled("%s", state.samplesNote.c_str());
}

}  // namespace glint
