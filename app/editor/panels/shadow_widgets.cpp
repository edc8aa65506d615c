// Shadow widgets of the lights section (see shadow_widgets.h).
#include "editor/panels/shadow_widgets.h"

#include <imgui.h>

#include <string>

#include "editor/panels/widgets.h"

namespace glint {

int shadowedLightsOtherThan(const Scene& scene, int except) {
    int count = 0;
    for (int i = 0; i < static_cast<int>(scene.lights.size()); ++i) count += i != except && scene.lights[i].castsShadows;
    return count;
}

bool drawShadowSettings(Light& light, int otherShadowedLights, std::string& refusal) {
    if (light.type == LightType::Ambient) return false;
    bool changed = false;
    const bool full = !light.castsShadows && otherShadowedLights >= kMaxShadowedLights;
    ImGui::BeginDisabled(full);
    changed |= ImGui::Checkbox("Casts shadows", &light.castsShadows);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(full ? "At most %d lights cast shadows at once" : "Objects block this light (shadow map; %d lights at most)",
                          kMaxShadowedLights);
    if (!light.castsShadows) return changed;
    ImGui::Indent();
    static constexpr int kResolutions[] = {256, 512, 1024, 2048, 4096};
    const std::string current = std::to_string(light.shadow.mapResolution) + "²";
    const std::string resolutionLabel = placeLabel("Map resolution", comboWidth(ImGui::CalcTextSize("4096²").x));
    if (ImGui::BeginCombo(resolutionLabel.c_str(), current.c_str())) {
        for (int resolution : kResolutions) {
            const std::string label = std::to_string(resolution) + "²";
            if (ImGui::Selectable(label.c_str(), resolution == light.shadow.mapResolution) &&
                resolution != light.shadow.mapResolution)
                light.shadow.mapResolution = resolution, changed = true;
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(light.type == LightType::Directional ? "Texels per side of the map over the whole scene"
                                                               : "Texels per side of the map (of each cube face for a point light)");
    changed |= boundedDrag("Depth bias", light.shadow.depthBias, 0.0f, kMaxShadowBiasTexels, "%.2f texels", refusal,
                           "Moves the receiver towards the light: more removes acne, too much detaches the shadow");
    changed |= boundedDrag("Normal offset", light.shadow.normalOffset, 0.0f, kMaxShadowBiasTexels, "%.2f texels", refusal,
                           "Moves the receiver along its normal: removes acne on surfaces the light grazes");
    changed |= boundedDrag("Filter radius", light.shadow.filterRadius, 0.0f, kMaxShadowFilterRadiusTexels, "%.2f texels",
                           refusal, "PCF kernel radius (16 Poisson taps): wider, softer edges; 0 = one bilinear tap");
    ImGui::Unindent();
    return changed;
}

}  // namespace glint
