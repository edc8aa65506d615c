// Assets (core/interchange/asset.h): a glTF's primitives and an OBJ's `usemtl` groups become
// one object each with their own materials, shared where the file shares them, placed by the
// node transforms in one frame; the stage rests the asset on its floor; a scene file keeps each
// part and reads it back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "interchange/asset.h"
#include "interchange/gltf.h"
#include "interchange/material_values.h"
#include "scene/scene_json.h"
#include "test_support.h"
#include "util/file_io.h"

namespace glint {
namespace {

const MeshShape& meshOf(const SceneObject& object) { return std::get<MeshShape>(object.shape); }

MeshBounds boundsOf(const SceneObject& object) { return meshBounds(*meshOf(object).mesh); }

// tests/files/assets/parts.gltf: a plinth (node 0, material Red) with a cube above it (its child,
// turned 45°: sides Red, top and bottom Gold) and a marker (a root node) without a material.
TEST(Asset, GltfPrimitivesAreObjectsWithTheirOwnMaterials) {
    auto asset = loadAsset(test::dataPath("files/assets/parts.gltf"));
    ASSERT_TRUE(asset.ok()) << asset.error().format();
    ASSERT_EQ(asset->objects.size(), 4u);
    std::vector<std::string> names;
    for (const SceneObject& object : asset->objects) names.push_back(object.name);
    EXPECT_EQ(names, (std::vector<std::string>{"Plinth", "Cube-0", "Cube-1", "Marker"}));  // depth first, assimp's primitive names
    ASSERT_EQ(asset->materials.size(), 3u);  // Red shared by the plinth and the cube's sides
    const auto materialOf = [&](size_t object) { return asset->materials.at(asset->objects[object].materialIndex); };
    EXPECT_EQ(materialOf(0).name, "Red");
    EXPECT_EQ(asset->objects[1].materialIndex, asset->objects[0].materialIndex);
    EXPECT_EQ(materialOf(2).name, "Gold");
    EXPECT_EQ(materialOf(2).analytic()->model, BrdfModel::OpenPbr);
    EXPECT_EQ(materialOf(3).name, "default");
    for (size_t i = 0; i < asset->objects.size(); ++i) {
        EXPECT_EQ(meshOf(asset->objects[i]).part, static_cast<int>(i));
        EXPECT_EQ(asset->objects[i].interpolation, SurfaceInterpolation::Phong);
    }
    // One frame for all: the plinth's 2 m (file units) span the unit sphere as the whole asset
    // does, the cube (1 m, turned 45° about y) stands on it and the marker at its corner.
    const MeshBounds plinth = boundsOf(asset->objects[0]), cube = boundsOf(asset->objects[1]), marker = boundsOf(asset->objects[3]);
    const float metre = (plinth.high.x - plinth.low.x) / 2.0f;
    EXPECT_NEAR(cube.low.y, plinth.high.y, 1e-5f);
    EXPECT_NEAR(cube.high.x - cube.low.x, std::sqrt(2.0f) * metre, 1e-4f);
    EXPECT_NEAR(marker.low.y, plinth.high.y, 1e-5f);
    EXPECT_NEAR(marker.high.x, plinth.high.x - 0.1f * metre, 1e-4f);
    EXPECT_EQ(asset->statistics.triangleCount, 36u);
}

// A Blender 4.x OBJ: its `usemtl` groups keep their materials; `Ns 0` (Blender's roughness 1) is
// read as no highlight.
TEST(Asset, ObjUsemtlGroupsKeepTheirMaterials) {
    auto asset = loadAsset(test::dataPath("files/assets/blender_two_materials.obj"));
    ASSERT_TRUE(asset.ok()) << asset.error().format();
    ASSERT_EQ(asset->objects.size(), 2u);
    ASSERT_EQ(asset->materials.size(), 2u);
    EXPECT_EQ(asset->objects[0].name, "Pedestal");  // assimp names a group after its material
    EXPECT_EQ(asset->objects[1].name, "Base");
    const Material& body = asset->materials.at(asset->objects[0].materialIndex);
    const Material& base = asset->materials.at(asset->objects[1].materialIndex);
    EXPECT_EQ(body.name, "Body");
    EXPECT_EQ(body.analytic()->model, BrdfModel::BlinnPhong);
    EXPECT_EQ(base.name, "Base");
    EXPECT_EQ(base.analytic()->model, BrdfModel::Lambert);
    EXPECT_EQ(paramValue(base, "albedo"), glm::vec3(0.2f, 0.3f, 0.6f));
    EXPECT_NEAR(boundsOf(asset->objects[0]).low.y, boundsOf(asset->objects[1]).high.y, 1e-5f);
    const bool warnedNs = std::any_of(asset->warnings.begin(), asset->warnings.end(),
                                      [](const Diagnostic& warning) { return warning.message.find("'Ns 0'") != std::string::npos; });
    EXPECT_TRUE(warnedNs);
}

// A mesh placed by two nodes is two parts, told apart by name.
TEST(Asset, InstancedMeshIsOnePartPerNode) {
    auto text = readTextFile(test::dataPath("files/assets/parts.gltf"));
    ASSERT_TRUE(text.ok());
    nlohmann::json gltf = nlohmann::json::parse(*text);
    gltf["nodes"].push_back({{"name", "Marker again"}, {"mesh", 2}, {"translation", {-0.8, 0.225, -0.8}}});
    gltf["scenes"][0]["nodes"] = {1, 3};
    const std::string path = test::outputDirectory("asset") + "/instanced.gltf";
    std::ofstream(path) << gltf.dump();
    auto asset = loadAsset(path);
    ASSERT_TRUE(asset.ok()) << asset.error().format();
    ASSERT_EQ(asset->objects.size(), 2u);
    EXPECT_EQ(asset->objects[0].name, "Marker");
    EXPECT_EQ(asset->objects[1].name, "Marker 2");
    EXPECT_NE(meshOf(asset->objects[0]).mesh, meshOf(asset->objects[1]).mesh);  // each placed by its node
    EXPECT_NEAR(boundsOf(asset->objects[0]).low.x, -boundsOf(asset->objects[1]).high.x, 1e-5f);
}

// A glTF's lights come with the asset: moved and scaled as its meshes are, their power by the
// square of the scale (the irradiance Φ/4πd² they give the asset stays), lifted with it onto the floor.
TEST(Asset, LightsMoveAndScaleWithTheAsset) {
    auto text = readTextFile(test::dataPath("files/assets/parts.gltf"));
    ASSERT_TRUE(text.ok());
    nlohmann::json gltf = nlohmann::json::parse(*text);
    gltf["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 10.0}}};
    gltf["nodes"].push_back({{"name", "Lamp"}, {"translation", {1.0, 3.0, 0.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    gltf["scenes"][0]["nodes"] = {0, 1, 3};
    const std::string path = test::outputDirectory("asset") + "/lamp.gltf";
    std::ofstream(path) << gltf.dump();
    auto file = loadGltf(path);
    auto parts = importMeshParts(path);
    auto asset = loadAsset(path);
    ASSERT_TRUE(file.ok() && parts.ok() && asset.ok()) << (asset ? "" : asset.error().format());
    ASSERT_EQ(asset->lights.size(), 1u);
    const Light& inFile = file->lights.at(0);
    const Light& light = asset->lights[0];
    const glm::vec3 expected = (glm::vec3(1, 3, 0) - parts->fileCentre) / parts->fileRadius;
    EXPECT_NEAR(glm::distance(light.position, expected), 0.0f, 1e-5f);
    EXPECT_NEAR(light.power, inFile.power / (parts->fileRadius * parts->fileRadius), 1e-4f * inFile.power);
    const Scene scene = assetStage(*asset, 64, 64);
    ASSERT_EQ(scene.lights.size(), 2u);  // the stage's key light and the lamp
    EXPECT_NEAR(scene.lights[1].position.y - light.position.y, meshOf(scene.objects[0]).center.y, 1e-6f);
}

// Two files' materials of one name in a scene stay distinct: names are made unique.
TEST(Asset, MaterialNamesAreUniqueInTheScene) {
    const std::string path = test::outputDirectory("asset") + "/twins.obj";
    std::ofstream(test::outputDirectory("asset") + "/twins.mtl") << "newmtl stage floor\nKd 0.1 0.1 0.1\n";
    std::ofstream(path) << "mtllib twins.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl stage floor\nf 1 2 3\nusemtl other\nf 1 2 4\n";
    auto asset = loadAsset(path);
    ASSERT_TRUE(asset.ok()) << asset.error().format();
    const Scene scene = assetStage(*asset, 64, 64);
    std::vector<std::string> names;
    for (const Material& material : scene.materials) names.push_back(material.name);
    EXPECT_EQ(names, (std::vector<std::string>{"stage floor 2", "default", "stage floor"}));
}

// On the stage the asset rests on the floor, the camera looks at it, and a saved scene reads
// every part back in place.
// The asset copied into the test's output folder, where its scene files are written (a scene
// reads only files in its own folder and below).
std::string assetBesideScenes() {
    const std::string copy = test::outputDirectory("asset") + "/parts.gltf";
    std::filesystem::copy_file(test::dataPath("files/assets/parts.gltf"), copy, std::filesystem::copy_options::overwrite_existing);
    return copy;
}

TEST(Asset, StageRestsTheAssetOnTheFloorAndItsSceneFileReadsBack) {
    auto asset = loadAsset(assetBesideScenes());
    ASSERT_TRUE(asset.ok()) << asset.error().format();
    const Scene scene = assetStage(*asset, 128, 96);
    ASSERT_EQ(scene.objects.size(), asset->objects.size() + 1);
    const SceneObject& floor = scene.objects.back();
    const float floorHeight = std::get<PlaneShape>(floor.shape).center.y;
    EXPECT_EQ(scene.materials.at(floor.materialIndex).name, "stage floor");
    float lowest = 1e9f;
    for (size_t i = 0; i + 1 < scene.objects.size(); ++i)
        lowest = std::min(lowest, boundsOf(scene.objects[i]).low.y + meshOf(scene.objects[i]).center.y);
    EXPECT_NEAR(lowest, floorHeight, 1e-5f);
    EXPECT_EQ(scene.msaaSamples, 4);

    const std::string file = test::outputDirectory("asset") + "/parts_scene.json";
    ASSERT_TRUE(saveScene(scene, file).ok());
    auto read = loadScene(file);
    ASSERT_TRUE(read.ok()) << read.error().format();
    ASSERT_EQ(read->objects.size(), scene.objects.size());
    for (size_t i = 0; i + 1 < scene.objects.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(meshOf(read->objects[i]).part, static_cast<int>(i));
        EXPECT_EQ(meshOf(read->objects[i]).center, meshOf(scene.objects[i]).center);
        EXPECT_EQ(meshOf(read->objects[i]).mesh->vertices.size(), meshOf(scene.objects[i]).mesh->vertices.size());
        EXPECT_EQ(read->materials.at(read->objects[i].materialIndex).name, scene.materials.at(scene.objects[i].materialIndex).name);
    }
}

TEST(Asset, PartOutsideTheFileIsALocatedError) {
    const std::string file = test::outputDirectory("asset") + "/bad_part.json";
    std::ofstream(file) << (R"({"format": "glint-scene", "version": 1, "materials": [{"name": "m", "model": "lambert"}],
 "objects": [{"shape": "mesh", "path": ")" + assetBesideScenes() + R"(", "part": 4, "material": "m"}]})");
    auto read = loadScene(file);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().format().find("bad_part.json:2:"), std::string::npos) << read.error().format();
    EXPECT_NE(read.error().message.find("there is no part 4"), std::string::npos) << read.error().format();
}

// A glTF of materials only is no asset: it opens as an interchange file (its material on the sphere).
TEST(Asset, MaterialOnlyGltfIsNoAsset) {
    EXPECT_FALSE(isAssetFile(test::dataPath("files/gltf/khronos/SheenAndEmission.gltf")));
    EXPECT_TRUE(isAssetFile(test::dataPath("files/assets/parts.gltf")));
    EXPECT_TRUE(isAssetFile(test::dataPath("files/obj/cube.obj")));
    EXPECT_FALSE(isAssetFile(test::dataPath("files/ply/tristrips_ascii.ply")));
}

// A .glb is told by its JSON chunk alone; one that is no .glb opens as an interchange file, whose
// reader says what is wrong.
TEST(Asset, GlbWithMeshesIsAnAsset) {
    EXPECT_TRUE(isAssetFile(test::dataPath("files/gltf/khronos/BoxTextured.glb")));
    EXPECT_FALSE(isAssetFile(test::dataPath("fuzz/corpus/gltf/dielectric.glb")));
    EXPECT_FALSE(isAssetFile(test::dataPath("files/gltf/khronos/SheenAndEmission.gltf") + ".missing.glb"));
}

}  // namespace
}  // namespace glint
