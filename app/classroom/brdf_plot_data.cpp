// The classroom BRDF plot data (see brdf_plot_data.h): f_r sampled along the plane of incidence and
// over the hemisphere, the delta lobes of mirror and glass, and the albedo quadrature. Each plot
// gathers its direction pairs first and evaluates them as one batch (one GPU pass when sampled).
// Section index: evaluation · directions · polar plot · 3D lobe · delta lobes · directional albedo.
#include "classroom/brdf_plot_data.h"

#include <algorithm>
#include <cmath>

#include "brdf/model_traits.h"
#include "classroom/surface_probe.h"
#include "environment/environment_lighting.h"
#include "interchange/measured_brdf.h"
#include "math/constants.h"
#include "render/environment_sampling.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

constexpr float kPlotDegrees = kPi / 180.0f;
const ShadingFrame kPlotFrame{};  // tangent x, bitangent y, normal z

// ---- evaluation ----------------------------------------------------------------------------

// f_r at each (incident[k], outgoing[k]): the sampler, the measured table or the model.
std::vector<glm::vec3> plotEval(const PlotMaterial& material, std::span<const glm::vec3> incident,
                                std::span<const glm::vec3> outgoing) {
    GLINT_CHECK(incident.size() == outgoing.size());
    if (material.sampler) {
        std::vector<glm::vec3> sampled = material.sampler(incident, outgoing);
        GLINT_CHECK(sampled.size() == incident.size());
        return sampled;
    }
    std::vector<glm::vec3> reflectance(incident.size());
    for (size_t k = 0; k < incident.size(); ++k)
        reflectance[k] = std::visit(
            Overloaded{[&](const AnalyticMaterial& analytic) {
                           return evalBrdf(analytic.model, analytic.values, incident[k], outgoing[k], kPlotFrame);
                       },
                       [&](const MeasuredMaterial& measured) {
                           return evalMeasuredBrdf(*measured.brdf, incident[k], outgoing[k], kPlotFrame);
                       },
                       [](const CustomMaterial&) -> glm::vec3 {
                           GLINT_CHECK(!"a .brdf material comes with its sampler");
                           return {};
                       }},
            material.kind);
    return reflectance;
}

// The albedo quadrature's outgoing directions (see directionalAlbedo) for one ω_i, appended.
void appendAlbedoDirections(glm::vec3 wi, int thetaSteps, int phiSteps, std::vector<glm::vec3>& incident,
                            std::vector<glm::vec3>& outgoing) {
    for (int t = 0; t < thetaSteps; ++t) {
        const float sin2Theta = (static_cast<float>(t) + 0.5f) / static_cast<float>(thetaSteps);  // u midpoints
        const float sinTheta = std::sqrt(sin2Theta);
        const float cosTheta = std::sqrt(1.0f - sin2Theta);
        for (int p = 0; p < phiSteps; ++p) {
            const float phi = 2.0f * kPi * (static_cast<float>(p) + 0.5f) / static_cast<float>(phiSteps);
            incident.push_back(wi);
            outgoing.push_back({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
        }
    }
}

// ∫ f cos θ dω = ∫∫ f · ½ du dφ with du = 1/thetaSteps, dφ = 2π/phiSteps, over one ω_i's samples.
glm::vec3 albedoFromSamples(std::span<const glm::vec3> reflectance, int thetaSteps, int phiSteps) {
    glm::vec3 sum(0.0f);
    for (const glm::vec3& value : reflectance) sum += value;
    return sum * (kPi / static_cast<float>(thetaSteps * phiSteps));
}

}  // namespace

// ---- directions ----------------------------------------------------------------------------

std::optional<PlotMaterial> plotMaterialFrom(const Material& material) {
    if (material.custom()) return std::nullopt;
    return PlotMaterial{material, {}};
}

bool samePlotMaterial(const PlotMaterial& a, const PlotMaterial& b) {
    const auto source = [](const Material& material) {  // the model's entry, or the .brdf or MERL file itself
        return std::visit(Overloaded{[](const AnalyticMaterial& analytic) -> const void* { return &modelInfo(analytic.model); },
                                     [](const auto& file) -> const void* { return file.brdf.get(); }},
                          material.kind);
    };
    return a.name == b.name && source(a) == source(b) && std::ranges::equal(paramValues(a), paramValues(b)) &&
           static_cast<bool>(a.sampler) == static_cast<bool>(b.sampler);
}

glm::vec3 plotIncidentDirection(float incidenceRadians) {
    return {-std::sin(incidenceRadians), 0.0f, std::cos(incidenceRadians)};
}

glm::vec3 plotOutgoingDirection(float outgoingRadians) {
    return {std::sin(outgoingRadians), 0.0f, std::cos(outgoingRadians)};
}

float plotLuminance(glm::vec3 rgb) { return 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b; }

// ---- environment -------------------------------------------------------------------------

std::optional<PlotEnvironmentAccuracy> plotEnvironmentAccuracy(const PlotMaterial& material, const Environment& environment,
                                                               float incidenceDegrees) {
    const AnalyticMaterial* analytic = material.analytic();
    if (!environment.enabled() || !analytic || material.sampler || !modelInfo(analytic->model).glslEnvironment)
        return std::nullopt;
    // The plot's frame turned so that its normal is +y and its +x (the mirror side) is +z.
    const ShadingFrame frame{glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    const glm::vec3 wo = frame.toWorld(plotOutgoingDirection(incidenceDegrees * kPlotDegrees));
    PlotEnvironmentAccuracy accuracy;
    accuracy.method = environmentApproximation(analytic->model, analytic->values, environment);
    accuracy.preview = environmentLighting(analytic->model, analytic->values, wo, frame, environment);
    accuracy.truth = sampleEnvironmentLighting(analytic->model, analytic->values, wo, frame, environment, 1u,
                                               kProbeEnvironmentSamples);
    return accuracy;
}

// ---- polar plot ----------------------------------------------------------------------------

PolarPlotData polarPlotData(const PlotMaterial& material, float incidenceDegrees, int sampleCount) {
    PolarPlotData data;
    data.incidenceDegrees = incidenceDegrees;
    sampleCount = std::max(sampleCount, 2);
    const std::vector<glm::vec3> incident(sampleCount, plotIncidentDirection(incidenceDegrees * kPlotDegrees));
    std::vector<glm::vec3> outgoing;
    for (int i = 0; i < sampleCount; ++i) {
        const float outgoingDegrees = -90.0f + 180.0f * static_cast<float>(i) / static_cast<float>(sampleCount - 1);
        data.outgoingDegrees.push_back(outgoingDegrees);
        outgoing.push_back(plotOutgoingDirection(outgoingDegrees * kPlotDegrees));
    }
    data.reflectance = plotEval(material, incident, outgoing);
    for (int i = 0; i < sampleCount; ++i)
        data.cosineWeighted.push_back(data.reflectance[i] * std::max(std::cos(data.outgoingDegrees[i] * kPlotDegrees), 0.0f));
    return data;
}

// ---- 3D lobe -------------------------------------------------------------------------------

LobeMesh lobeMesh(const PlotMaterial& material, float incidenceDegrees, int thetaSteps, int phiSteps) {
    LobeMesh mesh;
    mesh.incidenceDegrees = incidenceDegrees;
    mesh.thetaSteps = std::max(thetaSteps, 1);
    mesh.phiSteps = std::max(phiSteps, 3);
    std::vector<glm::vec3> outgoing;
    for (int t = 0; t <= mesh.thetaSteps; ++t) {
        // The last row sits just above the horizon, where cos θ_o is still positive.
        const float theta = std::min(static_cast<float>(t) / static_cast<float>(mesh.thetaSteps), 0.999f) * 0.5f * kPi;
        for (int p = 0; p < mesh.phiSteps; ++p) {
            const float phi = 2.0f * kPi * static_cast<float>(p) / static_cast<float>(mesh.phiSteps);
            outgoing.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
        }
    }
    const std::vector<glm::vec3> incident(outgoing.size(), plotIncidentDirection(incidenceDegrees * kPlotDegrees));
    const std::vector<glm::vec3> reflectance = plotEval(material, incident, outgoing);
    for (size_t k = 0; k < outgoing.size(); ++k) {
        const float radius = std::max(plotLuminance(reflectance[k]) * outgoing[k].z, 0.0f);
        mesh.points.push_back(radius * outgoing[k]);
        mesh.largestRadius = std::max(mesh.largestRadius, radius);
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
    const AnalyticMaterial* analytic = material.analytic();
    if (!analytic || material.sampler) return lobes;  // a table or a shader: f_r is all there is
    const std::optional<DeltaLobeWeights> weights = deltaLobeWeights(analytic->model, analytic->values, cosIncident);
    if (!weights) return lobes;
    lobes.hasReflection = true;
    lobes.reflectedDirection = mirrored;
    lobes.reflectedWeight = weights->reflected;
    if (const std::optional<float> eta = weights->refractiveIndex) {
        // Snell: sin θ_t = sin θ_i / η.
        const float sinTransmitted = std::sin(incidence) / *eta;
        const float cosTransmitted = std::sqrt(std::max(0.0f, 1.0f - sinTransmitted * sinTransmitted));
        lobes.hasTransmission = true;
        lobes.transmittedDirection = {sinTransmitted, 0.0f, -cosTransmitted};
        lobes.transmittedWeight = weights->transmitted;
        lobes.transmittedDegrees = std::asin(sinTransmitted) / kPlotDegrees;
    }
    return lobes;
}

// ---- directional albedo --------------------------------------------------------------------

glm::vec3 directionalAlbedo(const PlotMaterial& material, float incidenceDegrees, int thetaSteps, int phiSteps) {
    std::vector<glm::vec3> incident, outgoing;
    appendAlbedoDirections(plotIncidentDirection(incidenceDegrees * kPlotDegrees), thetaSteps, phiSteps, incident, outgoing);
    return albedoFromSamples(plotEval(material, incident, outgoing), thetaSteps, phiSteps);
}

AlbedoCurve albedoCurve(const PlotMaterial& material, int angleCount, int thetaSteps, int phiSteps) {
    AlbedoCurve curve;
    angleCount = std::max(angleCount, 2);
    std::vector<glm::vec3> incident, outgoing;  // every angle's samples: one batch
    for (int i = 0; i < angleCount; ++i) {
        const float incidenceDegrees = std::min(90.0f * static_cast<float>(i) / static_cast<float>(angleCount - 1), 89.5f);
        curve.incidenceDegrees.push_back(incidenceDegrees);
        appendAlbedoDirections(plotIncidentDirection(incidenceDegrees * kPlotDegrees), thetaSteps, phiSteps, incident, outgoing);
    }
    const std::vector<glm::vec3> reflectance = plotEval(material, incident, outgoing);
    const size_t perAngle = static_cast<size_t>(thetaSteps) * static_cast<size_t>(phiSteps);
    for (int i = 0; i < angleCount; ++i) {
        const glm::vec3 albedo =
            albedoFromSamples(std::span(reflectance).subspan(static_cast<size_t>(i) * perAngle, perAngle), thetaSteps, phiSteps);
        curve.albedo.push_back(albedo);
        curve.largestAlbedo = std::max({curve.largestAlbedo, albedo.r, albedo.g, albedo.b});
    }
    // A margin above the quadrature's error keeps exact conservers (white Lambert: 1.000) unflagged.
    curve.exceedsOne = curve.largestAlbedo > 1.001f;
    return curve;
}

}  // namespace glint
