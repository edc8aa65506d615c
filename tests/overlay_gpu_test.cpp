// Wireframe and normals overlays, headless: they change the displayed (8-bit) image in the
// overlay colours, never the radiance image; back faces and hidden edges stay hidden; the
// settings survive a save and a load, and nonsense is refused with its location.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gpu_test_support.h"
#include "scene/scene_json.h"
#include "test_support.h"

namespace glint {
namespace {

constexpr int kOverlayImageSize = 128;

// A lone default sphere, filling most of the picture.
Scene sphereScene() {
    Scene scene = defaultScene();
    scene.objects.resize(1);
    return scene;
}

RenderedImages render(const Scene& scene) {
    auto images = test::sharedHeadless().render(scene, kOverlayImageSize, kOverlayImageSize);
    EXPECT_TRUE(images.ok()) << images.error().format();
    return std::move(*images);
}

// Pixels whose display value is (nearly) the given 8-bit colour.
int pixelsOfColor(const DisplayImage& image, int r, int g, int b) {
    int count = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 3)
        count += std::abs(image.pixels[i] - r) <= 2 && std::abs(image.pixels[i + 1] - g) <= 2 &&
                 std::abs(image.pixels[i + 2] - b) <= 2;
    return count;
}

TEST(Overlays, WireframeAndNormalsChangeTheDisplayNotTheRadiance) {
    Scene scene = sphereScene();
    const RenderedImages plain = render(scene);
    scene.display.overlays.wireframe = true;
    const RenderedImages wireframe = render(scene);
    scene.display.overlays = {.wireframe = false, .normals = true};
    const RenderedImages normals = render(scene);

    EXPECT_EQ(plain.radiance.pixels, wireframe.radiance.pixels);
    EXPECT_EQ(plain.radiance.pixels, normals.radiance.pixels);
    // Orange edges (1, 0.62, 0.1) and cyan normals (0.25, 0.85, 1) as 8-bit display values.
    const int orange = pixelsOfColor(wireframe.display, 255, 158, 26);
    const int cyan = pixelsOfColor(normals.display, 64, 217, 255);
    EXPECT_EQ(pixelsOfColor(plain.display, 255, 158, 26), 0);
    EXPECT_GT(orange, kOverlayImageSize * kOverlayImageSize / 20) << "the sphere's tessellation should show";
    EXPECT_GT(cyan, 50);
    EXPECT_EQ(pixelsOfColor(wireframe.display, 64, 217, 255), 0);
}

TEST(Overlays, HiddenEdgesStayHidden) {
    // A plane far behind the sphere: where the sphere covers it, its edges are not drawn.
    Scene scene = sphereScene();
    scene.display.overlays.wireframe = true;
    const RenderedImages sphereOnly = render(scene);
    scene.objects.push_back({"wall", PlaneShape{.center = {0, 0, -3}, .normal = {0, 0, 1}, .size = {0.5f, 0.5f}}, 0});
    const RenderedImages withHiddenWall = render(scene);
    EXPECT_EQ(pixelsOfColor(sphereOnly.display, 255, 158, 26), pixelsOfColor(withHiddenWall.display, 255, 158, 26));
    // The same wall in front of the sphere shows its two triangles' edges.
    scene.objects.back().shape = PlaneShape{.center = {0, 0, 1.5f}, .normal = {0, 0, 1}, .size = {0.5f, 0.5f}};
    const RenderedImages withWallInFront = render(scene);
    EXPECT_NE(withWallInFront.display.pixels, sphereOnly.display.pixels);
}

TEST(Overlays, SettingsRoundTripThroughTheSceneFile) {
    Scene scene = sphereScene();
    scene.display.overlays = {.wireframe = true, .normals = true, .normalLength = 0.25f};
    auto loaded = parseScene(sceneToJson(scene).dump(2), "overlays.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().format();
    EXPECT_TRUE(loaded->display.overlays.wireframe);
    EXPECT_TRUE(loaded->display.overlays.normals);
    EXPECT_FLOAT_EQ(loaded->display.overlays.normalLength, 0.25f);
}

TEST(Overlays, NonPositiveNormalLengthIsRefusedWithItsLocation) {
    nlohmann::json json = sceneToJson(sphereScene());
    json["display"]["overlays"] = {{"normal_length", 0}};
    auto loaded = parseScene(json.dump(2), "bad_overlays.json");
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().format().find("bad_overlays.json:"), std::string::npos) << loaded.error().format();
    EXPECT_NE(loaded.error().format().find("normal_length"), std::string::npos) << loaded.error().format();
}

}  // namespace
}  // namespace glint
