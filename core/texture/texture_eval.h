// CPU evaluation of material textures at a surface point: the shape's (u, v) and object-space
// position, image sampling (nearest or bilinear at level 0, OpenGL's REPEAT addressing), the
// procedural textures, textured parameter values and the normal-mapped shading frame.
// Addressing outside [0, 1] follows OpenGL 4.6 §8.14.2 (Table 8.20) per axis: REPEAT, CLAMP_TO_EDGE
// or MIRRORED_REPEAT.
// The GLSL twin is shaders/common/textures.glsl; the reference renderer calls this.
#pragma once

#include <optional>
#include <vector>

#include "math/frame.h"
#include "scene/scene.h"

namespace glint {

struct TexturePoint {
    glm::vec2 uv{0.0f};                  // the shape's texture coordinates
    glm::vec3 objectPosition{0.0f};      // [m], world axes, origin at the shape's centre
};

// The shape's centre [m] (every shape has one): the origin of object-space positions.
glm::vec3 shapeCenter(const Shape& shape);

// `triangleUv`: for a hit on a shape drawn from triangles, its interpolated vertex UV (used as
// is). Otherwise the analytic UV: sphere u = azimuth/2π measured as the proxy mesh's (increasing
// along surfaceTangent()), v = 1 − polar angle/π (1 at +y); plane: its own frame, (0, 0) at the
// corner −tangent −bitangent.
TexturePoint texturePointOn(const Shape& shape, glm::vec3 position, std::optional<glm::vec2> triangleUv = std::nullopt);

// The texture's UV transform applied to the shape's uv (material_texture.h).
glm::vec2 transformedUv(const MaterialTexture& texture, glm::vec2 uv);
// OpenGL-style sampling of level 0: texel centres at (i + ½)/size, texel indices outside the
// image wrapped along u and v as OpenGL does.
glm::vec4 sampleImage(const TextureImage& image, glm::vec2 uv, bool bilinear, TextureWrap wrapU = TextureWrap::Repeat,
                      TextureWrap wrapV = TextureWrap::Repeat);
// The texture's raw value: an image's texel (linear RGBA), or mix(A, B, weight) of a procedural one.
glm::vec4 evaluateTexture(const MaterialTexture& texture, const TexturePoint& point);

// The material's packed values with each textured parameter replaced by its texture's value.
std::vector<float> texturedValues(const AnalyticMaterial& material, const TexturePoint& point);
// The occlusion map's value at the point (1 without one): what scales ambient and environment light.
float ambientOcclusion(const AnalyticMaterial& material, const TexturePoint& point);
// The frame whose normal is the normal map's (tangent space: n = 2·rgb − 1 along tangent,
// bitangent, normal), or `frame` itself when the material has no normal map; its coatNormal is
// the coat normal map's, read in `frame` too (zero without one).
ShadingFrame normalMappedFrame(const AnalyticMaterial& material, const TexturePoint& point, const ShadingFrame& frame);

}  // namespace glint
