// BRDF Explorer texts of two built-in models' twins, shared by the tests that compare a .brdf
// material with its twin (custom_brdf_gpu_test.cpp renders them, plot_sampling_gpu_test.cpp plots
// them): Lambert (albedo) and the normalised Blinn-Phong (diffuse, specular, exponent).
#pragma once

namespace glint::test {

inline constexpr const char* kLambertTwinBrdf = R"(analytic
::begin parameters
color albedo 0.8 0.8 0.8
::end parameters
::begin shader
const float PI = 3.14159265358979323846;
vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return albedo / PI; }
::end shader
)";

inline constexpr const char* kBlinnPhongTwinBrdf = R"(analytic
::begin parameters
color diffuse 0.5 0.1 0.1
float specular 0 1 0.04
float exponent 1 1000 64
::end parameters
::begin shader
const float PI = 3.14159265358979323846;
float powZeroIsOne(float base, float exponent) { return pow(base, exponent); }  // Glint has one too
vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)
{
    if (dot(N, L) <= 0.0 || dot(N, V) <= 0.0) return vec3(0.0);
    vec3 H = normalize(L + V);
    float lobe = powZeroIsOne(max(dot(N, H), 0.0), exponent);
    return diffuse / PI + vec3(specular * (exponent + 8.0) / (8.0 * PI) * lobe);
}
::end shader
)";

}  // namespace glint::test
