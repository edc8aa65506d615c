// The lights section: the list of lights (enable, select), add / duplicate / remove / solo, and
// the selected light's type (directional, point, spot, ambient), colour (sRGB picker, stored
// linear) and strength in radiometric units (irradiance M [W/m²], radiant power Φ [W] or
// radiance L_a) with the photometric value beside (lx, lm and cd, nit), direction, position,
// spot cone, the optional classic attenuation and the shadow settings (shadow_widgets.h).
// Values that make no sense are refused with a message.
#include <imgui.h>

#include "classroom/presentation.h"
#include <imgui_stdlib.h>

#include <cmath>
#include <string>

#include "editor/light_handles.h"
#include "editor/panels/panels.h"
#include "editor/panels/shadow_widgets.h"
#include "editor/panels/typed_numbers.h"
#include "editor/panels/widgets.h"
#include "light/light_type_name.h"
#include "light/photometry.h"

namespace glint {
namespace {

Light newLight(LightType type, const Scene& scene) {
    Light light;
    light.type = type;
    light.name = std::string(lightTypeName(type)) + " " + std::to_string(scene.lights.size() + 1);
    // Where the camera sees it (light_handles.h), aimed at what the camera looks at.
    light.position = newLightPosition(scene.camera);
    light.direction = glm::normalize(scene.camera.target - light.position);
    return light;
}

// Appends a light as one edit and selects it.
void addLight(EditorState& state, Light light, const char* label) {
    state.session.change(label).lights.push_back(std::move(light));
    state.selectedLight = static_cast<int>(state.session.scene().lights.size()) - 1;
}

void drawLightList(EditorState& state) {
    const Scene& scene = state.session.scene();
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        bool enabled = scene.lights[i].enabled;
        if (ImGui::Checkbox("##enabled", &enabled))
            state.session.change(enabled ? "Enable light" : "Disable light").lights[i].enabled = enabled;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Enabled");
        ImGui::SameLine();
        const std::string label = scene.lights[i].name + "  (" + lightTypeName(scene.lights[i].type) + ")";
        if (ImGui::Selectable(label.c_str(), state.selectedLight == static_cast<int>(i))) state.selectedLight = static_cast<int>(i);
        ImGui::PopID();
    }
    if (scene.lights.empty()) ImGui::TextDisabled("No lights: the scene is dark.");
}

void drawLightButtons(EditorState& state) {
    const Scene& scene = state.session.scene();
    const bool room = scene.lights.size() < static_cast<size_t>(kMaxLights);
    const bool selected = state.selectedLight < static_cast<int>(scene.lights.size());
    ImGui::BeginDisabled(!room);
    if (ImGui::Button("+ Directional")) addLight(state, newLight(LightType::Directional, scene), "Add light");
    sameLineIfFits(buttonWidth("+ Point"));
    if (ImGui::Button("+ Point")) addLight(state, newLight(LightType::Point, scene), "Add light");
    sameLineIfFits(buttonWidth("+ Spot"));
    if (ImGui::Button("+ Spot")) addLight(state, newLight(LightType::Spot, scene), "Add light");
    if (ImGui::Button("+ Ambient")) addLight(state, newLight(LightType::Ambient, scene), "Add light");
    sameLineIfFits(buttonWidth("Duplicate"));
    if (ImGui::Button("Duplicate") && selected) {
        Light copy = scene.lights[state.selectedLight];
        copy.name += " copy";
        if (shadowedLightsOtherThan(scene, -1) >= kMaxShadowedLights) copy.castsShadows = false;  // the limit
        addLight(state, std::move(copy), "Duplicate light");
    }
    ImGui::EndDisabled();
    if (!room && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
        ImGui::Text("%s.", lightLimitExplanation().c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    ImGui::BeginDisabled(!selected);
    sameLineIfFits(buttonWidth("Remove"));
    if (ImGui::Button("Remove")) {
        auto& lights = state.session.change("Remove light").lights;
        lights.erase(lights.begin() + state.selectedLight);
        state.selectedLight = std::max(0, state.selectedLight - 1);
    }
    if (ImGui::Button("Solo")) {
        auto& lights = state.session.change("Solo light").lights;
        for (size_t i = 0; i < lights.size(); ++i) lights[i].enabled = static_cast<int>(i) == state.selectedLight;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Enable only the selected light");
    sameLineIfFits(buttonWidth("All on"));
    if (ImGui::Button("All on")) {
        auto& lights = state.session.change("Enable all lights").lights;
        for (Light& light : lights) light.enabled = true;
    }
    ImGui::EndDisabled();
}

// Widgets on a copy of the light; returns true when the copy changed and is valid.
bool drawLightEditor(Light& light, std::string& refusal) {
    bool changed = false;
    ImGui::InputText("Name", &light.name);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    int type = static_cast<int>(light.type);
    const std::string typeLabel = placeLabel("Type", comboWidth(ImGui::CalcTextSize("directional").x));
    if (ImGui::Combo(typeLabel.c_str(), &type, "directional\0point\0spot\0ambient\0")) {
        light.type = static_cast<LightType>(type);
        changed = true;
    }
    changed |= linearColorEdit("Colour", light.color, "Linear-RGB filter on the light's strength (shown sRGB-encoded)");
    const LightPhotometry photometry = lightPhotometry(light);
    constexpr float kHuge = 1e9f;
    switch (light.type) {
        case LightType::Directional:
            changed |= boundedDrag("Irradiance M", light.irradiance, 0.0f, kHuge, "%.3f W/m²", refusal,
                                   "Irradiance on a surface facing the light, W/m²");
            ImGui::TextDisabled("  = %.4g lx (illuminance)", photometry.lux);
            break;
        case LightType::Point:
        case LightType::Spot:
            changed |= boundedDrag("Power Φ", light.power, 0.0f, kHuge, "%.2f W", refusal,
                                   "Radiant power of the isotropic point light: E = Φ/(4πd²)·cos θ");
            ImGui::TextDisabled("  = %.4g lm, I = %.4g cd%s", photometry.lumens, photometry.candelas,
                                light.type == LightType::Spot ? " on the axis" : "");
            break;
        case LightType::Ambient:
            changed |= boundedDrag("Radiance L_a", light.ambientRadiance, 0.0f, kHuge, "%.3f W/(sr·m²)", refusal,
                                   "Uniform radiance arriving from every direction");
            ImGui::TextDisabled("  = %.4g nit (luminance)", photometry.nits);
            break;
    }
    if (light.type == LightType::Directional || light.type == LightType::Spot) {
        glm::vec3 direction = light.direction;
        const std::string shown = placeLabel("Direction", threeNumbersWidth(false));
        if (editNumbers("Direction", &direction.x, 3, [&](float* typed) { return ImGui::DragFloat3(shown.c_str(), typed, 0.01f, -1.0f, 1.0f, "%.2f"); })) {
            if (glm::length(direction) > 1e-4f && std::isfinite(glm::length(direction)))
                light.direction = glm::normalize(direction), changed = true, refusal.clear();
            else refusal = "Direction must not be zero";
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The direction the light travels (normalised)");
    }
    if (light.type == LightType::Point || light.type == LightType::Spot) {
        glm::vec3 position = light.position;
        const std::string shown = placeLabel("Position m", threeNumbersWidth(false));
        if (editNumbers("Position m", &position.x, 3, [&](float* typed) { return ImGui::DragFloat3(shown.c_str(), typed, 0.02f, 0.0f, 0.0f, "%.2f"); })) {
            if (std::isfinite(position.x + position.y + position.z)) light.position = position, changed = true;
        }
    }
    if (light.type == LightType::Spot) {
        changed |= boundedDrag("Cone half angle", light.coneHalfAngleDegrees, 0.01f, 90.0f, "%.1f°", refusal,
                               "θ_c: nothing is lit outside the cone");
        changed |= boundedDrag("Falloff a", light.falloffExponent, 0.0f, 10000.0f, "%.2f", refusal,
                               "Hearn-Baker falloff cos^a α inside the cone");
        changed |= boundedDrag("Edge width", light.edgeWidthDegrees, 0.0f, light.coneHalfAngleDegrees, "%.1f°", refusal,
                               "Smooth edge inside the cone, w ≤ θ_c");
    }
    if (light.type == LightType::Point || light.type == LightType::Spot) {
        changed |= ImGui::Checkbox("Classic attenuation (not physical)", &light.attenuation.enabled);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("1/(a0 + a1·d + a2·d²) instead of the inverse-square law 1/d²");
        if (light.attenuation.enabled) {
            glm::vec3 coefficients = light.attenuation.coefficients;
            const std::string shown = placeLabel("a0 a1 a2", threeNumbersWidth(false));
            if (editNumbers("a0 a1 a2", &coefficients.x, 3, [&](float* typed) { return ImGui::DragFloat3(shown.c_str(), typed, 0.01f, 0.0f, 0.0f, "%.3f"); })) {
                const bool valid = coefficients.x >= 0 && coefficients.y >= 0 && coefficients.z >= 0 &&
                                   coefficients.x + coefficients.y + coefficients.z > 0;
                if (valid) light.attenuation.coefficients = coefficients, changed = true, refusal.clear();
                else refusal = "Attenuation coefficients must be ≥ 0 and not all zero";
            }
        }
    }
    return changed;
}

}  // namespace

void drawLightsSection(EditorState& state) {
    drawLightList(state);
    drawLightButtons(state);
    const Scene& scene = state.session.scene();
    if (state.selectedLight >= static_cast<int>(scene.lights.size())) return;
    ImGui::Separator();
    ImGui::PushID(state.selectedLight);  // numbers typed for one light never land on another
    Light edited = scene.lights[state.selectedLight];
    bool changed = drawLightEditor(edited, state.lightPanelMessage.text());
    if (advancedPanelsVisible(state.settings))  // presentation mode hides shadow-map settings
        changed |= drawShadowSettings(edited, shadowedLightsOtherThan(scene, state.selectedLight), state.lightPanelMessage.text());
    if (changed) state.session.change("Edit light").lights[state.selectedLight] = std::move(edited);
    if (!state.lightPanelMessage.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", state.lightPanelMessage.c_str());
    ImGui::PopID();
}

}  // namespace glint
