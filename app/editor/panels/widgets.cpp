// Shared panel widgets (see widgets.h).
#include "editor/panels/widgets.h"

#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "editor/color_space.h"

namespace glint {

bool linearColorEdit(const char* label, glm::vec3& linear, const char* tooltip) {
    float encoded[3] = {encodeSrgb(linear.r), encodeSrgb(linear.g), encodeSrgb(linear.b)};
    bool changed = false;
    if (ImGui::ColorEdit3(label, encoded, ImGuiColorEditFlags_Float)) {
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
    if (ImGui::DragFloat(label, &typed, speed, 0.0f, 0.0f, format)) {
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
