// The environment on the GPU: uploads a scene's environment map (base radiance, prefiltered
// levels and the irradiance map as a texture array; the lobes' albedo tables once) when the map changes, never per frame, and
// each frame fills the EnvironmentBlock (rotation, intensity, flags, sizes, the rest's mean, peak lights) and binds the textures.
// C++ mirror of the block in shaders/common/environment.glsl. It computes nothing itself.
#pragma once

#include <memory>

#include <glad/gl.h>
#include <glm/glm.hpp>

#include "environment/environment_map.h"
#include "gl/shader_program.h"
#include "scene/environment.h"

namespace glint {

struct alignas(16) EnvironmentBlockStd140 {
    glm::vec4 transform;  // x: cos(rotation), y: sin(rotation), z: intensity, w: peaks' minimum α
    glm::ivec4 flags;     // x: enabled, y: shown as background, z: peak lights
    glm::ivec4 sizes;     // x, y: base size; z, w: prefiltered size
    glm::vec4 residualMean;  // rgb: mean radiance of the map less its peaks, × the intensity
    glm::vec4 peakDirections[kMaxPeakLights];   // xyz: world space (turned by the rotation); w: sine of its radius
    glm::vec4 peakIrradiances[kMaxPeakLights];  // rgb [W/m²], × the intensity
};
static_assert(sizeof(EnvironmentBlockStd140) == (4 + 2 * kMaxPeakLights) * 16, "EnvironmentBlock std140 layout");

// Binding point and texture units, clear of the renderer's blocks 0-2 and low units.
inline constexpr GLuint kEnvironmentBinding = 6;
inline constexpr GLint kEnvironmentBaseUnit = 13, kEnvironmentPrefilteredUnit = 14, kEnvironmentLobeAlbedoUnit = 15;

class EnvironmentTextures {
public:
    EnvironmentTextures();  // needs a current context with GL loaded
    ~EnvironmentTextures();
    EnvironmentTextures(const EnvironmentTextures&) = delete;
    EnvironmentTextures& operator=(const EnvironmentTextures&) = delete;

    // Points a program's EnvironmentBlock and samplers at this object's binding and units.
    static void connect(const ShaderProgram& program);
    // Uploads the map if it is not the one on the GPU, fills the block, binds everything.
    void prepare(const Environment& environment);

private:
    GLuint baseTexture_ = 0, prefilteredTexture_ = 0, lobeAlbedoTexture_ = 0, uniformBuffer_ = 0;
    const void* uploadedMap_ = nullptr;
    std::shared_ptr<const void> keepAlive_;  // the uploaded map, so its address stays unique
};

}  // namespace glint
