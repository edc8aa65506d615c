// CPU evaluation of material textures (see texture_eval.h).
#include "texture/texture_eval.h"

#include <algorithm>
#include <cmath>

#include "math/constants.h"
#include "texture/procedural.h"

namespace glint {
namespace {

// OpenGL 4.6 Table 8.20: the texel index `index` of an axis of `size` texels under `mode`.
int wrap(int index, int size, TextureWrap mode) {
    switch (mode) {
        case TextureWrap::Repeat: return ((index % size) + size) % size;
        case TextureWrap::ClampToEdge: return std::clamp(index, 0, size - 1);
        case TextureWrap::MirroredRepeat: {
            const int shifted = ((index % (2 * size)) + 2 * size) % (2 * size) - size;
            return (size - 1) - (shifted >= 0 ? shifted : -(1 + shifted));  // (size − 1) − mirror(...)
        }
    }
    return 0;
}

float channelOf(glm::vec4 value, TextureChannel channel) { return value[static_cast<int>(channel)]; }

}  // namespace

glm::vec3 shapeCenter(const Shape& shape) {
    return std::visit([](const auto& concrete) { return concrete.center; }, shape);
}

TexturePoint texturePointOn(const Shape& shape, glm::vec3 position, std::optional<glm::vec2> triangleUv) {
    TexturePoint point;
    point.objectPosition = position - shapeCenter(shape);
    if (triangleUv) {
        point.uv = *triangleUv;
    } else if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
        const glm::vec3 n = (position - sphere->center) / sphere->radius;
        float u = std::atan2(-n.z, n.x) / (2.0f * kPi);
        if (u < 0.0f) u += 1.0f;
        point.uv = {u, 1.0f - std::acos(std::clamp(n.y, -1.0f, 1.0f)) / kPi};
    } else if (const auto* plane = std::get_if<PlaneShape>(&shape)) {
        const glm::vec3 local = ShadingFrame::fromNormal(glm::normalize(plane->normal)).toLocal(position - plane->center);
        point.uv = {local.x / plane->size.x + 0.5f, local.y / plane->size.y + 0.5f};
    }
    return point;
}

glm::vec2 transformedUv(const MaterialTexture& texture, glm::vec2 uv) {
    const glm::vec2 scaled = uv * texture.tiling;
    const float c = std::cos(texture.rotation), s = std::sin(texture.rotation);
    return glm::vec2(c * scaled.x - s * scaled.y, s * scaled.x + c * scaled.y) + texture.offset;
}

glm::vec4 sampleImage(const TextureImage& image, glm::vec2 uv, bool bilinear, TextureWrap wrapU, TextureWrap wrapV) {
    const float x = uv.x * image.width, y = uv.y * image.height;
    if (!bilinear)
        return image.texel(wrap(static_cast<int>(std::floor(x)), image.width, wrapU),
                           wrap(static_cast<int>(std::floor(y)), image.height, wrapV));
    const float left = std::floor(x - 0.5f), bottom = std::floor(y - 0.5f);
    const float fx = x - 0.5f - left, fy = y - 0.5f - bottom;
    const int x0 = wrap(static_cast<int>(left), image.width, wrapU), x1 = wrap(static_cast<int>(left) + 1, image.width, wrapU);
    const int y0 = wrap(static_cast<int>(bottom), image.height, wrapV), y1 = wrap(static_cast<int>(bottom) + 1, image.height, wrapV);
    const glm::vec4 lower = glm::mix(image.texel(x0, y0), image.texel(x1, y0), fx);
    const glm::vec4 upper = glm::mix(image.texel(x0, y1), image.texel(x1, y1), fx);
    return glm::mix(lower, upper, fy);
}

glm::vec4 evaluateTexture(const MaterialTexture& texture, const TexturePoint& point) {
    float weight = 0.0f;
    switch (texture.kind) {
        case TextureKind::Image:
            return sampleImage(*texture.image, transformedUv(texture, point.uv), texture.filter != TextureFilter::Nearest,
                               texture.wrapU, texture.wrapV);
        case TextureKind::Checker: weight = checkerWeight(transformedUv(texture, point.uv)); break;
        case TextureKind::Marble:
            weight = marbleWeight(point.objectPosition, texture.frequency, texture.turbulence, texture.octaves);
            break;
        case TextureKind::Wood:
            weight = woodWeight(point.objectPosition, texture.frequency, texture.turbulence, texture.octaves);
            break;
    }
    return glm::vec4(glm::mix(texture.valueA, texture.valueB, weight), 1.0f);
}

std::vector<float> texturedValues(const AnalyticMaterial& material, const TexturePoint& point) {
    std::vector<float> values = material.values;
    if (material.textures.empty()) return values;
    const auto table = modelInfo(material.model).params;
    for (const MaterialTexture& texture : material.textures) {
        const int index = findParam(table, texture.parameter);
        if (index < 0) continue;  // the normal map
        float* value = values.data() + packedOffset(table, index);
        const glm::vec4 sampled = evaluateTexture(texture, point);
        if (table[index].kind == ParamKind::Color) {
            const glm::vec3 color = glm::vec3(sampled) * texture.colorFactor;
            value[0] = color.r, value[1] = color.g, value[2] = color.b;
        } else if (texture.kind == TextureKind::Image) {
            value[0] = glm::mix(texture.range.x, texture.range.y, channelOf(sampled, texture.channel));
        } else {
            value[0] = sampled.r;
        }
    }
    return values;
}

float ambientOcclusion(const AnalyticMaterial& material, const TexturePoint& point) {
    for (const MaterialTexture& texture : material.textures) {
        if (texture.parameter != kOcclusionMapKey) continue;
        const glm::vec4 sampled = evaluateTexture(texture, point);
        return texture.kind == TextureKind::Image ? glm::mix(texture.range.x, texture.range.y, channelOf(sampled, texture.channel))
                                                  : sampled.r;
    }
    return 1.0f;
}

namespace {

// The normal that the normal map `texture` gives in `frame` (tangent space: n = 2·rgb − 1 with x
// and y scaled), or the frame's normal for a (½, ½, ½) texel, which has no direction.
glm::vec3 mappedNormal(const MaterialTexture& texture, const TexturePoint& point, const ShadingFrame& frame) {
    const glm::vec3 tangentSpace =
        (2.0f * glm::vec3(evaluateTexture(texture, point)) - 1.0f) * glm::vec3(texture.normalScale, texture.normalScale, 1.0f);
    const glm::vec3 normal = frame.toWorld(tangentSpace);
    const float length = glm::length(normal);
    return length < 1e-6f ? frame.normal : normal / length;
}

}  // namespace

ShadingFrame normalMappedFrame(const AnalyticMaterial& material, const TexturePoint& point, const ShadingFrame& frame) {
    ShadingFrame mapped = frame;
    for (const MaterialTexture& texture : material.textures)
        if (texture.parameter == kNormalMapKey)
            mapped = ShadingFrame::fromNormalAndTangent(mappedNormal(texture, point, frame), frame.tangent);
    for (const MaterialTexture& texture : material.textures)
        if (texture.parameter == kCoatNormalMapKey) mapped.coatNormal = mappedNormal(texture, point, frame);
    return mapped;
}

}  // namespace glint
