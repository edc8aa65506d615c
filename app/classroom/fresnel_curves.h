// Numbers behind the classroom Fresnel plot (issue 7): R_s, R_p, their unpolarised mean and
// Schlick's approximation against incidence angle, per RGB channel, for a complex index n + iκ,
// with Brewster's and the critical angle. Uses brdf/fresnel.h; draws nothing (app/classroom).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "classroom/brdf_plot_data.h"

namespace glint {

// The complex index of refraction n + iκ a material's Fresnel term uses, per channel.
struct ComplexIndex {
    glm::vec3 n{1.5f};
    glm::vec3 k{0.0f};
};

// The index of a material whose table has an "ior" parameter (scalar or per channel) and
// optionally "extinction" (κ); nullopt for models without one (Lambert, Phong, …), for a measured
// table and for a sampled .brdf shader (neither declares an index).
std::optional<ComplexIndex> materialComplexIndex(const PlotMaterial& material);
// What a material that declares no index is, for the message that says so ("a measured table
// (MERL)", "a .brdf shader"); empty for a model (which may still have none).
std::string kindWithoutIndex(const Material& material);

struct FresnelChannelCurves {
    std::vector<float> s, p, unpolarised, schlick;  // reflectance at each angle
    float brewsterDegrees = -1.0f;   // R_p = 0 (dielectric channels, κ = 0); < 0: none
    float criticalDegrees = -1.0f;   // total internal reflection beyond it (relative η < 1); < 0: none
    float relativeIndex = 1.0f;      // η = n_transmitted / n_incident as used
};

struct FresnelCurves {
    ComplexIndex index;
    bool fromInside = false;                        // light inside the material: η = 1/n
    std::vector<float> angleDegrees;                // 0 … 90
    std::array<FresnelChannelCurves, 3> channels;   // R, G, B
};

// fromInside: the light travels inside the material towards air (η = 1/n; conductors keep their
// index, light does not travel inside a metal). Schlick uses F0 of the same interface.
FresnelCurves fresnelCurves(const ComplexIndex& index, bool fromInside = false, int angleCount = 181);

}  // namespace glint
