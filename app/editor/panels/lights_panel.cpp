// The lights section: the list of lights (enable, select), add / duplicate / remove / solo, and
// the selected light's type, colour (sRGB picker, stored linear) and strength in radiometric
// units (irradiance M [W/m²] or radiant power Φ [W]), direction or position. Values that make
// no sense (negative strength, a zero direction) are refused with a message.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <string>

#include "editor/color_space.h"
#include "editor/panels/panels.h"

namespace glint {
namespace {

const char* typeLabel(LightType type) { return type == LightType::Directional ? "directional" : "point"; }

Light newLight(LightType type, const Scene& scene) {
    Light light;
    light.type = type;
    light.name = std::string(typeLabel(type)) + " " + std::to_string(scene.lights.size() + 1);
    light.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f));
    light.position = {0.0f, 2.5f, 2.0f};
    return light;
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
        const std::string label = scene.lights[i].name + "  (" + typeLabel(scene.lights[i].type) + ")";
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
    if (ImGui::Button("+ Directional")) {
        state.session.change("Add light").lights.push_back(newLight(LightType::Directional, scene));
        state.selectedLight = static_cast<int>(state.session.scene().lights.size()) - 1;
    }
    ImGui::SameLine();
    if (ImGui::Button("+ Point")) {
        state.session.change("Add light").lights.push_back(newLight(LightType::Point, scene));
        state.selectedLight = static_cast<int>(state.session.scene().lights.size()) - 1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Duplicate") && selected) {
        Light copy = scene.lights[state.selectedLight];
        copy.name += " copy";
        state.session.change("Duplicate light").lights.push_back(copy);
        state.selectedLight = static_cast<int>(state.session.scene().lights.size()) - 1;
    }
    ImGui::EndDisabled();
    if (!room && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("At most %d lights", kMaxLights);
    ImGui::BeginDisabled(!selected);
    if (ImGui::Button("Remove")) {
        auto& lights = state.session.change("Remove light").lights;
        lights.erase(lights.begin() + state.selectedLight);
        state.selectedLight = std::max(0, state.selectedLight - 1);
    }
    ImGui::SameLine();
    if (ImGui::Button("Solo")) {
        auto& lights = state.session.change("Solo light").lights;
        for (size_t i = 0; i < lights.size(); ++i) lights[i].enabled = static_cast<int>(i) == state.selectedLight;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Enable only the selected light");
    ImGui::SameLine();
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
    int type = light.type == LightType::Directional ? 0 : 1;
    if (ImGui::Combo("Type", &type, "directional\0point\0")) {
        light.type = type == 0 ? LightType::Directional : LightType::Point;
        changed = true;
    }
    float encoded[3] = {encodeSrgb(light.color.r), encodeSrgb(light.color.g), encodeSrgb(light.color.b)};
    if (ImGui::ColorEdit3("Colour", encoded, ImGuiColorEditFlags_Float)) {
        for (int c = 0; c < 3; ++c) light.color[c] = decodeSrgb(std::max(encoded[c], 0.0f));
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Linear-RGB filter on the light's strength (shown sRGB-encoded)");
    float& strength = light.type == LightType::Directional ? light.irradiance : light.power;
    float typed = strength;
    const char* format = light.type == LightType::Directional ? "%.3f W/m²" : "%.2f W";
    const char* label = light.type == LightType::Directional ? "Irradiance M" : "Power Φ";
    if (ImGui::DragFloat(label, &typed, strength * 0.01f + 0.01f, 0.0f, 0.0f, format)) {
        if (std::isfinite(typed) && typed >= 0.0f) strength = typed, changed = true, refusal.clear();
        else refusal = std::string(label) + " must be a number of at least 0";
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(light.type == LightType::Directional
                              ? "Irradiance on a surface facing the light, W/m²"
                              : "Radiant power, emitted evenly: E = Φ/(4πd²)·cos θ");
    if (light.type == LightType::Directional) {
        glm::vec3 direction = light.direction;
        if (ImGui::DragFloat3("Direction", &direction.x, 0.01f, -1.0f, 1.0f, "%.2f")) {
            if (glm::length(direction) > 1e-4f && std::isfinite(glm::length(direction)))
                light.direction = glm::normalize(direction), changed = true, refusal.clear();
            else refusal = "Direction must not be zero";
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The direction the light travels (normalised)");
    } else {
        glm::vec3 position = light.position;
        if (ImGui::DragFloat3("Position m", &position.x, 0.02f, 0.0f, 0.0f, "%.2f")) {
            if (std::isfinite(position.x + position.y + position.z)) light.position = position, changed = true;
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
    ImGui::PushID("selected light");
    Light edited = scene.lights[state.selectedLight];
    if (drawLightEditor(edited, state.lightPanelMessage))
        state.session.change("Edit light").lights[state.selectedLight] = std::move(edited);
    if (!state.lightPanelMessage.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", state.lightPanelMessage.c_str());
    ImGui::PopID();
}

}  // namespace glint
