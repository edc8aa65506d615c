// Procedural meshes: UV sphere, plane, cube and torus (see mesh.h).
#include "geometry/mesh.h"

#include <cmath>

#include "math/constants.h"
#include "math/frame.h"
#include "util/diagnostic.h"

namespace glint {

MeshBounds meshBounds(const Mesh& mesh) {
    MeshBounds bounds;
    for (const Vertex& vertex : mesh.vertices) {
        bounds.low = glm::min(bounds.low, vertex.position);
        bounds.high = glm::max(bounds.high, vertex.position);
    }
    return bounds;
}

Mesh makeUvSphere(glm::vec3 center, float radius, int segments, int rings) {
    GLINT_CHECK(segments >= 3 && rings >= 2 && radius > 0.0f);
    Mesh mesh;
    mesh.vertices.reserve(static_cast<size_t>(segments + 1) * (rings + 1));
    // The seam (u = 1) and the poles take the exact coordinates of u = 0 and of the axis, so that
    // every copy of a position is equal (sin 2π and sin π are not 0 in floats); mesh_topology.h
    // welds vertices by equal positions.
    for (int ring = 0; ring <= rings; ++ring) {
        const float v = static_cast<float>(ring) / rings;
        const float polar = v * kPi;  // 0 at +y
        const float sinPolar = ring == 0 || ring == rings ? 0.0f : std::sin(polar);
        const float cosPolar = ring == 0 ? 1.0f : ring == rings ? -1.0f : std::cos(polar);
        for (int segment = 0; segment <= segments; ++segment) {
            const float u = static_cast<float>(segment) / segments;
            const float azimuth = segment == segments ? 0.0f : u * 2.0f * kPi;
            const glm::vec3 normal{sinPolar * std::cos(azimuth), cosPolar, -sinPolar * std::sin(azimuth)};
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

void rotateMesh(Mesh& mesh, glm::vec3 pivot, glm::vec3 degrees) {
    if (degrees == glm::vec3(0.0f)) return;
    const glm::vec3 r = glm::radians(degrees);
    const glm::mat3 aboutX(1, 0, 0, 0, std::cos(r.x), std::sin(r.x), 0, -std::sin(r.x), std::cos(r.x));
    const glm::mat3 aboutY(std::cos(r.y), 0, -std::sin(r.y), 0, 1, 0, std::sin(r.y), 0, std::cos(r.y));
    const glm::mat3 aboutZ(std::cos(r.z), std::sin(r.z), 0, -std::sin(r.z), std::cos(r.z), 0, 0, 0, 1);
    const glm::mat3 turn = aboutZ * aboutY * aboutX;  // column-major: x is applied first
    for (Vertex& vertex : mesh.vertices) {
        vertex.position = pivot + turn * (vertex.position - pivot);
        vertex.normal = turn * vertex.normal;
        vertex.tangent = turn * vertex.tangent;
    }
}

Mesh makeCube(glm::vec3 center, float size) {
    GLINT_CHECK(size > 0.0f);
    Mesh mesh;
    const float half = 0.5f * size;
    // Each face: its outward normal and a tangent; the bitangent n × t completes the square.
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 tangents[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
    for (int face = 0; face < 6; ++face) {
        const glm::vec3 normal = normals[face], tangent = tangents[face];
        const glm::vec3 bitangent = glm::cross(normal, tangent);
        const auto first = static_cast<uint32_t>(mesh.vertices.size());
        const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2 corner : corners)
            mesh.vertices.push_back({center + half * (normal + corner.x * tangent + corner.y * bitangent), normal,
                                     0.5f * (corner + 1.0f), tangent});
        mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    return mesh;
}

Mesh makeTorus(glm::vec3 center, float majorRadius, float minorRadius, int segments, int rings) {
    GLINT_CHECK(segments >= 3 && rings >= 3 && majorRadius > 0.0f && minorRadius > 0.0f);
    Mesh mesh;
    mesh.vertices.reserve(static_cast<size_t>(segments + 1) * (rings + 1));
    // Both seams (u = 1, v = 1) take the exact coordinates of u = 0 and v = 0, as the sphere's.
    for (int ring = 0; ring <= rings; ++ring) {
        const float v = static_cast<float>(ring) / rings;
        const float tubeAngle = ring == rings ? 0.0f : v * 2.0f * kPi;
        for (int segment = 0; segment <= segments; ++segment) {
            const float u = static_cast<float>(segment) / segments;
            const float azimuth = segment == segments ? 0.0f : u * 2.0f * kPi;
            const glm::vec3 radial{std::cos(azimuth), 0.0f, -std::sin(azimuth)};
            const glm::vec3 normal = std::cos(tubeAngle) * radial + glm::vec3(0.0f, std::sin(tubeAngle), 0.0f);
            const glm::vec3 tangent{-std::sin(azimuth), 0.0f, -std::cos(azimuth)};
            mesh.vertices.push_back({center + majorRadius * radial + minorRadius * normal, normal, {u, v}, tangent});
        }
    }
    const int stride = segments + 1;
    for (int ring = 0; ring < rings; ++ring) {
        for (int segment = 0; segment < segments; ++segment) {
            const uint32_t a = ring * stride + segment, b = a + stride, c = b + 1, d = a + 1;
            mesh.indices.insert(mesh.indices.end(), {a, d, c, a, c, b});
        }
    }
    return mesh;
}

}  // namespace glint
