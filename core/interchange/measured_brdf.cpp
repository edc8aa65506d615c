// Measured (MERL) BRDFs as material data (see measured_brdf.h). Sections: albedo · material.
#include "interchange/measured_brdf.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "math/constants.h"
#include "scene/scene.h"

namespace glint {

// --- albedo ---------------------------------------------------------------------------------

namespace {

// ρ(θ_o) = ∫ f_r cos θ_i dω_i = π·E[f_r] over cosine-distributed ω_i (Malley's method:
// uniform points on the unit disc lifted to the hemisphere), on a stratified 32×32 grid of
// cell centres. The BRDF is isotropic, so the azimuth of ω_o does not matter.
glm::vec3 integrateDirectionalAlbedo(const MerlTable& table, float cosThetaOut) {
    constexpr int kGrid = 32;
    const ShadingFrame frame;  // the local frame: n = +z
    const glm::vec3 towardsViewer{std::sqrt(std::max(0.0f, 1.0f - cosThetaOut * cosThetaOut)), 0.0f, cosThetaOut};
    glm::vec3 sum(0.0f);
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const float radiusSquared = (i + 0.5f) / kGrid, azimuth = 2.0f * kPi * (j + 0.5f) / kGrid;
            const float radius = std::sqrt(radiusSquared);
            const glm::vec3 towardsLight{radius * std::cos(azimuth), radius * std::sin(azimuth), std::sqrt(1.0f - radiusSquared)};
            sum += lookupMerlTrilinear(table, towardsLight, towardsViewer, frame);
        }
    return kPi * sum / float(kGrid * kGrid);
}

}  // namespace

std::shared_ptr<const MeasuredBrdf> makeMeasuredBrdf(MerlTable table, std::string path) {
    auto brdf = std::make_shared<MeasuredBrdf>();
    brdf->table = std::move(table);
    brdf->displayName = std::filesystem::path(path).filename().string();
    brdf->path = std::move(path);
    for (int k = 0; k < kMeasuredAlbedoSamples; ++k)
        brdf->directionalAlbedo[k] = integrateDirectionalAlbedo(brdf->table, (k + 0.5f) / kMeasuredAlbedoSamples);
    return brdf;
}

Result<std::shared_ptr<const MeasuredBrdf>> loadMeasuredBrdf(const std::string& path) {
    auto table = loadMerl(path);
    if (!table) return table.error();
    return makeMeasuredBrdf(std::move(*table), path);
}

glm::vec3 evalMeasuredBrdf(const MeasuredBrdf& brdf, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    return lookupMerlTrilinear(brdf.table, wi, wo, frame);
}

glm::vec3 measuredDirectionalAlbedo(const MeasuredBrdf& brdf, float cosThetaOut) {
    const float position = std::clamp(cosThetaOut * kMeasuredAlbedoSamples - 0.5f, 0.0f, float(kMeasuredAlbedoSamples - 1));
    const int below = std::min(static_cast<int>(position), kMeasuredAlbedoSamples - 2);
    const float t = position - below;
    return (1.0f - t) * brdf.directionalAlbedo[below] + t * brdf.directionalAlbedo[below + 1];
}

// --- material -------------------------------------------------------------------------------

Material measuredBrdfMaterial(std::shared_ptr<const MeasuredBrdf> brdf) {
    std::string name = std::filesystem::path(brdf->displayName).stem().string();
    return Material{name.empty() ? "measured" : std::move(name), MeasuredMaterial{std::move(brdf)}};
}

Result<ImportedFile> importMerl(const std::string& path) {
    auto brdf = loadMeasuredBrdf(path);
    if (!brdf) return brdf.error();
    ImportedFile file;
    if (const size_t unmeasured = (*brdf)->table.negativeSamples; unmeasured > 0)
        file.warnings.push_back({{path}, std::to_string(unmeasured) + " samples are negative (not measured) and read as 0"});
    file.materials.push_back({measuredBrdfMaterial(std::move(*brdf)), {}});
    return file;
}

}  // namespace glint
