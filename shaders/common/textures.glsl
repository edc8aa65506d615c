// Material textures in the shader: image sampling with the surface's UV derivatives (mipmaps,
// trilinear or anisotropic per the texture's sampler state), the UV checker, Perlin noise,
// turbulence, marble and wood, and the tangent-space normal map. GLSL twin of
// core/texture/texture_eval.cpp and core/texture/procedural.cpp. Included by the generated
// material file only when the material has textures (after PERLIN_PERMUTATION and frame.glsl).

const int MAX_MATERIAL_TEXTURES = 8;  // kMaxMaterialTextures
const int TEXTURE_IMAGE = 0;
const int TEXTURE_CHECKER = 1;
const int TEXTURE_MARBLE = 2;
const int TEXTURE_WOOD = 3;

// Per slot, set by core/gl/material_textures.cpp.
uniform sampler2D textureImages[MAX_MATERIAL_TEXTURES];
uniform ivec4 textureSettings[MAX_MATERIAL_TEXTURES];  // x: kind, y: channel (0..3), z: octaves
uniform vec4 textureValueA[MAX_MATERIAL_TEXTURES];     // rgb: procedural value A (scalars in r)
uniform vec4 textureValueB[MAX_MATERIAL_TEXTURES];     // rgb: procedural value B
uniform vec4 textureScale[MAX_MATERIAL_TEXTURES];      // xy: tiling; z: frequency [1/m]; w: turbulence
uniform vec4 textureRange[MAX_MATERIAL_TEXTURES];      // xy: scalar images map texel t to mix(x, y, t)
uniform vec4 textureTransform[MAX_MATERIAL_TEXTURES];  // xy: UV offset; z: UV rotation [rad]; w: normal-map scale
uniform vec3 textureColorFactor[MAX_MATERIAL_TEXTURES];  // colour parameters: multiplies the value

uniform vec3 objectCenter;  // [m] origin of the object-space position (the shape's centre)

// Where the surface is being shaded; surface.frag sets it before shadeSurface().
struct TextureCoordinates {
    vec2 uv;
    vec2 uvDx, uvDy;       // screen-space derivatives of uv (for the mip level and anisotropy)
    vec3 objectPosition;   // [m], world axes, origin at the shape's centre
};
TextureCoordinates textureCoordinates;

// --- Perlin noise (Perlin, "Improving Noise", SIGGRAPH 2002) ---------------------------------

int permute(int i) { return PERLIN_PERMUTATION[i & 255]; }
float perlinFade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
float perlinGradient(int hash, float x, float y, float z) {
    int h = hash & 15;
    float u = h < 8 ? x : y;
    float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

float perlinNoise(vec3 point) {
    vec3 cell = floor(point);
    int X = int(cell.x) & 255, Y = int(cell.y) & 255, Z = int(cell.z) & 255;
    float x = point.x - cell.x, y = point.y - cell.y, z = point.z - cell.z;
    float u = perlinFade(x), v = perlinFade(y), w = perlinFade(z);
    int A = permute(X) + Y, AA = permute(A) + Z, AB = permute(A + 1) + Z;
    int B = permute(X + 1) + Y, BA = permute(B) + Z, BB = permute(B + 1) + Z;
    return mix(mix(mix(perlinGradient(permute(AA), x, y, z), perlinGradient(permute(BA), x - 1.0, y, z), u),
                   mix(perlinGradient(permute(AB), x, y - 1.0, z), perlinGradient(permute(BB), x - 1.0, y - 1.0, z), u), v),
               mix(mix(perlinGradient(permute(AA + 1), x, y, z - 1.0), perlinGradient(permute(BA + 1), x - 1.0, y, z - 1.0), u),
                   mix(perlinGradient(permute(AB + 1), x, y - 1.0, z - 1.0),
                       perlinGradient(permute(BB + 1), x - 1.0, y - 1.0, z - 1.0), u), v),
               w);
}

// Perlin 1985: turbulence(p) = Σ |noise(2^i p)| / 2^i.
float turbulence(vec3 point, int octaves) {
    float sum = 0.0, scale = 1.0;
    for (int i = 0; i < octaves; ++i, scale *= 2.0) sum += abs(perlinNoise(point * scale)) / scale;
    return sum;
}

float marbleWeight(vec3 objectPosition, float frequency, float amplitude, int octaves) {
    vec3 scaled = objectPosition * frequency;
    return 0.5 + 0.5 * sin(scaled.x + amplitude * turbulence(scaled, octaves));
}

float woodWeight(vec3 objectPosition, float frequency, float amplitude, int octaves) {
    vec3 scaled = objectPosition * frequency;
    float rings = sqrt(scaled.x * scaled.x + scaled.z * scaled.z) + 0.125 * amplitude * turbulence(scaled, octaves);
    return 0.5 + 0.5 * sin(2.0 * PI * rings);
}

float checkerWeight(vec2 tiledUv) {
    return ((int(floor(tiledUv.x)) + int(floor(tiledUv.y))) & 1) == 1 ? 1.0 : 0.0;
}

// --- evaluation ------------------------------------------------------------------------------

// The linear part of the texture's UV transform, R(rotation)·diag(tiling) (twin of transformedUv()).
mat2 uvTransform(int slot) {
    float c = cos(textureTransform[slot].z), s = sin(textureTransform[slot].z);
    return mat2(c, s, -s, c) * mat2(textureScale[slot].x, 0.0, 0.0, textureScale[slot].y);
}

// The texture's raw value at textureCoordinates: an image's filtered texel (linear RGBA) or
// mix(A, B, weight) of a procedural one.
vec4 evaluateTexture(int slot) {
    int kind = textureSettings[slot].x;
    mat2 linear = uvTransform(slot);
    vec2 uv = linear * textureCoordinates.uv + textureTransform[slot].xy;
    if (kind == TEXTURE_IMAGE) {
        TextureCoordinates c = textureCoordinates;
        return textureGrad(textureImages[slot], uv, linear * c.uvDx, linear * c.uvDy);
    }
    float weight;
    if (kind == TEXTURE_CHECKER) weight = checkerWeight(uv);
    else if (kind == TEXTURE_MARBLE)
        weight = marbleWeight(textureCoordinates.objectPosition, textureScale[slot].z, textureScale[slot].w, textureSettings[slot].z);
    else weight = woodWeight(textureCoordinates.objectPosition, textureScale[slot].z, textureScale[slot].w, textureSettings[slot].z);
    return vec4(mix(textureValueA[slot].rgb, textureValueB[slot].rgb, weight), 1.0);
}

vec3 textureColor(int slot) { return evaluateTexture(slot).rgb * textureColorFactor[slot]; }

float textureScalar(int slot) {
    vec4 value = evaluateTexture(slot);
    if (textureSettings[slot].x != TEXTURE_IMAGE) return value.r;
    return mix(textureRange[slot].x, textureRange[slot].y, value[textureSettings[slot].y]);
}

// Tangent-space normal map: n = 2·rgb − 1 along (tangent, bitangent, normal).
ShadingFrame normalMappedFrame(int slot, ShadingFrame frame) {
    float scale = textureTransform[slot].w;
    vec3 tangentSpace = (2.0 * evaluateTexture(slot).rgb - 1.0) * vec3(scale, scale, 1.0);
    vec3 normal = frame.tangent * tangentSpace.x + frame.bitangent * tangentSpace.y + frame.normal * tangentSpace.z;
    float normalLength = length(normal);
    if (normalLength < 1e-6) return frame;
    return frameFromNormalAndTangent(normal / normalLength, frame.tangent);
}

// --- texture coordinates of the shapes ------------------------------------------------------

// Sphere: twin of texturePointOn() in core/texture/texture_eval.cpp, from the exact hit point.
vec2 sphereUv(vec3 outwardNormal) {
    float u = atan(-outwardNormal.z, outwardNormal.x) / (2.0 * PI);
    if (u < 0.0) u += 1.0;
    return vec2(u, 1.0 - acos(clamp(outwardNormal.y, -1.0, 1.0)) / PI);
}

// Screen-space derivatives of uv; where u wraps (the sphere's seam at u = 0 ≡ 1) the
// derivative of fract(u + ½) is the continuous one (Tarini, "Cylindrical and Toroidal
// Parameterizations Without Vertex Seams", JGT 2012).
TextureCoordinates textureCoordinatesAt(vec2 uv, vec3 objectPosition) {
    TextureCoordinates c;
    c.uv = uv;
    c.objectPosition = objectPosition;
    vec2 dx = dFdx(uv), dy = dFdy(uv);
    float shiftedDx = dFdx(fract(uv.x + 0.5)), shiftedDy = dFdy(fract(uv.x + 0.5));
    if (abs(shiftedDx) < abs(dx.x)) dx.x = shiftedDx;
    if (abs(shiftedDy) < abs(dy.x)) dy.x = shiftedDy;
    c.uvDx = dx;
    c.uvDy = dy;
    return c;
}
