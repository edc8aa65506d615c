// The editor's BRDF Explorer actions without a window: a dropped .brdf goes onto the selected
// object after the child-process probe passes; a .bparam sets its values and is written back;
// a changed file hot-reloads, and a broken or endless change keeps the last good version with
// a located message; a material JSON that references the .brdf saves it as a relative path.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "runtime/brdf_probe.h"
#include "editor/custom_brdf_editor.h"
#include "editor/document.h"
#include "scene/scene_json.h"
#include "test_support.h"
#include "util/file_io.h"

namespace glint {
namespace {

constexpr const char* kBrdf = R"(analytic
::begin parameters
float gain 0 2 0.5
color tint 1 0.5 0.25
::end parameters
::begin shader
vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return tint * gain / 3.14159265; }
::end shader
)";

class EditorBrdf : public ::testing::Test {
protected:
    void SetUp() override {
        setBrdfProbeExecutable(GLINT_EXECUTABLE);  // this test binary is not `glint`
        directory_ = test::outputDirectory(std::string("editor_brdf/") +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        ::setenv("GLINT_STATE_DIR", (directory_ + "/state").c_str(), 1);
        ::setenv("GLINT_BRDF_TIMEOUT_S", "60", 1);  // a loaded machine may be slow to prove a good shader
    }
    void TearDown() override {
        ::unsetenv("GLINT_STATE_DIR");
        ::unsetenv("GLINT_BRDF_TIMEOUT_S");
    }
    std::string write(const std::string& name, const std::string& text) {
        const std::string path = directory_ + "/" + name;
        std::ofstream(path) << text;
        return path;
    }
    // Polls as the frame loop does (its clock a second further each time) until no probe is
    // pending (at most 60 s).
    void settle(EditorState& state) {
        for (int i = 0; i < 600; ++i) {
            pollCustomBrdfs(state, clockSeconds_ += 1.0);
            if (!state.customBrdfs.pending) return;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        FAIL() << "the probe never finished";
    }
    static const Material& selected(const EditorState& state) {
        const Scene& scene = state.session.scene();
        return scene.materials[scene.objects[state.selectedObject].materialIndex];
    }
    std::string directory_;
    double clockSeconds_ = 0.0;
};

TEST_F(EditorBrdf, DroppedBrdfAndBparamSetTheMaterial) {
    const std::string path = write("tinted.brdf", kBrdf);
    EditorState state;
    openDroppedFile(state, path);
    settle(state);
    ASSERT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    ASSERT_TRUE(selected(state).custom());
    EXPECT_EQ(selected(state).custom()->values, (std::vector<float>{0.5f, 1.0f, 0.5f, 0.25f}));

    openDroppedFile(state, write("values.bparam", "::begin parameters\nfloat gain 0 2 1.5\n::end parameters\n"));
    ASSERT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    EXPECT_EQ(selected(state).custom()->values[0], 1.5f);
    const std::string saved = directory_ + "/saved.bparam";
    ASSERT_TRUE(saveBparamTo(state, saved));
    EXPECT_TRUE(state.session.undo());  // the .bparam was one step
    EXPECT_EQ(selected(state).custom()->values[0], 0.5f);
    openDroppedFile(state, saved);
    EXPECT_EQ(selected(state).custom()->values[0], 1.5f);

    // Material JSON keeps a relative path to the .brdf and the values.
    const std::string json = directory_ + "/material.json";
    ASSERT_TRUE(saveMaterialTo(state, json));
    auto text = readTextFile(json);
    ASSERT_TRUE(text) << text.error().format();
    EXPECT_NE(text->find("\"brdf_file\": \"tinted.brdf\""), std::string::npos) << *text;
    auto reread = loadMaterial(json);
    ASSERT_TRUE(reread) << reread.error().format();
    EXPECT_EQ(reread->custom()->values, selected(state).custom()->values);
}

// A .bparam as BRDF Explorer writes it names its .brdf: dropped on a scene without that .brdf, it
// opens the .brdf with the file's values (the path written is found beside the .bparam).
TEST_F(EditorBrdf, BrdfExplorerBparamOpensTheBrdfItNames) {
    write("tinted.brdf", kBrdf);
    EditorState state;
    openDroppedFile(state, write("explorer.bparam", "bparam /elsewhere/tinted.brdf\n\n::begin parameters\n"
                                                    "float gain 0.000000 2.000000 1.250000\n"
                                                    "color tint 0.100000 0.200000 0.300000\n::end parameters\n"
                                                    "::begin isFunc\nvec3 f() { return vec3(0); }\n::end isFunc\n"));
    settle(state);
    ASSERT_TRUE(selected(state).custom()) << state.errorMessage;
    EXPECT_EQ(selected(state).custom()->values, (std::vector<float>{1.25f, 0.1f, 0.2f, 0.3f}));
    EXPECT_NE(state.errorMessage.find("explorer.bparam:7:1: warning: section 'isFunc' is skipped"), std::string::npos)
        << state.errorMessage;
}

TEST_F(EditorBrdf, BadFilesAreRefusedWithLocations) {
    EditorState state;
    openDroppedFile(state, write("bad.brdf", "analytic\n::begin parameters\nfloat gain 2 1 1\n::end parameters\n"));
    EXPECT_NE(state.errorMessage.find("bad.brdf:3:12: gain: min 2 is greater than max 1"), std::string::npos)
        << state.errorMessage;
    state.errorMessage.clear();
    openDroppedFile(state, write("orphan.bparam", "::begin parameters\nfloat gain 0 2 1\n::end parameters\n"));
    EXPECT_NE(state.errorMessage.find("open the .brdf file first"), std::string::npos);
    state.errorMessage.clear();
    openDroppedFile(state, write("broken.brdf", std::string(kBrdf).replace(std::string(kBrdf).find("return"), 6, "retur")));
    settle(state);
    EXPECT_NE(state.errorMessage.find("broken.brdf:7:"), std::string::npos) << state.errorMessage;
    EXPECT_FALSE(selected(state).custom());  // unchanged
}

TEST_F(EditorBrdf, ChangedFileReloadsAndBrokenChangesKeepTheLastGoodVersion) {
    const std::string path = write("live.brdf", kBrdf);
    EditorState state;
    openDroppedFile(state, path);
    settle(state);
    ASSERT_TRUE(selected(state).custom());
    const auto firstVersion = selected(state).custom()->brdf;
    const auto touch = [&, this](const std::string& text) {
        write("live.brdf", text);
        std::filesystem::last_write_time(path, std::filesystem::last_write_time(path) + std::chrono::seconds(5));
        settle(state);  // notices the change and starts the probe
        settle(state);
    };
    // A GLSL error: the message names the line, the material keeps the first version.
    std::string broken = kBrdf;
    broken.replace(broken.find("return"), 6, "retur");
    touch(broken);
    EXPECT_EQ(selected(state).custom()->brdf, firstVersion);
    EXPECT_NE(state.materialPanelMessage.text().find("live.brdf:7:"), std::string::npos) << state.materialPanelMessage.text();
    EXPECT_NE(state.materialPanelMessage.text().find("last good version stays"), std::string::npos);
    // A good change: reloaded, values kept where the parameter still exists.
    std::string brighter = kBrdf;
    brighter.replace(brighter.find("/ 3.14159265"), 12, "* 0.5");
    touch(brighter);
    EXPECT_NE(selected(state).custom()->brdf, firstVersion);
    EXPECT_TRUE(state.materialPanelMessage.text().empty()) << state.materialPanelMessage.text();
    EXPECT_EQ(selected(state).custom()->values, (std::vector<float>{0.5f, 1.0f, 0.5f, 0.25f}));
}

}  // namespace
}  // namespace glint
