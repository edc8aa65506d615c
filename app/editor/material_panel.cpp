// Material panel generated from the parameter table (see material_panel.h).
#include "editor/material_panel.h"

#include <algorithm>
#include <imgui.h>
#include <string>

#include "editor/color_space.h"

namespace glint {
namespace {

bool drawParam(const ParamSpec& spec, float* value) {
    bool changed = false;
    ImGui::PushID(spec.name);
    switch (spec.kind) {
        case ParamKind::Scalar: {
            std::string format = "%.4g";
            if (*spec.unit) format += std::string(" ") + spec.unit;
            ImGuiSliderFlags flags = ImGuiSliderFlags_NoRoundToFormat;
            if (spec.scale == ParamScale::Log) flags |= ImGuiSliderFlags_Logarithmic;
            float edited = *value;
            if (ImGui::SliderFloat(spec.label, &edited, spec.sliderMin, spec.sliderMax, format.c_str(), flags)) {
                // Ctrl+click typing may go past the slider but never past the valid range.
                if (edited >= spec.validMin && edited <= spec.validMax) *value = edited, changed = true;
            }
            break;
        }
        case ParamKind::Color: {
            if (spec.validMax > 1.0f) {
                // Not a colour but a per-channel quantity (an index of refraction): linear numbers.
                float edited[3] = {value[0], value[1], value[2]};
                if (ImGui::DragFloat3(spec.label, edited, 0.005f, spec.sliderMin, spec.sliderMax, "%.4g")) {
                    bool valid = true;
                    for (float channel : edited)
                        valid &= (spec.validMinExclusive ? channel > spec.validMin : channel >= spec.validMin) &&
                                 channel <= spec.validMax;
                    if (valid) std::copy(edited, edited + 3, value), changed = true;
                }
                break;
            }
            float encoded[3] = {encodeSrgb(value[0]), encodeSrgb(value[1]), encodeSrgb(value[2])};
            if (ImGui::ColorEdit3(spec.label, encoded, ImGuiColorEditFlags_Float)) {
                for (int c = 0; c < 3; ++c) value[c] = std::clamp(decodeSrgb(encoded[c]), spec.validMin, spec.validMax);
                changed = true;
            }
            break;
        }
        case ParamKind::Bool: {
            bool checked = *value != 0.0f;
            if (ImGui::Checkbox(spec.label, &checked)) *value = checked ? 1.0f : 0.0f, changed = true;
            break;
        }
        case ParamKind::Enum: {
            int selected = static_cast<int>(*value);
            const char* preview = spec.options[selected].label;
            if (ImGui::BeginCombo(spec.label, preview)) {
                for (size_t i = 0; i < spec.options.size(); ++i) {
                    if (ImGui::Selectable(spec.options[i].label, selected == static_cast<int>(i))) {
                        *value = static_cast<float>(i);
                        changed = true;
                    }
                }
                ImGui::EndCombo();
            }
            break;
        }
    }
    if (ImGui::IsItemHovered() && *spec.help) ImGui::SetTooltip("%s", spec.help);
    ImGui::SameLine();
    if (ImGui::SmallButton("R")) {
        for (int c = 0; c < componentCount(spec.kind); ++c) value[c] = spec.defaultValue[c];
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Reset to default");
    ImGui::PopID();
    return changed;
}

}  // namespace

bool drawMaterialPanel(Material& material) {
    bool changed = false;
    const ModelInfo& current = modelInfo(material.model);
    if (ImGui::BeginCombo("Model", current.label)) {
        for (const ModelInfo& info : allModels()) {
            if (ImGui::Selectable(info.label, info.model == material.model) && info.model != material.model) {
                material.model = info.model;
                material.values = defaultValues(info.params);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    const auto table = modelInfo(material.model).params;
    for (size_t i = 0; i < table.size(); ++i)
        changed |= drawParam(table[i], material.values.data() + packedOffset(table, static_cast<int>(i)));
    if (material.model == BrdfModel::Lambert) {
        // Show f_r beside ρ, where a teacher would look.
        ImGui::TextDisabled("f_r = ρ/π = (%.4f, %.4f, %.4f) 1/sr", material.values[0] * kInvPi,
                            material.values[1] * kInvPi, material.values[2] * kInvPi);
    }
    ImGui::PushTextWrapPos();
    ImGui::TextDisabled("%s", modelInfo(material.model).citation);
    ImGui::PopTextWrapPos();
    return changed;
}

}  // namespace glint
