// ShadowMaps: the depth maps of the lights that cast shadows (a 2D map for directional and spot
// lights, a cube map of distances for point lights), each re-rendered only when its light or the
// geometry change, and the ShadowBlock that shaders/common/shadows.glsl reads. It draws no
// colour and shades nothing; the projections come from core/render/shadow_projection.h.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gpu_mesh_cache.h"
#include "gl/shader_program.h"
#include "light/shadow_settings.h"
#include "render/shadow_projection.h"
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

    // The buffers of object `objectIndex` (gl/gpu_mesh_cache.h) at the detail the frame draws.
    using MeshOfObject = std::function<const GpuMesh&(size_t objectIndex)>;
    // Re-renders each map whose view changed since the last call: its light's projection, the
    // objects, or (for a full-detail frame) a map drawn for a drag. A drag frame (Simplified)
    // draws at no more than `dragResolution` texels a side. Then uploads the ShadowBlock. A map
    // skips the objects outside its frustum and the back faces of closed meshes its light sees
    // from outside (render/visibility.h). Changes GL state: framebuffer, viewport, depth test,
    // face culling, program.
    void update(const Scene& scene, const MeshOfObject& meshOf, MeshDetail detail, int dragResolution);
    // Binds the maps to their texture units and points `program`'s samplers at them.
    void bind(const ShaderProgram& program) const;
    // What the last update() uploaded (which light has which map: gl/shader_specialisation.h).
    const ShadowBlockStd140& block() const { return block_; }
    // How many update() calls re-rendered maps, and how many maps they drew (tests of the caching).
    long long renderCount() const { return renderCount_; }
    long long mapRenderCount() const { return mapRenderCount_; }
    // Whether a map in use was drawn for a drag (coarser, or from stand-ins): a full-detail frame draws it again.
    bool provisional() const;

private:
    struct Slot {
        GLuint texture2D = 0, cube = 0;
        int resolution2D = 0, resolutionCube = 0;
        std::vector<float> key;    // its light's projection and resolution at the last render
        int drawnResolution = 0;   // texels a side of that render
        bool provisional = false;  // drawn for a drag: from stand-ins, or below the light's resolution
    };
    ShadowMaps() = default;
    bool slotNeedsRender(size_t slotIndex, const std::vector<float>& key, bool geometryChanged, MeshDetail detail) const;
    // Draws one light's map (six faces for a cube) at `resolution`; returns whether a simplified
    // stand-in was drawn.
    bool renderMap(const Scene& scene, const MeshOfObject& meshOf, const Light& light, const ShadowProjection& projection,
                   int resolution, Slot& slot);
    // Draws the objects into the bound map; returns whether any was a simplified stand-in.
    bool drawObjects(const Scene& scene, const MeshOfObject& meshOf, const ShadowProjection& projection,
                     const glm::mat4& viewProjection) const;

    ShaderProgram depthProgram_;
    GLuint framebuffer_ = 0, uniformBuffer_ = 0;
    Slot slots_[kMaxShadowedLights];
    ShadowBlockStd140 block_{};
    std::string geometryKey_;  // the objects at the last update
    long long renderCount_ = 0, mapRenderCount_ = 0;
};

}  // namespace glint
