#version 410 core
// The bare shading pass of `glint bench` (core/gl/bare_shading_pass.h): the cost floor of
// shading, the same generated material and shadeSurface() as surface.frag, per pixel, with no
// scene: no ray cast, no depth, no background pass, no display transform. Not a picture anyone
// reads. The dome's points lie on the unit sphere at the origin (the bench spheres), so the traced
// lobes of mirror and glass see the same geometry as in the scene.
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "common/background.glsl"
#include "common/environment.glsl"
#include "common/shape.glsl"
#include "common/specular_transport.glsl"
#include "generated/material.glsl"
#include "common/shading.glsl"

out vec4 outRadiance;

void main() {
    // A normal and a view direction per pixel (a dome facing the viewer; neither a constant, so
    // the compiler cannot fold the BRDF away), as a camera's would be.
    vec2 ndc = 2.0 * gl_FragCoord.xy / viewportSize.xy - 1.0;
    vec3 normal = normalize(vec3(0.8 * ndc, 1.0));
    ShadingFrame frame = frameFromNormalAndTangent(normal, vec3(1.0, 0.0, 0.0));
    vec3 towardsViewer = normalize(vec3(-0.5 * ndc, 1.0));
    outRadiance = vec4(shadeSurface(normal, frame, towardsViewer), 1.0);
}
