// Cube, torus and mesh objects and the interpolation mode in scene JSON (round trips, located
// errors, mesh paths relative to the scene file), the procedural meshes, and the reference's
// triangle BVH against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "geometry/shape_mesh.h"
#include "mesh_test_files.h"
#include "render/triangle_bvh.h"
#include "scene/plane_edge_fade.h"
#include "scene/scene_json.h"
#include "test_support.h"
#include "util/reference_confinement.h"

namespace glint {
namespace {

std::string sceneWithObjects(const std::string& objects) {
    return R"({"format": "glint-scene", "version": 1, "materials": [{"name": "m", "model": "lambert"}],
               "objects": [)" + objects + "]}";
}

TEST(SceneShapes, CubeTorusAndInterpolationRoundTrip) {
    auto scene = parseScene(sceneWithObjects(R"(
        {"shape": "cube", "center": [1, 2, 3], "size": 0.5, "interpolation": "gouraud", "material": "m"},
        {"shape": "torus", "major_radius": 2, "minor_radius": 0.5, "segments": 10, "rings": 5, "material": "m"},
        {"shape": "sphere", "segments": 8, "rings": 4, "interpolation": "flat", "material": "m"},
        {"shape": "sphere", "material": "m"})"),
                            "shapes.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    ASSERT_EQ(scene->objects.size(), 4u);
    const auto& cube = std::get<CubeShape>(scene->objects[0].shape);
    EXPECT_EQ(cube.center, glm::vec3(1, 2, 3));
    EXPECT_EQ(cube.size, 0.5f);
    EXPECT_EQ(scene->objects[0].interpolation, SurfaceInterpolation::Gouraud);
    const auto& torus = std::get<TorusShape>(scene->objects[1].shape);
    EXPECT_EQ(torus.majorRadius, 2.0f);
    EXPECT_EQ(torus.segments, 10);
    EXPECT_EQ(scene->objects[1].interpolation, SurfaceInterpolation::Phong);  // the default for a torus
    EXPECT_EQ(scene->objects[2].interpolation, SurfaceInterpolation::Flat);
    EXPECT_EQ(scene->objects[3].interpolation, SurfaceInterpolation::Exact);  // the default for a sphere
    auto again = parseScene(sceneToJson(*scene).dump(), "again.json");
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(sceneToJson(*again), sceneToJson(*scene));
    EXPECT_FALSE(sceneToJson(*scene)["objects"][3].contains("interpolation"));
}

TEST(SceneShapes, PlaneEdgeFadeRoundTripsAndIsWrittenOnlyWhenSet) {
    auto scene = parseScene(sceneWithObjects(R"(
        {"shape": "plane", "size": [4, 2], "edge_fade": 0.5, "material": "m"},
        {"shape": "plane", "material": "m"})"),
                            "planes.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    const auto& faded = std::get<PlaneShape>(scene->objects[0].shape);
    EXPECT_EQ(faded.edgeFade, 0.5f);
    EXPECT_EQ(planeEdgeFadeRadii(faded), glm::vec2(0.5f, 1.0f));  // half the smaller side is 1 m
    EXPECT_EQ(planeEdgeFade(faded.center, planeEdgeFadeRadii(faded), faded.center + glm::vec3(0.4f, 0.0f, 0.0f)), 0.0f);
    EXPECT_EQ(planeEdgeFade(faded.center, planeEdgeFadeRadii(faded), faded.center + glm::vec3(0.75f, 0.0f, 0.0f)), 0.5f);
    EXPECT_EQ(planeEdgeFade(faded.center, planeEdgeFadeRadii(faded), faded.center + glm::vec3(1.2f, 0.0f, 0.0f)), 1.0f);
    EXPECT_EQ(std::get<PlaneShape>(scene->objects[1].shape).edgeFade, 0.0f);
    EXPECT_EQ(sceneToJson(*scene)["objects"][0]["edge_fade"], 0.5f);
    EXPECT_FALSE(sceneToJson(*scene)["objects"][1].contains("edge_fade")) << "a hard edge writes nothing";
    auto again = parseScene(sceneToJson(*scene).dump(), "again.json");
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(sceneToJson(*again), sceneToJson(*scene));
}

TEST(SceneShapes, BadShapeKeysAreLocated) {
    struct Case {
        const char* object;
        const char* mentions;
    };
    for (const Case& bad : {Case{R"({"shape": "torus", "interpolation": "exact", "material": "m"})", "exact"},
                            Case{R"({"shape": "cube", "size": -1, "material": "m"})", "size"},
                            Case{R"({"shape": "torus", "rings": 2, "material": "m"})", "rings"},
                            Case{R"({"shape": "sphere", "interpolation": "smooth", "material": "m"})", "interpolation"},
                            Case{R"({"shape": "mesh", "material": "m"})", "path"},
                            Case{R"({"shape": "mesh", "path": "nowhere.obj", "material": "m"})", "no such file"},
                            Case{R"({"shape": "mesh", "path": "x.obj", "scale": 0, "material": "m"})", "scale"},
                            Case{R"({"shape": "cube", "radius": 1, "material": "m"})", "radius"},
                            Case{R"({"shape": "plane", "edge_fade": 1.5, "material": "m"})", "edge_fade"},
                            Case{R"({"shape": "cube", "rotation": [0, 45], "material": "m"})", "'rotation'"},
                            Case{R"({"shape": "torus", "rotation": [0, 1e9, 0], "material": "m"})", "'rotation"},
                            Case{R"({"shape": "mesh", "path": "x.obj", "up": "x", "material": "m"})", "'up'"}}) {
        SCOPED_TRACE(bad.object);
        auto scene = parseScene(sceneWithObjects(bad.object), "bad.json");
        ASSERT_FALSE(scene.ok());
        EXPECT_EQ(scene.error().where.file, "bad.json");
        EXPECT_GT(scene.error().where.line, 0);
        EXPECT_NE(scene.error().format().find(bad.mentions), std::string::npos) << scene.error().format();
    }
}

TEST(SceneShapes, MeshPathIsRelativeToTheSceneAndFollowsASaveElsewhere) {
    const std::string folder = test::outputDirectory("scene_shapes");
    std::filesystem::create_directories(folder + "/assets");
    std::filesystem::create_directories(folder + "/elsewhere/deeper");
    test::writeObj(folder + "/assets/grid.obj", test::makeGrid(3));
    test::writeText(folder + "/scene.json",
                    sceneWithObjects(R"({"shape": "mesh", "path": "assets/grid.obj", "center": [0, 1, 0], "scale": 2,
                                         "smoothing_angle_degrees": 30, "interpolation": "flat", "material": "m"})"));
    auto scene = loadScene(folder + "/scene.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    const auto& mesh = std::get<MeshShape>(scene->objects[0].shape);
    ASSERT_TRUE(mesh.mesh);
    EXPECT_EQ(mesh.statistics.triangleCount, 18u);
    EXPECT_EQ(mesh.path, "assets/grid.obj");
    EXPECT_EQ(mesh.scale, 2.0f);
    EXPECT_EQ(mesh.smoothingAngleDegrees, 30.0f);
    EXPECT_EQ(boundingSphere(mesh).radius, 2.0f);
    ASSERT_TRUE(saveScene(*scene, folder + "/elsewhere/deeper/copy.json").ok());
    // The mesh is now outside the scene's folder: refused unless allowed (util/reference_confinement.h).
    auto refused = loadScene(folder + "/elsewhere/deeper/copy.json");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("refused '../../assets/grid.obj'"), std::string::npos) << refused.error().format();
    const OutsideReferencesAllowance allowed;
    auto copy = loadScene(folder + "/elsewhere/deeper/copy.json");
    ASSERT_TRUE(copy.ok()) << copy.error().format();
    EXPECT_EQ(std::get<MeshShape>(copy->objects[0].shape).path, "../../assets/grid.obj");
    EXPECT_EQ(copy->objects[0].interpolation, SurfaceInterpolation::Flat);
    EXPECT_EQ(std::get<MeshShape>(copy->objects[0].shape).statistics.triangleCount, 18u);
}

// "rotation" turns a cube, a torus or a mesh about its centre (x, then y, then z, in degrees), the
// same triangles for the GPU and the CPU reference (proceduralMesh); "up": "z" stands a mesh up.
TEST(SceneShapes, RotationTurnsTheTrianglesAboutTheCentreAndRoundTrips) {
    const std::string folder = test::outputDirectory("scene_shapes");
    test::writeText(folder + "/tall_z.obj", "v -0.1 0 0\nv 0.1 0 0\nv 0 0 4\nf 1 2 3\n");
    test::writeText(folder + "/rotated.json", sceneWithObjects(R"(
        {"shape": "cube", "center": [1, 0, 0], "size": 2, "rotation": [0, 45, 0], "material": "m"},
        {"shape": "torus", "major_radius": 1, "minor_radius": 0.25, "rotation": [90, 0, 0], "material": "m"},
        {"shape": "mesh", "path": "tall_z.obj", "up": "z", "rotation": [0, 0, 90], "material": "m"})"));
    auto scene = loadScene(folder + "/rotated.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    float farthestX = 0, farthestZ = 0, meshX = 0;
    for (const Vertex& vertex : proceduralMesh(scene->objects[0].shape).vertices)
        farthestX = std::max(farthestX, vertex.position.x - 1.0f);  // a corner turned onto the x axis: √2
    EXPECT_NEAR(farthestX, std::sqrt(2.0f), 1e-5f);
    for (const Vertex& vertex : proceduralMesh(scene->objects[1].shape).vertices)
        farthestZ = std::max(farthestZ, std::abs(vertex.position.z));  // the ring now stands in the xy plane
    EXPECT_NEAR(farthestZ, 0.25f, 1e-5f);
    for (const Vertex& vertex : proceduralMesh(scene->objects[2].shape).vertices)
        meshX = std::max(meshX, std::abs(vertex.position.x));  // stood up along y, then laid along x
    EXPECT_GT(meshX, 0.99f);
    auto again = parseScene(sceneToJson(*scene, folder + "/rotated.json").dump(), folder + "/rotated.json");
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(sceneToJson(*again), sceneToJson(*scene));
    EXPECT_EQ(std::get<TorusShape>(again->objects[1].shape).rotationDegrees, glm::vec3(90, 0, 0));
    EXPECT_EQ(std::get<MeshShape>(again->objects[2].shape).upAxis, MeshUpAxis::Z);
}

TEST(SceneShapes, BrokenMeshFailsTheSceneAtItsPathWithTheMeshFileNamed) {
    const std::string folder = test::outputDirectory("scene_shapes");
    test::writeText(folder + "/broken.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    test::writeText(folder + "/broken_scene.json",
                    sceneWithObjects(R"({"shape": "mesh", "path": "broken.obj", "material": "m"})"));
    auto scene = loadScene(folder + "/broken_scene.json");
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.error().format().find("broken_scene.json:"), std::string::npos);
    EXPECT_NE(scene.error().message.find("broken.obj"), std::string::npos) << scene.error().format();
}

TEST(SceneShapes, ProceduralMeshesAreClosedAndFaceOutwards) {
    for (const Mesh& mesh : {makeCube({0, 0, 0}, 2.0f), makeTorus({0, 0, 0}, 1.0f, 0.25f, 16, 8)}) {
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            const Vertex& a = mesh.vertices[mesh.indices[3 * t]];
            const Vertex& b = mesh.vertices[mesh.indices[3 * t + 1]];
            const Vertex& c = mesh.vertices[mesh.indices[3 * t + 2]];
            const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
            EXPECT_GT(glm::dot(face, a.normal + b.normal + c.normal), 0.0f);  // counter-clockwise seen from outside
            EXPECT_NEAR(glm::dot(a.tangent, a.normal), 0.0f, 1e-5f);
        }
    }
    EXPECT_EQ(makeCube({0, 0, 0}, 1.0f).triangleCount(), 12u);
    EXPECT_EQ(makeTorus({0, 0, 0}, 1.0f, 0.25f, 16, 8).triangleCount(), 2u * 16 * 8);
    const Mesh torus = makeTorus({0, 0, 0}, 1.0f, 0.25f, 16, 8);
    for (const Vertex& vertex : torus.vertices) {
        const glm::vec3 ring = glm::normalize(glm::vec3(vertex.position.x, 0.0f, vertex.position.z));
        EXPECT_NEAR(glm::distance(vertex.position, ring), 0.25f, 1e-5f);
    }
}

TEST(SceneShapes, BvhFindsTheSameNearestHitAsBruteForce) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
    std::vector<TriangleBvh::Triangle> triangles;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 centre{coordinate(random), coordinate(random), coordinate(random)};
        triangles.push_back({centre, centre + 0.1f * glm::vec3(coordinate(random), coordinate(random), coordinate(random)),
                             centre + 0.1f * glm::vec3(coordinate(random), coordinate(random), coordinate(random))});
    }
    const TriangleBvh bvh(triangles);
    EXPECT_GT(bvh.nodeCount(), 100u);
    EXPECT_LE(bvh.depth(), 60);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        Ray ray{{coordinate(random) * 3, coordinate(random) * 3, 3.0f}, {}};
        ray.direction = glm::normalize(glm::vec3(coordinate(random) * 0.3f, coordinate(random) * 0.3f, -1.0f));
        float nearest = std::numeric_limits<float>::infinity();
        for (const auto& triangle : triangles) {
            const TriangleBvh single({triangle});
            if (auto hit = single.intersect(ray, nearest)) nearest = hit->distance;
        }
        const auto hit = bvh.intersect(ray, std::numeric_limits<float>::infinity());
        ASSERT_EQ(hit.has_value(), std::isfinite(nearest)) << i;
        if (!hit) continue;
        ++hits;
        EXPECT_FLOAT_EQ(hit->distance, nearest);
        const auto& triangle = triangles[hit->triangle];
        const glm::vec3 point = (1 - hit->barycentric1 - hit->barycentric2) * triangle[0] + hit->barycentric1 * triangle[1] +
                                hit->barycentric2 * triangle[2];
        EXPECT_LT(glm::distance(point, ray.origin + hit->distance * ray.direction), 1e-4f);
    }
    EXPECT_GT(hits, 100);
}

}  // namespace
}  // namespace glint
