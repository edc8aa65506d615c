// The editor's object actions and IOR presets without a window: adding, duplicating and removing
// objects are one undo step each and select the new object; overlay toggles are undoable; an IOR
// preset sets n (and κ for metals) per channel, and a metal is refused by a model without κ.
#include <gtest/gtest.h>

#include "brdf/presets.h"
#include "editor/ior_presets.h"
#include "editor/object_actions.h"

namespace glint {
namespace {

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
