// Lights, ambient, backgrounds, mirror and glass on the GPU (OSMesa) against the CPU reference,
// pixel by pixel on linear float output (silhouettes excluded), plus linearity in the lights and
// the ambient white-out of a Lambert sphere.
#include <gtest/gtest.h>

#include "brdf/glass.h"
#include "render/specular_transport.h"
#include "gpu_test_support.h"
#include "test_support.h"

namespace glint {
namespace {

using test::renderGpu;

void expectAgreement(const Scene& scene, int width, int height, long minimumCompared) {
    const RadianceImage gpu = renderGpu(scene, width, height);
    const auto agreement = test::compareWithReference(scene, gpu);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative "
                                        << agreement.worstRelative << ")";
    EXPECT_GT(agreement.compared, minimumCompared);
}

Light ambientLight(float radiance, glm::vec3 color) {
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambientRadiance = radiance;
    ambient.color = color;
    return ambient;
}

Background skyBackground() {
    Background sky;
    sky.kind = BackgroundKind::Sky;
    return sky;
}

TEST(GpuLights, SpotLightsMatchTheCpuReference) {
    expectAgreement(test::loadTestScene("scenes/spot_light.json"), 256, 192, 40000);
}

TEST(GpuLights, AmbientLightMatchesTheCpuReference) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    scene.lights.push_back(ambientLight(0.3f, {0.8f, 0.9f, 1.0f}));
    expectAgreement(scene, 128, 96, 9000);
}

TEST(GpuLights, ClassicAttenuationMatchesTheCpuReference) {
    Scene scene = test::loadTestScene("scenes/spot_light.json");
    for (Light& light : scene.lights) light.attenuation = {true, {0.5f, 0.3f, 0.1f}};
    expectAgreement(scene, 128, 96, 9000);
}

// `count` lights, of every delta type in turn, around a Blinn-Phong sphere.
Scene manyLights(int count) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    scene.lights.clear();
    for (int i = 0; i < count; ++i) {
        const float angle = 2.0f * kPi * i / count;
        Light light;
        light.type = static_cast<LightType>(i % 3);
        light.name = "light " + std::to_string(i);
        light.color = {0.5f + 0.5f * std::cos(angle), 0.6f, 0.5f + 0.5f * std::sin(angle)};
        light.position = {2.5f * std::cos(angle), 1.0f + 0.5f * (i % 4), 2.5f * std::sin(angle)};
        light.direction = glm::normalize(-light.position);
        light.irradiance = 4.0f / count;
        light.power = 600.0f / count;
        light.coneHalfAngleDegrees = 25.0f;
        scene.lights.push_back(light);
    }
    return scene;
}

// One light to as many as the LightBlock holds.
TEST(GpuLights, OneToTheMaximumLightCountMatchTheCpuReference) {
    for (const int count : {1, 8, 16, 64, kMaxLights}) {
        SCOPED_TRACE(std::to_string(count) + " lights");
        expectAgreement(manyLights(count), 128, 96, 9000);
    }
}

TEST(GpuLights, RadianceIsLinearInTheLights) {
    Scene both = test::loadTestScene("scenes/spot_light.json");
    both.lights.resize(2);  // the two spots
    both.background.color = glm::vec3(0.0f);
    Scene first = both, second = both;
    first.lights = {both.lights[0]};
    second.lights = {both.lights[1]};
    const RadianceImage sum = renderGpu(both, 128, 96);
    const RadianceImage a = renderGpu(first, 128, 96), b = renderGpu(second, 128, 96);
    float worst = 0.0f, brightest = 0.0f;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 128; ++x)
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(sum.at(x, y)[c] - a.at(x, y)[c] - b.at(x, y)[c]));
                brightest = std::max(brightest, sum.at(x, y)[c]);
            }
    EXPECT_GT(brightest, 0.1f);
    EXPECT_LE(worst, 1e-5f * brightest) << "L(A + B) = L(A) + L(B)";
}

TEST(GpuLights, AmbientAloneWhitesOutALambertSphere) {
    // The lecture's white-out: under uniform radiance L_a alone a Lambert sphere reflects ρ·L_a
    // everywhere, with no shading left to show its shape.
    Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    const Light ambient = ambientLight(0.8f, {1.0f, 0.5f, 0.25f});
    scene.lights = {ambient};
    scene.msaaSamples = 1;  // every pixel of the sphere is checked, its silhouette's too
    const glm::vec3 albedo{scene.materials[0].analytic()->values[0], scene.materials[0].analytic()->values[1], scene.materials[0].analytic()->values[2]};
    const RadianceImage gpu = renderGpu(scene, 64, 64);
    const RadianceImage cpu = renderReference(scene, 64, 64);
    long onSphere = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            if (!intersectScene(scene, primaryRay(glm::inverse(scene.camera.viewProjection(1.0f)), x + 0.5f, y + 0.5f, 64, 64))) continue;
            ++onSphere;
            for (int c = 0; c < 3; ++c) {
                ASSERT_NEAR(gpu.at(x, y)[c], albedo[c] * 0.8f * ambient.color[c], 1e-6f) << x << "," << y;
                ASSERT_NEAR(cpu.at(x, y)[c], albedo[c] * 0.8f * ambient.color[c], 1e-6f) << x << "," << y;
            }
        }
    EXPECT_GT(onSphere, 2000);
}

TEST(GpuBackground, SkyGradientMatchesTheCpuReference) {
    Scene scene = test::loadTestScene("scenes/blinn_point.json");
    scene.background = skyBackground();
    expectAgreement(scene, 128, 96, 9000);
    // Every background pixel, too: the sky is evaluated per primary ray on both sides.
    const RadianceImage gpu = renderGpu(scene, 128, 96);
    EXPECT_GT(gpu.at(64, 1).b, gpu.at(64, 1).r) << "blue towards the zenith at the top";
}

TEST(GpuSpecular, MirrorAndGlassSpheresMatchTheCpuReferenceUnderTheSky) {
    expectAgreement(test::loadTestScene("scenes/glass_sphere.json"), 256, 192, 40000);
}

TEST(GpuSpecular, MirrorAndGlassSpheresMatchTheCpuReferenceUnderAConstantBackground) {
    Scene scene = test::loadTestScene("scenes/glass_sphere.json");
    scene.background = Background{BackgroundKind::Constant, {0.3f, 0.5f, 0.7f}};
    expectAgreement(scene, 128, 96, 9000);
}

TEST(GpuSpecular, ClassicTransparencyAndAThinPaneMatchTheCpuReference) {
    Scene scene = test::loadTestScene("scenes/glass_sphere.json");
    scene.materials[0].analytic()->values[4] = static_cast<float>(GlassTransparency::Classic);
    scene.materials[0].analytic()->values[5] = 0.6f;
    scene.objects.push_back({"pane", PlaneShape{{0, -0.8f, 0}, glm::normalize(glm::vec3(0, 1, 0.3f)), {4, 2}}, 0});
    expectAgreement(scene, 128, 96, 9000);
}

TEST(GpuSpecular, TotalInternalReflectionInsideAGlassSphere) {
    const Scene scene = test::loadTestScene("scenes/inside_glass.json");
    const RadianceImage gpu = renderGpu(scene, 128, 96);
    // The edge of the totally reflected region is an optical silhouette: there F rises to 1 with
    // an infinite slope in the angle, so one ulp of direction is a visible change. Excluded like
    // the geometric silhouettes: pixels whose 3×3 neighbourhood straddles it on the CPU.
    const RadianceImage cpu = renderReference(scene, 128, 96);
    std::vector<bool> criticalEdge(128 * 96, false);
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 128; ++x)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = std::clamp(x + dx, 0, 127), ny = std::clamp(y + dy, 0, 95);
                    criticalEdge[y * 128 + x] = criticalEdge[y * 128 + x] ||
                                                ((cpu.at(nx, ny).r == 0.0f) != (cpu.at(x, y).r == 0.0f));
                }
    const auto agreement = test::compareWithReference(scene, gpu, 1e-3f, 1e-5f, criticalEdge);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 128 * 96 * 9 / 10);
    // Beyond the critical angle no light leaves the sphere: a black region (Snell's window edge).
    long black = 0, lit = 0;
    for (const float value : gpu.pixels) (value == 0.0f ? black : lit)++;
    EXPECT_GT(black, 3 * 128 * 96 / 4 / 3) << "total internal reflection covers part of the view";
    EXPECT_GT(lit, 3 * 128 * 96 / 4) << "the window through the water";
}

}  // namespace
}  // namespace glint
