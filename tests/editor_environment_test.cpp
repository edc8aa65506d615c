// Choosing an environment in the editor: the map is made on a worker thread while frames go on,
// a newer choice supersedes a running one, and the scene, its undo history and errors stay
// consistent (app/editor/environment_loading.h).
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "editor/environment_loading.h"
#include "editor/panels/panels.h"
#include "editor_test_support.h"
#include "scene/scene_json.h"

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
    openEnvironmentFile(state, kStudioFile);
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
    openEnvironmentFile(state, kStudioFile);
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
    openEnvironmentFile(state, kStudioFile);
    state.environmentLoad->cancel();
    waitForEnvironment(state);
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const std::string broken = write("broken.hdr", "#?RADIANCE\nnot an image\n");
    openEnvironmentFile(state, broken);
    waitForEnvironment(state);
    EXPECT_NE(state.errorMessage.find("broken.hdr"), std::string::npos) << state.errorMessage;
    EXPECT_EQ(sceneToJson(state.session.scene()).dump(), before);
    EXPECT_FALSE(state.session.canUndo());
}

}  // namespace
}  // namespace glint
