// Scene JSON for shadows: "casts_shadows" and the "shadow" settings round-trip, default off
// (the default scene's lights too), and each nonsense value (negative bias, zero
// resolution, NaN, too many shadowed lights, shadows on an ambient light) is refused with a
// located message. Also the CPU shadow ray itself. No GL.
#include <gtest/gtest.h>

#include "render/shadow_projection.h"
#include "render/shadow_rays.h"
#include "scene/scene_json.h"
#include "located_error_support.h"
#include "test_support.h"

namespace glint {
namespace {

std::string sceneWithLights(const std::string& lightsJson) {
    return "{\n  \"format\": \"glint-scene\",\n  \"version\": 1,\n  \"lights\": [\n    " + lightsJson +
           "\n  ],\n  \"materials\": [{\"name\": \"m\", \"model\": \"lambert\"}],\n"
           "  \"objects\": [{\"shape\": \"sphere\", \"material\": \"m\"}]\n}";
}

using test::expectLocatedError;

TEST(SceneJsonShadows, SettingsLoadAndRoundTrip) {
    Scene scene = test::loadTestScene("scenes/shadows.json");
    ASSERT_EQ(scene.lights.size(), 4u);
    EXPECT_TRUE(scene.lights[0].castsShadows);
    EXPECT_EQ(scene.lights[1].shadow.mapResolution, 1024);
    EXPECT_FALSE(scene.lights[3].castsShadows);
    scene.lights[1].shadow = {256, 0.5f, 4.0f, 0.0f};
    scene.lights[2].castsShadows = false;
    auto loaded = parseScene(sceneToJson(scene).dump(2), "round_trip.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().format();
    for (size_t i = 0; i < scene.lights.size(); ++i) loaded->lights[i].direction = scene.lights[i].direction;  // renormalised
    EXPECT_EQ(sceneToJson(*loaded), sceneToJson(scene));
    EXPECT_EQ(loaded->lights[1].shadow.mapResolution, 256);
    EXPECT_EQ(loaded->lights[1].shadow.filterRadius, 0.0f);
    EXPECT_FALSE(loaded->lights[2].castsShadows);
    EXPECT_FALSE(sceneToJson(*loaded)["lights"][0].contains("shadow")) << "default settings are not written";
}

TEST(SceneJsonShadows, OffUnlessAskedFor) {
    auto scene = parseScene(sceneWithLights(R"({"type": "point"})"), "plain.json");
    ASSERT_TRUE(scene.ok()) << scene.error().format();
    EXPECT_FALSE(scene->lights[0].castsShadows) << "files written before shadows render as before";
}

TEST(SceneJsonShadows, NonsenseIsRefusedWithALocation) {
    expectLocatedError(sceneWithLights(R"({"type": "point", "shadow": {"depth_bias": -1}})"), 5, "depth_bias", "");
    expectLocatedError(sceneWithLights(R"({"type": "point", "shadow": {"normal_offset": -0.5}})"), 5, "normal_offset", "");
    expectLocatedError(sceneWithLights(R"({"type": "spot", "shadow": {"map_resolution": 0}})"), 5, "map_resolution", "");
    expectLocatedError(sceneWithLights(R"({"type": "spot", "shadow": {"map_resolution": 1024.5}})"), 5, "map_resolution",
                       "integer");
    // JSON has no NaN literal: a writer that emits one makes invalid JSON, refused where it stands.
    auto nan = parseScene(sceneWithLights(R"({"type": "directional", "shadow": {"filter_radius": NaN}})"), "bad.json");
    ASSERT_FALSE(nan.ok());
    EXPECT_EQ(nan.error().where.line, 5);
    EXPECT_NE(nan.error().message.find("invalid JSON"), std::string::npos) << nan.error().format();
    expectLocatedError(sceneWithLights(R"({"type": "directional", "shadow": {"filter_radius": 1e300}})"), 5,
                       "filter_radius", "");
    expectLocatedError(sceneWithLights(R"({"type": "directional", "casts_shadows": "yes"})"), 5, "casts_shadows",
                       "true or false");
    expectLocatedError(sceneWithLights(R"({"type": "ambient", "casts_shadows": true})"), 5, "casts_shadows",
                       "ambient lights cast no shadows");
    expectLocatedError(sceneWithLights(R"({"type": "point", "shadow": {"blur": 2}})"), 5, "blur", "");
    const std::string five = R"({"type": "point", "casts_shadows": true}, )";
    expectLocatedError(sceneWithLights(five + five + five + five + R"({"type": "point", "casts_shadows": true})"), 4,
                       "lights", "at most 4 lights can cast shadows");
}

// The CPU twin of the shadow map: a shadow ray from the floor under the sphere is blocked, one
// beside it is not, and a light that casts no shadows is never blocked.
TEST(ShadowRays, TheSphereBlocksTheFloorBelowIt) {
    Scene scene = test::loadTestScene("scenes/shadows.json");
    Light sun;
    sun.direction = {0.0f, -1.0f, 0.0f};
    sun.castsShadows = true;
    const SurfaceHit below{1.0f, {0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 1};
    const SurfaceHit beside{1.0f, {1.5f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 1};
    EXPECT_EQ(lightVisibility(scene, sun, below, lightArrival(sun, below.position)), 0.0f);
    EXPECT_EQ(lightVisibility(scene, sun, beside, lightArrival(sun, beside.position)), 1.0f);
    Light bulb;
    bulb.type = LightType::Point;
    bulb.castsShadows = true;
    bulb.position = {0.0f, -0.7f, 0.0f};  // between the floor and the sphere: nothing in the way
    EXPECT_EQ(lightVisibility(scene, bulb, below, lightArrival(bulb, below.position)), 1.0f);
    bulb.position = {0.0f, 2.0f, 0.0f};
    EXPECT_EQ(lightVisibility(scene, bulb, below, lightArrival(bulb, below.position)), 0.0f);
    bulb.castsShadows = false;
    EXPECT_EQ(lightVisibility(scene, bulb, below, lightArrival(bulb, below.position)), 1.0f);
}

TEST(ShadowProjection, MapsCoverTheSceneAndTheCone) {
    const Scene scene = test::loadTestScene("scenes/shadows.json");
    const BoundingSphere bounds = sceneBounds(scene);
    EXPECT_GT(bounds.radius, std::sqrt(18.0f));  // the 6 m floor's corners are inside
    const auto sun = shadowProjection(scene.lights[0], bounds);
    ASSERT_TRUE(sun);
    EXPECT_EQ(sun->kind, ShadowMapKind::Orthographic);
    for (float x : {-3.0f, 3.0f})
        for (float z : {-3.0f, 3.0f}) {
            const glm::vec4 clip = sun->viewProjection * glm::vec4(x, -1.0f, z, 1.0f);
            EXPECT_LE(glm::max(glm::abs(clip.x), glm::max(glm::abs(clip.y), glm::abs(clip.z))), 1.0f);
        }
    EXPECT_EQ(shadowProjection(scene.lights[1], bounds)->kind, ShadowMapKind::Perspective);
    EXPECT_EQ(shadowProjection(scene.lights[2], bounds)->kind, ShadowMapKind::Cube);
    EXPECT_FALSE(shadowProjection(scene.lights[3], bounds)) << "ambient";
    Light wideSpot = scene.lights[1];
    wideSpot.coneHalfAngleDegrees = 85.0f;
    EXPECT_EQ(shadowProjection(wideSpot, bounds)->kind, ShadowMapKind::Cube);
}

}  // namespace
}  // namespace glint
