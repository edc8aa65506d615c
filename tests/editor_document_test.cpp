// The editor's document actions without a window: opening scenes and materials (also by drag and
// drop), refusing corrupt files while keeping the work, the unsaved-changes guard, recent files
// kept between runs, autosave writing and removing the recovery file, camera actions as edits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "runtime/brdf_probe.h"
#include "editor/recovery.h"
#include "editor/mesh_loading.h"
#include "editor/camera_actions.h"
#include "editor/document.h"
#include "editor/settings.h"
#include "editor/texture_panel.h"
#include "image/image_io.h"
#include "interchange/merl.h"
#include "scene/scene_json.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"
#include "editor_test_support.h"
#include "environment_test_support.h"
#include "test_support.h"

namespace glint {
namespace {

// Each test gets its own state directory (recovery file, settings).
class EditorDocument : public test::EditorFixture {
protected:
    const char* suiteFolder() const override { return "editor_document"; }
};

TEST_F(EditorDocument, DroppedMaterialGoesOntoTheSelectedObjectAsOneUndoStep) {
    Material gold = Material::withDefaults("gold", BrdfModel::Lambert);
    gold.analytic()->values = {0.9f, 0.7f, 0.2f};
    const std::string path = directory_ + "/gold.json";
    ASSERT_TRUE(saveMaterial(gold, path).ok());
    EditorState state;
    state.selectedObject = 0;
    openDroppedFile(state, path);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Scene& scene = state.session.scene();
    EXPECT_EQ(scene.materials[scene.objects[0].materialIndex].name, "gold");
    EXPECT_TRUE(state.session.undo());
    EXPECT_EQ(state.session.scene().materials[0].name, defaultScene().materials[0].name);
}

TEST_F(EditorDocument, DroppedSceneOpensAndBecomesRecent) {
    Scene scene = defaultScene();
    scene.lights.resize(1);
    const std::string path = directory_ + "/one_light.json";
    ASSERT_TRUE(saveScene(scene, path).ok());
    EditorState state;
    openDroppedFile(state, path);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    EXPECT_EQ(state.session.scene().lights.size(), 1u);
    EXPECT_FALSE(state.session.dirty());
    EXPECT_FALSE(state.session.canUndo());
    // Recent files survive a restart (settings.json in the state directory).
    const Settings reloaded = loadSettings();
    ASSERT_FALSE(reloaded.recentFiles.empty());
    EXPECT_EQ(reloaded.recentFiles.front(), state.session.path());
}

TEST_F(EditorDocument, CorruptFilesAreRefusedWithTheirLineAndTheWorkIsKept) {
    EditorState state;
    state.session.change("Edit").lights[0].irradiance = 9.0f;
    state.session.settle(false);
    const std::string scenePath = write("bad_scene.json", "{\n  \"format\": \"glint-scene\",\n  \"version\": 1,\n  \"lights\": 7\n}\n");
    openSceneGuarded(state, scenePath);  // dirty: the prompt is asked for first
    EXPECT_TRUE(state.unsavedPromptRequested);
    runActionAfterPrompt(state);  // "Don't save"
    EXPECT_NE(state.errorMessage.find("bad_scene.json:4:"), std::string::npos) << state.errorMessage;
    EXPECT_FLOAT_EQ(state.session.scene().lights[0].irradiance, 9.0f);
    EXPECT_TRUE(state.session.canUndo());

    state.errorMessage.clear();
    const std::string materialPath = write("bad_material.json", "{\"format\": \"glint-material\", \"version\": 1,\n \"model\": \"plaster\"}");
    openDroppedFile(state, materialPath);
    EXPECT_NE(state.errorMessage.find("bad_material.json:2:"), std::string::npos) << state.errorMessage;
    EXPECT_FLOAT_EQ(state.session.scene().lights[0].irradiance, 9.0f);
}

TEST_F(EditorDocument, AnUnreadableRecoveryFileIsReportedAndKept) {
    const std::string damaged = stateDirectory() + "/recovery.json";  // as Glint wrote it before per-editor files
    ASSERT_TRUE(ensureParentDirectory(damaged).ok());
    std::ofstream(damaged) << "{ not json";
    EditorState state;
    startRecovery(state);
    EXPECT_NE(state.errorMessage.find("recovery.json"), std::string::npos) << state.errorMessage;
    EXPECT_TRUE(state.recoveryOffer.empty());
    autosave(state, 100.0, 5.0);
    finishRecovery(state);
    EXPECT_TRUE(std::filesystem::exists(damaged)) << "kept for the user to inspect";
}

// Two editors open at once: neither is offered the other's work while it runs; once one dies
// without a clean exit, the next start offers its file.
TEST_F(EditorDocument, OnlyTheRecoveryFilesOfEditorsNoLongerRunningAreOffered) {
    Scene otherWork = defaultScene();
    otherWork.lights[0].irradiance = 6.0f;
    const std::string other = stateDirectory() + "/recovery-999999.json";
    ASSERT_TRUE(ensureParentDirectory(other).ok());
    ASSERT_TRUE(writeFileAtomically(other, recoveryDocument(otherWork, "")).ok());
    const int otherLock = ::open((stateDirectory() + "/recovery-999999.lock").c_str(), O_RDWR | O_CREAT, 0644);
    ASSERT_EQ(::flock(otherLock, LOCK_EX), 0);

    EditorState running;
    startRecovery(running);
    EXPECT_TRUE(running.recoveryOffer.empty()) << "the other editor still runs";
    running.session.change("Edit").lights[0].irradiance = 2.0f;
    running.session.settle(false);
    autosave(running, 100.0, 5.0);
    EXPECT_FLOAT_EQ(loadRecovery(other)->scene.lights[0].irradiance, 6.0f) << "its file is untouched";
    finishRecovery(running);
    EXPECT_TRUE(std::filesystem::exists(other)) << "a clean exit removes only the editor's own file";

    ::close(otherLock);  // the other editor is killed
    EditorState next;
    startRecovery(next);
    ASSERT_EQ(next.recoveryOffer.size(), 1u);
    EXPECT_EQ(next.recoveryOffer[0].recoveryPath, other);
    EXPECT_FLOAT_EQ(next.recoveryOffer[0].scene.lights[0].irradiance, 6.0f);
    finishRecovery(next);
}

TEST_F(EditorDocument, QuitWithoutChangesNeedsNoPromptAndWithChangesWaitsForOne) {
    EditorState clean;
    requestQuit(clean);
    EXPECT_TRUE(clean.quitNow);
    EditorState dirty;
    dirty.session.change("Edit").lights[0].irradiance = 1.0f;
    requestQuit(dirty);
    EXPECT_FALSE(dirty.quitNow);
    EXPECT_TRUE(dirty.unsavedPromptRequested);
    runActionAfterPrompt(dirty);
    EXPECT_TRUE(dirty.quitNow);
}

TEST_F(EditorDocument, AutosaveWritesRecoveryWhileDirtyAndRemovesItWhenClean) {
    EditorState state;
    state.session.change("Edit").lights[0].irradiance = 4.0f;
    state.session.settle(false);
    const double interval = 5.0;
    EXPECT_GT(autosave(state, 100.0, interval), 1e8);  // written now: nothing left to wait for
    auto recovered = loadRecovery(recoveryFilePath());
    ASSERT_TRUE(recovered.ok()) << recovered.error().format();
    EXPECT_FLOAT_EQ(recovered->scene.lights[0].irradiance, 4.0f);
    // The next change waits for the interval, then is written.
    state.session.change("Edit").lights[0].irradiance = 5.0f;
    state.session.settle(false);
    EXPECT_NEAR(autosave(state, 101.0, interval), 4.0, 1e-9);
    EXPECT_GT(autosave(state, 105.0, interval), 1e8);
    EXPECT_FLOAT_EQ(loadRecovery(recoveryFilePath())->scene.lights[0].irradiance, 5.0f);
    // Saved: the next autosave removes the recovery file; a clean exit would too.
    ASSERT_TRUE(saveSceneTo(state, directory_ + "/saved.json"));
    autosave(state, 200.0, interval);
    EXPECT_FALSE(std::filesystem::exists(recoveryFilePath()));
}

TEST_F(EditorDocument, UiScaleIsKeptBetweenRunsAndNonsenseIgnored) {
    Settings settings;
    settings.uiScale = 1.75f;
    saveSettings(settings);
    EXPECT_FLOAT_EQ(loadSettings().uiScale, 1.75f);
    std::ofstream(std::string(std::getenv("GLINT_STATE_DIR")) + "/settings.json") << R"({"ui_scale": 40, "recent_files": [3]})";
    const Settings fallback = loadSettings();
    EXPECT_FLOAT_EQ(fallback.uiScale, 1.0f);
    EXPECT_TRUE(fallback.recentFiles.empty());
}

TEST_F(EditorDocument, CameraActionsAreUndoableEdits) {
    EditorState state;
    const Camera original = state.session.scene().camera;
    state.selectedObject = 0;  // the unit sphere at the origin
    frameSelected(state);
    const Camera framed = state.session.scene().camera;
    const float halfFov = glm::radians(0.5f * original.verticalFovDegrees);
    EXPECT_NEAR(glm::length(framed.target), 0.0f, 1e-5f);
    // The bounding sphere fills the vertical field of view with 10 % margin: d = 1.1 r / sin(fov/2).
    EXPECT_NEAR(glm::length(framed.position - framed.target), 1.1f / std::sin(halfFov), 1e-3f);
    toggleProjection(state);
    const Camera& orthographic = state.session.scene().camera;
    EXPECT_EQ(orthographic.projection, Projection::Orthographic);
    // Same apparent size at the target: h = 2 d tan(fov/2).
    EXPECT_NEAR(orthographic.orthoHeight, 2.0f * glm::length(framed.position - framed.target) * std::tan(halfFov), 1e-3f);
    EXPECT_EQ(state.session.undoLabel(), "Switch projection");
    ASSERT_TRUE(state.session.undo());
    ASSERT_TRUE(state.session.undo());
    EXPECT_EQ(state.session.scene().camera.position, original.position);
    EXPECT_FALSE(state.session.dirty());
    resetView(state);
    EXPECT_EQ(state.session.scene().camera.position, defaultScene().camera.position);
}


// The material panel's "Image file…": a file that fails leaves the material and the history as
// they were and says why; a good one becomes one undo step.
TEST_F(EditorDocument, TextureImageFromTheFileBrowserIsOneUndoStepAndFailuresChangeNothing) {
    EditorState state;
    state.textureMaterialIndex = state.session.scene().objects[0].materialIndex;
    state.textureParameter = "diffuse_albedo";  // the default sphere is Blinn-Phong
    const std::string before = sceneToJson(state.session.scene()).dump();
    openTextureFile(state, directory_ + "/absent.png");
    EXPECT_NE(state.errorMessage.find("absent.png"), std::string::npos) << state.errorMessage;
    EXPECT_NE(state.errorMessage.find("unchanged"), std::string::npos);
    const std::string corrupt = write("corrupt.png", "\x89PNG\r\n\x1a\nnot really");
    state.errorMessage.clear();
    openTextureFile(state, corrupt);
    EXPECT_FALSE(state.errorMessage.empty());
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
    EXPECT_FALSE(state.session.canUndo());

    DisplayImage image(4, 4);
    const std::string good = directory_ + "/good.png";
    ASSERT_TRUE(writeDisplayImage(image, good).ok());
    state.errorMessage.clear();
    openTextureFile(state, good);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Material& textured = state.session.scene().materials[state.textureMaterialIndex];
    ASSERT_EQ(textured.analytic()->textures.size(), 1u);
    EXPECT_EQ(textured.analytic()->textures[0].parameter, "diffuse_albedo");
    EXPECT_TRUE(state.session.undo());
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
}

// The working directory changed for the life of the object, as a user's shell would have it.
class WorkingDirectory {
public:
    explicit WorkingDirectory(const std::string& path) : previous_(std::filesystem::current_path()) {
        std::filesystem::current_path(path);
    }
    ~WorkingDirectory() { std::filesystem::current_path(previous_); }
    WorkingDirectory(const WorkingDirectory&) = delete;
    WorkingDirectory& operator=(const WorkingDirectory&) = delete;

private:
    std::filesystem::path previous_;
};

// `glint bunny.obj` and a scene that names every kind of referenced file (mesh, texture image,
// environment, .brdf, MERL table) by a relative path: after a crash the recovery file, read from
// another working directory, names the same files; saved elsewhere, the scene names them relative
// to its own folder and opens again.
TEST_F(EditorDocument, FilesOpenedByRelativePathsAreRecoveredAndSavedRelativeToTheSceneFile) {
    const std::string work = std::filesystem::absolute(directory_ + "/work").lexically_normal().string();
    std::filesystem::create_directories(work);
    std::ofstream(work + "/bunny.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    DisplayImage image(2, 2);
    std::fill(image.pixels.begin(), image.pixels.end(), uint8_t{128});
    ASSERT_TRUE(writeDisplayImage(image, work + "/wood.png").ok());
    test::writeTestHdr(work + "/sky.hdr", 32);
    std::ofstream(work + "/tinted.brdf") << "analytic\n::begin parameters\nfloat gain 0 2 0.5\n::end parameters\n"
                                            "::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) "
                                            "{ return vec3(gain / 3.14159265); }\n::end shader\n";
    std::ofstream(work + "/plaster.binary", std::ios::binary) << makeConstantMerl(glm::vec3(0.2f));
    std::ofstream(work + "/scene.json") << R"({"format": "glint-scene", "version": 1,
      "environment": {"type": "file", "file": "sky.hdr"},
      "lights": [],
      "materials": [
        {"name": "wood", "model": "lambert", "textures": {"albedo": {"type": "image", "file": "wood.png"}}},
        {"name": "tinted", "model": "brdf_file", "brdf_file": "tinted.brdf"},
        {"name": "plaster", "model": "merl", "merl_file": "plaster.binary"}],
      "objects": [
        {"name": "ball", "shape": "sphere", "material": "wood"},
        {"name": "statue", "shape": "mesh", "path": "bunny.obj", "material": "tinted"},
        {"name": "cube", "shape": "cube", "material": "plaster"}]})";
    setBrdfProbeExecutable(GLINT_EXECUTABLE);  // opening the .brdf proves its shader in `glint probe-brdf`
    ::setenv("GLINT_BRDF_TIMEOUT_S", "60", 1);  // a loaded machine may be slow to prove it
    EditorState state;
    {
        const WorkingDirectory inWork(work);
        openDroppedFile(state, "scene.json");
        ASSERT_TRUE(state.errorMessage.empty()) << state.errorMessage;
        test::loadMeshAndSettle(state, "bunny.obj");
        ASSERT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    }
    ::unsetenv("GLINT_BRDF_TIMEOUT_S");
    ASSERT_TRUE(state.session.dirty());
    autosave(state, 100.0, 5.0);

    const WorkingDirectory elsewhere(directory_);  // Glint started again from another folder
    auto recovered = loadRecovery(recoveryFilePath());
    ASSERT_TRUE(recovered.ok()) << recovered.error().format();
    const Scene& scene = recovered->scene;
    const auto meshFile = [&](size_t object) { return std::get<MeshShape>(scene.objects.at(object).shape).resolvedPath; };
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_EQ(meshFile(1), work + "/bunny.obj");
    EXPECT_EQ(meshFile(3), work + "/bunny.obj");
    EXPECT_EQ(scene.materials[0].analytic()->textures.at(0).file, work + "/wood.png");
    EXPECT_EQ(scene.environment.file, work + "/sky.hdr");
    ASSERT_TRUE(scene.materials[1].custom());
    EXPECT_EQ(scene.materials[1].custom()->brdf->file.path, work + "/tinted.brdf");
    ASSERT_TRUE(scene.materials[2].measured());
    EXPECT_EQ(scene.materials[2].measured()->brdf->path, work + "/plaster.binary");

    const std::string copy = directory_ + "/saved/copy.json";
    ASSERT_TRUE(ensureParentDirectory(copy).ok());
    ASSERT_TRUE(saveScene(scene, copy).ok());
    const nlohmann::json saved = nlohmann::json::parse(std::ifstream(copy));
    EXPECT_EQ(saved["objects"][1]["path"], "../work/bunny.obj");
    EXPECT_EQ(saved["objects"][3]["path"], "../work/bunny.obj");
    EXPECT_EQ(saved["materials"][0]["textures"]["albedo"]["file"], "../work/wood.png");
    EXPECT_EQ(saved["environment"]["file"], "../work/sky.hdr");
    EXPECT_EQ(saved["materials"][1]["brdf_file"], "../work/tinted.brdf");
    EXPECT_EQ(saved["materials"][2]["merl_file"], "../work/plaster.binary");
    // Outside the folder of the copy: refused unless allowed (util/reference_confinement.h).
    ASSERT_FALSE(loadScene(copy).ok());
    const OutsideReferencesAllowance allowed;
    auto reopened = loadScene(copy);
    ASSERT_TRUE(reopened.ok()) << reopened.error().format();
    EXPECT_EQ(sceneToJson(*reopened), sceneToJson(scene));
}

}  // namespace
}  // namespace glint
