// Typed numbers held until the typing ends (see typed_numbers.h).
#include "editor/panels/typed_numbers.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <array>
#include <unordered_map>

namespace glint {
namespace {

struct HeldNumbers {
    std::array<float, 4> values{};
    int frame = 0;  // the last frame the widget was typed into
};

// One entry per widget being typed into (at most one at a time in practice), keyed by ImGui ID.
std::unordered_map<ImGuiID, HeldNumbers>& heldNumbers() {
    static std::unordered_map<ImGuiID, HeldNumbers> held;
    return held;
}

// Whether the item just drawn (a group too: a colour edit or a row of three fields) holds the
// active text entry that ImGui opens on a slider or drag field.
bool typingIntoLastItem() {
    const ImGuiContext& context = *ImGui::GetCurrentContext();
    return ImGui::IsItemActive() && context.TempInputId != 0 && context.TempInputId == context.ActiveId;
}

}  // namespace

bool editNumbers(const char* label, float* values, int count, const std::function<bool(float*)>& widget) {
    auto& held = heldNumbers();
    const ImGuiID key = ImGui::GetID(label);
    const int frame = ImGui::GetFrameCount();
    auto found = held.find(key);
    // Typing into a widget that was not drawn last frame (its panel closed, another object shown)
    // was abandoned: its numbers are dropped rather than put where they were not typed.
    if (found != held.end() && found->second.frame < frame - 1) {
        held.erase(found);
        found = held.end();
    }
    std::array<float, 4> shown{};
    std::copy(values, values + count, shown.begin());
    if (found != held.end()) std::copy(found->second.values.begin(), found->second.values.begin() + count, values);
    const bool changed = widget(values);
    if (typingIntoLastItem()) {
        HeldNumbers& entry = held[key];
        std::copy(values, values + count, entry.values.begin());
        entry.frame = frame;
        return false;
    }
    if (found == held.end()) return changed;
    held.erase(found);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) return false;  // typing cancelled
    return !std::equal(values, values + count, shown.begin());
}

}  // namespace glint
