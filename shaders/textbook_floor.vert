#version 410 core
// The textbook floor's coverage (core/gl/textbook_floor_pass.h): a square facing the eye in the
// plane through the sphere's centre, just large enough to hold the sphere's silhouette (the
// tangent cone's section there has radius r·d/√(d² − r²) at distance d), so that only the pixels
// near the sphere run the fragment shader; the rest keep the cleared background.
uniform mat4 viewProjection;
uniform vec3 eye;      // [m], outside the sphere
uniform vec4 sphere;   // xyz: centre [m], w: radius [m]

void main() {
    vec3 toCentre = sphere.xyz - eye;
    float d = length(toCentre);
    vec3 w = toCentre / d;
    vec3 u = normalize(cross(w, abs(w.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    vec3 v = cross(u, w);
    float halfSide = sphere.w * d / sqrt(d * d - sphere.w * sphere.w);
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;  // a triangle strip of 4
    gl_Position = viewProjection * vec4(sphere.xyz + halfSide * (corner.x * u + corner.y * v), 1.0);
}
