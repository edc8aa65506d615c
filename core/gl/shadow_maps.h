// ShadowMaps: the depth maps of the lights that cast shadows (a 2D map for directional and spot
// lights, a cube map of distances for point lights), re-rendered only when those lights or the
// geometry change, and the ShadowBlock that shaders/common/shadows.glsl reads. It draws no
// colour and shades nothing; the projections come from core/render/shadow_projection.h.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader_program.h"
#include "light/shadow_settings.h"
#include "scene/scene.h"

namespace glint {

// std140 mirror of ShadowBlock in shaders/common/shadows.glsl.
struct ShadowBlockStd140 {
    glm::mat4 viewProjection[kMaxShadowedLights];
    glm::vec4 origin[kMaxShadowedLights];    // xyz: light position; w: ShadowMapKind
    glm::vec4 settings[kMaxShadowedLights];  // depth bias, normal offset, filter radius [texels], resolution
    glm::vec4 scale[kMaxShadowedLights];     // x: map side per unit clip w [m]; y: far plane [m]
    glm::ivec4 mapOfLight[kMaxLights / 4];   // per LightBlock index: slot or −1
};
static_assert(sizeof(ShadowBlockStd140) == kMaxShadowedLights * (64 + 3 * 16) + kMaxLights * 4, "ShadowBlock std140 layout");

// Uniform-block binding and texture units, kept clear of the ones the renderer and materials use.
inline constexpr unsigned kShadowBinding = 7;
inline constexpr int kFirstShadowTextureUnit = 24;  // 2D maps at 24..27, cube maps at 28..31

// Points a program's shadow samplers (shaders/common/shadows.glsl) at the shadow texture units,
// which any program that includes shading.glsl needs before it draws (two sampler types left on
// unit 0 make the draw fail), and binds its ShadowBlock to kShadowBinding.
void assignShadowSamplerUnits(const ShaderProgram& program);

class ShadowMaps {
public:
    static Result<std::unique_ptr<ShadowMaps>> create(const ShaderSources& sources);
    ~ShadowMaps();
    ShadowMaps(const ShadowMaps&) = delete;
    ShadowMaps& operator=(const ShadowMaps&) = delete;

    // Draws one object's mesh (or a sphere's proxy) with the depth program, after setting the
    // program's per-object placement uniforms.
    using DrawObject = std::function<void(size_t objectIndex, const ShaderProgram& depthProgram)>;
    // Re-renders the maps when a shadowed light or any object changed since the last call, and
    // uploads the ShadowBlock. Changes GL state: framebuffer, viewport, depth test, program.
    void update(const Scene& scene, const DrawObject& drawObject);
    // Binds the maps to their texture units and points `program`'s samplers at them.
    void bind(const ShaderProgram& program) const;
    // How many times update() re-rendered the maps (for tests of the caching).
    long long renderCount() const { return renderCount_; }

private:
    struct Slot {
        GLuint texture2D = 0, cube = 0;
        int resolution2D = 0, resolutionCube = 0;
    };
    ShadowMaps() = default;
    bool needsRender(const Scene& scene) const;
    void renderMaps(const Scene& scene, const DrawObject& drawObject);
    void drawObjects(const Scene& scene, const DrawObject& drawObject) const;

    ShaderProgram depthProgram_;
    GLuint framebuffer_ = 0, uniformBuffer_ = 0;
    Slot slots_[kMaxShadowedLights];
    ShadowBlockStd140 block_{};
    std::vector<float> lightKey_;  // what of the lights the maps depend on, at the last render
    std::string geometryKey_;      // the objects at the last render
    bool rendered_ = false;
    long long renderCount_ = 0;
};

}  // namespace glint
