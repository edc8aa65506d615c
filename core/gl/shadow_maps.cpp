// Shadow maps (see shadow_maps.h).
// Sections: light slots · creation · change detection · rendering · binding.
#include "gl/shadow_maps.h"

#include <algorithm>
#include <cstdint>
#include <iterator>

#include "geometry/shape_mesh.h"
#include "gl/gl_loader.h"
#include "render/visibility.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

// --- light slots ------------------------------------------------------------------------------

struct ShadowedLight {
    const Light* light;
    int lightBlockIndex;  // index in the LightBlock (the order of packFrameUniforms)
    ShadowProjection projection;
};

// The lights that get a shadow map: enabled delta lights with castsShadows, in LightBlock order
// (enabled non-ambient lights, as packFrameUniforms packs them), at most kMaxShadowedLights (the
// scene format and the editor refuse more).
std::vector<ShadowedLight> shadowedLights(const Scene& scene) {
    std::vector<ShadowedLight> shadowed;
    const BoundingSphere bounds = sceneBounds(scene);
    int lightBlockIndex = 0;
    for (const Light& light : scene.lights) {
        if (!light.enabled || light.type == LightType::Ambient) continue;
        if (lightBlockIndex == kMaxLights) break;
        const int index = lightBlockIndex++;
        if (!light.castsShadows || static_cast<int>(shadowed.size()) == kMaxShadowedLights) continue;
        shadowed.push_back({&light, index, *shadowProjection(light, bounds)});
    }
    return shadowed;
}

void setDepthTextureParameters(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // with comparison: bilinear PCF per tap
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

// (Re)allocates a depth texture of `resolution`² texels (six faces for a cube).
void ensureDepthTexture(GLuint& texture, int& allocated, int resolution, bool cube) {
    if (texture && allocated == resolution) return;
    if (!texture) glGenTextures(1, &texture);
    const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    glBindTexture(target, texture);
    if (cube) {
        for (int face = 0; face < 6; ++face)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_DEPTH_COMPONENT32F, resolution, resolution, 0,
                         GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, resolution, resolution, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    }
    setDepthTextureParameters(target);
    glBindTexture(target, 0);
    allocated = resolution;
}

}  // namespace

// --- creation ---------------------------------------------------------------------------------

Result<std::unique_ptr<ShadowMaps>> ShadowMaps::create(const ShaderSources& sources) {
    auto program = ShaderProgram::build(sources, "shadow_depth.vert", "shadow_depth.frag");
    if (!program) return program.error();
    std::unique_ptr<ShadowMaps> maps(new ShadowMaps());
    maps->depthProgram_ = std::move(*program);
    glGenFramebuffers(1, &maps->framebuffer_);
    glGenBuffers(1, &maps->uniformBuffer_);
    glBindBuffer(GL_UNIFORM_BUFFER, maps->uniformBuffer_);
    glBufferData(GL_UNIFORM_BUFFER, sizeof(ShadowBlockStd140), nullptr, GL_DYNAMIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBinding, maps->uniformBuffer_);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // PCF taps near a cube edge read across faces
    if (Status errors = takeGlErrors("shadow map creation"); !errors) return errors.error();
    return maps;
}

ShadowMaps::~ShadowMaps() {
    for (Slot& slot : slots_) {
        glDeleteTextures(1, &slot.texture2D);
        glDeleteTextures(1, &slot.cube);
    }
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteBuffers(1, &uniformBuffer_);
}

// --- change detection -------------------------------------------------------------------------

namespace {

// What one map's contents depend on of its light: the projection (which also follows the
// scene's bounds) and the map resolution. Not the biases or the filter, applied when the map is
// read.
std::vector<float> slotKey(const ShadowedLight& entry) {
    const ShadowProjection& projection = entry.projection;
    std::vector<float> key = {static_cast<float>(projection.kind), static_cast<float>(entry.light->shadow.mapResolution),
                              projection.lightPosition.x, projection.lightPosition.y, projection.lightPosition.z,
                              projection.nearPlane, projection.farPlane};
    key.insert(key.end(), &projection.viewProjection[0][0], &projection.viewProjection[0][0] + 16);
    return key;
}

// The objects as the scene file writes them (shape, placement, interpolation), and each imported
// mesh's identity (a reload makes a new one).
std::string geometryKey(const Scene& scene) {
    std::string key = sceneToJson(scene)["objects"].dump();
    for (const SceneObject& object : scene.objects)
        if (const auto* mesh = std::get_if<MeshShape>(&object.shape))
            key += " " + std::to_string(reinterpret_cast<std::uintptr_t>(mesh->mesh.get()));
    return key;
}

}  // namespace

bool ShadowMaps::slotNeedsRender(size_t slotIndex, const std::vector<float>& key, bool geometryChanged, MeshDetail detail) const {
    const Slot& slot = slots_[slotIndex];
    return geometryChanged || key != slot.key || (slot.provisional && detail == MeshDetail::Full);
}

// --- rendering --------------------------------------------------------------------------------

bool ShadowMaps::drawObjects(const Scene& scene, const MeshOfObject& meshOf, const ShadowProjection& projection,
                             const glm::mat4& viewProjection) const {
    bool drewSimplified = false;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        const BoundingSphere bounds = boundingSphere(object.shape);
        if (outsideFrustum(viewProjection, bounds)) continue;
        // As the surface pass: an exact sphere is ray-cast, any other surface keeps its triangles.
        const auto* sphere = drawnAsTriangles(object.shape, object.interpolation) ? nullptr : std::get_if<SphereShape>(&object.shape);
        glUniform1i(depthProgram_.uniform("shapeKind"), sphere ? 1 : 0);
        if (sphere) glUniform4f(depthProgram_.uniform("sphere"), sphere->center.x, sphere->center.y, sphere->center.z, sphere->radius);
        setTriangleUniforms(depthProgram_, object);
        const GpuMesh& mesh = meshOf(i);
        // Both faces of a sphere's proxy ray-cast the same depth; a closed mesh's back faces lie
        // behind its front faces as the light sees them.
        setFaceCulling(sphere ? CulledFaces::None : culledFaces(mesh.closure, beyondNearPlane(projection, bounds)));
        glBindVertexArray(mesh.vertexArray);
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
        drewSimplified = drewSimplified || mesh.simplified;
    }
    glDisable(GL_CULL_FACE);
    return drewSimplified;
}

bool ShadowMaps::renderMap(const Scene& scene, const MeshOfObject& meshOf, const Light& light,
                           const ShadowProjection& projection, int resolution, Slot& slot) {
    glViewport(0, 0, resolution, resolution);
    glUniform1i(depthProgram_.uniform("shadowKind"), static_cast<int>(projection.kind));
    const glm::vec3 origin = projection.kind == ShadowMapKind::Orthographic ? glm::normalize(light.direction)
                                                                             : projection.lightPosition;
    glUniform4f(depthProgram_.uniform("lightOrigin"), origin.x, origin.y, origin.z, projection.farPlane);
    bool drewSimplified = false;
    const auto drawInto = [&](const glm::mat4& viewProjection) {
        glClear(GL_DEPTH_BUFFER_BIT);
        glUniformMatrix4fv(depthProgram_.uniform("lightViewProjection"), 1, GL_FALSE, &viewProjection[0][0]);
        if (drawObjects(scene, meshOf, projection, viewProjection)) drewSimplified = true;
    };
    if (projection.kind == ShadowMapKind::Cube) {
        ensureDepthTexture(slot.cube, slot.resolutionCube, resolution, true);
        for (int face = 0; face < 6; ++face) {
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, slot.cube, 0);
            drawInto(cubeFaceViewProjection(projection, face));
        }
    } else {
        ensureDepthTexture(slot.texture2D, slot.resolution2D, resolution, false);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, slot.texture2D, 0);
        drawInto(projection.viewProjection);
    }
    return drewSimplified;
}

// Each map is drawn again when its light's projection, any object, or (for a full-detail frame)
// the detail it was drawn at changed. A drag frame draws a map that changed at no more than
// `dragResolution` texels a side (texel-based biases and filter grow with the texels), and the
// full frame after the drag draws it again at its own resolution.
void ShadowMaps::update(const Scene& scene, const MeshOfObject& meshOf, MeshDetail detail, int dragResolution) {
    const std::vector<ShadowedLight> shadowed = shadowedLights(scene);
    std::string geometry = geometryKey(scene);
    const bool geometryChanged = geometry != geometryKey_;
    geometryKey_ = std::move(geometry);
    bool stateSet = false, drew = false;
    for (size_t slotIndex = 0; slotIndex < shadowed.size(); ++slotIndex) {
        const ShadowedLight& entry = shadowed[slotIndex];
        std::vector<float> key = slotKey(entry);
        if (!slotNeedsRender(slotIndex, key, geometryChanged, detail)) continue;
        if (!stateSet) {
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
            glDrawBuffer(GL_NONE);
            glReadBuffer(GL_NONE);
            glDisable(GL_BLEND);
            glDisable(GL_SCISSOR_TEST);
            glEnable(GL_DEPTH_TEST);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_LESS);
            glUseProgram(depthProgram_.id());
            stateSet = true;
        }
        Slot& slot = slots_[slotIndex];
        const int resolution = entry.light->shadow.mapResolution;
        slot.drawnResolution = detail == MeshDetail::Full ? resolution : std::min(resolution, dragResolution);
        const bool drewSimplified = renderMap(scene, meshOf, *entry.light, entry.projection, slot.drawnResolution, slot);
        slot.provisional = drewSimplified || slot.drawnResolution < resolution;
        slot.key = std::move(key);
        drew = true;
        ++mapRenderCount_;
    }
    // A slot left unused forgets what it held: the objects may change before a light takes it again.
    for (size_t slotIndex = shadowed.size(); slotIndex < kMaxShadowedLights; ++slotIndex) slots_[slotIndex].key.clear();
    if (stateSet) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    if (drew) ++renderCount_;
    // The block is cheap: always rebuilt, so bias and filter edits need no new maps.
    block_ = ShadowBlockStd140{};
    for (glm::ivec4& entry : block_.mapOfLight) entry = glm::ivec4(-1);
    for (size_t slot = 0; slot < shadowed.size(); ++slot) {
        const ShadowedLight& entry = shadowed[slot];
        const ShadowSettings& settings = entry.light->shadow;
        block_.viewProjection[slot] = entry.projection.viewProjection;
        block_.origin[slot] = glm::vec4(entry.projection.lightPosition, static_cast<float>(entry.projection.kind));
        block_.settings[slot] = {settings.depthBias, settings.normalOffset, settings.filterRadius,
                                 static_cast<float>(slots_[slot].drawnResolution)};
        block_.scale[slot] = {entry.projection.sideScale, entry.projection.farPlane, 0.0f, 0.0f};
        block_.mapOfLight[entry.lightBlockIndex / 4][entry.lightBlockIndex % 4] = static_cast<int>(slot);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, uniformBuffer_);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof block_, &block_);
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBinding, uniformBuffer_);
}

bool ShadowMaps::provisional() const {
    return std::any_of(std::begin(slots_), std::end(slots_), [](const Slot& slot) { return !slot.key.empty() && slot.provisional; });
}

// --- binding ----------------------------------------------------------------------------------

void assignShadowSamplerUnits(const ShaderProgram& program) {
    GLint mapUnits[kMaxShadowedLights], cubeUnits[kMaxShadowedLights];
    for (int slot = 0; slot < kMaxShadowedLights; ++slot) {
        mapUnits[slot] = kFirstShadowTextureUnit + slot;
        cubeUnits[slot] = kFirstShadowTextureUnit + kMaxShadowedLights + slot;
    }
    glUniform1iv(program.uniform("shadowMaps"), kMaxShadowedLights, mapUnits);
    glUniform1iv(program.uniform("shadowCubes"), kMaxShadowedLights, cubeUnits);
    program.bindBlock("ShadowBlock", kShadowBinding);
}

void ShadowMaps::bind(const ShaderProgram& program) const {
    for (int slot = 0; slot < kMaxShadowedLights; ++slot) {
        glActiveTexture(GL_TEXTURE0 + kFirstShadowTextureUnit + slot);
        glBindTexture(GL_TEXTURE_2D, slots_[slot].texture2D);
        glActiveTexture(GL_TEXTURE0 + kFirstShadowTextureUnit + kMaxShadowedLights + slot);
        glBindTexture(GL_TEXTURE_CUBE_MAP, slots_[slot].cube);
    }
    glActiveTexture(GL_TEXTURE0);
    assignShadowSamplerUnits(program);
}

}  // namespace glint
