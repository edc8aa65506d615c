// The classroom Fresnel curves (see fresnel_curves.h): brdf/fresnel.h's exact equations and
// Schlick's approximation sampled against angle, and the marked angles per channel.
#include "classroom/fresnel_curves.h"

#include <algorithm>
#include <cmath>

#include "brdf/fresnel.h"
#include "interchange/material_values.h"
#include "math/constants.h"

namespace glint {
namespace {

constexpr float kFresnelDegrees = kPi / 180.0f;

}  // namespace

std::optional<ComplexIndex> materialComplexIndex(const PlotMaterial& material) {
    if (!material.analytic() || material.sampler) return std::nullopt;  // a table or a shader: no n to read
    const auto table = paramTable(material);
    if (findParam(table, "ior") < 0) return std::nullopt;
    return ComplexIndex{paramValue(material, "ior"),
                        findParam(table, "extinction") >= 0 ? paramValue(material, "extinction") : glm::vec3(0.0f)};
}

std::string kindWithoutIndex(const Material& material) {
    return std::visit(Overloaded{[](const AnalyticMaterial&) { return std::string(); },
                                 [](const CustomMaterial&) { return std::string("a .brdf shader"); },
                                 [](const MeasuredMaterial&) { return std::string("a measured table (MERL)"); }},
                      material.kind);
}

FresnelCurves fresnelCurves(const ComplexIndex& index, bool fromInside, int angleCount) {
    FresnelCurves curves;
    curves.index = index;
    curves.fromInside = fromInside;
    angleCount = std::max(angleCount, 2);
    for (int i = 0; i < angleCount; ++i)
        curves.angleDegrees.push_back(90.0f * static_cast<float>(i) / static_cast<float>(angleCount - 1));
    for (int c = 0; c < 3; ++c) {
        FresnelChannelCurves& channel = curves.channels[c];
        const bool conductor = index.k[c] != 0.0f;
        const float eta = fromInside && !conductor ? 1.0f / index.n[c] : index.n[c];
        channel.relativeIndex = eta;
        // F0 = ((n−1)² + κ²)/((n+1)² + κ²) is the same from either side of a dielectric interface.
        const float f0 = fresnelF0(glm::vec3(index.n[c]), glm::vec3(index.k[c])).x;
        if (!conductor) {
            channel.brewsterDegrees = brewsterAngle(eta) / kFresnelDegrees;
            if (eta < 1.0f) channel.criticalDegrees = criticalAngle(eta) / kFresnelDegrees;
        }
        for (float degrees : curves.angleDegrees) {
            const float cosIncident = std::cos(degrees * kFresnelDegrees);
            const Polarised polarised = conductor ? fresnelConductorPolarised(cosIncident, index.n[c], index.k[c])
                                                  : fresnelDielectricPolarised(cosIncident, eta);
            // Schlick from the dense side takes cos θ_t (Real-Time Rendering, 4th ed., §9.5.1);
            // beyond the critical angle it is 1, as the exact equations.
            float schlickCos = cosIncident;
            if (!conductor && eta < 1.0f) {
                const float sin2Transmitted = (1.0f - cosIncident * cosIncident) / (eta * eta);
                schlickCos = sin2Transmitted >= 1.0f ? 0.0f : std::sqrt(1.0f - sin2Transmitted);
            }
            channel.s.push_back(polarised.s);
            channel.p.push_back(polarised.p);
            channel.unpolarised.push_back(polarised.unpolarised());
            channel.schlick.push_back(fresnelSchlick(glm::vec3(f0), schlickCos).x);
        }
    }
    return curves;
}

}  // namespace glint
