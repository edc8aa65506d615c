// The compare view's pure parts: pane and divider rectangles of the split, grid and row layouts
// (app/classroom/compare_layout.h) and the pane scenes (compare_scenes.h: the subject, material
// swaps, a model change that keeps shared parameters, interpolation and tessellation). The
// rendered composite is tested in classroom_gpu_test.cpp.
#include <gtest/gtest.h>

#include "brdf/model_registry.h"
#include "classroom/compare_layout.h"
#include "classroom/compare_scenes.h"

namespace glint {
namespace {

TEST(CompareLayout, SplitPanesShareOneFullSizeRenderAcrossTheDivider) {
    const CompareGeometry split = compareGeometry(CompareLayout::Split, 2, 200, 100, 0.3f);
    ASSERT_EQ(split.panes.size(), 2u);
    EXPECT_EQ(split.panes[0].target.width, 60);
    EXPECT_EQ(split.panes[1].target.x, 60);
    EXPECT_EQ(split.panes[1].target.width, 140);
    EXPECT_EQ(split.panes[1].sourceX, 60);  // the right pane shows the right part of its render
    EXPECT_EQ(split.panes[1].renderWidth, 200);
    ASSERT_EQ(split.dividers.size(), 1u);
    EXPECT_EQ(split.dividers[0].x, 59);
    EXPECT_EQ(paneAt(split, 59, 50), 0);
    EXPECT_EQ(paneAt(split, 60, 50), 1);
    // At an edge one pane is empty and the divider stays inside the image.
    const CompareGeometry edge = compareGeometry(CompareLayout::Split, 2, 200, 100, 1.0f);
    EXPECT_EQ(edge.panes[1].target.width, 0);
    EXPECT_EQ(edge.dividers[0].x + edge.dividers[0].width, 200);
}

TEST(CompareLayout, GridAndRowPanesAreWholeRendersOfTheirOwnSize) {
    const CompareGeometry grid = compareGeometry(CompareLayout::Grid, 3, 101, 60, 0.5f);
    ASSERT_EQ(grid.panes.size(), 3u);
    EXPECT_EQ(grid.panes[1].target.x, 50);
    EXPECT_EQ(grid.panes[1].renderWidth, 51);
    EXPECT_EQ(grid.panes[2].target.y, 30);
    EXPECT_EQ(grid.panes[2].sourceX, 0);
    EXPECT_EQ(paneAt(grid, 80, 45), -1);  // the fourth cell is empty
    EXPECT_EQ(grid.dividers.size(), 2u);
    const CompareGeometry row = compareGeometry(CompareLayout::Row, 3, 90, 40, 0.5f);
    ASSERT_EQ(row.panes.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(row.panes[i].target.x, 30 * i);
    EXPECT_EQ(row.dividers.size(), 2u);
}

TEST(CompareScenes, TheSubjectIsTheFirstObjectThatIsNotAPlane) {
    Scene scene = defaultScene();  // sphere, then floor
    std::swap(scene.objects[0], scene.objects[1]);
    ASSERT_EQ(compareSubject(scene).value(), 1u);
    scene.objects.erase(scene.objects.begin() + 1);
    EXPECT_EQ(compareSubject(scene).value(), 0u);  // only a plane: the plane
    scene.objects.clear();
    EXPECT_FALSE(compareSubject(scene).ok());
}

TEST(CompareScenes, PanesDifferOnlyInTheSubject) {
    const Scene scene = defaultScene();
    const Scene gold = withSubjectMaterial(scene, 0, Material::withDefaults("gold", BrdfModel::CookTorrance));
    EXPECT_EQ(gold.materials.size(), scene.materials.size() + 1);
    EXPECT_EQ(gold.materials[gold.objects[0].materialIndex].name, "gold");
    EXPECT_EQ(gold.objects[1].materialIndex, scene.objects[1].materialIndex);
    const Scene flat = withSubjectInterpolation(scene, 0, SurfaceInterpolation::Flat, Tessellation{8, 4});
    EXPECT_EQ(flat.objects[0].interpolation, SurfaceInterpolation::Flat);
    EXPECT_EQ(std::get<SphereShape>(flat.objects[0].shape).segments, 8);
    EXPECT_EQ(std::get<SphereShape>(flat.objects[0].shape).rings, 4);
}

TEST(CompareScenes, AnotherModelKeepsTheParametersBothModelsName) {
    Material clay = Material::withDefaults("clay", BrdfModel::Lambert);
    clay.analytic()->values = {0.6f, 0.3f, 0.2f};  // albedo
    const Material rough = withModel(clay, BrdfModel::OrenNayar);
    EXPECT_EQ(rough.analytic()->model, BrdfModel::OrenNayar);
    const auto table = modelInfo(BrdfModel::OrenNayar).params;
    const int albedo = findParam(table, "albedo");
    ASSERT_GE(albedo, 0);
    EXPECT_FLOAT_EQ(rough.analytic()->values[packedOffset(table, albedo)], 0.6f);
    EXPECT_FLOAT_EQ(rough.analytic()->values[packedOffset(table, albedo) + 2], 0.2f);
    EXPECT_EQ(rough.analytic()->values.size(), defaultValues(table).size());
}

}  // namespace
}  // namespace glint
