// The IOR preset menu beside a material's index-of-refraction field: dielectrics (glass, water,
// ice, diamond) set n and clear κ; metals (core/brdf/presets.h) set n and κ per channel.
// Edits a Material in place; drawing the other parameters lives in material_panel.cpp.
#pragma once

#include "scene/scene.h"

namespace glint {

// A small "Presets" button on the current line opening the menu. Returns true when a preset was
// applied (the caller records it as one undo step). Metals are offered only where the model has
// an extinction κ next to its IOR.
bool drawIorPresetMenu(Material& material);

// Applies the named preset's n (and κ where the model has it) to `material`; false when the
// preset is unknown or cannot apply (a metal on a model without κ). Used by the menu and tests.
bool applyIorPreset(Material& material, const char* presetName);

}  // namespace glint
