// Mesh: an indexed triangle list with per-vertex normals, UVs and tangents, and the procedural
// shapes Glint draws (UV sphere with adjustable tessellation, plane). CPU data only: uploading
// it is the renderer's job.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace glint {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec3 tangent;  // along increasing u
};

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // three per triangle
    size_t triangleCount() const { return indices.size() / 3; }
};

// A UV sphere of `segments` slices around the pole axis (+y) and `rings` stacks from pole to
// pole (segments ≥ 3, rings ≥ 2). Vertices lie on the sphere of the given radius.
Mesh makeUvSphere(glm::vec3 center, float radius, int segments, int rings);

// A rectangle `size.x` by `size.y` centred at `center`, facing `normal`.
Mesh makePlane(glm::vec3 center, glm::vec3 normal, glm::vec2 size);

}  // namespace glint
