// The CPU reference renderer against the radiometry worked by hand: a Lambert sphere (ρ = 0.5)
// under a directional light of irradiance π W/m² seen along the light has L = ρ/π·π·n_z = 0.5·n_z.
#include <gtest/gtest.h>

#include "display/display_chain.h"
#include "geometry/mesh.h"
#include "render/reference_renderer.h"
#include "test_support.h"

namespace glint {
namespace {

TEST(ReferenceRenderer, LambertSunRadianceIsHalfNz) {
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    const RadianceImage image = renderReference(scene);
    ASSERT_EQ(image.width, 256);
    // The centre pixel is (127.5 + 0.5 …): the pixel whose centre is nearest the sphere's apex.
    EXPECT_NEAR(image.at(128, 128).g, 0.5f, 1e-3f);
    const float pixelSize = 2.2f / 256.0f;
    int checked = 0;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const float px = -1.1f + (x + 0.5f) * pixelSize, py = 1.1f - (y + 0.5f) * pixelSize;
            const float r2 = px * px + py * py;
            if (r2 > 0.95f * 0.95f) continue;  // well inside the disc
            const float nz = std::sqrt(1.0f - r2);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], 0.5f * nz, 1e-4f) << x << "," << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 38000);
    EXPECT_EQ(image.at(2, 2), glm::vec3(0.0f)) << "black background";
}

TEST(ReferenceRenderer, PointLightFollowsTheInverseSquareLaw) {
    Scene scene;
    scene.materials = {Material::withDefaults("white", BrdfModel::Lambert)};
    scene.materials[0].analytic()->values = {1, 1, 1};
    scene.objects.push_back({"floor", PlaneShape{{0, 0, 0}, {0, 1, 0}, {100, 100}}, 0});
    Light bulb;
    bulb.type = LightType::Point;
    bulb.power = 4.0f * kPi * 10.0f;  // intensity 10 W/sr
    bulb.position = {0, 2, 0};
    scene.lights = {bulb};
    const Ray down{{0, 1, 0}, {0, -1, 0}};
    const auto hit = intersectScene(scene, down);
    ASSERT_TRUE(hit.has_value());
    // E = I/d² · cos θ = 10/4 · 1; L = ρ/π · E.
    EXPECT_NEAR(shadeHit(scene, *hit, {0, 1, 0}).r, 2.5f / kPi, 1e-5f);
    const Ray slanted{{2, 1, 0}, {0, -1, 0}};
    const auto offAxis = intersectScene(scene, slanted);
    ASSERT_TRUE(offAxis.has_value());
    // d² = 8, cos θ = 2/√8.
    EXPECT_NEAR(shadeHit(scene, *offAxis, {0, 1, 0}).r, 10.0f / 8.0f * (2.0f / std::sqrt(8.0f)) / kPi, 1e-5f);
}

TEST(ReferenceRenderer, DisabledLightsAndLightsBehindAddNothing) {
    Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    scene.lights[0].enabled = false;
    EXPECT_EQ(renderReference(scene, 16, 16).at(8, 8), glm::vec3(0.0f));
    scene.lights[0].enabled = true;
    scene.lights[0].direction = {0, 0, 1};  // shining from behind the sphere
    EXPECT_EQ(renderReference(scene, 16, 16).at(8, 8), glm::vec3(0.0f));
}

TEST(ReferenceRenderer, SurfaceTangentIsTheMeshTangent) {
    // Sphere: the direction of increasing u, as makeUvSphere's vertex tangent, away from the poles.
    const SphereShape sphere{{0.5f, -1.0f, 2.0f}, 2.0f};
    const Mesh mesh = makeUvSphere(sphere.center, sphere.radius, 16, 8);
    int checked = 0;
    for (const Vertex& vertex : mesh.vertices) {
        if (std::abs(vertex.normal.y) > 0.999f) continue;
        const glm::vec3 tangent = surfaceTangent(sphere, vertex.normal);
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(tangent[c], vertex.tangent[c], 1e-5f);
        ++checked;
    }
    EXPECT_GT(checked, 100);
    // Poles: the u = 0 meridian's tangent, the same fallback as sphereTangent() in surface.frag.
    EXPECT_EQ(surfaceTangent(sphere, {0, 1, 0}), glm::vec3(0, 0, -1));
    EXPECT_EQ(surfaceTangent(sphere, {0, -1, 0}), glm::vec3(0, 0, -1));
    // Plane: its mesh tangent.
    const PlaneShape plane{{0, -1, 0}, {0.3f, 1.0f, 0.2f}, {4, 4}};
    const Mesh planeMesh = makePlane(plane.center, plane.normal, plane.size);
    const glm::vec3 tangent = surfaceTangent(plane, glm::normalize(plane.normal));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tangent[c], planeMesh.vertices[0].tangent[c], 1e-6f);
    // The hit carries it, unchanged by the two-sided flip of the normal.
    Scene scene;
    scene.materials = {Material::withDefaults("m", BrdfModel::Lambert)};
    scene.objects.push_back({"ball", sphere, 0});
    const auto hit = intersectScene(scene, {{0.5f, -1.0f, 10.0f}, {0, 0, -1}});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(glm::length(hit->tangent - glm::vec3(1, 0, 0)), 0.0f, 1e-5f) << "at +z the tangent is (+y) × z = +x";
}

TEST(DisplayChain, SrgbAndGammaAndExposure) {
    DisplaySettings display;
    EXPECT_EQ(quantize8(encodeForDisplay(0.0f, display)), 0);
    EXPECT_EQ(quantize8(encodeForDisplay(1.0f, display)), 255);
    EXPECT_EQ(quantize8(encodeForDisplay(0.5f, display)), 188);  // sRGB(0.5) = 0.7354
    EXPECT_EQ(quantize8(encodeForDisplay(7.0f, display)), 255);  // clamped
    display.exposureStops = -1.0f;
    EXPECT_EQ(quantize8(encodeForDisplay(1.0f, display)), 188);
    display = {0.0f, Transfer::Gamma, 2.2f};
    EXPECT_EQ(quantize8(encodeForDisplay(0.5f, display)), 186);  // 0.5^(1/2.2) = 0.7297
    // Tone curves: Reinhard maps 1 to 1/2; the ACES fit maps 1 to 2.54/3.16 = 0.8038; both stay
    // below 1 for bright values where "none" clips.
    EXPECT_FLOAT_EQ(applyToneMap(1.0f, ToneMap::Reinhard), 0.5f);
    EXPECT_NEAR(applyToneMap(1.0f, ToneMap::AcesFilmic), 2.54f / 3.16f, 1e-6f);
    EXPECT_LT(applyToneMap(50.0f, ToneMap::Reinhard), 1.0f);
    EXPECT_FLOAT_EQ(applyToneMap(7.0f, ToneMap::None), 7.0f);
    display = {0.0f, Transfer::Srgb, 2.2f, ToneMap::Reinhard};
    EXPECT_EQ(quantize8(encodeForDisplay(1.0f, display)), 188);  // sRGB(0.5)
}

TEST(DisplayChain, PbrNeutralKeepsHueAndCompressesOnlyHighlights) {
    // Below the compression start (0.76) it only subtracts the black offset, 0.04 once the
    // darkest channel reaches 0.08: the colour's hue and differences survive unchanged.
    const glm::vec3 dim = applyToneMap(glm::vec3(0.5f, 0.1f, 0.1f), ToneMap::PbrNeutral);
    EXPECT_NEAR(glm::length(dim - glm::vec3(0.46f, 0.06f, 0.06f)), 0.0f, 1e-6f);
    // White 1 → 0.96 after the offset, compressed to 1 − 0.24²/(0.96 + 0.24 − 0.76) = 0.86909.
    EXPECT_NEAR(applyToneMap(1.0f, ToneMap::PbrNeutral), 1.0f - 0.0576f / 0.44f, 1e-6f);
    EXPECT_LT(applyToneMap(1000.0f, ToneMap::PbrNeutral), 1.0f);
    // A bright saturated red stays red (the per-channel ACES curve pushes its green and blue up
    // towards its red far more).
    const glm::vec3 red = applyToneMap(glm::vec3(4.0f, 0.3f, 0.3f), ToneMap::PbrNeutral);
    const glm::vec3 aces = applyToneMap(glm::vec3(4.0f, 0.3f, 0.3f), ToneMap::AcesFilmic);
    EXPECT_GT(red.r - red.g, aces.r - aces.g);
    EXPECT_FLOAT_EQ(red.g, red.b);
}

}  // namespace
}  // namespace glint
