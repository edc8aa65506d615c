// What two model hooks return (brdf/model.h lists the hooks; brdf/model_traits.h asks them):
// the delta lobes in numbers, and the textbook form the cheapest hand-written shader draws.
#pragma once

#include <optional>

#include <glm/glm.hpp>

namespace glint {

// A model's delta lobes for light arriving from air at cos θ_i: the fractions reflected into the
// mirror direction and transmitted (refracted by Snell's law with the index η, when there is one).
struct DeltaLobeWeights {
    glm::vec3 reflected{0.0f};
    glm::vec3 transmitted{0.0f};
    std::optional<float> refractiveIndex;  // η of the far side relative to air; none: no refraction
};

// A form of a model that is exactly Lambert's ρ/π, plus, where `specular` is set, GGX with
// height-correlated Smith masking and Schlick's Fresnel from F0 (gl/textbook_floor_pass.h).
struct TextbookForm {
    struct Ggx {
        glm::vec3 f0;  // reflectance at normal incidence
        float alpha;   // GGX α
    };
    glm::vec3 diffuseAlbedo;
    std::optional<Ggx> specular;
};

}  // namespace glint
