// Physical and mathematical constants shared by core, with their units.
#pragma once

namespace glint {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;
// Luminous efficacy of 555 nm light: lumens per watt (the SI definition of the candela).
inline constexpr float kLumensPerWatt = 683.0f;

}  // namespace glint
