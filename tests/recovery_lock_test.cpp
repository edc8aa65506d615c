// The recovery files' locks (editor/recovery.h): an editor that ended without a clean exit leaves
// its lock file and half-written copies, removed at the next start while its work is offered; a
// running editor's lock is never taken, whatever the process ids. Editors are forked children.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "editor/recovery.h"
#include "scene/scene.h"
#include "test_support.h"
#include "util/file_io.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

// GLINT_STATE_DIR pointed at an empty folder for one test, unset again after it.
class RecoveryLocks : public ::testing::Test {
protected:
    void SetUp() override {
        directory = test::outputDirectory("recovery_locks") + "/" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(directory);
        fs::create_directories(directory);
        ::setenv("GLINT_STATE_DIR", directory.c_str(), 1);
    }
    void TearDown() override { ::unsetenv("GLINT_STATE_DIR"); }

    std::string directory;
};

// A forked editor that takes its lock, autosaves and leaves a half-written crash copy, then runs
// until end(), when it ends without a clean exit (as kill -9 would).
class ForkedEditor {
public:
    explicit ForkedEditor(const std::string& stateDirectory) {
        int pipeEnds[2];
        if (::pipe(pipeEnds) != 0) throw std::runtime_error("pipe failed");
        pid_ = ::fork();
        if (pid_ == 0) {
            ::close(pipeEnds[1]);
            if (!lockRecoveryFile()) ::_exit(2);
            if (!writeFileAtomically(recoveryFilePath(), recoveryDocument(defaultScene(), ""))) ::_exit(3);
            std::ofstream(recoveryFilePath() + ".crash") << "{\"format\": ";
            char byte = 0;
            while (::read(pipeEnds[0], &byte, 1) > 0) {}
            ::_exit(0);
        }
        ::close(pipeEnds[0]);
        release_ = pipeEnds[1];
        stem_ = stateDirectory + "/recovery-" + std::to_string(pid_);
        for (int tries = 0; tries < 2000 && !fs::exists(stem_ + ".json.crash"); ++tries) ::usleep(5000);
    }
    ~ForkedEditor() { end(); }

    // Its files: recovery-PID followed by `ending`.
    std::string file(const std::string& ending) const { return stem_ + ending; }

    void end() {
        if (release_ < 0) return;
        ::close(release_);
        release_ = -1;
        int status = 0;
        ::waitpid(pid_, &status, 0);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the editor's set-up failed: " << status;
    }

private:
    pid_t pid_ = -1;
    int release_ = -1;
    std::string stem_;
};

TEST_F(RecoveryLocks, ADeadEditorsLeftoversGoAndItsWorkIsOffered) {
    ForkedEditor editor(directory);
    ASSERT_TRUE(fs::exists(editor.file(".json.crash")));
    editor.end();
    ASSERT_TRUE(fs::exists(editor.file(".lock")));

    removeStaleRecoveryLeftovers();
    EXPECT_FALSE(fs::exists(editor.file(".lock")));
    EXPECT_FALSE(fs::exists(editor.file(".json.crash")));
    EXPECT_TRUE(fs::exists(editor.file(".json"))) << "the work itself stays until the user answers";
    EXPECT_EQ(orphanedRecoveryFiles(), std::vector<std::string>{editor.file(".json")});
}

TEST_F(RecoveryLocks, ARunningEditorsLockAndWorkAreLeftAlone) {
    ForkedEditor editor(directory);
    ASSERT_TRUE(fs::exists(editor.file(".json.crash")));

    removeStaleRecoveryLeftovers();
    EXPECT_TRUE(fs::exists(editor.file(".lock")));
    EXPECT_TRUE(fs::exists(editor.file(".json.crash")));
    EXPECT_TRUE(orphanedRecoveryFiles().empty()) << "a running editor's work is not offered";

    editor.end();
    removeStaleRecoveryLeftovers();
    EXPECT_FALSE(fs::exists(editor.file(".lock")));
}

TEST_F(RecoveryLocks, ThisEditorsOwnLockIsKeptUntilItsCleanExit) {
    ASSERT_TRUE(lockRecoveryFile());
    const std::string lock = directory + "/recovery-" + std::to_string(::getpid()) + ".lock";
    removeStaleRecoveryLeftovers();
    EXPECT_TRUE(fs::exists(lock));
    unlockRecoveryFile();
    EXPECT_FALSE(fs::exists(lock));
}

}  // namespace
}  // namespace glint
