// The surface probe's text (see probe_text.h).
// Sections: numbers · one light · total · display chain · the report.
#include "classroom/probe_text.h"

#include <cmath>
#include <sstream>

#include "light/light_type_name.h"
#include "util/text.h"

namespace glint {
namespace {

std::string probeVector(glm::vec3 v) {
    return "(" + formatProbeNumber(v.x) + ", " + formatProbeNumber(v.y) + ", " + formatProbeNumber(v.z) + ")";
}

std::string probeDegrees(float degrees) { return formatNumber(degrees, "%.1f°"); }

const char* toneMapName(ToneMap toneMap) {
    switch (toneMap) {
        case ToneMap::None: return "none";
        case ToneMap::Reinhard: return "Reinhard x/(1+x)";
        case ToneMap::AcesFilmic: return "ACES filmic";
        case ToneMap::PbrNeutral: return "Khronos PBR Neutral";
    }
    return "none";
}

}  // namespace

// --- numbers ---

std::string formatProbeNumber(float value) {
    const float magnitude = std::abs(value);
    if (value == 0.0f) return "0";
    if (!std::isfinite(value)) return value > 0 ? "∞" : "-∞";
    if (magnitude < 1e-3f || magnitude >= 1e5f) return formatNumber(value, "%.3e");
    if (magnitude < 10.0f) return formatNumber(value, "%.3f");
    if (magnitude < 100.0f) return formatNumber(value, "%.2f");
    return formatNumber(value, "%.1f");
}

std::string formatProbeRgb(glm::vec3 value) {
    const float largest = std::max({std::abs(value.r), std::abs(value.g), std::abs(value.b)});
    if (std::abs(value.r - value.g) <= 1e-6f * largest && std::abs(value.r - value.b) <= 1e-6f * largest)
        return formatProbeNumber(value.g);
    return probeVector(value);
}

// --- one light ---

std::vector<std::string> probeLightEquation(const ProbeLight& light) {
    std::vector<std::string> lines;
    const std::string filter = light.source.color == glm::vec3(1.0f) ? "" : " × colour " + formatProbeRgb(light.source.color);
    // E⊥: directional M; point Φ/(4π d²) (inverse-square law), spot × its cone factor.
    if (light.type == LightType::Directional) {
        if (filter.empty()) lines.push_back("E⊥ = M = " + formatProbeRgb(light.normalIrradiance) + " W/m²");
        else lines.push_back("E⊥ = M·colour = " + formatProbeNumber(light.source.amount) + " W/m²" + filter + " = " +
                             formatProbeRgb(light.normalIrradiance) + " W/m²");
    } else {
        const std::string spot = light.type == LightType::Spot ? "·spot" : "";
        const std::string spotValue = light.type == LightType::Spot ? " × " + formatProbeNumber(light.spotFactor) : "";
        if (light.classicAttenuation)
            lines.push_back("E⊥ = Φ/4π · 1/(a0 + a1·d + a2·d²)" + spot + " = " + formatProbeNumber(light.source.amount) +
                            " W/4π × " + formatProbeNumber(light.distanceFactor) + " 1/m²" + spotValue + filter + " = " +
                            formatProbeRgb(light.normalIrradiance) + " W/m²");
        else
            lines.push_back("E⊥ = Φ/(4π d²)" + spot + " = " + formatProbeNumber(light.source.amount) + " W / (4π × (" +
                            formatProbeNumber(light.distance) + " m)²)" + spotValue + filter + " = " +
                            formatProbeRgb(light.normalIrradiance) + " W/m²");
    }
    if (light.behindSurface) {
        lines.push_back("E = 0: the light is behind the surface (cos θ = " + formatProbeNumber(light.cosTheta) + ")");
    } else if (light.shadowed) {
        lines.push_back("E = 0: in shadow (the shadow ray hits an object)");
    } else {
        lines.push_back("E = E⊥·cos θ = " + formatProbeRgb(light.normalIrradiance) + " W/m² × " +
                        formatProbeNumber(light.cosTheta) + " = " + formatProbeRgb(light.irradiance) + " W/m²");
    }
    lines.push_back("L = f_r·E = " + formatProbeRgb(light.brdf) + " 1/sr × " + formatProbeRgb(light.irradiance) +
                    " W/m² = " + formatProbeRgb(light.radiance) + " W/(sr·m²)");
    return lines;
}

// --- total ---

std::string probeTotalEquation(const ProbeResult& result) {
    if (!result.hitSurface) return "L = L_background = " + formatProbeRgb(result.radiance) + " W/(sr·m²)";
    std::string symbols, values;
    int terms = 0;
    glm::vec3 pointTotal(0.0f);
    auto add = [&](const std::string& symbol, glm::vec3 value) {
        symbols += (symbols.empty() ? "" : " + ") + symbol;
        values += (values.empty() ? "" : " + ") + formatProbeRgb(value);
        pointTotal += value;
        ++terms;
    };
    glm::vec3 direct(0.0f);
    for (const ProbeLight& light : result.lights) direct += light.radiance;
    add("Σ f_r·E", direct);
    if (result.ambientRadiance != glm::vec3(0.0f)) add("k_a·L_a", result.ambientReflectance * result.ambientRadiance);
    if (result.environment != glm::vec3(0.0f)) add("L_environment", result.environment);
    if (result.specular != glm::vec3(0.0f)) add("L_mirror/glass (traced)", result.specular);
    const std::string sum = terms > 1 ? symbols + " = " + values : symbols;
    std::string line = "L = " + sum + " = ";
    if (result.gouraud)
        line = "L at the point = " + sum + " = " + formatProbeRgb(pointTotal) +
               " W/(sr·m²); the Gouraud pixel interpolates its corners' radiance: L = ";
    return line + formatProbeRgb(result.radiance) + " W/(sr·m²)";
}

// --- environment ---

std::string environmentAccuracyText(const std::string& method, glm::vec3 preview, glm::vec3 truth) {
    const float truthSum = glm::dot(truth, glm::vec3(1.0f));
    const float previewSum = glm::dot(preview, glm::vec3(1.0f));
    std::string error = truthSum > 0.0f ? formatNumber(100.0f * (previewSum / truthSum - 1.0f), "%+.1f%%") : "n/a";
    return "L_environment by " + method + ": " + formatProbeRgb(preview) + "; Monte-Carlo (" +
           std::to_string(kProbeEnvironmentSamples) + " samples) " + formatProbeRgb(truth) + " W/(sr·m²): error " + error;
}

std::string probeEnvironmentLine(const ProbeResult& result) {
    if (result.environmentMethod.empty()) return {};
    return environmentAccuracyText(result.environmentMethod, result.environment, result.environmentTruth);
}

// --- display chain ---

std::vector<std::string> probeDisplayEquation(const ProbeResult& result) {
    const DisplaySettings& display = result.displaySettings;
    const std::string encoding =
        display.transfer == Transfer::Srgb ? "sRGB" : formatNumber(display.gamma, "^(1/%.2f)");
    auto channelLine = [&](const ProbeDisplayChannel& channel, const std::string& name) {
        return name + formatProbeNumber(channel.radiance) + " × 2^" + formatNumber(display.exposureStops, "%.2f") +
               " = " + formatProbeNumber(channel.exposed) + " → tone map " + toneMapName(display.toneMap) + " " +
               formatProbeNumber(channel.toneMapped) + " → clamp " + formatProbeNumber(channel.clamped) + " → " + encoding +
               " " + formatProbeNumber(channel.encoded) + " → 8-bit " + std::to_string(channel.value8);
    };
    const auto& d = result.display;
    if (d[0].radiance == d[1].radiance && d[1].radiance == d[2].radiance) return {channelLine(d[0], "")};
    return {channelLine(d[0], "R: "), channelLine(d[1], "G: "), channelLine(d[2], "B: ")};
}

// --- the report ---

std::string probeReport(const ProbeResult& result) {
    std::ostringstream out;
    out << "probe pixel (" << result.pixelX << ", " << result.pixelY << ") of " << result.width << "x" << result.height
        << "\n";
    if (!result.hitSurface) {
        out << "no surface: the ray sees the background\n";
    } else {
        out << "object \"" << result.objectName << "\", material \"" << result.materialName << "\" (" << result.modelLabel
            << ")\n";
        out << "point " << probeVector(result.position) << " m, " << formatProbeNumber(result.hitDistance)
            << " m along the ray\n";
        out << "N " << probeVector(result.normal) << "\nV " << probeVector(result.towardsViewer) << "\n";
        if (result.gpuOnlyMaterial) {
            out << "custom .brdf material: evaluated on the GPU only, the probe cannot break it down\n";
            return out.str();
        }
        if (result.viewTransmitted) {
            const ProbeRefraction& t = *result.viewTransmitted;
            out << "view ray: η " << formatProbeNumber(t.etaIncident) << " → " << formatProbeNumber(t.etaTransmitted)
                << ", θ_i " << probeDegrees(t.incidentDegrees);
            if (t.criticalDegrees) out << ", critical angle " << probeDegrees(*t.criticalDegrees);
            if (t.totalInternalReflection) out << ": total internal reflection, no T\n";
            else out << ", θ_t " << probeDegrees(t.transmittedDegrees) << ", T " << probeVector(t.direction) << "\n";
        }
        for (const ProbeLight& light : result.lights) {
            out << "light " << light.lightIndex + 1 << " \"" << light.name << "\" (" << lightTypeName(light.type) << "): "
                << light.source.symbol << " = " << formatProbeNumber(light.source.amount) << " " << light.source.unit
                << " (" << formatProbeNumber(light.source.photometric) << " " << light.source.photometricUnit << ")";
            if (std::isfinite(light.distance)) out << ", d = " << formatProbeNumber(light.distance) << " m";
            out << "\n  L " << probeVector(light.towardsLight) << ", H " << probeVector(light.halfVector) << ", R "
                << probeVector(light.mirror) << "\n";
            out << "  θ_i = " << probeDegrees(light.incidentDegrees) << ", θ_r = " << probeDegrees(light.reflectedDegrees)
                << ", ∠(N,H) = " << probeDegrees(light.halfDegrees) << ", ∠(R,V) = "
                << probeDegrees(light.mirrorViewDegrees) << ", cos θ = " << formatProbeNumber(light.cosTheta) << "\n";
            if (light.transmitted) {
                if (light.transmitted->totalInternalReflection) out << "  T: total internal reflection\n";
                else out << "  T " << probeVector(light.transmitted->direction) << ", θ_t = "
                         << probeDegrees(light.transmitted->transmittedDegrees) << "\n";
            }
            for (const std::string& line : probeLightEquation(light)) out << "  " << line << "\n";
            out << "  photometric: E = " << formatProbeNumber(light.illuminance) << " lx, L = "
                << formatProbeNumber(light.luminance) << " nit\n";
        }
        if (result.ambientRadiance != glm::vec3(0.0f))
            out << "ambient: k_a = " << formatProbeRgb(result.ambientReflectance)
                << ", L_a = " << formatProbeRgb(result.ambientRadiance) << " W/(sr·m²)\n";
    }
    if (const std::string line = probeEnvironmentLine(result); !line.empty()) out << "environment: " << line << "\n";
    out << probeTotalEquation(result) << " (" << formatProbeNumber(result.luminance) << " nit)\n";
    for (const std::string& line : probeDisplayEquation(result)) out << "display: " << line << "\n";
    return out.str();
}

}  // namespace glint
