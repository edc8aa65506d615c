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
// Textures per material: each takes one texture unit and one slot of uniforms in the shader.
inline constexpr int kMaxMaterialTextures = 8;

enum class TextureKind { Image, Checker, Marble, Wood };
enum class TextureColorSpace { Srgb, Linear };  // how an image file's values are encoded
enum class TextureFilter { Nearest, Bilinear, Trilinear, Anisotropic };
enum class TextureChannel { R, G, B, A };  // where a scalar parameter reads an image

// Decoded image, linear RGBA floats, rows from the BOTTOM of the picture up (v = 0 is the
// bottom edge, as OpenGL's t), so the CPU and the GPU index it the same way.
struct TextureImage {
    std::string path;  // absolute
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
    std::string parameter;  // a Scalar or Color name of the model's table, or kNormalMapKey
    TextureKind kind = TextureKind::Checker;
    // Image
    std::string file;  // absolute path of the image (written relative to the scene file)
    TextureColorSpace colorSpace = TextureColorSpace::Srgb;
    TextureChannel channel = TextureChannel::R;  // scalar parameters only
    TextureFilter filter = TextureFilter::Trilinear;
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
    // Normal map: scales the tangent-space x and y before normalising (glTF's normalTexture.scale).
    float normalScale = 1.0f;
    // Checker, marble, wood: the two values (scalars use .x), in the parameter's unit.
    glm::vec3 valueA{0.0f}, valueB{1.0f};
    // Marble and wood: spatial frequency [1/m] of the object-space position, and turbulence.
    float frequency = 4.0f;
    float turbulence = 4.0f;  // amplitude of the turbulence added to the phase
    int octaves = 5;          // of the turbulence sum
};

}  // namespace glint
