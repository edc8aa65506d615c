// The simplified stand-ins of large meshes (geometry/mesh_simplify.h): the triangle budget is
// met without falling far below it, every vertex stays within its grid cell of the surface it
// replaces, the bounds shrink by at most a cell, normals and tangents are unit (and follow the
// surface), and the two sides of a thin wall keep their own normals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/mesh_simplify.h"

namespace glint {
namespace {

// An n×n grid of quads in the plane z = `z`, facing +z (or −z when `down`).
Mesh gridAt(int n, float z, bool down) {
    Mesh mesh;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            mesh.vertices.push_back({{float(x) / n, float(y) / n, z}, {0, 0, down ? -1.0f : 1.0f}, {float(x) / n, float(y) / n}, {1, 0, 0}});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 2, d = a + n + 1;
            if (down) mesh.indices.insert(mesh.indices.end(), {a, c, b, a, d, c});
            else mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        }
    return mesh;
}

TEST(MeshSimplify, SphereMeetsTheBudgetAndStaysOnItsSurface) {
    const Mesh sphere = makeUvSphere({0, 0, 0}, 1.0f, 200, 100);  // 39,800 triangles
    const size_t budget = 4000;
    const SimplifiedMesh simplified = simplifyMesh(sphere, budget);
    const Mesh& proxy = simplified.mesh;
    EXPECT_LE(proxy.triangleCount(), budget);
    EXPECT_GE(proxy.triangleCount(), budget / 2);  // not needlessly coarse
    ASSERT_GT(simplified.cellSize, 0.0f);
    const float cellDiagonal = simplified.cellSize * std::sqrt(3.0f);
    for (const Vertex& vertex : proxy.vertices) {
        // Inside its cell, which the sphere crosses: within a cell diagonal of the surface (the
        // quadric placement keeps it far closer).
        EXPECT_NEAR(glm::length(vertex.position), 1.0f, 0.1f * cellDiagonal);
        EXPECT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(vertex.normal, glm::normalize(vertex.position)), 0.99f);  // the sphere's normal
        EXPECT_NEAR(glm::length(vertex.tangent), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(vertex.tangent, vertex.normal), 0.0f, 1e-5f);
    }
    const MeshBounds before = meshBounds(sphere), after = meshBounds(proxy);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_GE(after.low[axis], before.low[axis]);  // never grows
        EXPECT_LE(after.high[axis], before.high[axis]);
        EXPECT_LE(after.low[axis] - before.low[axis], simplified.cellSize);  // shrinks by at most a cell
        EXPECT_LE(before.high[axis] - after.high[axis], simplified.cellSize);
    }
    for (uint32_t index : proxy.indices) ASSERT_LT(index, proxy.vertices.size());
}

TEST(MeshSimplify, TightBudgetsAreMet) {
    const Mesh torus = makeTorus({0, 0, 0}, 1.0f, 0.3f, 120, 60);
    for (size_t budget : {size_t{1}, size_t{50}, size_t{600}}) {
        SCOPED_TRACE(budget);
        EXPECT_LE(simplifyMesh(torus, budget).mesh.triangleCount(), budget);
    }
}

TEST(MeshSimplify, AMeshWithinTheBudgetComesBackUnchanged) {
    const Mesh cube = makeCube({0, 0, 0}, 1.0f);
    const SimplifiedMesh simplified = simplifyMesh(cube, 12);
    EXPECT_EQ(simplified.cellSize, 0.0f);
    EXPECT_EQ(simplified.mesh.indices, cube.indices);
}

TEST(MeshSimplify, TheTwoSidesOfAThinWallKeepTheirNormals) {
    // Two sheets 10⁻⁴ apart facing away from each other: both collapse into the same cells, and
    // each cell gets one vertex per side, so neither side's normal is averaged away.
    Mesh wall = gridAt(60, 0.0f, false);
    const Mesh back = gridAt(60, 1e-4f, true);
    const auto offset = static_cast<uint32_t>(wall.vertices.size());
    wall.vertices.insert(wall.vertices.end(), back.vertices.begin(), back.vertices.end());
    for (uint32_t index : back.indices) wall.indices.push_back(index + offset);
    const Mesh proxy = simplifyMesh(wall, 800).mesh;
    ASSERT_GT(proxy.triangleCount(), 100u);
    EXPECT_LE(proxy.triangleCount(), 800u);
    size_t up = 0, down = 0;
    for (const Vertex& vertex : proxy.vertices) {
        EXPECT_GT(std::abs(vertex.normal.z), 0.999f);
        (vertex.normal.z > 0.0f ? up : down) += 1;
    }
    EXPECT_EQ(up, down);
    // Both orientations of each collapsed triangle survive: the wall is seen from either side.
    size_t facingUp = 0;
    for (size_t t = 0; t < proxy.triangleCount(); ++t) {
        const glm::vec3 a = proxy.vertices[proxy.indices[3 * t]].position, b = proxy.vertices[proxy.indices[3 * t + 1]].position,
                        c = proxy.vertices[proxy.indices[3 * t + 2]].position;
        facingUp += glm::cross(b - a, c - a).z > 0.0f ? 1 : 0;
    }
    EXPECT_EQ(2 * facingUp, proxy.triangleCount());
}

}  // namespace
}  // namespace glint
