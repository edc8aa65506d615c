#version 410 core
// Shadow-map depth pass, fragment stage: the depth of the true surface as the light sees it. An
// analytic sphere is ray-cast from the light through the proxy's fragment, so its shadow has the
// exact silhouette; meshes keep their rasterised depth. Cube maps store distance / far plane.
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/shape.glsl"

const int SHADOW_ORTHOGRAPHIC = 0;
const int SHADOW_CUBE = 2;

uniform mat4 lightViewProjection;
uniform int shadowKind;
uniform vec4 lightOrigin;  // xyz: light position (perspective, cube) or travel direction (orthographic); w: far plane [m]

in vec3 worldPosition;

void main() {
    vec3 surface = worldPosition;
    float depth = gl_FragCoord.z;
    if (shapeKind == SHAPE_SPHERE) {
        // The ray of this map texel: parallel to the light's travel (orthographic) or from the
        // light through the proxy point; the proxy circumscribes the sphere, so every texel the
        // sphere covers has a proxy fragment.
        Ray ray;
        ray.origin = shadowKind == SHADOW_ORTHOGRAPHIC ? worldPosition : lightOrigin.xyz;
        ray.direction = shadowKind == SHADOW_ORTHOGRAPHIC ? lightOrigin.xyz : normalize(worldPosition - lightOrigin.xyz);
        float t = intersectSphere(ray);
        if (t < 0.0) discard;
        surface = ray.origin + t * ray.direction;
        vec4 clip = lightViewProjection * vec4(surface, 1.0);
        depth = 0.5 * (clip.z / clip.w) + 0.5;
    }
    if (shadowKind == SHADOW_CUBE) depth = length(surface - lightOrigin.xyz) / lightOrigin.w;
    gl_FragDepth = depth;
}
