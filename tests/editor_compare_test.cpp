// The editor's Compare window without a window (app/classroom/compare_view.h): each pane's choice
// (current material, another scene material, a preset, the current material under another model)
// puts that material on the selected object and nothing else changes; the interpolation lesson
// gives flat, Gouraud and Phong panes with the chosen tessellation. The rendered composite is
// tested in classroom_gpu_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>

#include "brdf/presets.h"
#include "classroom/compare_view.h"
#include "editor/editor_state.h"

namespace glint {
namespace {

const Material& subjectMaterialOf(const Scene& scene, size_t object) {
    return scene.materials.at(scene.objects.at(object).materialIndex);
}

TEST(EditorCompare, EachPaneChoicePutsItsMaterialOnTheSelectedObject) {
    EditorState state;  // the default scene: sphere (red plastic), floor (grey)
    state.selectedObject = 0;
    openCompareView(state, false);
    state.compare.layout = CompareLayout::Grid;
    state.compare.paneCount = 4;
    const int copper = static_cast<int>(findPreset("copper") - allPresets().data());
    const int orenNayar = static_cast<int>(std::find_if(allModels().begin(), allModels().end(),
                                                        [](const ModelInfo& info) { return info.model == BrdfModel::OrenNayar; }) -
                                           allModels().begin());
    using Kind = ComparePaneChoice::Kind;
    state.compare.choices[0] = {Kind::Current, 0};
    state.compare.choices[1] = {Kind::SceneMaterial, 1};
    state.compare.choices[2] = {Kind::Preset, copper};
    state.compare.choices[3] = {Kind::Model, orenNayar};
    auto panes = compareViewPanes(state);
    ASSERT_TRUE(panes.ok()) << panes.error().format();
    ASSERT_EQ(panes->size(), 4u);
    const Scene& scene = state.session.scene();
    EXPECT_EQ(subjectMaterialOf((*panes)[0].scene, 0).name, subjectMaterialOf(scene, 0).name);
    EXPECT_EQ(subjectMaterialOf((*panes)[1].scene, 0).name, scene.materials[1].name);
    EXPECT_EQ(subjectMaterialOf((*panes)[2].scene, 0).name, "copper");
    EXPECT_EQ(subjectMaterialOf((*panes)[3].scene, 0).analytic()->model, BrdfModel::OrenNayar);
    for (const ComparePaneScene& pane : *panes) {
        EXPECT_EQ(subjectMaterialOf(pane.scene, 1).name, subjectMaterialOf(scene, 1).name);  // the floor keeps its own
        EXPECT_EQ(pane.scene.camera.position, scene.camera.position);
        EXPECT_EQ(pane.scene.lights.size(), scene.lights.size());
    }
    EXPECT_EQ((*panes)[2].label, "copper");
}

TEST(EditorCompare, TheInterpolationLessonIsFlatGouraudPhongWithTheSliderTessellation) {
    EditorState state;
    state.selectedObject = 0;
    openCompareView(state, true);
    state.compare.tessellation = {9, 5};
    auto panes = compareViewPanes(state);
    ASSERT_TRUE(panes.ok()) << panes.error().format();
    ASSERT_EQ(panes->size(), 3u);
    const SurfaceInterpolation expected[3] = {SurfaceInterpolation::Flat, SurfaceInterpolation::Gouraud, SurfaceInterpolation::Phong};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ((*panes)[i].scene.objects[0].interpolation, expected[i]);
        EXPECT_EQ(std::get<SphereShape>((*panes)[i].scene.objects[0].shape).segments, 9);
        EXPECT_EQ(std::get<SphereShape>((*panes)[i].scene.objects[0].shape).rings, 5);
    }
}

}  // namespace
}  // namespace glint
