// Shared panel widgets (see widgets.h).
#include "editor/panels/widgets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <imgui.h>
#include <imgui_internal.h>

#include "editor/color_space.h"
#include "editor/panels/typed_numbers.h"

namespace glint {

float threeNumbersWidth(bool swatch) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float number = ImGui::CalcTextSize("0.000").x + 2.0f * style.FramePadding.x + 2.0f;
    return 3.0f * number + 2.0f * style.ItemInnerSpacing.x + (swatch ? style.ItemInnerSpacing.x + ImGui::GetFrameHeight() : 0.0f);
}

float comboWidth(float textWidth) { return textWidth + 2.0f * ImGui::GetStyle().FramePadding.x + ImGui::GetFrameHeight(); }

void drawProblemText(const std::string& text, bool wrapped) {
    if (wrapped) ImGui::PushTextWrapPos();
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", text.c_str());
    if (wrapped) ImGui::PopTextWrapPos();
}

float buttonWidth(const char* label) { return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x; }

float checkboxWidth(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

void sameLineIfFits(float itemWidth) {
    const float columnRight = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + itemWidth <= columnRight) ImGui::SameLine();
}

bool comboBox(const char* label, int* current, const char* zeroSeparatedItems) {
    float widest = 0.0f;
    for (const char* item = zeroSeparatedItems; *item; item += std::strlen(item) + 1)
        widest = std::max(widest, ImGui::CalcTextSize(item).x);
    const std::string shown = placeLabel(label, comboWidth(widest));
    return ImGui::Combo(shown.c_str(), current, zeroSeparatedItems);
}

std::string placeLabel(const char* label, float contentWidth, float trailing) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const char* labelEnd = ImGui::FindRenderedTextEnd(label);
    const float labelWidth = ImGui::CalcTextSize(label, labelEnd).x;
    const float beside = ImGui::GetContentRegionAvail().x - trailing - style.ItemInnerSpacing.x - labelWidth;
    if (beside >= contentWidth) {  // wider than the column's usual width where the content needs it
        ImGui::SetNextItemWidth(std::max(std::min(ImGui::CalcItemWidth(), beside), contentWidth));
        return label;
    }
    ImGui::TextUnformatted(label, labelEnd);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - trailing);
    return std::string("##") + label;
}

bool linearColorEdit(const char* label, glm::vec3& linear, const char* tooltip) {
    float encoded[3] = {encodeSrgb(linear.r), encodeSrgb(linear.g), encodeSrgb(linear.b)};
    bool changed = false;
    const std::string shown = placeLabel(label, threeNumbersWidth(true));
    if (editNumbers(label, encoded, 3, [&](float* typed) { return ImGui::ColorEdit3(shown.c_str(), typed, ImGuiColorEditFlags_Float); })) {
        for (int c = 0; c < 3; ++c) linear[c] = decodeSrgb(std::max(encoded[c], 0.0f));
        changed = true;
    }
    if (tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    return changed;
}

bool boundedDrag(const char* label, float& value, float minimum, float maximum, const char* format,
                 std::string& refusal, const char* tooltip) {
    float typed = value;
    bool changed = false;
    const float speed = std::max(std::abs(value) * 0.01f, 0.01f);
    char shownValue[64];
    std::snprintf(shownValue, sizeof shownValue, format, value);
    const float valueWidth = ImGui::CalcTextSize(shownValue).x + 2.0f * ImGui::GetStyle().FramePadding.x + 2.0f;
    const std::string shown = placeLabel(label, valueWidth);
    if (editNumbers(label, &typed, 1, [&](float* edited) { return ImGui::DragFloat(shown.c_str(), edited, speed, 0.0f, 0.0f, format); })) {
        if (std::isfinite(typed) && typed >= minimum && typed <= maximum) {
            value = typed;
            changed = true;
            refusal.clear();
        } else {
            char text[160];
            std::snprintf(text, sizeof text, "%s: %g refused; it must lie in [%g, %g]", label, typed, minimum, maximum);
            refusal = text;
        }
    }
    if (tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
    return changed;
}

}  // namespace glint
