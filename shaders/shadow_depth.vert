#version 410 core
// Shadow-map depth pass, vertex stage: world position of the object's mesh (or a sphere's proxy)
// into the light's clip space. Writes no colour; see shadow_depth.frag.
layout(location = 0) in vec3 inPosition;

uniform mat4 lightViewProjection;  // world → clip of the map (or of one cube face)
uniform vec4 placement;            // as surface.vert: xyz offset [m], w uniform scale

out vec3 worldPosition;

void main() {
    worldPosition = placement.xyz + placement.w * inPosition;
    gl_Position = lightViewProjection * vec4(worldPosition, 1.0);
}
