// The editor's object actions and IOR presets without a window: adding, duplicating and removing
// objects are one undo step each and select the new object; overlay toggles are undoable; loading
// a mesh adds an object, and a corrupt or cancelled load leaves the scene exactly as it was; an IOR
// preset sets n (and κ for metals) per channel, and a metal is refused by a model without κ.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "brdf/presets.h"
#include "editor/ior_presets.h"
#include "editor/mesh_loading.h"
#include "editor/object_actions.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

TEST(EditorObjects, CubeAndTorusGetTheirShapesAndTheTorusIsInterpolated) {
    EditorState state;
    addObject(state, ObjectKind::Cube);
    addObject(state, ObjectKind::Torus);
    const Scene& scene = state.session.scene();
    ASSERT_TRUE(std::holds_alternative<CubeShape>(scene.objects[scene.objects.size() - 2].shape));
    ASSERT_TRUE(std::holds_alternative<TorusShape>(scene.objects.back().shape));
    EXPECT_EQ(scene.objects.back().interpolation, SurfaceInterpolation::Phong);  // a torus has no exact mode
    EXPECT_EQ(std::string(shapeLabel(scene.objects.back().shape)), "Torus");
}

TEST(EditorObjects, AddingAnObjectIsOneUndoStepWithItsOwnMaterial) {
    EditorState state;
    const Scene before = state.session.scene();
    addObject(state, ObjectKind::Sphere);
    state.session.settle(false);
    const Scene& scene = state.session.scene();
    ASSERT_EQ(scene.objects.size(), before.objects.size() + 1);
    EXPECT_EQ(scene.objects.back().name, "sphere 2");  // the default scene already has a "sphere"
    EXPECT_EQ(state.selectedObject, static_cast<int>(scene.objects.size()) - 1);
    EXPECT_EQ(scene.objects.back().materialIndex, static_cast<int>(scene.materials.size()) - 1);
    EXPECT_EQ(state.session.undoLabel(), "Add sphere");
    ASSERT_TRUE(state.session.undo());
    EXPECT_EQ(state.session.scene().objects.size(), before.objects.size());
    EXPECT_EQ(state.session.scene().materials.size(), before.materials.size());
}

TEST(EditorObjects, DuplicateCopiesShapeAndMaterialBesideTheOriginal) {
    EditorState state;
    duplicateObject(state, 0);
    state.session.settle(false);
    const Scene& scene = state.session.scene();
    const SceneObject& copy = scene.objects.back();
    EXPECT_EQ(copy.name, "sphere 2");
    EXPECT_NE(copy.materialIndex, scene.objects[0].materialIndex);
    EXPECT_EQ(scene.materials[copy.materialIndex].values, scene.materials[scene.objects[0].materialIndex].values);
    EXPECT_FLOAT_EQ(std::get<SphereShape>(copy.shape).radius, std::get<SphereShape>(scene.objects[0].shape).radius);
    EXPECT_FALSE(duplicateObject(state, 99));
}

TEST(EditorObjects, RemoveKeepsTheSelectionInRangeAndUndoBringsTheObjectBack) {
    EditorState state;
    const size_t count = state.session.scene().objects.size();
    state.selectedObject = static_cast<int>(count) - 1;
    ASSERT_TRUE(removeObject(state, state.selectedObject));
    state.session.settle(false);
    EXPECT_EQ(state.session.scene().objects.size(), count - 1);
    EXPECT_EQ(state.selectedObject, static_cast<int>(count) - 2);
    EXPECT_FALSE(removeObject(state, -1));
    ASSERT_TRUE(state.session.undo());
    EXPECT_EQ(state.session.scene().objects.size(), count);
}

TEST(EditorObjects, OverlayTogglesAreUndoable) {
    EditorState state;
    toggleWireframe(state);
    state.session.settle(false);
    toggleNormals(state);
    state.session.settle(false);
    EXPECT_TRUE(state.session.scene().display.overlays.wireframe);
    EXPECT_TRUE(state.session.scene().display.overlays.normals);
    state.session.undo();
    EXPECT_FALSE(state.session.scene().display.overlays.normals);
    state.session.undo();
    EXPECT_FALSE(state.session.scene().display.overlays.wireframe);
}

// Runs the frame loop's polling until the load finishes (at most 60 s).
void waitForMeshLoad(EditorState& state) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (pollMeshLoad(state) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_FALSE(state.meshLoad) << "the mesh load did not finish";
}

// Loads a mesh file the way the editor does and closes the undo step, as the frame loop would.
void loadMeshAndSettle(EditorState& state, const std::string& path) {
    startMeshLoad(state, path);
    waitForMeshLoad(state);
    state.session.settle(false);
}

std::string writeFile(const std::string& name, const std::string& text) {
    const std::string path = test::outputDirectory("editor_objects") + "/" + name;
    std::ofstream(path) << text;
    return path;
}

TEST(EditorMeshLoad, AMeshFileBecomesAnObjectInOneUndoStep) {
    const std::string path = writeFile("tetrahedron.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    EditorState state;
    const size_t objects = state.session.scene().objects.size();
    loadMeshAndSettle(state, path);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Scene& scene = state.session.scene();
    ASSERT_EQ(scene.objects.size(), objects + 1);
    const auto* mesh = std::get_if<MeshShape>(&scene.objects.back().shape);
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(scene.objects.back().name, "tetrahedron");
    EXPECT_EQ(mesh->statistics.triangleCount, 4u);
    EXPECT_EQ(mesh->mesh->triangleCount(), 4u);
    EXPECT_EQ(state.selectedObject, static_cast<int>(objects));
    ASSERT_TRUE(state.session.undo());
    EXPECT_EQ(state.session.scene().objects.size(), objects);
}

TEST(EditorMeshLoad, AnObjGetsTheMaterialItsMtlLibraryNames) {
    writeFile("paints.mtl", "newmtl paint\nKd 0.8 0.1 0.1\nillum 1\n\nnewmtl other\nKd 0 0 1\nillum 1\n");
    const std::string path = writeFile("painted.obj",
                                       "mtllib paints.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl paint\n"
                                       "f 1 3 2\nf 1 2 4\nf 1 4 3\nusemtl other\nf 2 3 4\n");
    EditorState state;
    loadMeshAndSettle(state, path);
    const Scene& scene = state.session.scene();
    const Material& material = scene.materials.at(scene.objects.back().materialIndex);
    EXPECT_EQ(material.name, "paint");
    EXPECT_NEAR(material.values[0], 0.8f, 1e-6f);
    EXPECT_NEAR(material.values[1], 0.1f, 1e-6f);
    EXPECT_NEAR(material.values[2], 0.1f, 1e-6f);
    // One material per Glint mesh: the second is named in the status line, at the first usemtl.
    EXPECT_NE(state.statusMessage.find("painted.obj:6: the file uses 2 materials"), std::string::npos)
        << state.statusMessage;
}

TEST(EditorMeshLoad, AnObjWhoseMtlLibraryIsMissingLoadsWithTheDefaultMaterialAndSaysWhy) {
    const std::string path = writeFile("unpainted.obj", "mtllib missing.mtl\nusemtl paint\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EditorState state;
    const size_t objects = state.session.scene().objects.size();
    loadMeshAndSettle(state, path);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Scene& scene = state.session.scene();
    ASSERT_EQ(scene.objects.size(), objects + 1);
    const Material& material = scene.materials.at(scene.objects.back().materialIndex);
    EXPECT_EQ(material.model, BrdfModel::Lambert);
    EXPECT_EQ(material.name, "unpainted material");
    EXPECT_NE(state.statusMessage.find("unpainted.obj:1: material library 'missing.mtl' not used"), std::string::npos)
        << state.statusMessage;
    EXPECT_NE(state.statusMessage.find("unpainted.obj:2: 'usemtl paint': no such material"), std::string::npos)
        << state.statusMessage;
}

TEST(EditorMeshLoad, ACorruptMeshShowsFileAndLineAndLeavesTheSceneAsItWas) {
    const std::string path = writeFile("corrupt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    EditorState state;
    addObject(state, ObjectKind::Cube);  // some work with an undo history
    state.session.settle(false);
    const std::string before = sceneToJson(state.session.scene()).dump();
    const std::string undoLabel = state.session.undoLabel();
    startMeshLoad(state, path);
    waitForMeshLoad(state);
    state.session.settle(false);
    EXPECT_NE(state.errorMessage.find("corrupt.obj"), std::string::npos) << state.errorMessage;
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
    EXPECT_EQ(state.session.undoLabel(), undoLabel);
}

TEST(EditorMeshLoad, CancelLeavesTheSceneAsItWas) {
    // A grid big enough (about 20 MB of text) that the import is still parsing when the cancel arrives.
    std::string text;
    constexpr int kSide = 400;
    for (int y = 0; y <= kSide; ++y)
        for (int x = 0; x <= kSide; ++x) text += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const int corner = y * (kSide + 1) + x + 1;
            text += "f " + std::to_string(corner) + " " + std::to_string(corner + 1) + " " +
                    std::to_string(corner + kSide + 2) + "\nf " + std::to_string(corner) + " " +
                    std::to_string(corner + kSide + 2) + " " + std::to_string(corner + kSide + 1) + "\n";
        }
    const std::string path = writeFile("big_grid.obj", text);
    EditorState state;
    const std::string before = sceneToJson(state.session.scene()).dump();
    startMeshLoad(state, path);
    state.meshLoad->cancel();
    waitForMeshLoad(state);
    state.session.settle(false);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    EXPECT_NE(state.statusMessage.find("Cancelled"), std::string::npos) << state.statusMessage;
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
    EXPECT_FALSE(state.session.canUndo());
}

TEST(EditorMeshLoad, ASecondLoadWaitsForTheFirst) {
    const std::string path = writeFile("triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EditorState state;
    startMeshLoad(state, path);
    const MeshLoadJob* first = state.meshLoad.get();
    startMeshLoad(state, path);
    EXPECT_EQ(state.meshLoad.get(), first);
    EXPECT_NE(state.statusMessage.find("Still loading"), std::string::npos);
    waitForMeshLoad(state);
}

glm::vec3 param(const Material& material, const char* name) {
    const auto table = modelInfo(material.model).params;
    const int offset = packedOffset(table, findParam(table, name));
    return {material.values[offset], material.values[offset + 1], material.values[offset + 2]};
}

TEST(IorPresets, MetalsSetNAndKappaPerChannelDielectricsClearKappa) {
    Material material = Material::withDefaults("m", BrdfModel::CookTorrance);
    ASSERT_TRUE(applyIorPreset(material, "gold"));
    const Material gold = findPreset("gold")->material();
    EXPECT_EQ(param(material, "ior"), param(gold, "ior"));
    EXPECT_EQ(param(material, "extinction"), param(gold, "extinction"));
    ASSERT_TRUE(applyIorPreset(material, "diamond"));
    EXPECT_EQ(param(material, "ior"), glm::vec3(2.42f));
    EXPECT_EQ(param(material, "extinction"), glm::vec3(0.0f));
    // The roughness and the rest are the user's, not the preset's.
    EXPECT_EQ(material.values.size(), Material::withDefaults("m", BrdfModel::CookTorrance).values.size());
}

TEST(IorPresets, GlassModelTakesDielectricsButNoMetal) {
    Material glass = Material::withDefaults("g", BrdfModel::Glass);
    ASSERT_TRUE(applyIorPreset(glass, "water"));
    const auto table = modelInfo(BrdfModel::Glass).params;
    EXPECT_FLOAT_EQ(glass.values[packedOffset(table, findParam(table, "ior"))], 1.333f);
    const Material unchanged = glass;
    EXPECT_FALSE(applyIorPreset(glass, "copper"));
    EXPECT_EQ(glass.values, unchanged.values);
    EXPECT_FALSE(applyIorPreset(glass, "unobtainium"));
    Material lambert = Material::withDefaults("l", BrdfModel::Lambert);
    EXPECT_FALSE(applyIorPreset(lambert, "glass"));
}

}  // namespace
}  // namespace glint
