// The screen-space transmission backdrop on the CPU (see transmission_backdrop.h).
#include "render/transmission_backdrop.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "brdf/model_traits.h"

namespace glint {

bool transmitsLight(const Material& kind) {
    const AnalyticMaterial* analytic = kind.analytic();
    if (!analytic) return false;
    // A texture may take a scalar anywhere in its range: the material transmits where any does.
    const auto table = modelInfo(analytic->model).params;
    std::vector<float> utmost = analytic->values;
    for (const MaterialTexture& texture : analytic->textures)
        if (const int index = findParam(table, texture.parameter); index >= 0 && table[index].kind == ParamKind::Scalar)
            utmost[packedOffset(table, index)] = std::isfinite(table[index].validMax) ? table[index].validMax : table[index].sliderMax;
    return transmits(analytic->model, utmost);
}

bool drawsTransmissionBackdrop(const Scene& scene) {
    const auto transmissive = [&](const SceneObject& object) { return transmitsLight(scene.materials.at(object.materialIndex)); };
    return std::any_of(scene.objects.begin(), scene.objects.end(), transmissive) &&
           !std::all_of(scene.objects.begin(), scene.objects.end(), transmissive);
}

TransmissionBackdrop::TransmissionBackdrop(const OpaquePassImage& opaque, const glm::mat4& viewProjection)
    : viewProjection_(viewProjection) {
    Level base{opaque.width, opaque.height, {}};
    base.texels.resize(static_cast<size_t>(base.width) * base.height);
    for (int y = 0; y < base.height; ++y)
        for (int x = 0; x < base.width; ++x) base.texels[static_cast<size_t>(y) * base.width + x] = opaque.at(x, base.height - 1 - y);
    levels_.push_back(std::move(base));
    // GL's mip sizes (halved, rounded down, at least 1); each texel the mean of its 2×2 texels
    // one level up, clamped at an odd edge (transmission_downsample.frag).
    while (levels_.back().width > 1 || levels_.back().height > 1) {
        const Level& above = levels_.back();
        Level next{std::max(1, above.width / 2), std::max(1, above.height / 2), {}};
        next.texels.resize(static_cast<size_t>(next.width) * next.height);
        for (int y = 0; y < next.height; ++y)
            for (int x = 0; x < next.width; ++x) {
                const int x0 = std::min(2 * x, above.width - 1), x1 = std::min(2 * x + 1, above.width - 1);
                const int y0 = std::min(2 * y, above.height - 1), y1 = std::min(2 * y + 1, above.height - 1);
                next.texels[static_cast<size_t>(y) * next.width + x] =
                    0.25f * (above.at(x0, y0) + above.at(x1, y0) + above.at(x0, y1) + above.at(x1, y1));
            }
        levels_.push_back(std::move(next));
    }
}

float TransmissionBackdrop::levelFor(float perceptualRoughness, float ior) const {
    return std::log2(static_cast<float>(levels_.front().width)) * perceptualRoughness * std::clamp(2.0f * ior - 2.0f, 0.0f, 1.0f);
}

namespace {

template <class Level>
glm::vec4 bilinearInLevel(const Level& level, glm::vec2 uv) {
    const glm::vec2 position = uv * glm::vec2(level.width, level.height) - 0.5f;
    const glm::vec2 corner = glm::floor(position), weight = position - corner;
    const int x0 = std::clamp(static_cast<int>(corner.x), 0, level.width - 1);
    const int x1 = std::clamp(static_cast<int>(corner.x) + 1, 0, level.width - 1);
    const int y0 = std::clamp(static_cast<int>(corner.y), 0, level.height - 1);
    const int y1 = std::clamp(static_cast<int>(corner.y) + 1, 0, level.height - 1);
    const glm::vec4 bottom = glm::mix(level.at(x0, y0), level.at(x1, y0), weight.x);
    const glm::vec4 top = glm::mix(level.at(x0, y1), level.at(x1, y1), weight.x);
    return glm::mix(bottom, top, weight.y);
}

}  // namespace

glm::vec4 TransmissionBackdrop::sample(glm::vec2 uv, float level) const {
    const float clamped = std::clamp(level, 0.0f, static_cast<float>(levelCount() - 1));
    const int lower = static_cast<int>(std::floor(clamped));
    const int upper = std::min(lower + 1, levelCount() - 1);
    if (upper == lower || clamped == static_cast<float>(lower)) return bilinearInLevel(levels_[lower], uv);
    return glm::mix(bilinearInLevel(levels_[lower], uv), bilinearInLevel(levels_[upper], uv), clamped - static_cast<float>(lower));
}

std::optional<glm::vec4> TransmissionBackdrop::behind(glm::vec3 exitPoint, glm::vec3 direction, glm::vec3 viewDirection,
                                                      float level) const {
    if (glm::dot(direction, viewDirection) <= 0.0f) return std::nullopt;
    const glm::vec4 clip = viewProjection_ * glm::vec4(exitPoint, 1.0f);
    if (clip.w <= 0.0f) return std::nullopt;
    const glm::vec2 uv = 0.5f * glm::vec2(clip.x, clip.y) / clip.w + 0.5f;
    if (uv.x < 0.0f || uv.x > 1.0f || uv.y < 0.0f || uv.y > 1.0f) return std::nullopt;
    return sample(uv, level);
}

}  // namespace glint
