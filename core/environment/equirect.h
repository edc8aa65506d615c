// Equirectangular radiance images and their one sampling rule, bilinear at a single level:
// u = 0.5 + atan2(x, −z)/2π (wraps), v = acos(y)/π (clamps), texel centres at (i + ½)/size.
// The GLSL twin is shaders/common/environment.glsl; the two must agree texel for texel.
// No file reading (environment_file.h) and no filtering across levels.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace glint {

struct EquirectImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> texels;  // linear radiance, row-major, top row (+y) first

    EquirectImage() = default;
    EquirectImage(int w, int h) : width(w), height(h), texels(static_cast<size_t>(w) * h, glm::vec3(0.0f)) {}
    glm::vec3 at(int x, int y) const { return texels[static_cast<size_t>(y) * width + x]; }
    glm::vec3& at(int x, int y) { return texels[static_cast<size_t>(y) * width + x]; }
};

// Unit direction → (u, v) in [0,1]² and back (the direction through a texel's centre).
glm::vec2 equirectCoordinates(glm::vec3 direction);
glm::vec3 equirectDirection(glm::vec2 coordinates);

// Bilinear lookup at a unit direction: wraps around in u, clamps at the poles in v.
glm::vec3 sampleEquirect(const EquirectImage& image, glm::vec3 direction);
// The same at equirectCoordinates(direction), for lookups of one direction in several images.
glm::vec3 sampleEquirectAt(const EquirectImage& image, glm::vec2 coordinates);

// The solid angle [sr] of a texel in row y: (2π/width)·(cos θ_top − cos θ_bottom).
float texelSolidAngle(int y, int width, int height);

// Half the size in each direction, each texel the solid-angle-weighted mean of its four.
EquirectImage downsampleEquirect(const EquirectImage& image);

}  // namespace glint
