// The edit model: steps, gestures as one step, undo/redo, the dirty flag, history limits; messages
// dropped when the scene changes after them; the recovery document round trip; and the crash guard writing the published copy when a child
// process dies of SIGSEGV, SIGABRT or SIGTERM.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "editor/crash_guard.h"
#include "editor/edit_session.h"
#include "editor/recovery.h"
#include "editor/scene_message.h"
#include "scene/scene_json.h"
#include "test_support.h"
#include "util/file_io.h"

namespace glint {
namespace {

float sphereFirstValue(const EditSession& session) { return session.scene().materials[0].analytic()->values[0]; }

// A change (labelled `label`) that sets the sphere material's first value; returns the value it had.
float changeSphereFirstValue(EditSession& session, const char* label, float value) {
    const float before = sphereFirstValue(session);
    session.change(label).materials[0].analytic()->values[0] = value;
    return before;
}

TEST(EditSession, StartsCleanWithNothingToUndo) {
    EditSession session;
    EXPECT_FALSE(session.dirty());
    EXPECT_FALSE(session.canUndo());
    EXPECT_FALSE(session.canRedo());
    EXPECT_FALSE(session.undo());
}

TEST(EditSession, OneChangeIsOneStepThatUndoAndRedoRestore) {
    EditSession session;
    const float original = changeSphereFirstValue(session, "Edit albedo", 0.25f);
    EXPECT_TRUE(session.dirty());
    EXPECT_TRUE(session.settle(false));
    EXPECT_EQ(session.undoLabel(), "Edit albedo");
    ASSERT_TRUE(session.undo());
    EXPECT_FLOAT_EQ(sphereFirstValue(session), original);
    EXPECT_FALSE(session.dirty());
    EXPECT_EQ(session.redoLabel(), "Edit albedo");
    ASSERT_TRUE(session.redo());
    EXPECT_FLOAT_EQ(sphereFirstValue(session), 0.25f);
    EXPECT_TRUE(session.dirty());
}

TEST(EditSession, AGestureIsOneStepHoweverManyFramesItLasts) {
    EditSession session;
    const float original = sphereFirstValue(session);
    for (int frame = 1; frame <= 30; ++frame) {
        changeSphereFirstValue(session, "Drag", frame / 30.0f);
        EXPECT_FALSE(session.settle(/*gestureInProgress=*/true));
    }
    EXPECT_TRUE(session.settle(false));
    ASSERT_TRUE(session.undo());
    EXPECT_FLOAT_EQ(sphereFirstValue(session), original);
    EXPECT_FALSE(session.canUndo());
}

TEST(EditSession, UndoDuringAGestureClosesItFirst) {
    EditSession session;
    const float original = changeSphereFirstValue(session, "Drag", 0.1f);
    EXPECT_TRUE(session.canUndo());
    ASSERT_TRUE(session.undo());
    EXPECT_FLOAT_EQ(sphereFirstValue(session), original);
}

TEST(EditSession, AStepThatChangesNothingIsDropped) {
    EditSession session;
    const float original = changeSphereFirstValue(session, "Drag", 0.9f);
    changeSphereFirstValue(session, "Drag", original);
    EXPECT_FALSE(session.settle(false));
    EXPECT_FALSE(session.canUndo());
    EXPECT_FALSE(session.dirty());
}

TEST(EditSession, ANewStepClearsRedo) {
    EditSession session;
    session.change("A").lights[0].irradiance = 1.0f;
    session.settle(false);
    session.undo();
    EXPECT_TRUE(session.canRedo());
    session.change("B").lights[0].irradiance = 2.0f;
    session.settle(false);
    EXPECT_FALSE(session.canRedo());
}

TEST(EditSession, DirtyFollowsTheSavedStateThroughUndoAndRedo) {
    EditSession session;
    session.change("A").lights[0].irradiance = 1.0f;
    session.settle(false);
    const auto settledBeforeSave = session.settledRevision();
    session.markSaved("/tmp/a.json");
    EXPECT_FALSE(session.dirty());
    EXPECT_GT(session.settledRevision(), settledBeforeSave) << "autosave must notice the save";
    EXPECT_EQ(session.path(), "/tmp/a.json");
    session.undo();
    EXPECT_TRUE(session.dirty());
    session.redo();
    EXPECT_FALSE(session.dirty());
}

TEST(EditSession, ReplaceClearsHistoryAndRecoveredWorkIsDirty) {
    EditSession session;
    session.change("A").lights[0].irradiance = 1.0f;
    session.settle(false);
    session.replace(defaultScene(), "opened.json");
    EXPECT_FALSE(session.canUndo());
    EXPECT_FALSE(session.dirty());
    session.replace(defaultScene(), "", /*dirty=*/true);
    EXPECT_TRUE(session.dirty());
}

TEST(EditSession, HistoryIsBoundedAndRevisionsGrow) {
    EditSession session;
    const auto firstRevision = session.revision();
    for (size_t i = 0; i < EditSession::kMaxUndoSteps + 10; ++i) {
        session.change("Step").lights[0].irradiance = 1.0f + static_cast<float>(i);
        session.settle(false);
    }
    EXPECT_GT(session.revision(), firstRevision);
    size_t undone = 0;
    while (session.undo()) ++undone;
    EXPECT_EQ(undone, EditSession::kMaxUndoSteps);
    EXPECT_TRUE(session.dirty());  // the oldest steps fell off: the opened state is out of reach
}

// A refusal stays while the scene stays as it was, and goes with the next edit, undo or new scene;
// a message written in the frame of a change ("Undone") belongs to the scene after it.
TEST(SceneMessage, IsDroppedWhenTheSceneChangesAfterIt) {
    EditSession session;
    SceneMessage refusal;
    refusal = "Diffuse albedo ρ_d: each channel must be at least 0";
    refusal.expire(session.revision());
    refusal.expire(session.revision());
    EXPECT_FALSE(refusal.empty()) << "nothing changed: the refusal still holds";
    changeSphereFirstValue(session, "Edit albedo", 0.25f);
    session.settle(false);
    refusal.expire(session.revision());
    EXPECT_TRUE(refusal.empty());

    SceneMessage status;
    ASSERT_TRUE(session.undo());
    status = "Undone";
    status.expire(session.revision());
    status.expire(session.revision());
    EXPECT_EQ(status.text(), "Undone");
    ASSERT_TRUE(session.redo());
    status = "Redone";
    status.expire(session.revision());
    EXPECT_EQ(status.text(), "Redone");
    ASSERT_TRUE(session.undo());
    status = "Undone";  // the same words again, about a new change: kept
    status.expire(session.revision());
    EXPECT_EQ(status.text(), "Undone");

    // A widget writing through text(), then a new scene.
    refusal.text() = "Gamma: 0 refused; it must lie in [0.1, 10]";
    refusal.expire(session.revision());
    EXPECT_FALSE(refusal.empty());
    session.replace(defaultScene(), "");
    refusal.expire(session.revision());
    status.expire(session.revision());
    EXPECT_TRUE(refusal.empty());
    EXPECT_TRUE(status.empty());
}

TEST(Recovery, DocumentRoundTripsSceneAndPath) {
    Scene scene = defaultScene();
    scene.lights[0].irradiance = 7.5f;
    const std::string path = test::outputDirectory("recovery") + "/round_trip.json";
    ASSERT_TRUE(writeFileAtomically(path, recoveryDocument(scene, "/home/artist/shiny.json")).ok());
    auto recovered = loadRecovery(path);
    ASSERT_TRUE(recovered.ok()) << recovered.error().format();
    EXPECT_EQ(recovered->scenePath, "/home/artist/shiny.json");
    EXPECT_EQ(sceneToJson(recovered->scene), sceneToJson(scene));
}

TEST(Recovery, DamagedFileGivesADiagnosticNamingIt) {
    const std::string path = test::outputDirectory("recovery") + "/damaged.json";
    ASSERT_TRUE(writeFileAtomically(path, "{\"format\": \"glint-recovery\", \"scene\": ").ok());
    auto recovered = loadRecovery(path);
    ASSERT_FALSE(recovered.ok());
    EXPECT_NE(recovered.error().format().find("damaged.json"), std::string::npos);
}

TEST(Recovery, LocationFollowsTheEnvironment) {
    const std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
    ::setenv("GLINT_STATE_DIR", "/tmp/glint-state-test", 1);
    const std::string file = "/recovery-" + std::to_string(::getpid()) + ".json";  // one per running editor
    EXPECT_EQ(recoveryFilePath(), "/tmp/glint-state-test" + file);
    ::unsetenv("GLINT_STATE_DIR");
    ::setenv("XDG_STATE_HOME", "/tmp/xdg-state", 1);
    EXPECT_EQ(recoveryFilePath(), "/tmp/xdg-state/glint" + file);
    ::unsetenv("XDG_STATE_HOME");
    ::setenv("HOME", "/home/artist", 1);
    EXPECT_EQ(recoveryFilePath(), "/home/artist/.local/state/glint" + file);
    ::setenv("HOME", home.c_str(), 1);
}

// Forks a child that publishes a copy and dies of `signalNumber`; returns what it left behind.
std::string crashChildAndRead(int signalNumber, const std::string& name) {
    const std::string path = test::outputDirectory("crash_guard") + "/" + name + ".json";
    std::filesystem::remove(path);
    const pid_t child = ::fork();
    if (child == 0) {
        installCrashGuard(path);
        publishCrashCopy("first");
        publishCrashCopy("latest copy of " + name);
        std::raise(signalNumber);
        ::_exit(0);  // not reached
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status)) << "the child must still die of the signal";
    if (WIFSIGNALED(status)) {
        EXPECT_EQ(WTERMSIG(status), signalNumber);
    }
    auto text = readTextFile(path);
    return text ? *text : std::string("(no file)");
}

TEST(CrashGuard, WritesTheLatestCopyOnSegfaultAbortAndTerm) {
    EXPECT_EQ(crashChildAndRead(SIGSEGV, "segv"), "latest copy of segv");
    EXPECT_EQ(crashChildAndRead(SIGABRT, "abrt"), "latest copy of abrt");
    EXPECT_EQ(crashChildAndRead(SIGTERM, "term"), "latest copy of term");
}

TEST(CrashGuard, WritesNothingWhenTheCopyIsEmpty) {
    const std::string path = test::outputDirectory("crash_guard") + "/clean.json";
    std::filesystem::remove(path);
    const pid_t child = ::fork();
    if (child == 0) {
        installCrashGuard(path);
        publishCrashCopy("");
        std::raise(SIGTERM);
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status));
    EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace glint
