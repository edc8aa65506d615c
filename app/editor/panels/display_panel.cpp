// The display section: exposure (stops), tone map (none, Reinhard, ACES filmic), the transfer
// function (sRGB or a pure gamma), and the background (a constant radiance or the sky
// gradient), then the Environment section (environment_section.cpp). Each change goes through
// the edit API.
#include <imgui.h>

#include "classroom/presentation.h"

#include "editor/panels/panels.h"
#include "editor/panels/widgets.h"

namespace glint {

void drawDisplaySection(EditorState& state) {
    const Scene& scene = state.session.scene();
    DisplaySettings display = scene.display;
    bool changed = false;
    changed |= ImGui::SliderFloat("Exposure", &display.exposureStops, -10.0f, 10.0f, "%+.2f EV");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Radiance is multiplied by 2^EV before encoding");
    int toneMap = static_cast<int>(display.toneMap);
    if (ImGui::Combo("Tone map", &toneMap, "none (clip)\0Reinhard\0ACES filmic\0")) {
        display.toneMap = static_cast<ToneMap>(toneMap);
        changed = true;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("none: values above 1 clip · Reinhard: x/(1+x) · ACES filmic: Narkowicz's 2015 fit");
    int transfer = display.transfer == Transfer::Srgb ? 0 : 1;
    if (ImGui::Combo("Encoding", &transfer, "sRGB\0gamma\0")) {
        display.transfer = transfer == 0 ? Transfer::Srgb : Transfer::Gamma;
        changed = true;
    }
    if (display.transfer == Transfer::Gamma) {
        float gamma = display.gamma;
        if (ImGui::SliderFloat("Gamma", &gamma, 1.0f, 3.0f, "%.2f")) {
            if (gamma > 0.0f && std::isfinite(gamma)) display.gamma = gamma, changed = true;
        }
    }
    if (changed) state.session.change("Edit display").display = display;

    Background background = scene.background;
    bool backgroundChanged = false;
    int kind = background.kind == BackgroundKind::Constant ? 0 : 1;
    if (ImGui::Combo("Background", &kind, "constant\0sky gradient\0")) {
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
}

}  // namespace glint
