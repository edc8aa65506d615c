#version 410 core
// Wireframe overlay: each drawn triangle becomes its three edges (a closed line strip).
// Closed shapes skip triangles facing away (counter-clockwise in NDC is the front, as the
// surface pass's back-face culling assumes); two-sided planes keep both sides.
layout(triangles) in;
layout(line_strip, max_vertices = 4) out;

uniform bool cullBackFaces;

void main() {
    if (cullBackFaces && gl_in[0].gl_Position.w > 0.0 && gl_in[1].gl_Position.w > 0.0 && gl_in[2].gl_Position.w > 0.0) {
        vec2 a = gl_in[0].gl_Position.xy / gl_in[0].gl_Position.w;
        vec2 b = gl_in[1].gl_Position.xy / gl_in[1].gl_Position.w;
        vec2 c = gl_in[2].gl_Position.xy / gl_in[2].gl_Position.w;
        float twiceSignedArea = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (twiceSignedArea <= 0.0) return;
    }
    for (int i = 0; i < 4; ++i) {
        gl_Position = gl_in[i % 3].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
