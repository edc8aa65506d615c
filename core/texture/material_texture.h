// MaterialTexture: one parameter of a material driven by a texture (an image file, a UV checker,
// or a solid marble or wood texture after Perlin 1985) instead of its constant, or the normal map.
// Plain data; reading images is texture_image.h, evaluation texture_eval.h, JSON texture_json.h.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace glint {

// The key of the tangent-space normal map in a material's "textures" (not a table parameter).
inline constexpr const char* kNormalMapKey = "normal";
// The key of the ambient-occlusion map (glTF's occlusionTexture; not a table parameter): a scalar
// in [0, 1] by which only the ambient and environment light are scaled, never the lights'.
inline constexpr const char* kOcclusionMapKey = "occlusion";
// The key of the coat's tangent-space normal map (OpenPBR's geometry_coat_normal, glTF's
// clearcoatNormalTexture; not a table parameter): tilts the openpbr coat lobe's normal only, in
// the tangent frame of the surface before the normal map.
inline constexpr const char* kCoatNormalMapKey = "coat_normal";
// Whether a "textures" key is a tangent-space normal map (the surface's or the coat's).
inline bool isNormalMapKey(const std::string& key) { return key == kNormalMapKey || key == kCoatNormalMapKey; }
// Whether a "textures" key is one of these maps rather than a parameter of the model's table.
inline bool isSurfaceMapKey(const std::string& key) { return isNormalMapKey(key) || key == kOcclusionMapKey; }
// Textures per material: each takes one texture unit and one slot of uniforms in the shader.
inline constexpr int kMaxMaterialTextures = 8;

enum class TextureKind { Image, Checker, Marble, Wood };
enum class TextureColorSpace { Srgb, Linear };  // how an image file's values are encoded
enum class TextureFilter { Nearest, Bilinear, Trilinear, Anisotropic };
// OpenGL's minification filters (glTF samplers' minFilter); Default: the one `filter` implies
// (nearest: NEAREST, bilinear: LINEAR, trilinear and anisotropic: LINEAR_MIPMAP_LINEAR).
enum class TextureMinFilter { Default, Nearest, Linear, NearestMipmapNearest, LinearMipmapNearest, NearestMipmapLinear, LinearMipmapLinear };
// OpenGL's addressing outside [0, 1] along u or v (glTF samplers' wrapS, wrapT).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };
enum class TextureChannel { R, G, B, A };  // where a scalar parameter reads an image

// Decoded image, linear RGBA floats, rows from the BOTTOM of the picture up (v = 0 is the
// bottom edge, as OpenGL's t), so the CPU and the GPU index it the same way.
struct TextureImage {
    std::string path;  // absolute; an image inside a glTF is "FILE#/images/N" (interchange/gltf_images.h)
    long long modifiedAt = 0;  // file modification time [ns since the epoch] when decoded
    TextureColorSpace colorSpace = TextureColorSpace::Srgb;  // how the file was decoded
    int width = 0, height = 0;
    std::vector<float> rgba;  // linear, 4 floats per texel
    glm::vec4 texel(int x, int y) const {
        const float* p = &rgba[(static_cast<size_t>(y) * width + x) * 4];
        return {p[0], p[1], p[2], p[3]};
    }
};

struct MaterialTexture {
    std::string parameter;  // a Scalar or Color name of the model's table, or a surface map's key (above)
    TextureKind kind = TextureKind::Checker;
    // Image
    std::string file;  // absolute path of the image (written relative to the scene file)
    int gltfImage = -1;  // ≥ 0: the image is images[gltfImage] inside `file`, a .gltf or .glb
    TextureColorSpace colorSpace = TextureColorSpace::Srgb;
    TextureChannel channel = TextureChannel::R;  // scalar parameters only
    TextureFilter filter = TextureFilter::Trilinear;  // magnification: nearest for Nearest, else linear
    TextureMinFilter minFilter = TextureMinFilter::Default;
    TextureWrap wrapU = TextureWrap::Repeat, wrapV = TextureWrap::Repeat;
    glm::vec2 range{0.0f, 1.0f};  // scalar parameters: value = mix(range.x, range.y, texel)
    std::shared_ptr<const TextureImage> image;  // decoded when the material is read
    // Image and checker: the UV transform uv' = R(rotation)·(tiling ⊙ uv) + offset, in Glint's UV
    // (v up), R turning counter-clockwise; tiling is the repetitions across the shape's UV square
    // (negative mirrors). glTF's KHR_texture_transform converts to it (interchange/gltf_textures.h).
    glm::vec2 tiling{1.0f, 1.0f};
    glm::vec2 offset{0.0f, 0.0f};
    float rotation = 0.0f;  // radians
    // Colour parameters: multiplies the texture's value (glTF's baseColorFactor, emissiveFactor).
    glm::vec3 colorFactor{1.0f};
    // Normal maps: scale the tangent-space x and y before normalising (glTF's normalTexture.scale,
    // clearcoatNormalTexture.scale).
    float normalScale = 1.0f;
    // Checker, marble, wood: the two values (scalars use .x), in the parameter's unit.
    glm::vec3 valueA{0.0f}, valueB{1.0f};
    // Marble and wood: spatial frequency [1/m] of the object-space position, and turbulence.
    float frequency = 4.0f;
    float turbulence = 4.0f;  // amplitude of the turbulence added to the phase
    int octaves = 5;          // of the turbulence sum
};

}  // namespace glint
