// The classroom BRDF plot data (see brdf_plot_data.h): evalBrdf sampled along the plane of
// incidence and over the hemisphere, the delta lobes of mirror and glass, and the albedo quadrature.
// Section index: directions · polar plot · 3D lobe · delta lobes · directional albedo.
#include "classroom/brdf_plot_data.h"

#include <algorithm>
#include <cmath>

#include "brdf/fresnel.h"
#include "brdf/glass.h"
#include "brdf/mirror.h"
#include "math/constants.h"

namespace glint {
namespace {

constexpr float kPlotDegrees = kPi / 180.0f;
const ShadingFrame kPlotFrame{};  // tangent x, bitangent y, normal z

glm::vec3 plotEval(const PlotMaterial& material, glm::vec3 wi, glm::vec3 wo) {
    return evalBrdf(material.model, material.values, wi, wo, kPlotFrame);
}

}  // namespace

// ---- directions ----------------------------------------------------------------------------

std::optional<PlotMaterial> plotMaterialFrom(const Material& material) {
    if (material.custom) return std::nullopt;
    return PlotMaterial{material.name, material.model, material.values};
}

glm::vec3 plotIncidentDirection(float incidenceRadians) {
    return {-std::sin(incidenceRadians), 0.0f, std::cos(incidenceRadians)};
}

glm::vec3 plotOutgoingDirection(float outgoingRadians) {
    return {std::sin(outgoingRadians), 0.0f, std::cos(outgoingRadians)};
}

float plotLuminance(glm::vec3 rgb) { return 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b; }

// ---- polar plot ----------------------------------------------------------------------------

PolarPlotData polarPlotData(const PlotMaterial& material, float incidenceDegrees, int sampleCount) {
    PolarPlotData data;
    data.incidenceDegrees = incidenceDegrees;
    sampleCount = std::max(sampleCount, 2);
    const glm::vec3 wi = plotIncidentDirection(incidenceDegrees * kPlotDegrees);
    for (int i = 0; i < sampleCount; ++i) {
        const float outgoingDegrees = -90.0f + 180.0f * static_cast<float>(i) / static_cast<float>(sampleCount - 1);
        const float outgoing = outgoingDegrees * kPlotDegrees;
        const glm::vec3 reflectance = plotEval(material, wi, plotOutgoingDirection(outgoing));
        data.outgoingDegrees.push_back(outgoingDegrees);
        data.reflectance.push_back(reflectance);
        data.cosineWeighted.push_back(reflectance * std::max(std::cos(outgoing), 0.0f));
    }
    return data;
}

// ---- 3D lobe -------------------------------------------------------------------------------

LobeMesh lobeMesh(const PlotMaterial& material, float incidenceDegrees, int thetaSteps, int phiSteps) {
    LobeMesh mesh;
    mesh.incidenceDegrees = incidenceDegrees;
    mesh.thetaSteps = std::max(thetaSteps, 1);
    mesh.phiSteps = std::max(phiSteps, 3);
    const glm::vec3 wi = plotIncidentDirection(incidenceDegrees * kPlotDegrees);
    for (int t = 0; t <= mesh.thetaSteps; ++t) {
        // The last row sits just above the horizon, where cos θ_o is still positive.
        const float theta = std::min(static_cast<float>(t) / static_cast<float>(mesh.thetaSteps), 0.999f) * 0.5f * kPi;
        for (int p = 0; p < mesh.phiSteps; ++p) {
            const float phi = 2.0f * kPi * static_cast<float>(p) / static_cast<float>(mesh.phiSteps);
            const glm::vec3 wo{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
            const float radius = std::max(plotLuminance(plotEval(material, wi, wo)) * wo.z, 0.0f);
            mesh.points.push_back(radius * wo);
            mesh.largestRadius = std::max(mesh.largestRadius, radius);
        }
    }
    return mesh;
}

// ---- delta lobes ---------------------------------------------------------------------------

DeltaLobes deltaLobes(const PlotMaterial& material, float incidenceDegrees) {
    DeltaLobes lobes;
    const float incidence = incidenceDegrees * kPlotDegrees;
    const float cosIncident = std::cos(incidence);
    const glm::vec3 wi = plotIncidentDirection(incidence);
    const glm::vec3 mirrored{-wi.x, -wi.y, wi.z};
    if (material.model == BrdfModel::Mirror) {
        const MirrorParams mirror = unpackMirror(material.values.data());
        lobes.hasReflection = true;
        lobes.reflectedDirection = mirrored;
        lobes.reflectedWeight = fresnelComplexIndex(cosIncident, mirror.ior, mirror.extinction);
    } else if (material.model == BrdfModel::Glass) {
        const GlassParams glass = unpackGlass(material.values.data());
        // Snell: sin θ_t = sin θ_i / η; from air into glass (η ≥ 1) there is no total internal reflection.
        const float sinTransmitted = std::sin(incidence) / glass.ior;
        const float cosTransmitted = std::sqrt(std::max(0.0f, 1.0f - sinTransmitted * sinTransmitted));
        const float reflected = glass.transparency == GlassTransparency::Fresnel
                                    ? fresnelDielectric(cosIncident, glass.ior)
                                    : 1.0f - glass.transmission;
        lobes.hasReflection = lobes.hasTransmission = true;
        lobes.reflectedDirection = mirrored;
        lobes.reflectedWeight = glm::vec3(reflected);
        lobes.transmittedDirection = {sinTransmitted, 0.0f, -cosTransmitted};
        lobes.transmittedWeight = glm::vec3(1.0f - reflected);
        lobes.transmittedDegrees = std::asin(sinTransmitted) / kPlotDegrees;
    }
    return lobes;
}

// ---- directional albedo --------------------------------------------------------------------

glm::vec3 directionalAlbedo(const PlotMaterial& material, float incidenceDegrees, int thetaSteps, int phiSteps) {
    const glm::vec3 wi = plotIncidentDirection(incidenceDegrees * kPlotDegrees);
    glm::vec3 sum(0.0f);
    for (int t = 0; t < thetaSteps; ++t) {
        const float sin2Theta = (static_cast<float>(t) + 0.5f) / static_cast<float>(thetaSteps);  // u midpoints
        const float sinTheta = std::sqrt(sin2Theta);
        const float cosTheta = std::sqrt(1.0f - sin2Theta);
        for (int p = 0; p < phiSteps; ++p) {
            const float phi = 2.0f * kPi * (static_cast<float>(p) + 0.5f) / static_cast<float>(phiSteps);
            const glm::vec3 wo{sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
            sum += plotEval(material, wi, wo);
        }
    }
    // ∫ f cos θ dω = ∫∫ f · ½ du dφ with du = 1/thetaSteps, dφ = 2π/phiSteps.
    return sum * (kPi / static_cast<float>(thetaSteps * phiSteps));
}

AlbedoCurve albedoCurve(const PlotMaterial& material, int angleCount, int thetaSteps, int phiSteps) {
    AlbedoCurve curve;
    angleCount = std::max(angleCount, 2);
    for (int i = 0; i < angleCount; ++i) {
        const float incidenceDegrees = std::min(90.0f * static_cast<float>(i) / static_cast<float>(angleCount - 1), 89.5f);
        const glm::vec3 albedo = directionalAlbedo(material, incidenceDegrees, thetaSteps, phiSteps);
        curve.incidenceDegrees.push_back(incidenceDegrees);
        curve.albedo.push_back(albedo);
        curve.largestAlbedo = std::max({curve.largestAlbedo, albedo.r, albedo.g, albedo.b});
    }
    // A margin above the quadrature's error keeps exact conservers (white Lambert: 1.000) unflagged.
    curve.exceedsOne = curve.largestAlbedo > 1.001f;
    return curve;
}

}  // namespace glint
