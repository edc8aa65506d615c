// The editor's object actions and IOR presets without a window: adding, duplicating and removing
// objects are one undo step each and select the new object; the selection is kept in the scene
// after an undo removed it; overlay toggles are undoable; loading
// a mesh adds an object, and a corrupt or cancelled load leaves the scene exactly as it was; an IOR
// preset sets n (and κ for metals) per channel, and a metal is refused by a model without κ.
#include <gtest/gtest.h>

#include <fstream>

#include "brdf/presets.h"
#include "editor/ior_presets.h"
#include "editor/light_handles.h"
#include "editor/mesh_loading.h"
#include "editor/model_limits.h"
#include "editor/object_actions.h"
#include "scene/scene_json.h"
#include "editor_test_support.h"
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
    EXPECT_EQ(scene.materials[copy.materialIndex].analytic()->values, scene.materials[scene.objects[0].materialIndex].analytic()->values);
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

// The monkey soak (issue 41): an object added and selected, Ctrl+Z, then a dropped .mtl wrote its
// material through the stale selection into freed memory (AddressSanitizer, heap-use-after-free).
TEST(EditorObjects, UndoingTheSelectedObjectsAdditionLeavesASelectionInTheScene) {
    EditorState state;
    addObject(state, ObjectKind::Cube);
    state.session.settle(false);
    ASSERT_TRUE(state.session.undo());
    const int count = static_cast<int>(state.session.scene().objects.size());
    ASSERT_EQ(state.selectedObject, count);  // the cube's place, no longer in the scene
    keepSelectionInScene(state);
    EXPECT_EQ(state.selectedObject, count - 1);
    state.session.change("Remove all").objects.clear();
    keepSelectionInScene(state);
    EXPECT_EQ(state.selectedObject, 0);
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

std::string writeFile(const std::string& name, const std::string& text) {
    const std::string path = test::outputDirectory("editor_objects") + "/" + name;
    std::ofstream(path) << text;
    return path;
}

// Loads the mesh file `path` into `state`: no error, one object more (fatal if not).
void loadAsOneMoreObject(EditorState& state, const std::string& path) {
    const size_t objects = state.session.scene().objects.size();
    test::loadMeshAndSettle(state, path);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    ASSERT_EQ(state.session.scene().objects.size(), objects + 1);
}

TEST(EditorMeshLoad, AMeshFileBecomesAnObjectInOneUndoStep) {
    const std::string path = writeFile("tetrahedron.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    EditorState state;
    const size_t objects = state.session.scene().objects.size();
    ASSERT_NO_FATAL_FAILURE(loadAsOneMoreObject(state, path));
    const Scene& scene = state.session.scene();
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
    test::loadMeshAndSettle(state, path);
    const Scene& scene = state.session.scene();
    const Material& material = scene.materials.at(scene.objects.back().materialIndex);
    EXPECT_EQ(material.name, "paint");
    EXPECT_NEAR(material.analytic()->values[0], 0.8f, 1e-6f);
    EXPECT_NEAR(material.analytic()->values[1], 0.1f, 1e-6f);
    EXPECT_NEAR(material.analytic()->values[2], 0.1f, 1e-6f);
    // One material per Glint mesh: the second is named in the status line, at the first usemtl.
    EXPECT_NE(state.statusMessage.text().find("painted.obj:6: the file uses 2 materials"), std::string::npos)
        << state.statusMessage.text();
}

TEST(EditorMeshLoad, AnObjWhoseMtlLibraryIsMissingLoadsWithTheDefaultMaterialAndSaysWhy) {
    const std::string path = writeFile("unpainted.obj", "mtllib missing.mtl\nusemtl paint\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EditorState state;
    ASSERT_NO_FATAL_FAILURE(loadAsOneMoreObject(state, path));
    const Scene& scene = state.session.scene();
    const Material& material = scene.materials.at(scene.objects.back().materialIndex);
    EXPECT_EQ(material.analytic()->model, BrdfModel::Lambert);
    EXPECT_EQ(material.name, "unpainted material");
    EXPECT_NE(state.statusMessage.text().find("unpainted.obj:1: material library 'missing.mtl' not used"), std::string::npos)
        << state.statusMessage.text();
    EXPECT_NE(state.statusMessage.text().find("unpainted.obj:2: 'usemtl paint': no such material"), std::string::npos)
        << state.statusMessage.text();
}

TEST(EditorMeshLoad, ACorruptMeshShowsFileAndLineAndLeavesTheSceneAsItWas) {
    const std::string path = writeFile("corrupt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    EditorState state;
    addObject(state, ObjectKind::Cube);  // some work with an undo history
    state.session.settle(false);
    const std::string before = sceneToJson(state.session.scene()).dump();
    const std::string undoLabel = state.session.undoLabel();
    startMeshLoad(state, path);
    test::waitForMeshLoad(state);
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
    test::waitForMeshLoad(state);
    state.session.settle(false);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    EXPECT_NE(state.statusMessage.text().find("Cancelled"), std::string::npos) << state.statusMessage.text();
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
    EXPECT_NE(state.statusMessage.text().find("Still loading"), std::string::npos);
    test::waitForMeshLoad(state);
}

glm::vec3 param(const Material& material, const char* name) {
    const auto table = modelInfo(material.analytic()->model).params;
    const int offset = packedOffset(table, findParam(table, name));
    return {material.analytic()->values[offset], material.analytic()->values[offset + 1], material.analytic()->values[offset + 2]};
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
    EXPECT_EQ(material.analytic()->values.size(), Material::withDefaults("m", BrdfModel::CookTorrance).analytic()->values.size());
}

TEST(IorPresets, GlassModelTakesDielectricsButNoMetal) {
    Material glass = Material::withDefaults("g", BrdfModel::Glass);
    ASSERT_TRUE(applyIorPreset(glass, "water"));
    const auto table = modelInfo(BrdfModel::Glass).params;
    EXPECT_FLOAT_EQ(glass.analytic()->values[packedOffset(table, findParam(table, "ior"))], 1.333f);
    const Material unchanged = glass;
    EXPECT_FALSE(applyIorPreset(glass, "copper"));
    EXPECT_EQ(glass.analytic()->values, unchanged.analytic()->values);
    EXPECT_FALSE(applyIorPreset(glass, "unobtainium"));
    Material lambert = Material::withDefaults("l", BrdfModel::Lambert);
    EXPECT_FALSE(applyIorPreset(lambert, "glass"));
}

// A new light lands inside the view of the camera as it is (it used to appear at a fixed point,
// off-screen from the default camera), in front of it and not hidden by the default ball.
TEST(EditorLights, ANewLightIsPlacedWhereTheCameraSeesIt) {
    const Scene scene = defaultScene();
    std::vector<Camera> cameras(5, scene.camera);
    cameras[1].position = 2.0f * cameras[1].target - cameras[1].position;  // orbited to the far side
    cameras[2].position = cameras[2].target + 6.0f * (cameras[2].position - cameras[2].target);  // far away
    cameras[3].projection = Projection::Orthographic;
    cameras[4].position = cameras[4].target + glm::vec3(0.05f, 5.0f, 0.0f);  // looking straight down
    for (const Camera& camera : cameras) {
        const glm::vec3 light = newLightPosition(camera);
        for (const float aspect : {1.0f, 16.0f / 9.0f}) {
            const glm::vec4 clip = camera.viewProjection(aspect) * glm::vec4(light, 1.0f);
            ASSERT_GT(clip.w, 0.0f);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            EXPECT_LT(std::abs(ndc.x), 0.9f) << "camera at " << camera.position.x << ", " << camera.position.y << ", " << camera.position.z;
            EXPECT_LT(std::abs(ndc.y), 0.9f) << "camera at " << camera.position.x << ", " << camera.position.y << ", " << camera.position.z;
            EXPECT_GT(ndc.z, -1.0f);
            EXPECT_LT(ndc.z, 1.0f);
        }
    }
    EXPECT_FALSE(hiddenFromCamera(scene, newLightPosition(scene.camera))) << "the default ball hides the new light";
}

// A light handle behind the default ball is hidden from the camera (drawn faint, not over the
// ball); one in front of it, or beside it in the open, is not.
TEST(EditorLights, AHandleBehindTheBallIsHiddenFromTheCamera) {
    const Scene scene = defaultScene();
    const glm::vec3 centre = std::get<SphereShape>(scene.objects[0].shape).center;
    const glm::vec3 towardsCamera = glm::normalize(scene.camera.position - centre);
    EXPECT_TRUE(hiddenFromCamera(scene, centre - 2.0f * towardsCamera));
    EXPECT_FALSE(hiddenFromCamera(scene, centre + 2.0f * towardsCamera));
}

// The note on what a delta-lobe model leaves out shows only where it applies.
TEST(EditorModelLimits, MirrorAndGlassSayWhatTheyDoNotShowWhereItApplies) {
    Scene scene = defaultScene();
    const int object = 0;
    const int material = scene.objects[object].materialIndex;
    EXPECT_TRUE(modelLimitNotes(scene, object).empty()) << "the default material reflects the lights";
    scene.materials[material] = Material::withDefaults("mirror", BrdfModel::Mirror);
    const auto mirrorNotes = modelLimitNotes(scene, object);
    ASSERT_EQ(mirrorNotes.size(), scene.objects.size() > 1 ? 2u : 1u);
    EXPECT_NE(mirrorNotes[0].find("no highlight of the point, spot or directional lights"), std::string::npos);
    for (Light& light : scene.lights) light.enabled = light.type == LightType::Ambient;
    scene.objects.resize(1);
    EXPECT_TRUE(modelLimitNotes(scene, object).empty()) << "no delta light and nothing else to see";
    scene.objects.push_back(scene.objects[0]);
    scene.materials[material] = Material::withDefaults("glass", BrdfModel::Glass);
    const auto glassNotes = modelLimitNotes(scene, object);
    ASSERT_EQ(glassNotes.size(), 1u);
    EXPECT_NE(glassNotes[0].find("not the other objects"), std::string::npos);
}

}  // namespace
}  // namespace glint
