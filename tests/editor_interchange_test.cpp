// Interchange files in the editor without a window: a dropped (or File ▸ Open'ed) .mtl puts its
// material on the selected object and a .gltf also adds its lights, each as one undo step (a file
// with several materials asks which one first); a
// malformed file shows file:line and leaves the scene and its history as they were. A MERL
// .binary becomes a measured material that the scene saves by its path. File ▸ Export material…
// writes .gltf or .mtl with the format's warnings. `glint FILE` opens every type as File ▸ Open.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <functional>
#include <thread>
#include <tuple>

#include "runtime/brdf_probe.h"
#include "editor/custom_brdf_editor.h"
#include "editor/document.h"
#include "editor/mesh_loading.h"
#include "editor/interchange_export.h"
#include "editor/interchange_open.h"
#include "interchange/gltf.h"
#include "interchange/mtl.h"
#include "interchange/measured_brdf.h"
#include "scene/scene_json.h"
#include "editor_test_support.h"
#include "test_support.h"

namespace glint {
namespace {

class EditorInterchange : public test::EditorFixture {
protected:
    const char* suiteFolder() const override { return "editor_interchange"; }
};

TEST_F(EditorInterchange, DroppedMtlGoesOntoTheSelectedObjectAsOneUndoStep) {
    EditorState state;
    state.selectedObject = 1;
    const int materialIndex = state.session.scene().objects[1].materialIndex;
    openDroppedFile(state, write("shiny.MTL", "newmtl shiny\nKd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNs 80\nillum 2\n"));
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Material& material = state.session.scene().materials[materialIndex];
    EXPECT_EQ(material.name, "shiny");
    EXPECT_EQ(material.analytic()->model, BrdfModel::BlinnPhong);
    EXPECT_NE(state.statusMessage.text().find("material 'shiny'"), std::string::npos);
    EXPECT_TRUE(state.session.undo());
    EXPECT_EQ(state.session.scene().materials[materialIndex].name, defaultScene().materials[materialIndex].name);
}

TEST_F(EditorInterchange, DroppedGltfBringsItsMaterialAndLights) {
    EditorState state;
    const size_t lightsBefore = state.session.scene().lights.size();
    openDroppedFile(state, write("lamp.gltf", R"({"asset": {"version": "2.0"},
        "materials": [{"name": "brass", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.7, 0.3, 1]}}],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 50}]}},
        "nodes": [{"translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}}]})"));
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Scene& scene = state.session.scene();
    EXPECT_EQ(scene.materials[scene.objects[0].materialIndex].name, "brass");
    ASSERT_EQ(scene.lights.size(), lightsBefore + 1);
    EXPECT_EQ(scene.lights.back().position, glm::vec3(0, 3, 0));
    EXPECT_TRUE(state.session.undo());
    EXPECT_EQ(state.session.scene().lights.size(), lightsBefore);
}

// A file with several materials asks which one: offered by index and name, the first preselected.
TEST_F(EditorInterchange, AFileWithSeveralMaterialsAsksWhichOneAndAppliesTheChoice) {
    const std::string gltf = write("pair.gltf", R"({"asset": {"version": "2.0"},
        "materials": [{"name": "brass", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.7, 0.3, 1]}},
                      {"name": "glow", "emissiveFactor": [1, 1, 1], "alphaMode": "BLEND"}],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 50}]}},
        "nodes": [{"translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}}]})");
    const std::string mtl = write("pair.mtl", "newmtl paint\nKd 0.8 0.1 0.1\nillum 1\n\nnewmtl shiny\nKd 0.2 0.4 0.6\nKs 0.5 0.5 0.5\nNs 80\nillum 2\n");
    for (const auto& [path, first, second] : {std::tuple{gltf, "brass", "glow"}, std::tuple{mtl, "paint", "shiny"}}) {
        SCOPED_TRACE(path);
        EditorState state;
        const Scene before = state.session.scene();
        const int materialIndex = before.objects[0].materialIndex;
        openDroppedFile(state, path);
        EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
        ASSERT_TRUE(state.materialChoice.has_value());
        ASSERT_EQ(state.materialChoice->file.materials.size(), 2u);
        EXPECT_EQ(state.materialChoice->file.materials[0].material.name, first);
        EXPECT_EQ(state.materialChoice->file.materials[1].material.name, second);
        EXPECT_EQ(state.materialChoice->selected, 0);
        // Nothing changes while the question is open.
        EXPECT_EQ(state.session.scene().materials[materialIndex].name, before.materials[materialIndex].name);
        EXPECT_EQ(state.session.scene().lights.size(), before.lights.size());

        takeMaterialChoice(state, 1);
        EXPECT_FALSE(state.materialChoice.has_value());
        const Scene& scene = state.session.scene();
        EXPECT_EQ(scene.materials[materialIndex].name, second);
        EXPECT_NE(state.statusMessage.text().find(std::string("material '") + second + "' (2 of 2)"), std::string::npos)
            << state.statusMessage.text();
        const bool isGltf = path == gltf;
        EXPECT_EQ(scene.lights.size(), before.lights.size() + (isGltf ? 1 : 0));
        // The chosen material's warnings only: the glTF's second one blends alpha, its first does not.
        EXPECT_EQ(state.errorMessage.find("alpha") != std::string::npos, isGltf) << state.errorMessage;
        EXPECT_TRUE(state.session.undo());  // one step
        EXPECT_EQ(state.session.scene().materials[materialIndex].name, before.materials[materialIndex].name);
        EXPECT_EQ(state.session.scene().lights.size(), before.lights.size());
        EXPECT_FALSE(state.session.undo());

        // Cancelling changes nothing and records no step.
        EditorState cancelled;
        openDroppedFile(cancelled, path);
        ASSERT_TRUE(cancelled.materialChoice.has_value());
        cancelMaterialChoice(cancelled);
        EXPECT_FALSE(cancelled.materialChoice.has_value());
        EXPECT_EQ(cancelled.session.scene().materials[materialIndex].name, before.materials[materialIndex].name);
        EXPECT_EQ(cancelled.session.scene().lights.size(), before.lights.size());
        EXPECT_FALSE(cancelled.session.undo());
    }
}

TEST_F(EditorInterchange, WarningsAreShownAfterOpening) {
    EditorState state;
    openDroppedFile(state, write("veil.gltf", R"({"asset": {"version": "2.0"},
        "materials": [{"alphaMode": "BLEND"}]})"));
    EXPECT_NE(state.errorMessage.find("with warnings"), std::string::npos);
    EXPECT_NE(state.errorMessage.find("alpha"), std::string::npos);
    EXPECT_EQ(state.session.scene().materials[state.session.scene().objects[0].materialIndex].analytic()->model, BrdfModel::OpenPbr);
}

TEST_F(EditorInterchange, MalformedFileShowsFileAndLineAndChangesNothing) {
    EditorState state;
    const Scene before = state.session.scene();
    const std::string path = write("broken.mtl", "newmtl a\nKd 0.5 0.5 0.5\nNs lots\n");
    openDroppedFile(state, path);
    EXPECT_NE(state.errorMessage.find(path + ":3: 'lots' is not a number"), std::string::npos) << state.errorMessage;
    EXPECT_EQ(state.session.scene().materials[0].name, before.materials[0].name);
    EXPECT_FALSE(state.session.undo());  // no step was recorded
    state.errorMessage.clear();
    openDroppedFile(state, write("broken.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"materials\": [{\"alphaMode\": 3}]}"));
    EXPECT_NE(state.errorMessage.find("broken.gltf:2:"), std::string::npos) << state.errorMessage;
    EXPECT_FALSE(state.session.undo());
}

TEST_F(EditorInterchange, DroppedMerlFileBecomesAMeasuredMaterialAndSavesWithTheScene) {
    EditorState state;
    const int materialIndex = state.session.scene().objects[0].materialIndex;
    openDroppedFile(state, write("plaster.binary", makeConstantMerl(glm::vec3(0.2f))));
    EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
    const Material& material = state.session.scene().materials[materialIndex];
    ASSERT_TRUE(material.measured());
    EXPECT_EQ(material.measured()->brdf->displayName, "plaster.binary");
    EXPECT_NE(state.statusMessage.text().find("material 'plaster'"), std::string::npos);
    const nlohmann::json saved = sceneToJson(state.session.scene(), write("scene.json", "{}"));
    EXPECT_EQ(saved["materials"][materialIndex]["merl_file"], "plaster.binary");
    EXPECT_TRUE(state.session.undo());
    EXPECT_FALSE(state.session.scene().materials[materialIndex].measured());
    openDroppedFile(state, write("short.binary", std::string(40, '\0')));
    EXPECT_NE(state.errorMessage.find("not a MERL BRDF"), std::string::npos) << state.errorMessage;
}

TEST_F(EditorInterchange, ExportMaterialWritesGltfOrMtlAndShowsWhatTheFormatLoses) {
    EditorState state;
    const Scene before = state.session.scene();
    const std::string gltfPath = write("ball.gltf", "old");
    EXPECT_TRUE(exportMaterialTo(state, gltfPath));
    auto gltf = loadGltf(gltfPath);
    ASSERT_TRUE(gltf.ok()) << gltf.error().format();
    EXPECT_EQ(gltf->materials.at(0).material.name, before.materials[before.objects[0].materialIndex].name);
    EXPECT_EQ(gltf->lights.size(), before.lights.size());
    EXPECT_NE(state.errorMessage.find("cannot hold everything"), std::string::npos) << state.errorMessage;  // Blinn-Phong in glTF
    state.errorMessage.clear();
    const std::string mtlPath = write("ball.MTL", "");
    EXPECT_TRUE(exportMaterialTo(state, mtlPath));
    auto mtl = loadMtl(mtlPath);
    ASSERT_TRUE(mtl.ok()) << mtl.error().format();
    EXPECT_EQ(mtl->materials.size(), 1u);
    EXPECT_NE(state.statusMessage.text().find("Exported material"), std::string::npos);
    EXPECT_FALSE(exportMaterialTo(state, write("ball.txt", "")));
    EXPECT_NE(state.errorMessage.find("must end in .mtl, .gltf or .mtlx"), std::string::npos) << state.errorMessage;
    EXPECT_FALSE(state.session.dirty());  // exporting changes nothing
}

// A .glb holding `json` as its only chunk.
std::string glbOf(std::string json) {
    while (json.size() % 4 != 0) json += ' ';
    const auto word = [](uint32_t value) {
        std::string bytes(4, '\0');
        std::memcpy(bytes.data(), &value, 4);
        return bytes;
    };
    const uint32_t length = static_cast<uint32_t>(json.size());
    return word(0x46546C67) + word(2) + word(12 + 8 + length) + word(length) + word(0x4E4F534A) + json;
}

// `glint FILE` starts the editor on the default scene and opens FILE as File ▸ Open and a drop do
// (editor.cpp runEditor → openDroppedFile). Each type on a fresh start, polled as the frame loop
// polls until the .brdf probe or the mesh load is done; and a broken file of each family shows
// its located error and leaves the default scene.
TEST_F(EditorInterchange, EveryFileTypeOpensFromTheCommandLine) {
    setBrdfProbeExecutable(GLINT_EXECUTABLE);  // this test binary is not `glint`
    ::setenv("GLINT_BRDF_TIMEOUT_S", "60", 1);  // a loaded machine may be slow to prove a good shader
    const auto openOnStart = [](const std::string& path, const std::function<void(const EditorState&)>& check) {
        EditorState state;
        openDroppedFile(state, path);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        double clock = 0.0;
        while ((state.customBrdfs.pending || state.meshLoad) && std::chrono::steady_clock::now() < deadline) {
            pollCustomBrdfs(state, clock += 1.0);
            pollMeshLoad(state);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        check(state);
    };
    const auto subject = [](const EditorState& state) -> const Material& {
        const Scene& scene = state.session.scene();
        return scene.materials[scene.objects[state.selectedObject].materialIndex];
    };
    const Scene start = defaultScene();
    Scene chalkScene = start;
    chalkScene.materials[chalkScene.objects[0].materialIndex].name = "chalk";
    const std::string scenePath = directory_ + "/chalk_scene.json";
    ASSERT_TRUE(saveScene(chalkScene, scenePath).ok());
    openOnStart(scenePath, [&](const EditorState& state) {
        EXPECT_TRUE(state.errorMessage.empty()) << state.errorMessage;
        EXPECT_EQ(state.session.path(), std::filesystem::absolute(scenePath).lexically_normal().string());
        EXPECT_EQ(subject(state).name, "chalk");
    });
    openOnStart(write("gold.json", R"({"format": "glint-material", "version": 1, "name": "gold", "model": "lambert"})"),
                [&](const EditorState& state) { EXPECT_EQ(subject(state).name, "gold") << state.errorMessage; });
    openOnStart(write("shiny.mtl", "newmtl shiny\nKd 0.2 0.4 0.6\n"),
                [&](const EditorState& state) { EXPECT_EQ(subject(state).name, "shiny") << state.errorMessage; });
    const std::string lamp = R"({"asset": {"version": "2.0"}, "materials": [{"name": "brass"}],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 50}]}},
        "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}}]})";
    for (const std::string& path : {write("lamp.gltf", lamp), write("lamp.glb", glbOf(lamp))})
        openOnStart(path, [&](const EditorState& state) {
            EXPECT_EQ(subject(state).name, "brass") << path << ": " << state.errorMessage;
            EXPECT_EQ(state.session.scene().lights.size(), start.lights.size() + 1) << path;
        });
    openOnStart(write("plaster.binary", makeConstantMerl(glm::vec3(0.2f))),
                [&](const EditorState& state) { EXPECT_TRUE(subject(state).measured()) << state.errorMessage; });
    openOnStart(write("flat.brdf", "analytic\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) "
                                   "{ return vec3(0.1); }\n::end shader\n"),
                [&](const EditorState& state) { EXPECT_TRUE(subject(state).custom()) << state.errorMessage; });
    // An asset replaces the scene: its part and the stage's floor, untitled.
    openOnStart(write("triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), [&](const EditorState& state) {
        const Scene& scene = state.session.scene();
        ASSERT_EQ(scene.objects.size(), 2u) << state.errorMessage;
        EXPECT_EQ(std::get<MeshShape>(scene.objects[0].shape).part, 0);
        EXPECT_EQ(scene.objects[1].name, "floor");
        EXPECT_EQ(state.session.path(), "");
    });
    openOnStart(test::dataPath("files/assets/parts.gltf"), [&](const EditorState& state) {
        const Scene& scene = state.session.scene();
        ASSERT_EQ(scene.objects.size(), 5u) << state.errorMessage;  // four parts and the floor
        EXPECT_EQ(scene.materials.size(), 4u);                       // three of the file's and the floor's
        EXPECT_NE(state.statusMessage.text().find("4 parts, 3 materials"), std::string::npos) << state.statusMessage.text();
    });
    // Broken files: the error names the file and where, the default scene stays.
    const std::pair<std::string, std::string> broken[] = {
        {write("broken_scene.json", "{\"format\": \"glint-scene\",\n \"version\": }"), "broken_scene.json:2:"},
        {write("short.binary", std::string(40, '\0')), "short.binary"},
        {write("broken.brdf", "analytic\n::begin parameters\nfloat gain\n::end parameters\n"), "broken.brdf:3:"},
        {write("broken.obj", "v 0 0 0\nf 1 2 3\n"), "broken.obj"}};
    for (const auto& file : broken) {
        const std::string& path = file.first;     // not a structured binding: clang 14 (the
        const std::string& located = file.second;  // sanitizer build) cannot capture those
        openOnStart(path, [&](const EditorState& state) {
            EXPECT_NE(state.errorMessage.find(located), std::string::npos) << path << ": " << state.errorMessage;
            EXPECT_EQ(state.session.scene().objects.size(), start.objects.size()) << path;
            EXPECT_EQ(subject(state).name, start.materials[start.objects[0].materialIndex].name) << path;
        });
    }
    ::unsetenv("GLINT_BRDF_TIMEOUT_S");
}

}  // namespace
}  // namespace glint
