#version 410 core
// The BRDF sampling pass (core/gl/brdf_sampler.h): one fragment per direction pair, writing f_r
// [1/sr] of a custom .brdf shader at (ω_i, ω_o) read from two float textures, in the local frame
// (tangent x, bitangent y, normal z). The same includes as surface.frag up to the generated
// material, so the .brdf sees what it sees when it renders; no lighting, no display encoding.
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/background.glsl"
#include "common/environment.glsl"
#include "common/shape.glsl"
#include "common/specular_transport.glsl"
#include "generated/material.glsl"

uniform sampler2D incidentDirections;  // ω_i per texel (rgb)
uniform sampler2D outgoingDirections;  // ω_o per texel (rgb)

out vec4 reflectance;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec3 wi = texelFetch(incidentDirections, texel, 0).xyz;
    vec3 wo = texelFetch(outgoingDirections, texel, 0).xyz;
    ShadingFrame frame;
    frame.tangent = vec3(1.0, 0.0, 0.0);
    frame.bitangent = vec3(0.0, 1.0, 0.0);
    frame.normal = vec3(0.0, 0.0, 1.0);
    frame.coatNormal = vec3(0.0);
    reflectance = vec4(GLINT_EVAL_BRDF(loadMaterialParams(), wi, wo, frame), 1.0);
}
