// Images in memory: linear float radiance (RGB, W/(sr·m²)) and display-encoded 8-bit RGB.
// Rows run top to bottom. Reading and writing files is image_io.h.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace glint {

struct RadianceImage {
    int width = 0, height = 0;
    std::vector<float> pixels;  // RGB, row-major, top row first

    RadianceImage() = default;
    RadianceImage(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h * 3, 0.0f) {}
    glm::vec3 at(int x, int y) const {
        const float* p = &pixels[(static_cast<size_t>(y) * width + x) * 3];
        return {p[0], p[1], p[2]};
    }
    void set(int x, int y, glm::vec3 value) {
        float* p = &pixels[(static_cast<size_t>(y) * width + x) * 3];
        p[0] = value.r, p[1] = value.g, p[2] = value.b;
    }
};

struct DisplayImage {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  // RGB, row-major, top row first

    DisplayImage() = default;
    DisplayImage(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h * 3, 0) {}
};

}  // namespace glint
