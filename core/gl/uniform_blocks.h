// C++ mirrors of the std140 uniform blocks in shaders/common/uniforms.glsl, size-checked
// (after Filament's UibStructs.h). Change both together.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace glint {

struct alignas(16) FrameBlockStd140 {
    glm::mat4 viewProjection;
    glm::mat4 inverseViewProjection;
    glm::vec4 viewportSize;
    glm::vec4 background;       // rgb: constant background radiance
    glm::vec4 skyZenith;        // rgb: sky gradient radiances
    glm::vec4 skyHorizon;
    glm::vec4 skyGround;
    glm::vec4 ambientRadiance;  // rgb: Σ L_a of the ambient lights
    glm::ivec4 lightCount;
    glm::ivec4 backgroundKind;  // x: 0 constant, 1 sky
};
static_assert(sizeof(FrameBlockStd140) == 2 * 64 + 8 * 16, "FrameBlock std140 layout");

// 16 floats, none spare, so that kMaxLights lights fill the 16 KiB uniform block OpenGL 4.1
// guarantees: the spot's edge and falloff ride in the w of emission and attenuation, and the
// inverse-square law is the distance law (0, 0, 1) rather than a flag.
struct GpuLightStd140 {
    glm::vec4 position;     // w = 1 point or spot, w = 0 directional (xyz towards the light)
    glm::vec4 emission;     // rgb: E⊥ [W/m²] (directional) or intensity Φ/4π [W/sr] (point, spot); w: cos(θ_c − edge width)
    glm::vec4 spotAxis;     // xyz: spot axis; w: cos θ_c, −2 for lights without a cone
    glm::vec4 attenuation;  // xyz: a0, a1, a2 of I/(a0 + a1·d + a2·d²), (0, 0, 1) for the inverse-square law; w: falloff exponent a
};
static_assert(sizeof(GpuLightStd140) == 64, "GpuLight std140 layout");
inline const glm::vec3 kInverseSquareLaw{0.0f, 0.0f, 1.0f};  // GpuLightStd140::attenuation.xyz of a physical light

struct LightBlockStd140 {
    GpuLightStd140 lights[kMaxLights];
};
static_assert(sizeof(LightBlockStd140) == 16384, "LightBlock std140 layout: OpenGL 4.1's guaranteed GL_MAX_UNIFORM_BLOCK_SIZE");

inline constexpr int kMaterialBlockFloats = 48;
struct MaterialBlockStd140 {
    float values[kMaterialBlockFloats];  // vec4 materialValues[12]
};
static_assert(sizeof(MaterialBlockStd140) == 192, "MaterialBlock std140 layout");

enum UniformBinding { kFrameBinding = 0, kLightBinding = 1, kMaterialBinding = 2 };

}  // namespace glint
