// Environment maps in the editor: a choice or the environment a scene file names is made on a
// worker thread while frames go on, a newer choice supersedes a running one, opening another scene
// cancels a choice, and the scene, its undo history, Save and errors stay consistent
// (app/editor/environment_loading.h).
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "editor/document.h"
#include "editor/environment_loading.h"
#include "editor/recovery.h"
#include "editor_test_support.h"
#include "environment/environment_map.h"
#include "scene/scene_json.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"

namespace glint {
namespace {

class EditorEnvironment : public test::EditorFixture {
protected:
    const char* suiteFolder() const override { return "editor_environment"; }
};

const std::string kStudioFile = test::dataPath("environments/studio_small_01_256.exr");

// Runs the frame loop's polling until the map is ready (at most 60 s); returns the frames drawn.
int waitForEnvironment(EditorState& state) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    int frames = 0;
    while (pollEnvironmentLoad(state) && std::chrono::steady_clock::now() < deadline) {
        ++frames;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    EXPECT_FALSE(state.environmentLoad) << "the environment map was not made within 60 s";
    return frames;
}

TEST_F(EditorEnvironment, AChosenFileIsPrecomputedWhileFramesGoOnThenBecomesOneUndoStep) {
    EditorState state;
    const std::string before = sceneToJson(state.session.scene()).dump();
    const auto previousMap = state.session.scene().environment.map;
    startEnvironmentLoad(state, EnvironmentKind::File, kStudioFile);
    // The choice returned at once: the map is still being made and the scene keeps its studio.
    ASSERT_TRUE(state.environmentLoad) << "the map was made on the UI thread";
    EXPECT_FALSE(state.environmentLoad->finished());
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
    EXPECT_FALSE(state.session.canUndo());
    const int frames = waitForEnvironment(state);
    EXPECT_GT(frames, 0) << "no frame completed while the map was pending";
    const Environment& environment = state.session.scene().environment;
    EXPECT_EQ(environment.kind, EnvironmentKind::File);
    EXPECT_EQ(environment.file, kStudioFile);
    ASSERT_TRUE(environment.map);
    EXPECT_EQ(environment.map->radiance.width, 256);
    EXPECT_EQ(state.session.undoLabel(), "Environment file");
    ASSERT_TRUE(state.session.undo());
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
    EXPECT_EQ(state.session.scene().environment.map, previousMap);
}

TEST_F(EditorEnvironment, ANewerChoiceSupersedesOneStillRunning) {
    EditorState state;
    startEnvironmentLoad(state, EnvironmentKind::File, kStudioFile);
    startEnvironmentLoad(state, EnvironmentKind::Sky);
    waitForEnvironment(state);
    EXPECT_EQ(state.session.scene().environment.kind, EnvironmentKind::Sky);
    EXPECT_TRUE(state.session.scene().environment.map);
    ASSERT_TRUE(state.session.undo());  // one step: the superseded file never reached the scene
    EXPECT_EQ(state.session.scene().environment.kind, EnvironmentKind::Studio);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
}

TEST_F(EditorEnvironment, CancelAndAnUnusableFileLeaveTheSceneAsItWas) {
    EditorState state;
    const std::string before = sceneToJson(state.session.scene()).dump();
    startEnvironmentLoad(state, EnvironmentKind::File, kStudioFile);
    state.environmentLoad->cancel();
    waitForEnvironment(state);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const std::string broken = write("broken.hdr", "#?RADIANCE\nnot an image\n");
    startEnvironmentLoad(state, EnvironmentKind::File, broken);
    waitForEnvironment(state);
    EXPECT_NE(state.errorMessage.find("broken.hdr"), std::string::npos) << state.errorMessage;
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
    EXPECT_FALSE(state.session.canUndo());
}

// A scene file naming `environment` (a file beside it or a built-in) for one sphere.
std::string sceneNaming(const std::string& environment) {
    return R"({"format": "glint-scene", "version": 1, "environment": )" + environment +
           R"(, "materials": [{"name": "m", "model": "lambert"}], "objects": [{"shape": "sphere", "material": "m"}]})";
}

TEST_F(EditorEnvironment, AnOpenedSceneShowsAtOnceAndItsMapJoinsWithoutAStep) {
    std::filesystem::copy_file(kStudioFile, directory_ + "/studio.exr", std::filesystem::copy_options::overwrite_existing);
    const std::string path = write("lit.json", sceneNaming(R"({"type": "file", "file": "studio.exr", "intensity": 2})"));
    EditorState state;
    openSceneFile(state, path);
    ASSERT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Environment& named = state.session.scene().environment;
    EXPECT_EQ(named.kind, EnvironmentKind::File);
    EXPECT_EQ(named.file, directory_ + "/studio.exr");
    EXPECT_FALSE(named.map) << "the map was made on the UI thread while opening";
    state.session.change("Edit environment").environment.rotationDegrees = 30.0f;  // an edit while it is made
    state.session.settle(false);
    const int frames = waitForEnvironment(state);
    EXPECT_GT(frames, 0) << "no frame completed while the map was pending";
    ASSERT_TRUE(state.session.scene().environment.map);
    EXPECT_EQ(state.session.scene().environment.map->radiance.width, 256);
    EXPECT_EQ(state.session.undoLabel(), "Edit environment") << "the map arriving is no step";
    ASSERT_TRUE(state.session.undo());
    EXPECT_TRUE(state.session.scene().environment.map) << "the state before the edit lost its map";
    EXPECT_EQ(state.session.scene().environment.intensity, 2.0f);
    EXPECT_FALSE(state.session.dirty()) << "the map arriving marked the scene modified";
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
}

TEST_F(EditorEnvironment, SaveWhileTheMapIsMadeKeepsTheEnvironmentAndRecoveryMakesItToo) {
    const OutsideReferencesAllowance allowed;  // the scene names the test data's map, outside its folder
    const std::string path = write("lit.json", sceneNaming(R"({"type": "file", "file": ")" + kStudioFile + R"("})"));
    EditorState state;
    openSceneFile(state, path);
    ASSERT_TRUE(pollEnvironmentLoad(state)) << "the map is not being made";
    ASSERT_TRUE(saveSceneTo(state, directory_ + "/saved.json"));
    auto saved = loadScene(directory_ + "/saved.json", EnvironmentMapLoading::Later);
    ASSERT_TRUE(saved) << saved.error().format();
    EXPECT_EQ(saved->environment.kind, EnvironmentKind::File);
    EXPECT_EQ(saved->environment.file, kStudioFile);
    // Recovered work names its environment the same way and gets its map on the worker.
    ASSERT_TRUE(writeFileAtomically(directory_ + "/recovery.json", recoveryDocument(state.session.scene(), path)));
    auto recovered = loadRecovery(directory_ + "/recovery.json");
    ASSERT_TRUE(recovered) << recovered.error().format();
    EXPECT_FALSE(recovered->scene.environment.map);
    state.session.replace(recovered->scene, recovered->scenePath, true);
    waitForEnvironment(state);
    EXPECT_TRUE(state.session.scene().environment.map);
    EXPECT_FALSE(state.session.canUndo());
}

TEST_F(EditorEnvironment, OpeningAnotherSceneCancelsAPendingChoice) {
    for (const bool openFile : {true, false}) {
        EditorState state;
        startEnvironmentLoad(state, EnvironmentKind::File, kStudioFile);
        if (openFile) openSceneFile(state, test::dataPath("scenes/lambert_sun.json"));
        else newScene(state);
        ASSERT_TRUE(state.errorMessage.empty()) << state.errorMessage;
        const std::string opened = sceneToJson(state.session.scene()).dump();
        waitForEnvironment(state);
        EXPECT_EQ(sceneToJson(state.session.scene()).dump(), opened) << "the choice landed on the other scene";
        EXPECT_FALSE(state.session.canUndo());
        EXPECT_FALSE(state.session.dirty());
    }
}

TEST_F(EditorEnvironment, AnOpenedSceneWhoseMapFailsStaysOpenNamingIt) {
    write("broken.hdr", "#?RADIANCE\nnot an image\n");
    const std::string path = write("broken.json", sceneNaming(R"({"type": "file", "file": "broken.hdr"})"));
    EditorState state;
    openSceneFile(state, path);
    EXPECT_EQ(state.session.path(), path) << state.errorMessage;
    waitForEnvironment(state);
    EXPECT_NE(state.errorMessage.find("broken.hdr"), std::string::npos) << state.errorMessage;
    EXPECT_EQ(state.session.scene().environment.file, directory_ + "/broken.hdr");
    EXPECT_FALSE(pollEnvironmentLoad(state)) << "a map that failed is made again";
    EXPECT_FALSE(state.session.canUndo());
    EXPECT_FALSE(state.session.dirty());
}

TEST_F(EditorEnvironment, ADroppedHdrFileIsAChoice) {
    EditorState state;
    openDroppedFile(state, kStudioFile);
    ASSERT_TRUE(state.environmentLoad);
    EXPECT_TRUE(state.environmentLoad->choice);
    waitForEnvironment(state);
    EXPECT_EQ(state.session.undoLabel(), "Environment file");
}

}  // namespace
}  // namespace glint
