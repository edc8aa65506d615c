// Material panel generated from the parameter table (see material_panel.h).
#include "editor/material_panel.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "brdf/model_switch.h"
#include "brdf/param_table.h"
#include "editor/color_space.h"
#include "editor/ior_presets.h"
#include "editor/panels/typed_numbers.h"
#include "editor/panels/widgets.h"
#include "editor/texture_panel.h"
#include "interchange/custom_brdf.h"
#include "interchange/measured_brdf.h"
#include "texture/texture_edit.h"
#include "util/text.h"

namespace glint {
namespace {

std::string formatRange(const ParamSpec& spec) {
    const std::string least = (spec.validMinExclusive ? "greater than " : "at least ") + formatNumber(spec.validMin);
    return spec.validMax == kUnbounded ? least : least + " and at most " + formatNumber(spec.validMax);
}

// Takes three typed channels into `value` when each is valid; otherwise says why in `refusal`.
bool takeChannels(const ParamSpec& spec, const float typed[3], float* value, std::string& refusal) {
    if (!std::all_of(typed, typed + 3, [&](float channel) { return spec.accepts(channel); })) {
        refusal = std::string(spec.label) + ": each channel must be " + formatRange(spec);
        return false;
    }
    std::copy(typed, typed + 3, value);
    refusal.clear();
    return true;
}

// A positive channel below this reads "≈ 0" (dragChannels).
constexpr float kShownAsZero = 1e-4f;

// Room the buttons after a widget take on its line (R, then Presets beside an index or the
// texture button) [px].
float buttonsWidth(const std::vector<const char*>& buttonsAfter) {
    float width = 0.0f;
    for (const char* button : buttonsAfter) width += ImGui::GetStyle().ItemSpacing.x + buttonWidth(button);
    return width;
}

// Narrows the next slider, where ImGui's default (65 % of the column) would push the label and the
// buttons after it past the column's edge; a long label such as "Diffuse albedo ρ_d" keeps them in view.
void fitSliderWidth(const ParamSpec& spec, const std::vector<const char*>& buttonsAfter) {
    const ImGuiStyle& style = ImGui::GetStyle();
    // One spacing to spare: ImGui's widths round to whole pixels.
    const float trailing = style.ItemSpacing.x + style.ItemInnerSpacing.x + ImGui::CalcTextSize(spec.label, nullptr, true).x +
                           buttonsWidth(buttonsAfter);
    const float fitted = ImGui::GetContentRegionAvail().x - trailing;
    ImGui::SetNextItemWidth(std::max(4.0f * ImGui::GetFontSize(), std::min(ImGui::CalcItemWidth(), fitted)));
}

// Room the combo of an enum parameter needs to show its widest option [px].
float optionsComboWidth(const ParamSpec& spec) {
    float widest = 0.0f;
    for (const auto& option : spec.options) widest = std::max(widest, ImGui::CalcTextSize(option.label).x);
    return comboWidth(widest);
}

// Where the next widget's label goes and how wide the widget is (panels/widgets.h): three numbers
// and combos take their own line under the label when the column is too narrow for them beside it.
std::string placeParamLabel(const ParamSpec& spec, const std::vector<const char*>& buttonsAfter) {
    const float trailing = buttonsWidth(buttonsAfter);
    switch (spec.kind) {
        case ParamKind::PerChannel: return placeLabel(spec.label, threeNumbersWidth(false), trailing);
        case ParamKind::Color: return placeLabel(spec.label, threeNumbersWidth(true), trailing);
        case ParamKind::Enum: return placeLabel(spec.label, optionsComboWidth(spec), trailing);
        case ParamKind::Scalar: fitSliderWidth(spec, buttonsAfter); break;
        case ParamKind::Bool: break;
    }
    return spec.label;
}

// Three linear numbers side by side as DragFloat3 draws them, each with its own format: a channel
// at a vanishing positive value (gold's red index n = 1e-8, a lossless conductor) reads "≈ 0", not
// "1e-08".
bool dragChannels(const char* label, float* values, float minimum, float maximum) {
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    bool changed = false;
    ImGui::BeginGroup();
    ImGui::PushID(label);
    ImGui::PushMultiItemsWidths(3, ImGui::CalcItemWidth());
    for (int c = 0; c < 3; ++c) {
        ImGui::PushID(c);
        if (c > 0) ImGui::SameLine(0, spacing);
        const char* format = values[c] > 0.0f && values[c] < kShownAsZero ? "≈ 0" : "%.4g";
        changed |= ImGui::DragFloat("##channel", &values[c], 0.005f, minimum, maximum, format);
        ImGui::PopID();
        ImGui::PopItemWidth();
    }
    ImGui::PopID();
    if (const char* labelEnd = ImGui::FindRenderedTextEnd(label); labelEnd != label) {
        ImGui::SameLine(0, spacing);
        ImGui::TextUnformatted(label, labelEnd);
    }
    ImGui::EndGroup();
    return changed;
}

// A Scalar's slider; Ctrl+click typing may go past the slider but never past the valid range.
bool drawScalar(const ParamSpec& spec, const char* label, float* value, std::string& refusal) {
    std::string format = "%.4g";
    if (*spec.unit) format += std::string(" ") + spec.unit;
    ImGuiSliderFlags flags = ImGuiSliderFlags_NoRoundToFormat;
    if (spec.scale == ParamScale::Log) flags |= ImGuiSliderFlags_Logarithmic;
    float edited = *value;
    if (!editNumbers(spec.label, &edited, 1, [&](float* typed) {
            return ImGui::SliderFloat(label, typed, spec.sliderMin, spec.sliderMax, format.c_str(), flags);
        }))
        return false;
    if (!spec.accepts(edited)) {
        refusal = std::string(spec.label) + ": " + formatNumber(edited) + " refused; it must be " + formatRange(spec);
        return false;
    }
    *value = edited;
    refusal.clear();
    return true;
}

// A PerChannel's three linear numbers (an index of refraction, an absorption coefficient: not a
// colour), or a Color's picker in sRGB.
bool drawChannels(const ParamSpec& spec, const char* label, float* value, std::string& refusal) {
    if (spec.kind == ParamKind::PerChannel) {
        float edited[3] = {value[0], value[1], value[2]};
        return editNumbers(spec.label, edited, 3, [&](float* typed) { return dragChannels(label, typed, spec.sliderMin, spec.sliderMax); }) &&
               takeChannels(spec, edited, value, refusal);
    }
    float encoded[3] = {encodeSrgb(value[0]), encodeSrgb(value[1]), encodeSrgb(value[2])};
    if (!editNumbers(spec.label, encoded, 3, [&](float* typed) { return ImGui::ColorEdit3(label, typed, ImGuiColorEditFlags_Float); }))
        return false;
    const float linear[3] = {decodeSrgb(encoded[0]), decodeSrgb(encoded[1]), decodeSrgb(encoded[2])};
    return takeChannels(spec, linear, value, refusal);
}

bool drawEnum(const ParamSpec& spec, const char* label, float* value) {
    const int selected = static_cast<int>(*value);
    if (!ImGui::BeginCombo(label, spec.options[selected].label)) return false;
    bool changed = false;
    for (size_t i = 0; i < spec.options.size(); ++i) {
        if (ImGui::Selectable(spec.options[i].label, selected == static_cast<int>(i))) {
            *value = static_cast<float>(i);
            changed = true;
        }
    }
    ImGui::EndCombo();
    return changed;
}

// The parameter's help, and what a value kept just above 0 means.
void paramTooltip(const ParamSpec& spec, const float* value) {
    const bool nearZero = spec.kind == ParamKind::PerChannel && std::any_of(value, value + 3, [](float v) { return v > 0.0f && v < kShownAsZero; });
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(spec.help);
    if (nearZero)
        ImGui::Text("≈ 0: below %g, kept just above 0 (%g) as the value must be positive; for a metal's index n, "
                    "all of that colour is reflected.", kShownAsZero, *std::min_element(value, value + 3));
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// Typed values beyond the slider are kept when the table's valid range allows them, and refused
// with a message in `refusal` when it does not (never clamped silently). `buttonsAfter` names the
// buttons the caller puts on the same line, so that the widget leaves room for them.
bool drawParam(const ParamSpec& spec, float* value, std::string& refusal, const std::vector<const char*>& buttonsAfter) {
    bool changed = false;
    ImGui::PushID(spec.name);
    const std::string shown = placeParamLabel(spec, buttonsAfter);
    const char* label = shown.c_str();
    switch (spec.kind) {
        case ParamKind::Scalar: changed = drawScalar(spec, label, value, refusal); break;
        case ParamKind::PerChannel:
        case ParamKind::Color: changed = drawChannels(spec, label, value, refusal); break;
        case ParamKind::Bool: {
            bool checked = *value != 0.0f;
            if (ImGui::Checkbox(label, &checked)) *value = checked ? 1.0f : 0.0f, changed = true;
            break;
        }
        case ParamKind::Enum: changed = drawEnum(spec, label, value); break;
    }
    if (ImGui::IsItemHovered() && *spec.help) paramTooltip(spec, value);
    ImGui::SameLine();
    if (ImGui::SmallButton("R")) {
        for (int c = 0; c < componentCount(spec.kind); ++c) value[c] = spec.defaultValue[c];
        changed = true;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Reset to default");
    ImGui::PopID();
    return changed;
}

// The rows of the material's parameter table; `analytic`, a built-in model's material (else a
// .brdf file's), adds the IOR presets and the texture controls.
bool drawParamRows(Material& material, AnalyticMaterial* analytic, std::string& refusal, std::string& textureFileRequest) {
    bool changed = false;
    const auto table = paramTable(material);
    const std::span<float> values = paramValues(material);
    for (size_t i = 0; i < table.size(); ++i) {
        const bool indexOfRefraction = analytic && std::string_view(table[i].name) == "ior";
        const bool texturable = analytic && (table[i].kind == ParamKind::Scalar || table[i].kind == ParamKind::Color);
        std::vector<const char*> buttonsAfter = {"R"};
        if (indexOfRefraction) buttonsAfter.push_back("Presets");
        if (texturable) buttonsAfter.push_back("Tex");
        changed |= drawParam(table[i], values.data() + packedOffset(table, static_cast<int>(i)), refusal, buttonsAfter);
        // The IOR preset menu sits beside the index field (it sets κ too where the model has it).
        if (indexOfRefraction) changed |= drawIorPresetMenu(material);
        if (!texturable) continue;
        // The texture button, where its label ("Checker", "Image", …) no longer fits beside a long
        // parameter label, opens the next line, above the texture's settings.
        ImGui::SameLine();
        const bool wraps = ImGui::GetContentRegionAvail().x < buttonWidth(textureButtonLabel(*analytic, table[i].name));
        if (wraps) ImGui::NewLine(), ImGui::Indent();
        changed |= drawTextureControls(*analytic, table[i].name, &table[i], textureFileRequest, refusal);
        if (wraps) ImGui::Unindent();
    }
    return changed;
}

// A built-in model's rows: its parameters, its maps and what the model is.
bool drawAnalyticRows(Material& material, AnalyticMaterial& analytic, std::string& refusal, std::string& textureFileRequest) {
    bool changed = drawParamRows(material, &analytic, refusal, textureFileRequest);
    std::string unused;
    ImGui::TextUnformatted("Ambient occlusion");
    ImGui::SameLine();
    changed |= drawTextureControls(analytic, kOcclusionMapKey, texturableParam(analytic.model, kOcclusionMapKey, unused),
                                   textureFileRequest, refusal);
    ImGui::TextUnformatted("Normal map");
    ImGui::SameLine();
    changed |= drawTextureControls(analytic, kNormalMapKey, nullptr, textureFileRequest, refusal);
    if (modelInfo(analytic.model).coatNormalMap) {
        ImGui::TextUnformatted("Coat normal map");
        ImGui::SameLine();
        changed |= drawTextureControls(analytic, kCoatNormalMapKey, nullptr, textureFileRequest, refusal);
    }
    if (const char* constantForm = modelInfo(analytic.model).constantForm) {
        // Show f_r beside its parameters, where a teacher would look (any pair of directions will do).
        const glm::vec3 up(0.0f, 0.0f, 1.0f);
        const glm::vec3 f = evalBrdf(analytic.model, analytic.values, up, up, ShadingFrame::fromNormal(up));
        ImGui::TextDisabled("f_r = %s = (%.4f, %.4f, %.4f) 1/sr", constantForm, f.r, f.g, f.b);
    }
    ImGui::PushTextWrapPos();
    ImGui::TextDisabled("%s", modelInfo(analytic.model).citation);
    ImGui::TextDisabled("Environment light: %s", modelInfo(analytic.model).environmentResponse);
    ImGui::PopTextWrapPos();
    return changed;
}

}  // namespace

bool drawMaterialPanel(Material& material, std::string& refusal, std::string& textureFileRequest) {
    bool changed = false;
    // A .brdf file (its own table, GPU only) or a MERL table (no parameters) replaces the model.
    const std::string modelLabel =
        std::visit(Overloaded{[](const AnalyticMaterial& analytic) { return std::string(modelInfo(analytic.model).label); },
                              [](const CustomMaterial& custom) { return custom.brdf->displayName; },
                              [](const MeasuredMaterial& measured) { return "measured (MERL): " + measured.brdf->displayName; }},
                   material.kind);
    float widestModel = ImGui::CalcTextSize(modelLabel.c_str()).x;
    for (const ModelInfo& info : allModels()) widestModel = std::max(widestModel, ImGui::CalcTextSize(info.label).x);
    const std::string modelComboLabel = placeLabel("Model", comboWidth(widestModel));
    if (ImGui::BeginCombo(modelComboLabel.c_str(), modelLabel.c_str())) {
        for (const ModelInfo& info : allModels()) {
            const bool current = material.analytic() && material.analytic()->model == info.model;
            if (ImGui::Selectable(info.label, current) && !current) {
                // What the two models share (colour, roughness, index) carries over; the panel says what did not.
                const ModelSwitch switched = switchModel(material, info.model);
                material = switched.material;
                refusal = std::string("Switched to ") + info.label + ": " + switched.summary() + ".";
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    changed |= std::visit(
        Overloaded{[&](AnalyticMaterial& analytic) { return drawAnalyticRows(material, analytic, refusal, textureFileRequest); },
                   [&](const CustomMaterial& custom) {
                       const bool edited = drawParamRows(material, nullptr, refusal, textureFileRequest);
                       ImGui::PushTextWrapPos();
                       ImGui::TextDisabled("BRDF Explorer file %s (reloads when it changes)", custom.brdf->file.path.c_str());
                       ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1.0f), "GPU preview only: the CPU reference "
                                                                          "(glint render --reference) cannot run .brdf shaders.");
                       ImGui::PopTextWrapPos();
                       return edited;
                   },
                   [](const MeasuredMaterial& measured) {
                       ImGui::PushTextWrapPos();
                       ImGui::TextDisabled("Measured BRDF %s (Matusik et al., A Data-Driven Reflectance Model, SIGGRAPH 2003): "
                                           "no parameters; the table is interpolated trilinearly.", measured.brdf->path.c_str());
                       ImGui::TextDisabled("Ambient and environment light: the measured directional albedo times the diffuse "
                                           "irradiance (no glossy reflection of the environment).");
                       ImGui::PopTextWrapPos();
                       return false;
                   }},
        material.kind);
    return changed;
}

}  // namespace glint
