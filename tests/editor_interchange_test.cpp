// Interchange files in the editor without a window: a dropped (or File ▸ Open'ed) .mtl puts its
// material on the selected object and a .gltf also adds its lights, each as one undo step; a
// malformed file shows file:line and leaves the scene and its history as they were. A MERL
// .binary becomes a measured material that the scene saves by its path. File ▸ Export material…
// writes .gltf or .mtl with the format's warnings.
#include <gtest/gtest.h>

#include "editor/document.h"
#include "editor/interchange_export.h"
#include "interchange/gltf.h"
#include "interchange/mtl.h"
#include "interchange/measured_brdf.h"
#include "scene/scene_json.h"
#include "editor_test_support.h"

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
    EXPECT_EQ(material.model, BrdfModel::BlinnPhong);
    EXPECT_NE(state.statusMessage.find("material 'shiny'"), std::string::npos);
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

TEST_F(EditorInterchange, WarningsAreShownAfterOpening) {
    EditorState state;
    openDroppedFile(state, write("glow.gltf", R"({"asset": {"version": "2.0"},
        "materials": [{"emissiveFactor": [1, 1, 1]}]})"));
    EXPECT_NE(state.errorMessage.find("with warnings"), std::string::npos);
    EXPECT_NE(state.errorMessage.find("emission"), std::string::npos);
    EXPECT_EQ(state.session.scene().materials[state.session.scene().objects[0].materialIndex].model, BrdfModel::CookTorrance);
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
    ASSERT_TRUE(material.measured);
    EXPECT_EQ(material.measured->displayName, "plaster.binary");
    EXPECT_NE(state.statusMessage.find("material 'plaster'"), std::string::npos);
    const nlohmann::json saved = sceneToJson(state.session.scene(), write("scene.json", "{}"));
    EXPECT_EQ(saved["materials"][materialIndex]["merl_file"], "plaster.binary");
    EXPECT_TRUE(state.session.undo());
    EXPECT_FALSE(state.session.scene().materials[materialIndex].measured);
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
    EXPECT_NE(state.statusMessage.find("Exported material"), std::string::npos);
    EXPECT_FALSE(exportMaterialTo(state, write("ball.txt", "")));
    EXPECT_NE(state.errorMessage.find("must end in .mtl or .gltf"), std::string::npos) << state.errorMessage;
    EXPECT_FALSE(state.session.dirty());  // exporting changes nothing
}

}  // namespace
}  // namespace glint
