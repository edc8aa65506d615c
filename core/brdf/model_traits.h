// What a model does, asked of packed values at run time (brdf/model.h lists the hooks behind
// these; ModelInfo holds the constant ones). Code outside core/brdf asks these rather than
// comparing against a particular model.
#pragma once

#include <optional>
#include <span>

#include "brdf/model_registry.h"
#include "brdf/trait_forms.h"

namespace glint {

// The model's delta lobes for light arriving from air at cos θ_i; none when it has none.
std::optional<DeltaLobeWeights> deltaLobeWeights(BrdfModel model, std::span<const float> values, float cosIncident);

// Whether light passes through the surface (glass; OpenPBR with some transmission).
bool transmits(BrdfModel model, std::span<const float> values);

// The textbook form of the values (trait_forms.h), when they have one.
std::optional<TextbookForm> textbookForm(BrdfModel model, std::span<const float> values);

}  // namespace glint
