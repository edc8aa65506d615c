// Mesh: an indexed triangle list with per-vertex normals, UVs and tangents, and the procedural
// shapes Glint draws (UV sphere with adjustable tessellation, plane). CPU data only: uploading
// it is the renderer's job.
#pragma once

#include <cstdint>
#include <limits>
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

// The smallest axis-aligned box holding a mesh's vertex positions (low > high: no vertices).
struct MeshBounds {
    glm::vec3 low{std::numeric_limits<float>::max()}, high{-std::numeric_limits<float>::max()};
};
MeshBounds meshBounds(const Mesh& mesh);

// What the importer found in a mesh file (geometry/mesh_import.h); shown in the editor.
// Which of the file's axes points up: Y (glTF, OBJ from most tools) or Z (CAD, 3ds Max, Blender
// files exported without the axis conversion); a Z-up mesh is turned a quarter about x.
enum class MeshUpAxis { Y, Z };

struct MeshStatistics {
    size_t vertexCount = 0;
    size_t triangleCount = 0;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // in the file's own units, before centring
    bool hadNormals = false;  // false: normals were generated (always for STL, whose facet normals are not kept)
    bool hadUvs = false;      // false: tangents are a fallback, not from UVs
    size_t degenerateTrianglesDropped = 0;  // zero-area faces removed
    size_t pointsAndLinesDropped = 0;       // faces of one or two corners (OBJ `p` and `l`, PLY edges) left out
    size_t meshesMerged = 0;                // meshes of the file's node tree merged into one
    double loadSeconds = 0.0;               // wall time of the whole import
};

// A UV sphere of `segments` slices around the pole axis (+y) and `rings` stacks from pole to
// pole (segments ≥ 3, rings ≥ 2). Vertices lie on the sphere of the given radius.
Mesh makeUvSphere(glm::vec3 center, float radius, int segments, int rings);

// A rectangle `size.x` by `size.y` centred at `center`, facing `normal`.
Mesh makePlane(glm::vec3 center, glm::vec3 normal, glm::vec2 size);

// An axis-aligned cube of edge `size`: 24 vertices (four per face, with the face's normal), 12
// triangles.
Mesh makeCube(glm::vec3 center, float size);
// Turns the mesh about `pivot` by Euler angles [degrees]: about x, then y, then z (positions,
// normals and tangents alike; a rotation keeps them unit length).
void rotateMesh(Mesh& mesh, glm::vec3 pivot, glm::vec3 degrees);

// A torus around +y (segments ≥ 3 around the axis, rings ≥ 3 around the tube) with analytic
// normals; u runs around the axis, v around the tube.
Mesh makeTorus(glm::vec3 center, float majorRadius, float minorRadius, int segments, int rings);

}  // namespace glint
