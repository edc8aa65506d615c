// Equirectangular mapping and bilinear sampling (see equirect.h).
#include "environment/equirect.h"

#include <algorithm>
#include <cmath>

#include "math/constants.h"

namespace glint {

glm::vec2 equirectCoordinates(glm::vec3 direction) {
    const float u = 0.5f + std::atan2(direction.x, -direction.z) * (0.5f * kInvPi);
    const float v = std::acos(std::clamp(direction.y, -1.0f, 1.0f)) * kInvPi;
    return {u, v};
}

glm::vec3 equirectDirection(glm::vec2 coordinates) {
    const float azimuth = (coordinates.x - 0.5f) * 2.0f * kPi;
    const float polar = coordinates.y * kPi;
    const float sinPolar = std::sin(polar);
    return {sinPolar * std::sin(azimuth), std::cos(polar), -sinPolar * std::cos(azimuth)};
}

glm::vec3 sampleEquirect(const EquirectImage& image, glm::vec3 direction) {
    return sampleEquirectAt(image, equirectCoordinates(direction));
}

glm::vec3 sampleEquirectAt(const EquirectImage& image, glm::vec2 uv) {
    const float x = uv.x * image.width - 0.5f, y = uv.y * image.height - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int column0 = ((static_cast<int>(x0) % image.width) + image.width) % image.width;
    const int column1 = (column0 + 1) % image.width;
    const int row0 = std::clamp(static_cast<int>(y0), 0, image.height - 1);
    const int row1 = std::clamp(static_cast<int>(y0) + 1, 0, image.height - 1);
    const glm::vec3 top = image.at(column0, row0) * (1.0f - fx) + image.at(column1, row0) * fx;
    const glm::vec3 bottom = image.at(column0, row1) * (1.0f - fx) + image.at(column1, row1) * fx;
    return top * (1.0f - fy) + bottom * fy;
}

float texelSolidAngle(int y, int width, int height) {
    const float polarTop = kPi * y / height, polarBottom = kPi * (y + 1) / height;
    return 2.0f * kPi / width * (std::cos(polarTop) - std::cos(polarBottom));
}

EquirectImage downsampleEquirect(const EquirectImage& image) {
    EquirectImage half(std::max(1, image.width / 2), std::max(1, image.height / 2));
    for (int y = 0; y < half.height; ++y) {
        const int row0 = std::min(2 * y, image.height - 1), row1 = std::min(2 * y + 1, image.height - 1);
        const float weight0 = texelSolidAngle(row0, image.width, image.height);
        const float weight1 = texelSolidAngle(row1, image.width, image.height);
        for (int x = 0; x < half.width; ++x) {
            const int column0 = std::min(2 * x, image.width - 1), column1 = std::min(2 * x + 1, image.width - 1);
            const glm::vec3 sum = (image.at(column0, row0) + image.at(column1, row0)) * weight0 +
                                  (image.at(column0, row1) + image.at(column1, row1)) * weight1;
            half.at(x, y) = sum / (2.0f * (weight0 + weight1));
        }
    }
    return half;
}

}  // namespace glint
