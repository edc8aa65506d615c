// Procedural textures that need no files: Perlin's improved noise (Perlin, "Improving Noise",
// SIGGRAPH 2002), turbulence and the solid marble and wood of Perlin, "An Image Synthesizer",
// SIGGRAPH 1985, and a UV checker. Pure functions; the GLSL twins are in shaders/common/textures.glsl.
#pragma once

#include <array>
#include <string>

#include <glm/glm.hpp>

namespace glint {

// Ken Perlin's reference permutation of 0..255 (the GLSL twin gets it from perlinTableGlsl()).
const std::array<int, 256>& perlinPermutation();
// "const int PERLIN_PERMUTATION[256] = int[](...);" for the shader.
std::string perlinTableGlsl();

// Improved noise in [-1, 1] at a point (2002).
float perlinNoise(glm::vec3 point);
// turbulence(p) = Σ_{i<octaves} |noise(2^i p)| / 2^i (1985, §"Turbulence").
float turbulence(glm::vec3 point, int octaves);
// Blend weights in [0, 1] (0 → value A, 1 → value B) at an object-space point [m]:
// marble: ½ + ½·sin(f·x + a·turbulence(f·p)), veins across x (1985, "marble");
// wood: ½ + ½·sin(2π·(f·|p.xz| + a·turbulence(f·p)/8)), rings around the y axis.
float marbleWeight(glm::vec3 objectPosition, float frequency, float turbulenceAmplitude, int octaves);
float woodWeight(glm::vec3 objectPosition, float frequency, float turbulenceAmplitude, int octaves);
// 0 or 1: squares of a checker over the tiled UV square.
float checkerWeight(glm::vec2 tiledUv);

}  // namespace glint
