// Mesh import (core/geometry/mesh_import.h): every format loads a grid the test writes itself
// with the right vertex and triangle counts; the real meshes in ../shared/assets/meshes load;
// progress and cancel; and a malformed corpus fails with a message naming the file.
#include <gtest/gtest.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "geometry/mesh_import.h"
#include "mesh_test_files.h"
#include "test_support.h"
#include "util/file_io.h"

namespace glint {
namespace {

std::string meshPath(const std::string& name) { return test::outputDirectory("mesh_import") + "/" + name; }

// A 2×2 grid: 9 vertices, 8 triangles, all facing +z.
void expectGrid(const std::string& path) {
    SCOPED_TRACE(path);
    auto imported = importMesh(path);
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    const MeshStatistics& statistics = imported->statistics;
    EXPECT_EQ(statistics.triangleCount, 8u);
    EXPECT_EQ(statistics.vertexCount, 9u);
    EXPECT_EQ(imported->mesh->vertices.size(), 9u);
    EXPECT_EQ(imported->mesh->indices.size(), 24u);
    EXPECT_EQ(statistics.degenerateTrianglesDropped, 0u);
    EXPECT_EQ(statistics.boundsMin, glm::vec3(0, 0, 0));
    EXPECT_EQ(statistics.boundsMax, glm::vec3(2, 2, 0));
    float farthest = 0.0f;
    for (const Vertex& vertex : imported->mesh->vertices) {
        farthest = std::max(farthest, glm::length(vertex.position));
        EXPECT_NEAR(std::abs(vertex.normal.z), 1.0f, 1e-5f);  // generated or from the file: the grid's normal
        EXPECT_NEAR(glm::length(vertex.tangent), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(vertex.tangent, vertex.normal), 0.0f, 1e-5f);
    }
    EXPECT_NEAR(farthest, 1.0f, 1e-5f);  // centred and scaled into the unit sphere
    EXPECT_GE(statistics.loadSeconds, 0.0);
}

TEST(MeshImport, EachFormatLoadsTheGridWithTheRightCounts) {
    const test::GridMesh grid = test::makeGrid(2);
    test::writeObj(meshPath("grid.obj"), grid);
    test::writePly(meshPath("grid_ascii.ply"), grid, false);
    test::writePly(meshPath("grid_binary.ply"), grid, true);
    test::writeStl(meshPath("grid_ascii.stl"), grid, false);
    test::writeStl(meshPath("grid_binary.stl"), grid, true);
    test::writeGltf(meshPath("grid.gltf"), grid);
    test::writeGlb(meshPath("grid.glb"), grid);
    for (const char* name : {"grid.obj", "grid_ascii.ply", "grid_binary.ply", "grid_ascii.stl", "grid_binary.stl",
                             "grid.gltf", "grid.glb"})
        expectGrid(meshPath(name));
}

// Assimp 5.2.5 cannot read back the binary FBX its exporter writes ("block offset is out of
// range"), so the test writes ASCII FBX ("fbxa").
TEST(MeshImport, FbxWrittenByAssimpsExporterLoads) {
    test::writeObj(meshPath("for_fbx.obj"), test::makeGrid(2));
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(meshPath("for_fbx.obj"), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    Assimp::Exporter exporter;
    ASSERT_EQ(exporter.Export(scene, "fbxa", meshPath("grid.fbx")), aiReturn_SUCCESS) << exporter.GetErrorString();
    expectGrid(meshPath("grid.fbx"));
}

TEST(MeshImport, FromMemoryWithAFormatHint) {
    const test::GridMesh grid = test::makeGrid(3);
    test::writePly(meshPath("memory.ply"), grid, true);
    auto bytes = readTextFile(meshPath("memory.ply"));  // any bytes
    ASSERT_TRUE(bytes.ok());
    auto imported = importMeshFromMemory(bytes->data(), bytes->size(), "ply", "in-memory grid");
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    EXPECT_EQ(imported->statistics.triangleCount, 18u);
    EXPECT_EQ(imported->statistics.vertexCount, 16u);
}

TEST(MeshImport, NodeTransformsPlaceEachMesh) {
    // Two triangles in two glTF nodes, the second moved by +10 in x: the merged bounds span both.
    const std::string positions = std::string(reinterpret_cast<const char*>(std::array<float, 9>{0, 0, 0, 1, 0, 0, 0, 1, 0}.data()), 36);
    const std::string uri = "data:application/octet-stream;base64," + test::base64(positions);
    test::writeText(meshPath("two_nodes.gltf"),
                    R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],)"
                    R"("nodes":[{"mesh":0},{"mesh":0,"translation":[10,0,0]}],)"
                    R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
                    R"("buffers":[{"byteLength":36,"uri":")" + uri + R"("}],)"
                    R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
                    R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]})");
    auto imported = importMesh(meshPath("two_nodes.gltf"));
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    EXPECT_EQ(imported->statistics.triangleCount, 2u);
    EXPECT_EQ(imported->statistics.meshesMerged, 2u);
    EXPECT_FLOAT_EQ(imported->statistics.boundsMax.x, 11.0f);
}

TEST(MeshImport, ProgressReachesOneAndCancelStops) {
    test::writeObj(meshPath("progress.obj"), test::makeGrid(100));
    std::vector<float> fractions;
    auto imported = importMesh(meshPath("progress.obj"), {}, [&](float fraction) {
        fractions.push_back(fraction);
        return true;
    });
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    EXPECT_EQ(imported->statistics.triangleCount, 20000u);
    ASSERT_GE(fractions.size(), 2u);
    EXPECT_EQ(fractions.back(), 1.0f);
    for (float fraction : fractions) EXPECT_TRUE(fraction >= 0.0f && fraction <= 1.0f) << fraction;

    int calls = 0;
    auto cancelled = importMesh(meshPath("progress.obj"), {}, [&](float) { return ++calls < 2; });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_TRUE(isImportCancellation(cancelled.error())) << cancelled.error().format();
    EXPECT_EQ(calls, 2);  // no progress after the cancel
}

TEST(MeshImport, ZeroAreaFacesAreDroppedAndCounted) {
    test::writeText(meshPath("some_degenerate.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 2 2 3\n");
    auto imported = importMesh(meshPath("some_degenerate.obj"));
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    EXPECT_EQ(imported->statistics.triangleCount, 1u);
    EXPECT_EQ(imported->statistics.vertexCount, 3u);
    EXPECT_GE(imported->statistics.degenerateTrianglesDropped, 1u);
}

TEST(MeshImport, TheSharedRealMeshesLoad) {
    const std::filesystem::path folder = std::filesystem::path(GLINT_TEST_DATA_DIR) / "../../shared/assets/meshes";
    if (!std::filesystem::exists(folder)) GTEST_SKIP() << "no " << folder << " (the shared assets are not checked out)";
    struct Expected {
        const char* name;
        size_t positions, faces;
        bool uvs;
    };
    for (const Expected& expected : {Expected{"cow.obj", 2903, 5804, false}, Expected{"spot.obj", 2930, 5856, true},
                                     Expected{"teapot.obj", 3644, 6320, false}}) {
        SCOPED_TRACE(expected.name);
        auto imported = importMesh((folder / expected.name).string());
        ASSERT_TRUE(imported.ok()) << imported.error().format();
        const MeshStatistics& statistics = imported->statistics;
        EXPECT_EQ(statistics.triangleCount + statistics.degenerateTrianglesDropped, expected.faces);
        // Creases (normals generated at 60°) and UV seams split vertices, identical ones merge:
        // a closed mesh has about half as many vertices as triangles (Euler), never more than 3×.
        EXPECT_GE(statistics.vertexCount, expected.faces / 2);
        EXPECT_LE(statistics.vertexCount, 3 * expected.faces);
        std::printf("%s: %zu positions in the file -> %zu vertices, %zu triangles, %zu zero-area dropped\n", expected.name,
                    expected.positions, statistics.vertexCount, statistics.triangleCount,
                    statistics.degenerateTrianglesDropped);
        EXPECT_FALSE(statistics.hadNormals);
        EXPECT_EQ(statistics.hadUvs, expected.uvs);
    }
}

// --- malformed corpus --------------------------------------------------------------------------

void expectRefused(const std::string& name, const std::string& content, const std::string& mentions = {}) {
    SCOPED_TRACE(name);
    const std::string path = meshPath(name);
    test::writeText(path, content);
    auto imported = importMesh(path);
    ASSERT_FALSE(imported.ok()) << "loaded " << imported->statistics.triangleCount << " triangles";
    EXPECT_EQ(imported.error().where.file, path);
    EXPECT_NE(imported.error().format().find(path), std::string::npos);
    if (!mentions.empty()) {
        EXPECT_NE(imported.error().message.find(mentions), std::string::npos) << imported.error().format();
    }
}

TEST(MeshImport, MalformedFilesAreRefusedWithTheFileNamed) {
    const test::GridMesh grid = test::makeGrid(2);
    auto missing = importMesh(meshPath("does_not_exist.obj"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("no such file"), std::string::npos);
    expectRefused("empty.obj", "", "empty");
    expectRefused("wrong_header.ply", "plx\nformat ascii 1.0\nend_header\n");
    expectRefused("text.glb", "this is not a binary glTF file at all");
    expectRefused("not_a_mesh.stl", "\x01\x02\x03");
    expectRefused("unknown.xyz", "v 0 0 0\n", "extension");
    expectRefused("nan_vertex.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "finite");
    expectRefused("infinite_vertex.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n",
                  "finite");
    expectRefused("index_out_of_range.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99\n");
    expectRefused("end_header_run_on.ply",  // assimp 5.2.5 would never return (fuzz_mesh_import found it)
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header0\n0  0\n1 0 0\n0 1 0\n3 0 1 2\n",
                  "end_header0");
    expectRefused("header_cut_short.ply",  // assimp 5.2.5 would never return
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty", "without end_header");
    expectRefused("lying_face_size.ply",  // a 38,888,888-gon: assimp's Triangulate would take ages
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n38888888 0 1 2\n",
                  "corners");
    expectRefused("index_out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
    expectRefused("all_zero_area.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "zero area");
    expectRefused("no_faces.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\n");
    // Lying sizes: a binary STL claiming 1000 facets with data for 8; a binary PLY cut short.
    test::writeStl(meshPath("lying.stl"), grid, true);
    {
        std::fstream patch(meshPath("lying.stl"), std::ios::in | std::ios::out | std::ios::binary);
        patch.seekp(80);
        const uint32_t claimed = 1000;
        patch.write(reinterpret_cast<const char*>(&claimed), 4);
    }
    auto lying = importMesh(meshPath("lying.stl"));
    EXPECT_FALSE(lying.ok());
    test::writePly(meshPath("truncated.ply"), test::makeGrid(20), true);
    std::filesystem::resize_file(meshPath("truncated.ply"), std::filesystem::file_size(meshPath("truncated.ply")) / 2);
    auto truncated = importMesh(meshPath("truncated.ply"));
    ASSERT_FALSE(truncated.ok());
    EXPECT_EQ(truncated.error().where.file, meshPath("truncated.ply"));
    // glTF whose accessor claims more vertices than its buffer holds.
    const std::string buffer = test::gridBuffer(grid);
    std::string json = test::gltfJson(grid, buffer.size(), "data:application/octet-stream;base64," + test::base64(buffer));
    json.replace(json.find("\"count\":9"), 9, "\"count\":900");
    expectRefused("lying_accessor.gltf", json);
}

// What assimp 5.2.5 reads silently half: an OBJ cut short (a face of fewer than three corners, a
// corner or a vertex cut in half), OBJ and glTF indices past the vertices (assimp drops the
// triangle). Each is refused with its line, or its JSON key.
TEST(MeshImport, CutShortAndOutOfRangeFilesAreRefusedWhereTheyBreak) {
    const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
    const std::pair<const char*, std::string> objs[] = {
        {"f 1 2 3\nf 2 4\n", ":6:1: cannot load mesh: a face with 2 corner(s)"},
        {"f 1 2 3\nf 2 4 3/\n", ":6:1: cannot load mesh: face corner '3/' is incomplete"},
        {"f 1//1 2//1 3//\n", ":5:1: cannot load mesh: face corner '3//' is incomplete"},
        {"f 1 2 0\n", ":5:1: cannot load mesh: face corner '0': vertex index 0"},
        {"f 1 2 5\n", ":5:1: cannot load mesh: face corner '5' uses vertex 5, but the file has only 4 vertices"},
        {"f -1 -2 -5\n", ":5:1: cannot load mesh: face corner '-5' counts back 5 vertices"},
        {"f 1 2 3\nv 1 1\n", ":6:1: cannot load mesh: a vertex needs x y z (2 number(s) given"},
    };
    for (const auto& [faces, expected] : objs) {
        const std::string path = meshPath("cut.obj");
        test::writeText(path, v + faces);
        auto imported = importMesh(path);
        ASSERT_FALSE(imported.ok()) << faces;
        EXPECT_EQ(imported.error().format(), path + expected + imported.error().format().substr(path.size() + expected.size()))
            << imported.error().format();
    }
    test::GridMesh grid = test::makeGrid(2);
    grid.indices.back() = 99;
    test::writeGlb(meshPath("index_out_of_range.glb"), grid);
    auto glb = importMesh(meshPath("index_out_of_range.glb"));
    ASSERT_FALSE(glb.ok());
    EXPECT_NE(glb.error().format().find("index_out_of_range.glb (JSON chunk):1:"), std::string::npos) << glb.error().format();
    EXPECT_NE(glb.error().message.find("/accessors/1: index 23 is 99, but mesh 0 primitive 0 has only 9 vertices"),
              std::string::npos)
        << glb.error().format();
    test::writeGltf(meshPath("index_out_of_range.gltf"), grid);
    EXPECT_FALSE(importMesh(meshPath("index_out_of_range.gltf")).ok());
    // Continued lines and points and lines: read, and the points and lines counted as dropped.
    test::writeText(meshPath("lines.obj"), v + "f 1 2 \\\n 3\nl 1 2\np 4\n");
    auto lines = importMesh(meshPath("lines.obj"));
    ASSERT_TRUE(lines.ok()) << lines.error().format();
    EXPECT_EQ(lines->statistics.triangleCount, 1u);
    EXPECT_EQ(lines->statistics.pointsAndLinesDropped, 2u);
}

// PLY triangle strips (assimp 5.2.5 would read each as one polygon) become their triangles, every
// other one flipped so that all face the same way; -1 separates strips; the binary file too.
TEST(MeshImport, PlyTriangleStripsBecomeTrianglesWoundAlike) {
    const std::string files = std::string(GLINT_TEST_DATA_DIR) + "/files/ply/";
    auto ascii = importMesh(files + "tristrips_ascii.ply");
    ASSERT_TRUE(ascii.ok()) << ascii.error().format();
    EXPECT_EQ(ascii->statistics.triangleCount, 8u);
    for (const Vertex& vertex : ascii->mesh->vertices) EXPECT_NEAR(vertex.normal.z, 1.0f, 1e-5f);
    auto binary = importMesh(files + "tristrips_binary.ply");
    ASSERT_TRUE(binary.ok()) << binary.error().format();
    EXPECT_EQ(binary->statistics.triangleCount, 4u);
    for (const Vertex& vertex : binary->mesh->vertices) EXPECT_NEAR(vertex.normal.z, 1.0f, 1e-5f);
    // A strip cut short is refused, naming the element.
    auto bytes = readTextFile(files + "tristrips_binary.ply");
    ASSERT_TRUE(bytes.ok());
    auto cut = importMeshFromMemory(bytes->data(), bytes->size() - 6, "ply", "cut.ply");
    ASSERT_FALSE(cut.ok());
    EXPECT_NE(cut.error().message.find("element 'tristrips' record 0 is malformed or cut short"), std::string::npos)
        << cut.error().format();
}

// A Z-up file (CAD, 3ds Max) turned upright: its +z becomes +y.
TEST(MeshImport, ZUpMeshesStandUp) {
    test::writeText(meshPath("tall_z.obj"), "v 0 0 0\nv 0.1 0 0\nv 0 0 4\nf 1 2 3\n");
    auto yUp = importMesh(meshPath("tall_z.obj"));
    auto zUp = importMesh(meshPath("tall_z.obj"), MeshImportOptions{60.0f, MeshUpAxis::Z});
    ASSERT_TRUE(yUp.ok() && zUp.ok());
    float yExtentAsIs = 0, yExtentTurned = 0;
    for (const Vertex& vertex : yUp->mesh->vertices) yExtentAsIs = std::max(yExtentAsIs, std::abs(vertex.position.y));
    for (const Vertex& vertex : zUp->mesh->vertices) yExtentTurned = std::max(yExtentTurned, std::abs(vertex.position.y));
    EXPECT_LT(yExtentAsIs, 0.01f);
    EXPECT_GT(yExtentTurned, 0.99f);
}

TEST(MeshImport, SmoothingAngleOutsideItsRangeIsRefused) {
    test::writeObj(meshPath("angle.obj"), test::makeGrid(1));
    EXPECT_FALSE(importMesh(meshPath("angle.obj"), MeshImportOptions{-1.0f}).ok());
    EXPECT_FALSE(importMesh(meshPath("angle.obj"), MeshImportOptions{180.5f}).ok());
    EXPECT_FALSE(importMesh(meshPath("angle.obj"), MeshImportOptions{std::nanf("")}).ok());
    EXPECT_TRUE(importMesh(meshPath("angle.obj"), MeshImportOptions{0.0f}).ok());
    EXPECT_TRUE(importMesh(meshPath("angle.obj"), MeshImportOptions{180.0f}).ok());
}

TEST(MeshImport, ExtensionsAreRecognisedCaseInsensitively) {
    EXPECT_TRUE(isMeshFile("a/b/Model.OBJ"));
    EXPECT_TRUE(isMeshFile("x.glb"));
    EXPECT_FALSE(isMeshFile("scene.json"));
}

}  // namespace
}  // namespace glint
