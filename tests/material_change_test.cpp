// The pixels a change of material values reaches (render/material_change.h): the changed
// material's objects only, and nothing (a whole redraw) for any other change.
#include <gtest/gtest.h>

#include "render/material_change.h"
#include "scene/scene.h"

namespace glint {
namespace {

constexpr int kWidth = 320, kHeight = 240;

TEST(MaterialChange, ReachesOnlyTheObjectsThatWearTheMaterial) {
    const Scene before = defaultScene();  // the sphere, then the floor that fills the lower frame
    Scene after = before;
    paramValues(after.materials[0])[0] = 0.1f;
    const auto sphere = materialChange(before, after, kWidth, kHeight);
    ASSERT_TRUE(sphere.has_value());
    EXPECT_GT(sphere->rect.width * sphere->rect.height, 0);
    EXPECT_LT(sphere->rect.width * sphere->rect.height, kWidth * kHeight / 2);
    EXPECT_EQ(sphere->materials, (std::vector<bool>{true, false}));
    after = before;
    paramValues(after.materials[1])[0] = 0.5f;  // the floor's
    const auto floor = materialChange(before, after, kWidth, kHeight);
    ASSERT_TRUE(floor.has_value());
    EXPECT_GT(floor->rect.width * floor->rect.height, sphere->rect.width * sphere->rect.height);
    EXPECT_EQ(floor->materials, (std::vector<bool>{false, true}));
}

TEST(MaterialChange, AnyOtherChangeRedrawsEverything) {
    const Scene before = defaultScene();
    Scene after = before;
    EXPECT_FALSE(materialChange(before, after, kWidth, kHeight)) << "nothing changed";
    paramValues(after.materials[0])[0] = 0.1f;
    after.lights[0].irradiance = 2.0f;
    EXPECT_FALSE(materialChange(before, after, kWidth, kHeight)) << "a light too";
    after = before;
    paramValues(after.materials[0])[0] = 0.1f;
    after.camera.position.x += 0.1f;
    EXPECT_FALSE(materialChange(before, after, kWidth, kHeight)) << "the camera too";
    after = before;
    after.materials[0] = Material::withDefaults(before.materials[0].name, BrdfModel::Lambert);
    EXPECT_FALSE(materialChange(before, after, kWidth, kHeight)) << "another model";
    after = before;
    after.materials[1] = Material::withDefaults("stage floor", BrdfModel::Glass);  // the sphere shows through it
    Scene glassBefore = after;
    paramValues(after.materials[0])[0] = 0.1f;
    EXPECT_FALSE(materialChange(glassBefore, after, kWidth, kHeight)) << "a transmissive object sees the others";
    after = before;
    after.materials[1].analytic()->textures.push_back(MaterialTexture{.parameter = "albedo"});
    Scene texturedBefore = after;
    paramValues(after.materials[0])[0] = 0.1f;
    EXPECT_FALSE(materialChange(texturedBefore, after, kWidth, kHeight))
        << "a texture file may change on disk under the same scene";
}

}  // namespace
}  // namespace glint
