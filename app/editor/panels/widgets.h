// Small widgets shared by the panels: a colour picker that shows sRGB-encoded values while the
// scene stores linear RGB (docs/architecture.md), a non-negative number field that refuses (with a
// message) what the scene would refuse, and where a wide widget's label goes. No panel layout here.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace glint {

// Room three numbers need side by side, each "0.000" unclipped [px]; `swatch` adds a colour's.
float threeNumbersWidth(bool swatch);
// Room a combo needs to show an option `textWidth` wide, and its arrow [px].
float comboWidth(float textWidth);
// A problem for the user to fix (a shader that does not compile), in red; wrapped at the window's
// edge, or clipped there.
void drawProblemText(const std::string& text, bool wrapped = true);
// Width of a button (or small button) showing `label`, and of a checkbox with its label [px].
float buttonWidth(const char* label);
float checkboxWidth(const char* label);
// Before an item on a row (buttons, checkboxes): stays on the line when an item `itemWidth` wide
// fits in what is left of the column, else the item starts the next line (nothing cut at the edge).
void sameLineIfFits(float itemWidth);
// ImGui::Combo over "a\0b\0" items, wide enough for the widest of them or with its label above.
bool comboBox(const char* label, int* current, const char* zeroSeparatedItems);
// A widget whose content needs `contentWidth` [px] (three numbers, a combo's longest option) and
// that leaves `trailing` [px] after it on its line for buttons: when the column leaves it less room
// beside its label, the label goes on its own line above and the widget takes the line's width.
// Sets the next item's width; returns the label to give the widget ("##…" when it went above).
std::string placeLabel(const char* label, float contentWidth, float trailing = 0.0f);

// Edits a linear-RGB radiance or filter through an sRGB-encoded picker; negatives are refused.
// Its label goes above it where the column is too narrow for three numbers beside it.
bool linearColorEdit(const char* label, glm::vec3& linear, const char* tooltip);
// A drag field for a value in [minimum, maximum]; a typed value outside is refused into `refusal`.
// Its label goes above it where the column is too narrow to show the value beside it.
bool boundedDrag(const char* label, float& value, float minimum, float maximum, const char* format,
                 std::string& refusal, const char* tooltip);

}  // namespace glint
