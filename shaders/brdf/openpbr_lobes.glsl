// The OpenPBR model's lobes: GLSL twin of core/brdf/openpbr_lobes.h (see there for the papers).
#include "brdf/fresnel.glsl"
#include "brdf/microfacet.glsl"

const float OPENPBR_MIN_ALPHA = 1e-3;            // kOpenPbrMinAlpha
const float OPENPBR_MIN_FUZZ_ROUGHNESS = 0.07;   // kOpenPbrMinFuzzRoughness

vec2 openPbrAlphas(float roughness, float anisotropy) {
    float inverse = 1.0 - anisotropy;
    float alphaT = min(1.0, roughness * roughness * sqrt(2.0 / (1.0 + inverse * inverse)));
    return vec2(max(alphaT, OPENPBR_MIN_ALPHA), max(inverse * alphaT, OPENPBR_MIN_ALPHA));
}

float openPbrEquivalentRoughness(vec2 alphas) { return sqrt(sqrt(alphas.x * alphas.y)); }

float ggxLobe(vec3 wi, vec3 wo, vec2 alphas) {
    vec3 halfway = normalize(wi + wo);
    return distributionGgxAnisotropic(halfway, alphas.x, alphas.y) *
           smithHeightCorrelated(lambdaGgxAnisotropic(wi, alphas.x, alphas.y),
                                 lambdaGgxAnisotropic(wo, alphas.x, alphas.y)) /
           (4.0 * wi.z * wo.z);
}

vec3 schlickF90(vec3 f0, vec3 f90, float cosine) {
    float m = clamp(1.0 - cosine, 0.0, 1.0);
    return f0 + (f90 - f0) * (m * m * m * m * m);
}

float dielectricF0(float eta) { return ((eta - 1.0) / (eta + 1.0)) * ((eta - 1.0) / (eta + 1.0)); }

const float FON_CONSTANT_1 = 0.5 - 2.0 / (3.0 * PI);
const float FON_CONSTANT_2 = 2.0 / 3.0 - 28.0 / (15.0 * PI);

float fujiiAlbedo(float cosine, float roughness) {
    float m = 1.0 - cosine;
    float gOverPi = m * (0.0571085289 + m * (0.491881867 + m * (-0.332181442 + m * 0.0714429953)));
    return (1.0 + roughness * gOverPi) / (1.0 + FON_CONSTANT_1 * roughness);
}

float fujiiAverageAlbedo(float roughness) {
    return (1.0 + FON_CONSTANT_2 * roughness) / (1.0 + FON_CONSTANT_1 * roughness);
}

vec3 eonMultipleAlbedo(vec3 albedo, float roughness) {
    float average = fujiiAverageAlbedo(roughness);
    return albedo * albedo * average / (1.0 - albedo * (1.0 - average));
}

vec3 eonLobe(vec3 albedo, float roughness, vec3 wi, vec3 wo) {
    float s = dot(wi, wo) - wi.z * wo.z;
    float sOverT = s > 0.0 ? s / max(wi.z, wo.z) : s;
    float single = (1.0 + roughness * sOverT) / (1.0 + FON_CONSTANT_1 * roughness);
    float multiple = max(1e-7, 1.0 - fujiiAlbedo(wo.z, roughness)) * max(1e-7, 1.0 - fujiiAlbedo(wi.z, roughness)) /
                     max(1e-7, 1.0 - fujiiAverageAlbedo(roughness));
    return (albedo * single + eonMultipleAlbedo(albedo, roughness) * multiple) * INV_PI;
}

vec3 eonAlbedo(vec3 albedo, float roughness, float cosOut) {
    float single = fujiiAlbedo(cosOut, roughness);
    return albedo * single + eonMultipleAlbedo(albedo, roughness) * (1.0 - single);
}

float sheenLobe(vec3 wi, vec3 wo, float roughness) {
    float r = max(roughness, OPENPBR_MIN_FUZZ_ROUGHNESS);
    float inverseAlpha = 1.0 / (r * r);
    vec3 halfway = normalize(wi + wo);
    float sin2Half = max(0.0, 1.0 - halfway.z * halfway.z);
    float distribution = (2.0 + inverseAlpha) * pow(sin2Half, 0.5 * inverseAlpha) / (2.0 * PI);
    return distribution / (4.0 * (wi.z + wo.z - wi.z * wo.z));
}

vec3 thinFilmSensitivity(float opticalPathNm, vec3 shift) {
    float phase = 2.0 * PI * opticalPathNm * 1e-9;
    const vec3 value = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const vec3 position = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 variance = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    vec3 xyz = value * sqrt(2.0 * PI * variance) * cos(position * phase + shift) * exp(-phase * phase * variance);
    xyz.x += 9.7470e-14 * sqrt(2.0 * PI * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x) *
             exp(-4.5282e+09 * phase * phase);
    xyz /= 1.0685e-7;
    return vec3(3.2404542 * xyz.x - 1.5371385 * xyz.y - 0.4985314 * xyz.z,
                -0.9692660 * xyz.x + 1.8760108 * xyz.y + 0.0415560 * xyz.z,
                0.0556434 * xyz.x - 0.2040259 * xyz.y + 1.0572252 * xyz.z);
}

vec3 thinFilmFresnel(float outsideIor, float filmIor, float thicknessNm, float cosine, vec3 baseF0) {
    float t = clamp(thicknessNm / 30.0, 0.0, 1.0);
    float ior = outsideIor + (filmIor - outsideIor) * t * t * (3.0 - 2.0 * t);
    float sin2Film = (outsideIor / ior) * (outsideIor / ior) * (1.0 - cosine * cosine);
    if (sin2Film >= 1.0) return vec3(1.0);
    float cosFilm = sqrt(1.0 - sin2Film);
    float r0 = ((ior - outsideIor) / (ior + outsideIor)) * ((ior - outsideIor) / (ior + outsideIor));
    float r12 = schlickF90(vec3(r0), vec3(1.0), cosine).x;
    float t121 = 1.0 - r12;
    float phi12 = ior < outsideIor ? PI : 0.0;
    float phi21 = PI - phi12;
    vec3 sqrtF0 = sqrt(clamp(baseF0, vec3(0.0), vec3(0.9999)));
    vec3 baseIor = (1.0 + sqrtF0) / (1.0 - sqrtF0);
    vec3 baseR0 = ((baseIor - ior) / (baseIor + ior)) * ((baseIor - ior) / (baseIor + ior));
    vec3 r23 = schlickF90(baseR0, vec3(1.0), cosFilm);
    vec3 phi23 = vec3(baseIor.x < ior ? PI : 0.0, baseIor.y < ior ? PI : 0.0, baseIor.z < ior ? PI : 0.0);
    float opticalPath = 2.0 * ior * thicknessNm * cosFilm;
    vec3 phi = vec3(phi21) + phi23;
    vec3 r123 = clamp(r12 * r23, vec3(1e-5), vec3(0.9999));
    vec3 rs = t121 * t121 * r23 / (1.0 - r123);
    vec3 reflectance = r12 + rs;
    vec3 cm = rs - t121;
    for (int m = 1; m <= 2; ++m) {
        cm *= sqrt(r123);
        reflectance += cm * 2.0 * thinFilmSensitivity(float(m) * opticalPath, float(m) * phi);
    }
    return clamp(reflectance, vec3(0.0), vec3(1.0));
}
