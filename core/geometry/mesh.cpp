// Procedural meshes: UV sphere and plane (see mesh.h).
#include "geometry/mesh.h"

#include <cmath>

#include "math/constants.h"
#include "math/frame.h"
#include "util/diagnostic.h"

namespace glint {

Mesh makeUvSphere(glm::vec3 center, float radius, int segments, int rings) {
    GLINT_CHECK(segments >= 3 && rings >= 2 && radius > 0.0f);
    Mesh mesh;
    mesh.vertices.reserve(static_cast<size_t>(segments + 1) * (rings + 1));
    for (int ring = 0; ring <= rings; ++ring) {
        const float v = static_cast<float>(ring) / rings;
        const float polar = v * kPi;  // 0 at +y
        for (int segment = 0; segment <= segments; ++segment) {
            const float u = static_cast<float>(segment) / segments;
            const float azimuth = u * 2.0f * kPi;
            const glm::vec3 normal{std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                   -std::sin(polar) * std::sin(azimuth)};
            const glm::vec3 tangent{-std::sin(azimuth), 0.0f, -std::cos(azimuth)};
            mesh.vertices.push_back({center + radius * normal, normal, {u, 1.0f - v}, tangent});
        }
    }
    const int stride = segments + 1;
    for (int ring = 0; ring < rings; ++ring) {
        for (int segment = 0; segment < segments; ++segment) {
            const uint32_t a = ring * stride + segment, b = a + stride, c = b + 1, d = a + 1;
            if (ring != 0) mesh.indices.insert(mesh.indices.end(), {a, b, d});
            if (ring != rings - 1) mesh.indices.insert(mesh.indices.end(), {d, b, c});
        }
    }
    return mesh;
}

Mesh makePlane(glm::vec3 center, glm::vec3 normal, glm::vec2 size) {
    const ShadingFrame frame = ShadingFrame::fromNormal(glm::normalize(normal));
    const glm::vec3 halfU = frame.tangent * (0.5f * size.x);
    const glm::vec3 halfV = frame.bitangent * (0.5f * size.y);
    Mesh mesh;
    mesh.vertices = {
        {center - halfU - halfV, frame.normal, {0, 0}, frame.tangent},
        {center + halfU - halfV, frame.normal, {1, 0}, frame.tangent},
        {center + halfU + halfV, frame.normal, {1, 1}, frame.tangent},
        {center - halfU + halfV, frame.normal, {0, 1}, frame.tangent},
    };
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

}  // namespace glint
