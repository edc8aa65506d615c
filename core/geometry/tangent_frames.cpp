// Vertex tangents from UVs (see tangent_frames.h).
#include "geometry/tangent_frames.h"

#include <cmath>

#include "math/frame.h"

namespace glint {

void completeTangents(Mesh& mesh) {
    std::vector<char> fromUvs(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) fromUvs[i] = mesh.vertices[i].tangent == glm::vec3(0.0f);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        if (!fromUvs[i0] && !fromUvs[i1] && !fromUvs[i2]) continue;
        const Vertex &v0 = mesh.vertices[i0], &v1 = mesh.vertices[i1], &v2 = mesh.vertices[i2];
        // p1 − p0 = Δu1·∂p/∂u + Δv1·∂p/∂v and likewise for p2: solve the 2×2 system for ∂p/∂u.
        const glm::vec3 edge1 = v1.position - v0.position, edge2 = v2.position - v0.position;
        const glm::vec2 delta1 = v1.uv - v0.uv, delta2 = v2.uv - v0.uv;
        const float determinant = delta1.x * delta2.y - delta2.x * delta1.y;
        if (determinant == 0.0f) continue;
        // Unit per triangle, so that neither the mesh's units nor its UV scale matter.
        const glm::vec3 alongU = glm::normalize((edge1 * delta2.y - edge2 * delta1.y) / determinant);
        if (!std::isfinite(alongU.x + alongU.y + alongU.z)) continue;
        for (const uint32_t index : {i0, i1, i2})
            if (fromUvs[index]) mesh.vertices[index].tangent += alongU;
    }
    for (Vertex& vertex : mesh.vertices) vertex.tangent = ShadingFrame::fromNormalAndTangent(vertex.normal, vertex.tangent).tangent;
}

}  // namespace glint
