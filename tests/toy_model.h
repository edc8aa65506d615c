// A test-only BRDF model: proof that a model is only its own files. It joins no list of Glint's;
// model_machinery_test.cpp runs it through the generic machinery (unpacking checked against the
// table, dispatch, GLSL names and constants, the Markdown reference) with no edit elsewhere.
#pragma once

#include <glm/glm.hpp>

#include "brdf/model.h"
#include "math/constants.h"
#include "math/frame.h"

namespace glint::test {

enum class ToyFalloff { Linear = 0, Squared = 1 };

inline constexpr EnumOption kToyFalloffOptions[] = {
    {"linear", "cos θ_o"},
    {"squared", "cos² θ_o"},
};

inline constexpr ParamSpec kToyTable[] = {
    {.name = "tint", .label = "Tint", .unit = "", .kind = ParamKind::Color, .defaultValue = {0.25f, 0.5f, 0.75f},
     .help = "Reflectance ρ"},
    {.name = "strength", .label = "Strength", .unit = "", .kind = ParamKind::Scalar, .sliderMax = 2, .validMax = 2,
     .defaultValue = {1.5f, 0, 0}, .help = "Scale on ρ"},
    {.name = "falloff", .label = "Falloff", .unit = "", .kind = ParamKind::Enum, .defaultValue = {1, 0, 0},
     .options = kToyFalloffOptions, .help = "Weight towards the viewer"},
    {.name = "double_sided", .label = "Double-sided", .unit = "", .kind = ParamKind::Bool, .defaultValue = {1, 0, 0},
     .help = "Reflects from the back too"},
};

struct ToySheen {
    struct Params {
        glm::vec3 tint;
        float strength;
        ToyFalloff falloff;
        bool doubleSided;
    };
    static constexpr const char* id = "toy_sheen";
    static constexpr const char* label = "Toy sheen";
    static constexpr const char* citation = "none: a test model";
    static constexpr bool reciprocal = false, energyConserving = false;
    static constexpr const auto& params = kToyTable;
    static glm::vec3 eval(const Params& p, glm::vec3, glm::vec3 wo, const ShadingFrame& frame) {
        const float cosOut = frame.cosTheta(wo);
        return p.tint * p.strength * kInvPi * (p.falloff == ToyFalloff::Squared ? cosOut * cosOut : cosOut);
    }
    static glm::vec3 ambientReflectance(const Params& p, glm::vec3, const ShadingFrame&) { return p.tint; }
};

}  // namespace glint::test
