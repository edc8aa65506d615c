// Small widgets shared by the panels: a colour picker that shows sRGB-encoded values while the
// scene stores linear RGB (DESIGN.md), and a non-negative number field that refuses (with a
// message) what the scene would refuse. No panel layout here.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace glint {

// Edits a linear-RGB radiance or filter through an sRGB-encoded picker; negatives are refused.
bool linearColorEdit(const char* label, glm::vec3& linear, const char* tooltip);
// A drag field for a value in [minimum, maximum]; a typed value outside is refused into `refusal`.
bool boundedDrag(const char* label, float& value, float minimum, float maximum, const char* format,
                 std::string& refusal, const char* tooltip);

}  // namespace glint
