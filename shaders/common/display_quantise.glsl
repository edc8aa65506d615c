// Quantisation to N intensity levels with an optional ordered dither (Bayer 2×2, 4×4, clustered-dot
// halftone); twin of core/display/quantisation.h (matrices and citations there). Pure functions of
// the encoded value and the pixel; no encoding here (display_encode.glsl).

uniform int levels;  // 2..256
#ifdef GLINT_DISPLAY_DITHER  // a compile-time constant in a specialised program (gl/shader_specialisation.h)
const int dither = GLINT_DISPLAY_DITHER;
#else
uniform int dither;  // 0: none, 1: Bayer 2×2, 2: Bayer 4×4, 3: clustered-dot halftone 4×4
#endif

const int kBayer2[4] = int[4](0, 2, 3, 1);
const int kBayer4[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
const int kHalftone4[16] = int[16](12, 5, 6, 13, 4, 0, 1, 7, 11, 3, 2, 8, 15, 10, 9, 14);

// The threshold added before rounding down at a pixel counted from the lower-left corner.
float ditherThreshold(ivec2 pixel) {
    int column = pixel.x & 3, row = pixel.y & 3;
    if (dither == 1) return (float(kBayer2[(row & 1) * 2 + (column & 1)]) + 0.5) / 4.0;
    if (dither == 2) return (float(kBayer4[row * 4 + column]) + 0.5) / 16.0;
    if (dither == 3) return (float(kHalftone4[row * 4 + column]) + 0.5) / 16.0;
    return 0.5;
}

// k/(levels−1) with k = ⌊value·(levels−1) + threshold⌋ clamped to 0..levels−1, then rounded to the
// 8-bit value it is stored as.
vec3 quantiseToLevels(vec3 encoded, ivec2 pixel) {
    float steps = float(levels - 1);
    vec3 level = clamp(floor(clamp(encoded, 0.0, 1.0) * steps + ditherThreshold(pixel)), 0.0, steps);
    return floor(level / steps * 255.0 + 0.5) / 255.0;
}
