// Normals and tangents of imported meshes (core/geometry/mesh_builder.h, crease_normals.h,
// tangent_frames.h): a cube and an octagonal prism (smooth 45° sides, sharp 90° rims) written by
// the test in every format without normals give the same vertices and normals in all of them at
// every crease angle; normals in the file are kept; a UV'd quad's tangent runs along +u.
#include <gtest/gtest.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <tuple>

#include "geometry/mesh_builder.h"
#include "geometry/mesh_import.h"
#include "mesh_test_files.h"
#include "test_support.h"

namespace glint {
namespace {

std::string normalsMeshPath(const std::string& name) { return test::outputDirectory("mesh_normals") + "/" + name; }

// Quads (a, b, c, d), counter-clockwise seen from outside, as two triangles each.
void addQuad(test::GridMesh& mesh, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
}

test::GridMesh cubeMesh() {
    test::GridMesh cube;
    cube.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    addQuad(cube, 0, 3, 2, 1), addQuad(cube, 4, 5, 6, 7), addQuad(cube, 0, 1, 5, 4);
    addQuad(cube, 1, 2, 6, 5), addQuad(cube, 2, 3, 7, 6), addQuad(cube, 3, 0, 4, 7);
    return cube;
}

// An octagon with integer corners (neighbouring sides 45° apart) swept 3 along +z, capped by
// fans from the centres: 16 ring positions and 2 centres, 32 triangles.
test::GridMesh prismMesh() {
    test::GridMesh prism;
    const glm::vec2 octagon[8] = {{2, 1}, {1, 2}, {-1, 2}, {-2, 1}, {-2, -1}, {-1, -2}, {1, -2}, {2, -1}};
    for (float z : {0.0f, 3.0f})
        for (const glm::vec2 corner : octagon) prism.positions.push_back({corner, z});
    prism.positions.push_back({0, 0, 0});
    prism.positions.push_back({0, 0, 3});
    for (uint32_t i = 0; i < 8; ++i) {
        const uint32_t next = (i + 1) % 8;
        addQuad(prism, i, next, 8 + next, 8 + i);
        prism.indices.insert(prism.indices.end(), {16, next, i, 17, 8 + i, 8 + next});
    }
    return prism;
}

// Assimp 5.2.5 reads back only the ASCII FBX its exporter writes (see mesh_import_test.cpp).
void writeFbx(const std::string& path, const test::GridMesh& mesh) {
    test::writeObj(path + ".obj", mesh);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path + ".obj", 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    Assimp::Exporter exporter;
    ASSERT_EQ(exporter.Export(scene, "fbxa", path), aiReturn_SUCCESS) << exporter.GetErrorString();
}

struct Format {
    const char* file;  // name suffix, extension included
    std::function<void(const std::string&, const test::GridMesh&)> write;
    bool uvs;
};

const std::vector<Format>& formats() {
    static const std::vector<Format> all = {
        {".obj", test::writeObj, true},
        {"_ascii.ply", [](const std::string& path, const test::GridMesh& mesh) { test::writePly(path, mesh, false); }, true},
        {"_binary.ply", [](const std::string& path, const test::GridMesh& mesh) { test::writePly(path, mesh, true); }, true},
        {"_ascii.stl", [](const std::string& path, const test::GridMesh& mesh) { test::writeStl(path, mesh, false); }, false},
        {"_binary.stl", [](const std::string& path, const test::GridMesh& mesh) { test::writeStl(path, mesh, true); }, false},
        {".gltf", test::writeGltf, true},
        {".glb", test::writeGlb, true},
        {".fbx", writeFbx, true},
    };
    return all;
}

// The vertices as (position, normal), sorted, so that formats listing them in other orders compare.
std::vector<std::pair<glm::vec3, glm::vec3>> sortedVertices(const Mesh& mesh) {
    std::vector<std::pair<glm::vec3, glm::vec3>> vertices;
    for (const Vertex& vertex : mesh.vertices) vertices.push_back({vertex.position, vertex.normal});
    const auto key = [](const std::pair<glm::vec3, glm::vec3>& v) {
        const auto q = [](float x) { return std::lround(x * 1e4f); };
        return std::tuple(q(v.first.x), q(v.first.y), q(v.first.z), q(v.second.x), q(v.second.y), q(v.second.z));
    };
    std::sort(vertices.begin(), vertices.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
    return vertices;
}

ImportedMesh load(const std::string& path, float creaseAngleDegrees) {
    auto imported = importMesh(path, MeshImportOptions{creaseAngleDegrees});
    EXPECT_TRUE(imported.ok()) << imported.error().format();
    return imported.ok() ? *imported : ImportedMesh{std::make_shared<const Mesh>(), {}};
}

TEST(MeshNormals, EveryFormatWithoutNormalsGivesTheSameNormalsAtEveryCreaseAngle) {
    struct Shape {
        const char* name;
        test::GridMesh mesh;
        size_t triangles;
        // Vertices at crease angles 0°, 60°, 89°, 91°, 180°: the cube's 90° edges split below
        // 90° (4 per face) and smooth above (one per corner); the prism's 45° sides smooth from
        // 60° on, its 90° rims from 91° on.
        std::array<size_t, 5> vertices;
    };
    const Shape shapes[] = {{"cube", cubeMesh(), 12, {24, 24, 24, 8, 8}}, {"prism", prismMesh(), 32, {50, 34, 34, 18, 18}}};
    const float angles[] = {0.0f, 60.0f, 89.0f, 91.0f, 180.0f};
    for (const Shape& shape : shapes) {
        for (const Format& format : formats()) format.write(normalsMeshPath(shape.name + std::string(format.file)), shape.mesh);
        for (size_t a = 0; a < std::size(angles); ++a) {
            const ImportedMesh reference = load(normalsMeshPath(shape.name + std::string(".obj")), angles[a]);
            for (const Format& format : formats()) {
                SCOPED_TRACE(shape.name + std::string(format.file) + " at " + std::to_string(angles[a]) + "°");
                const ImportedMesh imported = load(normalsMeshPath(shape.name + std::string(format.file)), angles[a]);
                EXPECT_FALSE(imported.statistics.hadNormals);  // STL's facet normals are not vertex normals
                EXPECT_EQ(imported.statistics.triangleCount, shape.triangles);
                ASSERT_EQ(imported.statistics.vertexCount, shape.vertices[a]);
                const auto expected = sortedVertices(*reference.mesh), actual = sortedVertices(*imported.mesh);
                for (size_t i = 0; i < actual.size(); ++i) {
                    EXPECT_LT(glm::length(actual[i].first - expected[i].first), 1e-5f) << "vertex " << i;
                    EXPECT_LT(glm::length(actual[i].second - expected[i].second), 1e-5f) << "vertex " << i;
                }
            }
        }
    }
}

glm::vec3 faceNormal(const Mesh& mesh, size_t triangle) {
    const glm::vec3 p0 = mesh.vertices[mesh.indices[3 * triangle]].position;
    const glm::vec3 p1 = mesh.vertices[mesh.indices[3 * triangle + 1]].position;
    const glm::vec3 p2 = mesh.vertices[mesh.indices[3 * triangle + 2]].position;
    return glm::normalize(glm::cross(p1 - p0, p2 - p0));
}

TEST(MeshNormals, CreaseAngleZeroIsFlatAndOneEightySmoothEverywhere) {
    const std::string path = normalsMeshPath("prism_flat_smooth.ply");
    test::writePly(path, prismMesh(), true);  // indexed: every triangle shares its corners
    const ImportedMesh flat = load(path, 0.0f);
    for (size_t t = 0; t < flat.mesh->triangleCount(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_LT(glm::length(flat.mesh->vertices[flat.mesh->indices[3 * t + k]].normal - faceNormal(*flat.mesh, t)), 1e-6f);
    const ImportedMesh smooth = load(path, 180.0f);
    std::set<std::tuple<float, float, float>> positions;
    for (const Vertex& vertex : smooth.mesh->vertices) positions.insert({vertex.position.x, vertex.position.y, vertex.position.z});
    EXPECT_EQ(smooth.mesh->vertices.size(), positions.size());  // one normal per position
}

TEST(MeshNormals, ACubesRightAngledEdgesSplitBelowNinetyDegreesAndSmoothAbove) {
    const std::string path = normalsMeshPath("cube_edges.glb");
    test::writeGlb(path, cubeMesh());
    const ImportedMesh split = load(path, 89.0f), smooth = load(path, 91.0f);
    for (const Vertex& vertex : split.mesh->vertices) {  // the faces' own normals
        const glm::vec3 size = glm::abs(vertex.normal);
        EXPECT_NEAR(std::max({size.x, size.y, size.z}), 1.0f, 1e-6f);
    }
    for (const Vertex& vertex : smooth.mesh->vertices)  // along the diagonals (angle-weighted)
        EXPECT_LT(glm::length(vertex.normal - glm::sign(vertex.position) / std::sqrt(3.0f)), 1e-6f);
}

TEST(MeshNormals, AVertexSharedByAHundredThousandFacesIsSmoothedInOnePass) {
    // A disc fanned from its centre: comparing every face at the centre with every other would
    // take 10¹⁰ steps (minutes); the flat fan needs one pass.
    test::GridMesh disc;
    const int segments = 100000;
    disc.positions.push_back({0, 0, 0});
    for (int i = 0; i < segments; ++i) {
        const float angle = 2.0f * 3.14159265f * float(i) / segments;
        disc.positions.push_back({std::cos(angle), std::sin(angle), 0.0f});
        disc.indices.insert(disc.indices.end(), {0u, uint32_t(1 + i), uint32_t(1 + (i + 1) % segments)});
    }
    test::writePly(normalsMeshPath("fan_disc.ply"), disc, true);
    const ImportedMesh imported = load(normalsMeshPath("fan_disc.ply"), 30.0f);
    EXPECT_EQ(imported.statistics.vertexCount, disc.positions.size());
    for (const Vertex& vertex : imported.mesh->vertices) EXPECT_LT(glm::length(vertex.normal - glm::vec3(0, 0, 1)), 1e-5f);
}

TEST(MeshNormals, NormalsInTheFileAreKept) {
    // A cube whose file normals point along the diagonals: kept even at a 0° crease angle.
    std::string obj;
    for (const glm::vec3& p : cubeMesh().positions)
        obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\nvn " +
               std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    const test::GridMesh cube = cubeMesh();
    for (size_t i = 0; i < cube.indices.size(); i += 3) {
        obj += "f";
        for (size_t k = i; k < i + 3; ++k) obj += " " + std::to_string(cube.indices[k] + 1) + "//" + std::to_string(cube.indices[k] + 1);
        obj += "\n";
    }
    test::writeText(normalsMeshPath("cube_with_normals.obj"), obj);
    const ImportedMesh imported = load(normalsMeshPath("cube_with_normals.obj"), 0.0f);
    EXPECT_TRUE(imported.statistics.hadNormals);
    EXPECT_EQ(imported.statistics.vertexCount, 8u);
    for (const Vertex& vertex : imported.mesh->vertices)
        EXPECT_LT(glm::length(vertex.normal - glm::sign(vertex.position) / std::sqrt(3.0f)), 1e-6f);
}

TEST(MeshTangents, AUvQuadsTangentRunsAlongPlusUInEveryFormatWithUvs) {
    // A unit quad facing +z whose u grows along +y (v along −x): the tangent is +y, not the
    // fallback ⟂ the normal (which for +z is +x).
    test::GridMesh quad;
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (const glm::vec3& p : quad.positions) quad.uvs.push_back({p.y, 1.0f - p.x});
    addQuad(quad, 0, 1, 2, 3);
    for (const Format& format : formats()) {
        if (!format.uvs) continue;
        SCOPED_TRACE(format.file);
        const std::string path = normalsMeshPath("uv_quad" + std::string(format.file));
        format.write(path, quad);
        const ImportedMesh imported = load(path, 60.0f);
        EXPECT_TRUE(imported.statistics.hadUvs);
        EXPECT_EQ(imported.statistics.vertexCount, 4u);
        for (const Vertex& vertex : imported.mesh->vertices) {
            EXPECT_LT(glm::length(vertex.normal - glm::vec3(0, 0, 1)), 1e-6f);
            EXPECT_LT(glm::length(vertex.tangent - glm::vec3(0, 1, 0)), 1e-5f) << vertex.tangent.x << " " << vertex.tangent.y;
        }
    }
}

TEST(MeshBuilder, EqualPositionsWeldAndMinusZeroIsZero) {
    MeshBuilder builder(60.0f);
    const uint32_t a = builder.addVertex({0, 0, 0}), b = builder.addVertex({1, 0, 0}), c = builder.addVertex({0, 1, 0});
    const uint32_t a2 = builder.addVertex({-0.0f, 0, -0.0f}), d = builder.addVertex({1, 1, 0}), c2 = builder.addVertex({0, 1, 0});
    EXPECT_TRUE(builder.addTriangle(a, b, c));
    EXPECT_TRUE(builder.addTriangle(b, d, c2));
    EXPECT_FALSE(builder.addTriangle(a2, b, b));  // zero area, counted
    EXPECT_EQ(builder.degenerateTrianglesDropped(), 1u);
    std::optional<Mesh> mesh = builder.build();
    ASSERT_TRUE(mesh);
    EXPECT_EQ(mesh->vertices.size(), 4u);  // a and a2 weld, and c and c2
    EXPECT_EQ(mesh->indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
    int calls = 0;
    MeshBuilder cancelled(60.0f);
    cancelled.addTriangle(cancelled.addVertex({0, 0, 0}), cancelled.addVertex({1, 0, 0}), cancelled.addVertex({0, 1, 0}));
    EXPECT_FALSE(cancelled.build([&](float) { return ++calls < 1; }));
    EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace glint
