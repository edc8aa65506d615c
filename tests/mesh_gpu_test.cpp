// Triangle meshes on the GPU against the CPU reference's BVH, pixel by pixel: flat, Gouraud and
// Phong interpolation on a cube, a torus and a tessellated sphere, an imported mesh with its
// placement; the tessellation shows in the picture; trianglesDrawn counts what was drawn.
#include <gtest/gtest.h>

#include "geometry/mesh_import.h"
#include "gpu_test_support.h"
#include "mesh_test_files.h"
#include "test_support.h"

namespace glint {
namespace {

constexpr int kMeshImageSize = 96;

Scene meshStage(Shape shape, SurfaceInterpolation interpolation) {
    Scene scene;
    scene.camera.position = {1.6f, 1.9f, 3.4f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.background.color = {0.02f, 0.02f, 0.03f};
    Material plastic = Material::withDefaults("plastic", BrdfModel::BlinnPhong);
    scene.materials = {plastic};
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {1.5f, 2.0f, 2.0f};
    bulb.power = 120.0f;
    Light sky;
    sky.type = LightType::Directional;
    sky.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
    sky.irradiance = 0.8f;
    scene.lights = {bulb, sky};
    scene.objects.push_back({"shape", std::move(shape), 0, interpolation});
    return scene;
}

// Pixels whose 3×3 neighbourhood meets another triangle (where the flat normal or a cube's face
// changes, rasterizer and ray may pick either side of an edge).
std::vector<bool> triangleEdges(const Scene& scene, int width, int height) {
    const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(static_cast<float>(width) / height));
    std::vector<int> triangleAt(static_cast<size_t>(width) * height, -1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (auto hit = intersectScene(scene, primaryRay(inverse, x + 0.5f, y + 0.5f, width, height)); hit && hit->triangle)
                triangleAt[y * width + x] = hit->triangle->index;
    std::vector<bool> edge(triangleAt.size(), false);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
                    if (triangleAt[ny * width + nx] != triangleAt[y * width + x]) edge[y * width + x] = true;
                }
    return edge;
}

void expectAgreement(const Scene& scene, bool excludeTriangleEdges, long minimumCompared) {
    auto images = test::sharedHeadless().render(scene, kMeshImageSize, kMeshImageSize);
    ASSERT_TRUE(images.ok()) << images.error().format();
    const auto agreement = test::compareWithReference(scene, images->radiance, 1e-3f, 1e-5f,
                                                      excludeTriangleEdges ? triangleEdges(scene, kMeshImageSize, kMeshImageSize) : std::vector<bool>{});
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative " << agreement.worstRelative << ")";
    EXPECT_GT(agreement.compared, minimumCompared);
}

const SurfaceInterpolation kModes[] = {SurfaceInterpolation::Flat, SurfaceInterpolation::Gouraud, SurfaceInterpolation::Phong};
const char* kModeNames[] = {"exact", "flat", "gouraud", "phong"};

TEST(MeshGpu, CubeMatchesTheCpuReferenceInEveryMode) {
    for (SurfaceInterpolation mode : kModes) {
        SCOPED_TRACE(kModeNames[static_cast<int>(mode)]);
        expectAgreement(meshStage(CubeShape{{0, 0, 0}, 1.4f}, mode), true, 2500);
    }
}

TEST(MeshGpu, TorusMatchesTheCpuReferenceInEveryMode) {
    for (SurfaceInterpolation mode : kModes) {
        SCOPED_TRACE(kModeNames[static_cast<int>(mode)]);
        expectAgreement(meshStage(TorusShape{{0, 0, 0}, 0.9f, 0.35f, 24, 12}, mode), mode == SurfaceInterpolation::Flat, 1500);
    }
}

// "rotation" turns the triangles both renderers draw (geometry/shape_mesh.h).
TEST(MeshGpu, RotatedCubeAndTorusMatchTheCpuReference) {
    expectAgreement(meshStage(CubeShape{{0, 0, 0}, 1.4f, {20, 35, 10}}, SurfaceInterpolation::Flat), true, 2500);
    expectAgreement(meshStage(TorusShape{{0, 0, 0}, 0.9f, 0.35f, 24, 12, {70, 0, 15}}, SurfaceInterpolation::Flat), true, 1500);
}

TEST(MeshGpu, TessellatedSphereMatchesTheCpuReferenceInEveryMode) {
    for (SurfaceInterpolation mode : kModes) {
        SCOPED_TRACE(kModeNames[static_cast<int>(mode)]);
        expectAgreement(meshStage(SphereShape{{0, 0, 0}, 1.0f, 12, 6}, mode), mode == SurfaceInterpolation::Flat, 2000);
    }
}

// Gouraud shades in the vertex shader: every model's program must compile there (mirror and
// glass trace their delta lobes per vertex too) and agree with the reference.
TEST(MeshGpu, EveryModelMatchesTheCpuReferenceInGouraud) {
    for (const ModelInfo& info : allModels()) {
        SCOPED_TRACE(info.id);
        Scene scene = meshStage(SphereShape{{0, 0, 0}, 1.0f, 16, 8}, SurfaceInterpolation::Gouraud);
        scene.materials[0] = Material::withDefaults("material", info.model);
        expectAgreement(scene, false, 2000);
    }
}

TEST(MeshGpu, ImportedMeshWithItsPlacementMatchesTheCpuReference) {
    const std::string path = test::outputDirectory("mesh_gpu") + "/octahedron.obj";
    test::writeText(path, "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                          "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
    auto imported = importMesh(path, MeshImportOptions{120.0f});  // smooth across the octahedron's edges
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    MeshShape mesh;
    mesh.path = path;
    mesh.mesh = imported->mesh;
    mesh.statistics = imported->statistics;
    mesh.center = {0.2f, -0.1f, 0.0f};
    mesh.scale = 1.3f;
    for (SurfaceInterpolation mode : kModes) {
        SCOPED_TRACE(kModeNames[static_cast<int>(mode)]);
        expectAgreement(meshStage(mesh, mode), mode == SurfaceInterpolation::Flat, 2000);
    }
}

TEST(MeshGpu, TessellationChangesThePictureExceptForTheExactSphere) {
    auto render = [](int segments, int rings, SurfaceInterpolation mode) {
        auto images = test::sharedHeadless().render(meshStage(SphereShape{{0, 0, 0}, 1.0f, segments, rings}, mode), kMeshImageSize, kMeshImageSize);
        EXPECT_TRUE(images.ok());
        return images->radiance;
    };
    auto difference = [](const RadianceImage& a, const RadianceImage& b) {
        double sum = 0.0;
        for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
        return sum / a.pixels.size();
    };
    EXPECT_GT(difference(render(8, 4, SurfaceInterpolation::Gouraud), render(64, 32, SurfaceInterpolation::Gouraud)), 1e-3);
    EXPECT_GT(difference(render(8, 4, SurfaceInterpolation::Flat), render(64, 32, SurfaceInterpolation::Flat)), 1e-3);
    EXPECT_EQ(difference(render(8, 4, SurfaceInterpolation::Exact), render(64, 32, SurfaceInterpolation::Exact)), 0.0);
}

TEST(MeshGpu, TrianglesDrawnCountsTheMeshes) {
    Scene scene = meshStage(TorusShape{{0, 0, 0}, 0.9f, 0.35f, 24, 12}, SurfaceInterpolation::Phong);
    scene.objects.push_back({"box", CubeShape{{0, 1, 0}, 0.3f}, 0, SurfaceInterpolation::Flat});
    auto images = test::sharedHeadless().render(scene, 32, 32);
    ASSERT_TRUE(images.ok()) << images.error().format();
    EXPECT_EQ(test::sharedHeadless().renderer().trianglesDrawn(), 2 * 24 * 12 + 12);
}

}  // namespace
}  // namespace glint
