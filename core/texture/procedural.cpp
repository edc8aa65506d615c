// Procedural textures: Perlin noise, turbulence, marble, wood, checker (see procedural.h).
#include "texture/procedural.h"

#include <cmath>

#include "math/constants.h"

namespace glint {
namespace {

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }  // 6t⁵ − 15t⁴ + 10t³

// Dot product with one of 12 edge gradients, picked by the low 4 bits of the hash (2002).
float gradient(int hash, float x, float y, float z) {
    const int h = hash & 15;
    const float u = h < 8 ? x : y;
    const float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

int permute(int i) { return perlinPermutation()[i & 255]; }

}  // namespace

const std::array<int, 256>& perlinPermutation() {
    static const std::array<int, 256> table = {
        151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,  69,  142,
        8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,  197, 62,  94,  252, 219, 203,
        117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165,
        71,  134, 139, 48,  27,  166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,
        55,  46,  245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,
        18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250,
        124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,  182, 189,
        28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
        129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
        242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,
        181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114,
        67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};
    return table;
}

std::string perlinTableGlsl() {
    std::string glsl = "const int PERLIN_PERMUTATION[256] = int[](";
    for (int i = 0; i < 256; ++i) glsl += (i ? "," : "") + std::to_string(perlinPermutation()[i]);
    return glsl + ");\n";
}

float perlinNoise(glm::vec3 point) {
    const glm::vec3 cell = glm::floor(point);
    const int X = static_cast<int>(cell.x) & 255, Y = static_cast<int>(cell.y) & 255, Z = static_cast<int>(cell.z) & 255;
    const float x = point.x - cell.x, y = point.y - cell.y, z = point.z - cell.z;
    const float u = fade(x), v = fade(y), w = fade(z);
    const int A = permute(X) + Y, AA = permute(A) + Z, AB = permute(A + 1) + Z;
    const int B = permute(X + 1) + Y, BA = permute(B) + Z, BB = permute(B + 1) + Z;
    const auto lerp = [](float t, float a, float b) { return a + t * (b - a); };
    return lerp(w,
                lerp(v, lerp(u, gradient(permute(AA), x, y, z), gradient(permute(BA), x - 1, y, z)),
                     lerp(u, gradient(permute(AB), x, y - 1, z), gradient(permute(BB), x - 1, y - 1, z))),
                lerp(v, lerp(u, gradient(permute(AA + 1), x, y, z - 1), gradient(permute(BA + 1), x - 1, y, z - 1)),
                     lerp(u, gradient(permute(AB + 1), x, y - 1, z - 1), gradient(permute(BB + 1), x - 1, y - 1, z - 1))));
}

float turbulence(glm::vec3 point, int octaves) {
    float sum = 0.0f, scale = 1.0f;
    for (int i = 0; i < octaves; ++i, scale *= 2.0f) sum += std::abs(perlinNoise(point * scale)) / scale;
    return sum;
}

float marbleWeight(glm::vec3 objectPosition, float frequency, float turbulenceAmplitude, int octaves) {
    const glm::vec3 scaled = objectPosition * frequency;
    return 0.5f + 0.5f * std::sin(scaled.x + turbulenceAmplitude * turbulence(scaled, octaves));
}

float woodWeight(glm::vec3 objectPosition, float frequency, float turbulenceAmplitude, int octaves) {
    const glm::vec3 scaled = objectPosition * frequency;
    const float rings = std::sqrt(scaled.x * scaled.x + scaled.z * scaled.z) +
                        0.125f * turbulenceAmplitude * turbulence(scaled, octaves);
    return 0.5f + 0.5f * std::sin(2.0f * kPi * rings);
}

float checkerWeight(glm::vec2 tiledUv) {
    const int sum = static_cast<int>(std::floor(tiledUv.x)) + static_cast<int>(std::floor(tiledUv.y));
    return (sum & 1) ? 1.0f : 0.0f;
}

}  // namespace glint
