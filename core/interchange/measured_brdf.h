// MeasuredBrdf: a loaded MERL .binary table made into something a material can carry (shared,
// never copied: the table is 90·90·180·3 floats), with its directional albedo precomputed for
// ambient and environment light. Evaluation only; the file format lives in merl.h.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "interchange/imported.h"
#include "interchange/merl.h"

namespace glint {

// Directional albedo ρ(θ_o) = ∫ f_r cos θ_i dω_i, tabulated at cos θ_o = (k + ½)/N.
inline constexpr int kMeasuredAlbedoSamples = 32;

struct MeasuredBrdf {
    MerlTable table;
    std::string path;         // the file read
    std::string displayName;  // the file name without folders, for the UI
    std::array<glm::vec3, kMeasuredAlbedoSamples> directionalAlbedo{};

    MeasuredBrdf() = default;
    MeasuredBrdf(const MeasuredBrdf&) = delete;
    MeasuredBrdf& operator=(const MeasuredBrdf&) = delete;
};

// Wraps a parsed table (computing its albedo table); `path` names it.
std::shared_ptr<const MeasuredBrdf> makeMeasuredBrdf(MerlTable table, std::string path);
Result<std::shared_ptr<const MeasuredBrdf>> loadMeasuredBrdf(const std::string& path);

// f_r [1/sr]: the trilinear lookup (merl.h), which the GLSL twin shaders/brdf/merl.glsl repeats.
glm::vec3 evalMeasuredBrdf(const MeasuredBrdf& brdf, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame);
// ρ(θ_o) interpolated linearly in cos θ_o between the tabulated samples (clamped at the ends).
glm::vec3 measuredDirectionalAlbedo(const MeasuredBrdf& brdf, float cosThetaOut);

// A material carrying the table, named after the file.
Material measuredBrdfMaterial(std::shared_ptr<const MeasuredBrdf> brdf);
// The import_formats.h row for .binary: one measured material, and a warning when the file has
// unmeasured (negative) samples, which read as 0.
Result<ImportedFile> importMerl(const std::string& path);

}  // namespace glint
