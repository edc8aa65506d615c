// Program specialisation preludes (see shader_specialisation.h).
#include "gl/shader_specialisation.h"

#include <array>
#include <string_view>
#include <vector>

#include "brdf/model_registry.h"
#include "brdf/param_table.h"
#include "environment/environment_map.h"
#include "gl/material_glsl.h"

namespace glint {
namespace {

std::string define(const std::string& name, const std::string& value) { return "#define " + name + " " + value + "\n"; }

// The kind constants of shaders/common/lights.glsl.
constexpr std::array<const char*, 3> kLightKinds = {"LIGHT_DIRECTIONAL", "LIGHT_POINT", "LIGHT_ANY"};
constexpr int kAnyLight = 2;

// The kLightKinds entry that a packed light needs.
int lightKind(const GpuLightStd140& light) {
    if (light.position.w == 0.0f) return 0;
    const bool inverseSquare = glm::vec3(light.attenuation) == kInverseSquareLaw, noCone = light.spotAxis.w <= -1.5f;
    return inverseSquare && noCone ? 1 : kAnyLight;
}

// Looped lights: LightBlock indices [first, end), all of kLightKinds[kind].
struct LightRun {
    int first, end, kind;
};

// Appends light i to the last run when it continues it, else starts a run.
void extend(std::vector<LightRun>& runs, int i, int kind) {
    if (!runs.empty() && runs.back().end == i && runs.back().kind == kind) ++runs.back().end;
    else runs.push_back({i, i + 1, kind});
}

// The lights, for shaders/common/shading.glsl. GLINT_LIGHT_SUM(term): term(i, kind, shadow-map slot
// or −1, map kind) summed, unrolled, over the first kMaxUnrolledLights lights and every shadowed one
// (so that each reads its own map). GLINT_LOOPED_LIGHT_SUM(run): run(first, end, kind) summed over
// the other lights' runs of one kind, each a loop whose body is compiled for that kind; where the
// kinds alternate so often that this would make more than kMaxLightRuns loops, one loop of
// LIGHT_ANY per stretch between unrolled lights. So no light runs a shadow lookup it does not need,
// as the generic loop does (which took over from an unrolled sum at 9 lights: the frame went from
// 1.1 to 5.8 times its floor), and the program stops growing past kMaxUnrolledLights, the shadowed
// lights and kMaxLightRuns loops (docs/performance.md, "Many lights").
std::string lightSum(const FrameUniforms& frame, const ShadowBlockStd140& shadows) {
    std::string unrolled;
    std::vector<LightRun> byKind, stretches;
    for (int i = 0; i < frame.frame.lightCount.x; ++i) {
        const int kind = lightKind(frame.lights.lights[i]);
        const int slot = shadows.mapOfLight[i / 4][i % 4];
        if (slot < 0 && i >= kMaxUnrolledLights) {
            extend(byKind, i, kind);
            extend(stretches, i, kAnyLight);
            continue;
        }
        const int mapKind = slot >= 0 ? static_cast<int>(shadows.origin[slot].w) : 0;
        unrolled += (unrolled.empty() ? "term(" : " + term(") + std::to_string(i) + ", " + kLightKinds[kind] + ", " +
                    std::to_string(slot) + ", " + std::to_string(mapKind) + ")";
    }
    std::string looped;
    for (const LightRun& run : byKind.size() <= kMaxLightRuns ? byKind : stretches)
        looped += (looped.empty() ? "run(" : " + run(") + std::to_string(run.first) + ", " + std::to_string(run.end) + ", " +
                  kLightKinds[run.kind] + ")";
    return define("GLINT_LIGHT_SUM(term)", unrolled.empty() ? "vec3(0.0)" : "(" + unrolled + ")") +
           (looped.empty() ? "" : define("GLINT_LOOPED_LIGHT_SUM(run)", "(" + looped + ")"));
}

}  // namespace

std::string frameSpecialisation(const FrameUniforms& frame, const ShadowBlockStd140& shadows, const Environment& environment,
                                const std::optional<DisplaySettings>& fusedDisplay) {
    return lightSum(frame, shadows) + backgroundSpecialisation(frame, environment, fusedDisplay);
}

std::string backgroundSpecialisation(const FrameUniforms& frame, const Environment& environment,
                                     const std::optional<DisplaySettings>& fusedDisplay) {
    std::string text;
    // As EnvironmentTextures::prepare() sets the block's flags.
    const bool environmentOn = environment.enabled();
    text += define("GLINT_ENVIRONMENT_ENABLED", environmentOn ? "1" : "0");
    text += define("GLINT_ENVIRONMENT_SHOWN", environmentOn && environment.showAsBackground ? "1" : "0");
    text += define("GLINT_ENVIRONMENT_PEAKS", std::to_string(environmentOn ? environment.map->peaks.size() : 0));
    text += define("GLINT_BACKGROUND_KIND", std::to_string(frame.frame.backgroundKind.x));
    text += define("GLINT_FUSED_DISPLAY", fusedDisplay ? "1" : "0");
    if (fusedDisplay) text += displaySpecialisation(*fusedDisplay);
    return text;
}

std::string displaySpecialisation(const DisplaySettings& display) {
    // The orders of enums Transfer, ToneMap and Dither (display_encode.glsl, display_quantise.glsl).
    return define("GLINT_DISPLAY_TRANSFER", std::to_string(static_cast<int>(display.transfer))) +
           define("GLINT_DISPLAY_TONE_MAP", std::to_string(static_cast<int>(display.toneMap))) +
           define("GLINT_DISPLAY_DITHER", std::to_string(static_cast<int>(display.dither)));
}

std::string materialSpecialisation(const AnalyticMaterial& material) {
    const auto table = modelInfo(material.model).params;
    const TexturedParams textured = TexturedParams::of(material);
    std::string text;
    int offset = 0;
    for (int index = 0; index < static_cast<int>(table.size()); ++index) {
        const ParamSpec& spec = table[index];
        const float value = offset < static_cast<int>(material.values.size()) ? material.values[offset] : 0.0f;
        // As the generic loadMaterialParams() reads them: int(v + 0.5) and v > 0.5.
        if (spec.kind == ParamKind::Enum) text += define("GLINT_PARAM_" + std::string(spec.name), std::to_string(static_cast<int>(value + 0.5f)));
        if (spec.kind == ParamKind::Bool) text += define("GLINT_PARAM_" + std::string(spec.name), value > 0.5f ? "true" : "false");
        // A layer weighted 0 (OpenPBR's coat, fuzz, thin film, transmission, ...) is compiled out.
        if (spec.layerWeight && value == 0.0f && !textured.has(index))
            text += define("GLINT_PARAM_" + std::string(spec.name), "0.0");
        offset += componentCount(spec.kind);
    }
    return text;
}

}  // namespace glint
