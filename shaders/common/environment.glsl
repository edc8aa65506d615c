// The environment map on the GPU: GLSL twin of core/environment (equirect.cpp's bilinear lookup,
// environment_map.cpp's irradiance map and prefiltered levels, lobe_albedo.cpp's tables, and
// environment_lighting.cpp's lookups) and of render/miss_radiance.h. Every lookup is a manual
// bilinear of texelFetch'ed float texels, so the CPU reference computes the same numbers.
// Needs frame.glsl and background.glsl first. Defines GLINT_HAS_ENVIRONMENT for the model hooks.
#include "brdf/fresnel.glsl"
#define GLINT_HAS_ENVIRONMENT

const int PREFILTERED_LEVELS = 5;  // kPrefilteredLevels
const int LOBE_ALBEDO_SIZE = 32;   // kLobeAlbedoSize
const int MAX_PEAK_LIGHTS = 8;     // kMaxPeakLights

layout(std140) uniform EnvironmentBlock {
    vec4 environmentTransform;  // x: cos(rotation), y: sin(rotation), z: intensity, w: peaks' minimum α
    ivec4 environmentFlags;     // x: 1 when the scene has an environment; y: 1 when shown as background;
                                // z: the map's peak lights
    ivec4 environmentSizes;     // x, y: base level size; z, w: prefiltered level size
    vec4 environmentResidualMean;  // rgb: mean radiance of the map less its peaks, × the intensity
    vec4 environmentPeakDirections[MAX_PEAK_LIGHTS];  // xyz: world space; w: sine of its radius
    vec4 environmentPeakIrradiances[MAX_PEAK_LIGHTS]; // rgb [W/m²], × the intensity
};
uniform sampler2D environmentBase;             // the radiance image
uniform sampler2DArray environmentPrefiltered; // layer k − 1: perceptual roughness k/L; layer L: E(n)/π;
                                               // layer L + k: roughness k/L of the map less its peaks
uniform sampler2D environmentLobeTables;      // lobe_albedo.h's tables: split-sum scale A and bias B per
                                               // microfacet pair, one albedo (r) per Blinn-Phong, Phong and
                                               // Ward variant, Ward's GGX stand-in (r', t) per variant, the
                                               // F82 share C (r) per pair, the pairs' stand-ins but GGX-Smith's
const int MICROFACET_SPLIT_SUM = 0, BLINN_PHONG_ALBEDO = 4, PHONG_ALBEDO = 8, WARD_ALBEDO = 12, WARD_STAND_IN = 14,
          MICROFACET_F82 = 16, MICROFACET_STAND_IN = 20;  // LobeAlbedoTable
const int GGX_SMITH_PAIR = 3;  // microfacetPair(Ggx, Smith)

// Whether the scene has an environment, and shows it as the background: compile-time constants
// in a specialised program (gl/shader_specialisation.h), else the block's flags.
#ifdef GLINT_ENVIRONMENT_ENABLED
bool environmentEnabled() { return GLINT_ENVIRONMENT_ENABLED != 0; }
bool environmentShown() { return GLINT_ENVIRONMENT_ENABLED != 0 && GLINT_ENVIRONMENT_SHOWN != 0; }
#else
bool environmentEnabled() { return environmentFlags.x != 0; }
bool environmentShown() { return environmentFlags.x != 0 && environmentFlags.y != 0; }
#endif

vec3 environmentMapDirection(vec3 d) {
    float c = environmentTransform.x, s = environmentTransform.y;
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

vec3 fetchEnvironmentLevel(int level, ivec2 texel) {
    if (level == 0) return texelFetch(environmentBase, texel, 0).rgb;
    return texelFetch(environmentPrefiltered, ivec3(texel, level - 1), 0).rgb;
}

// The four texels around direction d (map axes) in a size.x × size.y equirect image and the
// bilinear weights between them: twin of sampleEquirect().
struct EquirectTexels {
    ivec4 corners;  // column0, row0, column1, row1
    vec2 weight;    // towards column1, towards row1
};

EquirectTexels equirectTexels(vec3 d, ivec2 size) {
    float u = 0.5 + atan(d.x, -d.z) * (0.5 * INV_PI);
    float v = acos(clamp(d.y, -1.0, 1.0)) * INV_PI;
    float x = u * float(size.x) - 0.5, y = v * float(size.y) - 0.5;
    float x0 = floor(x), y0 = floor(y);
    int column0 = int(x0);
    if (column0 < 0) column0 += size.x;
    if (column0 >= size.x) column0 -= size.x;
    int column1 = column0 + 1 == size.x ? 0 : column0 + 1;
    int row0 = clamp(int(y0), 0, size.y - 1), row1 = clamp(int(y0) + 1, 0, size.y - 1);
    return EquirectTexels(ivec4(column0, row0, column1, row1), vec2(x - x0, y - y0));
}

vec3 bilinear(vec3 c00, vec3 c10, vec3 c01, vec3 c11, vec2 weight) {
    vec3 top = c00 * (1.0 - weight.x) + c10 * weight.x, bottom = c01 * (1.0 - weight.x) + c11 * weight.x;
    return top * (1.0 - weight.y) + bottom * weight.y;
}

// Bilinear at one level (0: base, k: prefiltered k, L + 1: irradiance, L + 1 + k: residual k).
vec3 sampleEnvironmentLevel(int level, vec3 d) {
    EquirectTexels e = equirectTexels(d, level == 0 ? environmentSizes.xy : environmentSizes.zw);
    return bilinear(fetchEnvironmentLevel(level, e.corners.xy), fetchEnvironmentLevel(level, e.corners.zy),
                    fetchEnvironmentLevel(level, e.corners.xw), fetchEnvironmentLevel(level, e.corners.zw), e.weight);
}

// The same at a level k ≥ 1 of the prefiltered array: one fetch a texel where a level that may be
// the base takes two (llvmpipe runs both arms of a choice).
vec3 samplePrefilteredLevel(int level, vec3 d) {
    EquirectTexels e = equirectTexels(d, environmentSizes.zw);
    int layer = level - 1;
    return bilinear(texelFetch(environmentPrefiltered, ivec3(e.corners.xy, layer), 0).rgb,
                    texelFetch(environmentPrefiltered, ivec3(e.corners.zy, layer), 0).rgb,
                    texelFetch(environmentPrefiltered, ivec3(e.corners.xw, layer), 0).rgb,
                    texelFetch(environmentPrefiltered, ivec3(e.corners.zw, layer), 0).rgb, e.weight);
}

// Radiance arriving from a world direction: intensity × base level.
vec3 environmentRadiance(vec3 worldDirection) {
    return environmentTransform.z * sampleEnvironmentLevel(0, environmentMapDirection(worldDirection));
}

// E(n)/π from the irradiance map: twin of diffuseRadiance().
vec3 environmentDiffuseRadiance(vec3 normal) {
    return environmentTransform.z * sampleEnvironmentLevel(PREFILTERED_LEVELS + 1, environmentMapDirection(normal));
}

// Prefiltered radiance for perceptual roughness r: twin of prefilteredRadiance().
vec3 environmentSpecularRadiance(vec3 worldDirection, float perceptualRoughness) {
    vec3 d = environmentMapDirection(worldDirection);
    float level = clamp(perceptualRoughness, 0.0, 1.0) * float(PREFILTERED_LEVELS);
    int lower = min(int(level), PREFILTERED_LEVELS - 1);
    float t = level - float(lower);
    return environmentTransform.z * (sampleEnvironmentLevel(lower, d) * (1.0 - t) +
                                     samplePrefilteredLevel(lower + 1, d) * t);
}

// The map's peak lights (twins of environmentUsesPeaks, environmentPeakDirection and
// environmentPeakIrradiance in environment_lighting.cpp, which fill the block): their count a
// compile-time constant in a specialised program (the sum unrolled), else the block's.
#ifdef GLINT_ENVIRONMENT_PEAKS
int environmentPeakCount() { return GLINT_ENVIRONMENT_PEAKS; }
#else
int environmentPeakCount() { return environmentFlags.z; }
#endif

bool environmentUsesPeaks(float alpha) { return alpha >= environmentTransform.w && environmentPeakCount() > 0; }

vec3 environmentPeakDirection(int k) { return environmentPeakDirections[k].xyz; }

vec3 environmentPeakIrradiance(int k) { return environmentPeakIrradiances[k].rgb; }

const float PEAK_WIDENING = 0.5;  // kPeakWidening

// Twin of environmentPeakAlpha().
float environmentPeakAlpha(int k, float alpha) {
    float spread = PEAK_WIDENING * environmentPeakDirections[k].w;
    return min(1.0, sqrt(alpha * alpha + spread * spread));
}

// Twin of gaussianSlopePeakAlpha(): a Gaussian slope lobe (Ward's, Beckmann's) widened for a light by
// half the variance GGX's is.
float environmentGaussianSlopePeakAlpha(float alpha, float widened) {
    return sqrt(alpha * alpha + 0.5 * (widened * widened - alpha * alpha));
}

// Twin of sumOverPeaks() in environment_lighting.cpp: runs STATEMENT for every peak light k
// where a lobe of roughness ALPHA takes them, with its direction `wi` and the widened roughness
// `widened` (a macro: GLSL has no callbacks). A do-while loop with a dynamic count, so that a lobe
// below the map's peak-light α costs llvmpipe one masked pass, not every light's: it runs both arms
// of a choice (an unrolled sum inside an if), and a for loop's body once more after its last pass.
#define ENVIRONMENT_EACH_PEAK(ALPHA, WO, FRAME, STATEMENT)                                                  \
    {                                                                                                     \
        int peakCount = environmentUsesPeaks(ALPHA) && cosTheta(FRAME, WO) > 0.0 ? environmentPeakCount() : 0; \
        int k = 0;                                                                                        \
        do {                                                                                              \
            if (k < peakCount) {                                                                          \
                vec3 wi = environmentPeakDirection(k);                                                    \
                float widened = environmentPeakAlpha(k, ALPHA);                                           \
                STATEMENT                                                                                 \
            }                                                                                             \
        } while (++k < peakCount);                                                                        \
    }

// Twin of peakLighting(): adds to SUM Σ_k f_r(ω_k; α_k) cos θ_k E_k over the peak lights above the
// surface, LOBE being the glossy lobe's f_r cos θ_i (Fresnel included) for `wi` at `widened`.
#define ENVIRONMENT_ADD_PEAKS(SUM, ALPHA, WO, FRAME, LOBE) \
    ENVIRONMENT_EACH_PEAK(ALPHA, WO, FRAME, if (cosTheta(FRAME, wi) > 0.0) SUM += (LOBE) * environmentPeakIrradiance(k);)

// Twin of glossyRadiance(): the prefiltered map (environmentSpecularRadiance) at perceptual roughness
// PERCEPTUAL, less its peaks where a lobe of GGX roughness ALPHA takes them (residualPrefilteredRadiance(),
// environment_map.cpp: r clamped to ≥ 1/L), as one pair of lookups whose levels are picked (llvmpipe
// would run both arms of a choice of calls).
vec3 environmentGlossyRadianceAt(vec3 worldDirection, float alpha, float perceptual) {
    bool residual = environmentUsesPeaks(alpha);
    vec3 d = environmentMapDirection(worldDirection);
    float level = clamp(perceptual * float(PREFILTERED_LEVELS), residual ? 1.0 : 0.0, float(PREFILTERED_LEVELS));
    int lower = min(int(level), PREFILTERED_LEVELS - 1);
    float t = level - float(lower);
    int first = residual ? PREFILTERED_LEVELS + 1 + lower : lower;
    return environmentTransform.z * (sampleEnvironmentLevel(first, d) * (1.0 - t) + samplePrefilteredLevel(first + 1, d) * t);
}

vec3 environmentGlossyRadiance(vec3 worldDirection, float alpha) {
    return environmentGlossyRadianceAt(worldDirection, alpha, sqrt(alpha));
}

// Twin of obliqueGlossyRadiance(): the lobe along `direction` seen at θ_o, narrower across the plane
// of incidence by cos θ_o, as two lookups either side of it in that plane.
const float OBLIQUE_FADE_ALPHA = 0.6;  // kObliqueFadeAlpha

vec3 environmentObliqueGlossyRadiance(vec3 direction, ShadingFrame frame, vec3 wo, float alpha, float perceptual) {
    float cosOut = clamp(cosTheta(frame, wo), 0.0, 1.0);
    float fade = clamp(1.0 - alpha / OBLIQUE_FADE_ALPHA, 0.0, 1.0);
    vec3 across = frame.normal - direction * dot(frame.normal, direction);  // in the plane of incidence
    float acrossLength = length(across);
    vec3 offset = acrossLength > 1e-6 ? across * (fade * alpha * sqrt(1.0 - cosOut * cosOut) / acrossLength) : vec3(0.0);
    float narrowed = perceptual * sqrt(1.0 - fade + fade * cosOut);
    // A rough lobe (fade 0) takes one lookup. A do-while loop, so that llvmpipe runs the second only
    // where a pixel needs it: it runs both arms of a choice, and a for loop's body once more (masked)
    // after its last pass.
    int lookups = fade > 0.0 ? 2 : 1;
    vec3 sum = vec3(0.0);
    int i = 0;
    do {
        sum += environmentGlossyRadianceAt(normalize(i == 0 ? direction + offset : direction - offset), alpha, narrowed);
    } while (++i < lookups);
    return sum / float(lookups);
}

// Table TABLE at (cos θ_o, r): twin of sampleLobeAlbedo() in lobe_albedo.cpp.
vec2 sampleLobeAlbedo(int table, float cosOut, float perceptualRoughness) {
    float last = float(LOBE_ALBEDO_SIZE - 1);
    float x = clamp(cosOut * float(LOBE_ALBEDO_SIZE) - 0.5, 0.0, last);
    float y = clamp(perceptualRoughness * last, 0.0, last);
    int x0 = int(x), y0 = int(y);
    int x1 = min(x0 + 1, LOBE_ALBEDO_SIZE - 1), y1 = min(y0 + 1, LOBE_ALBEDO_SIZE - 1);
    float fx = x - float(x0), fy = y - float(y0);
    int base = table * LOBE_ALBEDO_SIZE;
    vec2 top = texelFetch(environmentLobeTables, ivec2(x0, base + y0), 0).rg * (1.0 - fx) +
               texelFetch(environmentLobeTables, ivec2(x1, base + y0), 0).rg * fx;
    vec2 bottom = texelFetch(environmentLobeTables, ivec2(x0, base + y1), 0).rg * (1.0 - fx) +
                  texelFetch(environmentLobeTables, ivec2(x1, base + y1), 0).rg * fx;
    return top * (1.0 - fy) + bottom * fy;
}

// Helpers of the model hooks (twins of environment_lighting.cpp).
vec3 environmentMirrorDirection(vec3 wo, ShadingFrame frame) {
    return 2.0 * cosTheta(frame, wo) * frame.normal - wo;
}

// Twin of smoothWeights(): the weights of E(u)/π, E(−u)/π and the mean radiance matching a
// diffuse-like lobe's bands 0-2 (BANDS: its first two Legendre moments per unit albedo).
vec3 environmentSmoothWeights(vec2 bands) {
    return vec3(0.75 * bands.x + 2.0 * bands.y, 2.0 * bands.y - 0.75 * bands.x, 1.0 - 4.0 * bands.y);
}

// Twin of the diffuse-like lightingOf(): the lookups for ALBEDO, the lobe's direction U and WEIGHTS,
// and (a macro) each peak light's own f_r cos θ_k in place of what they gave it, LOBE being f_r for `wi`.
vec3 environmentSmoothRadiance(vec3 albedo, vec3 u, vec3 weights) {
    return albedo * (weights.x * environmentDiffuseRadiance(u) + weights.y * environmentDiffuseRadiance(-u) +
                     weights.z * environmentResidualMean.rgb);
}
#define ENVIRONMENT_ADD_SMOOTH_PEAKS(SUM, ALBEDO, U, WEIGHTS, WO, FRAME, LOBE)                                      \
    ENVIRONMENT_EACH_PEAK(1.0, WO, FRAME, {                                                                         \
        float toward = dot(U, wi);                                                                                  \
        SUM += ((LOBE) * max(cosTheta(FRAME, wi), 0.0) -                                                            \
                (ALBEDO) * INV_PI * ((WEIGHTS).x * max(toward, 0.0) + (WEIGHTS).y * max(-toward, 0.0))) *           \
               environmentPeakIrradiance(k);                                                                        \
    })

// Twin of lobeAlbedo(): the directional albedo of table TABLE for a lobe of GGX roughness ALPHA.
float environmentLobeAlbedo(int table, vec3 wo, ShadingFrame frame, float alpha) {
    return sampleLobeAlbedo(table, max(cosTheta(frame, wo), 0.0), sqrt(alpha)).x;
}

// Twin of towardsMirror(): n + (R − n) t, normalised.
vec3 environmentTowardsMirror(vec3 wo, ShadingFrame frame, float t) {
    return normalize(frame.normal + (environmentMirrorDirection(wo, frame) - frame.normal) * t);
}

// Twin of dominantDirection() (Lagarde & de Rousiers 2014).
vec3 environmentDominantDirection(vec3 wo, ShadingFrame frame, float alpha) {
    float smoothness = clamp(1.0 - alpha, 0.0, 1.0);
    float factor = smoothness * (sqrt(smoothness) + alpha);
    return environmentTowardsMirror(wo, frame, factor);
}

// Twin of splitSumSpecular(): F0·A + B − a·C with the F82 form's F0 and a (f82FresnelOf) from the
// tables of the lobe's D × G pair (microfacetPair), along the dominant direction, or for a pair but
// GGX with Smith along its GGX stand-in.
vec3 environmentSplitSumSpecular(vec3 f0, vec3 coefficient, float alpha, int pair, vec3 wo, ShadingFrame frame) {
    float perceptual = sqrt(alpha), cosOut = max(cosTheta(frame, wo), 0.0);
    vec2 scaleBias = sampleLobeAlbedo(MICROFACET_SPLIT_SUM + pair, cosOut, perceptual);
    vec3 f82 = all(equal(coefficient, vec3(0.0))) ? vec3(0.0)
                                                   : coefficient * sampleLobeAlbedo(MICROFACET_F82 + pair, cosOut, perceptual).x;
    vec3 direction = environmentDominantDirection(wo, frame, alpha);
    float level = perceptual;
    if (pair != GGX_SMITH_PAIR) {
        vec2 standIn = sampleLobeAlbedo(MICROFACET_STAND_IN + pair, cosOut, perceptual);
        direction = environmentTowardsMirror(wo, frame, standIn.y);
        level = standIn.x;
    }
    return environmentObliqueGlossyRadiance(direction, frame, wo, alpha, level) * (f0 * scaleBias.x + scaleBias.y - f82);
}

// What a secondary ray sees (twin of MissRadiance::operator()), and a primary ray (::primary).
vec3 missRadiance(vec3 direction) {
    return environmentEnabled() ? environmentRadiance(direction) : backgroundRadiance(direction);
}

// What a ray leaving a rough interface sees (twin of MissRadiance::rough).
vec3 missRadianceRough(vec3 direction, float perceptualRoughness) {
    return environmentEnabled() ? environmentSpecularRadiance(direction, perceptualRoughness) : backgroundRadiance(direction);
}

vec3 primaryMissRadiance(vec3 direction) {
    return environmentShown() ? environmentRadiance(direction) : backgroundRadiance(direction);
}
