// Shadows on the GPU (OSMesa) against the CPU reference's shadow rays: a sphere over a plane under
// a directional, a spot and a point light, compared per pixel outside silhouettes and penumbrae;
// the umbra equals the ambient-only picture exactly; linearity; a golden; and the shadow maps are
// re-rendered only when shadowed lights or geometry change.
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test_support.h"
#include "render/shadow_rays.h"
#include "test_support.h"

namespace glint {
namespace {

constexpr int kWidth = 160, kHeight = 120;

RadianceImage renderGpu(const Scene& scene) {
    auto images = test::sharedHeadless().render(scene, kWidth, kHeight);
    EXPECT_TRUE(images.ok()) << images.error().format();
    return images.ok() ? images->radiance : RadianceImage(kWidth, kHeight);
}

// The shadows scene with only light `index` (and no ambient when `withAmbient` is false) on.
Scene sceneWithLight(int index, bool withAmbient = true) {
    Scene scene = test::loadTestScene("scenes/shadows.json");
    for (int i = 0; i < static_cast<int>(scene.lights.size()); ++i) {
        const bool ambient = scene.lights[i].type == LightType::Ambient;
        scene.lights[i].enabled = ambient ? withAmbient : i == index;
    }
    return scene;
}

// Per pixel, which lights reach the primary hit (cos θ > 0, inside a spot's cone, CPU shadow ray):
// one bit per light; −1 for the background.
std::vector<int> cpuLitMask(const Scene& scene) {
    const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(static_cast<float>(kWidth) / kHeight));
    std::vector<int> mask(static_cast<size_t>(kWidth) * kHeight, -1);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const auto hit = intersectScene(scene, primaryRay(inverse, x + 0.5f, y + 0.5f, kWidth, kHeight));
            if (!hit) continue;
            int bits = 0;
            for (size_t i = 0; i < scene.lights.size(); ++i) {
                const Light& light = scene.lights[i];
                if (!light.enabled || light.type == LightType::Ambient) continue;
                const LightArrival arrival = lightArrival(light, hit->position);
                const bool reaches = glm::dot(arrival.towardsLight, hit->normal) > 0.0f &&
                                     std::max({arrival.normalIrradiance.r, arrival.normalIrradiance.g, arrival.normalIrradiance.b}) > 0.0f;  // spot: inside the cone
                if (reaches && lightVisibility(scene, light, *hit, arrival) > 0.0f)
                    bits |= 1 << i;
            }
            mask[y * kWidth + x] = bits;
        }
    return mask;
}

// The penumbra band: pixels whose 5×5 neighbourhood does not agree on which lights reach it.
// The GPU's PCF kernel (radius 1.5 texels, bilinear taps) and its biases (depth 1, normal 3
// texels) move and blur the shadow edge by a few shadow-map texels, under 0.5 cm here, less than
// a pixel (about 3 cm at this size); two pixels on each side cover it, and the terminator on
// the sphere (cos θ = 0, where the map sees the sphere shadow itself) with it.
std::vector<bool> penumbraBand(const std::vector<int>& litMask) {
    std::vector<bool> band(litMask.size(), false);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int nx = std::clamp(x + dx, 0, kWidth - 1), ny = std::clamp(y + dy, 0, kHeight - 1);
                    band[y * kWidth + x] = band[y * kWidth + x] || litMask[ny * kWidth + nx] != litMask[y * kWidth + x];
                }
    return band;
}

void expectShadowedAgreement(const Scene& scene) {
    const auto band = penumbraBand(cpuLitMask(scene));
    const auto agreement = test::compareWithReference(scene, renderGpu(scene), 1e-3f, 1e-5f, band);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative " << agreement.worstRelative << ")";
    EXPECT_GT(agreement.compared, kWidth * kHeight * 3 / 4);
}

TEST(GpuShadows, DirectionalLightMatchesTheCpuShadowRays) { expectShadowedAgreement(sceneWithLight(0)); }
TEST(GpuShadows, SpotLightMatchesTheCpuShadowRays) { expectShadowedAgreement(sceneWithLight(1)); }
TEST(GpuShadows, PointLightMatchesTheCpuShadowRays) { expectShadowedAgreement(sceneWithLight(2)); }
TEST(GpuShadows, ThreeShadowedLightsTogetherMatchTheCpuShadowRays) {
    expectShadowedAgreement(test::loadTestScene("scenes/shadows.json"));
}

// A wide spot (cone over 80°) is shadowed through a cube map, as a point light.
TEST(GpuShadows, WideSpotLightUsesACubeMapAndMatches) {
    Scene scene = sceneWithLight(1);
    scene.lights[1].coneHalfAngleDegrees = 85.0f;
    expectShadowedAgreement(scene);
}

// In the umbra of the only light, the floor shows exactly what the ambient light alone gives, on
// the GPU and on the CPU.
TEST(GpuShadows, UmbraOnTheFloorEqualsTheAmbientOnlyPicture) {
    for (int light = 0; light < 3; ++light) {
        SCOPED_TRACE(light);
        const Scene scene = sceneWithLight(light);
        Scene ambientOnly = scene;
        ambientOnly.lights[light].enabled = false;
        const RadianceImage gpu = renderGpu(scene), gpuAmbient = renderGpu(ambientOnly);
        const RadianceImage cpu = renderReference(scene, kWidth, kHeight);
        const RadianceImage cpuAmbient = renderReference(ambientOnly, kWidth, kHeight);
        const std::vector<int> lit = cpuLitMask(scene);
        const auto band = penumbraBand(lit);
        const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(static_cast<float>(kWidth) / kHeight));
        int umbraPixels = 0, litFloorPixels = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const auto hit = intersectScene(scene, primaryRay(inverse, x + 0.5f, y + 0.5f, kWidth, kHeight));
                if (!hit || hit->objectIndex != 1 || band[y * kWidth + x]) continue;  // the floor, away from edges
                if (lit[y * kWidth + x] != 0) {
                    ++litFloorPixels;
                    EXPECT_GT(gpu.at(x, y).g, gpuAmbient.at(x, y).g) << x << "," << y;
                    continue;
                }
                ++umbraPixels;
                ASSERT_EQ(gpu.at(x, y), gpuAmbient.at(x, y)) << "GPU umbra at " << x << "," << y;
                ASSERT_EQ(cpu.at(x, y), cpuAmbient.at(x, y)) << "CPU umbra at " << x << "," << y;
            }
        EXPECT_GT(umbraPixels, 200);
        EXPECT_GT(litFloorPixels, 2000);
    }
}

// L(A + B + C) = L(A) + L(B) + L(C) with every light shadowed (no ambient, black background).
TEST(GpuShadows, RadianceStaysLinearInShadowedLights) {
    Scene all = test::loadTestScene("scenes/shadows.json");
    all.lights.resize(3);
    all.background.color = glm::vec3(0.0f);
    RadianceImage sum = renderGpu(all);
    float worst = 0.0f, brightest = 0.0f;
    std::vector<RadianceImage> parts;
    for (int light = 0; light < 3; ++light) {
        Scene alone = sceneWithLight(light, false);
        alone.background.color = glm::vec3(0.0f);
        parts.push_back(renderGpu(alone));
    }
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c) {
                const float parted = parts[0].at(x, y)[c] + parts[1].at(x, y)[c] + parts[2].at(x, y)[c];
                worst = std::max(worst, std::abs(sum.at(x, y)[c] - parted));
                brightest = std::max(brightest, sum.at(x, y)[c]);
            }
    EXPECT_GT(brightest, 0.1f);
    EXPECT_LE(worst, 1e-5f * brightest) << "L(A + B + C) = L(A) + L(B) + L(C)";
}

// Turning shadows off gives back the unshadowed picture, which differs in the shadow.
TEST(GpuShadows, CastsShadowsOffRemovesTheShadow) {
    Scene shadowed = sceneWithLight(0);
    Scene unshadowed = shadowed;
    unshadowed.lights[0].castsShadows = false;
    const RadianceImage withShadow = renderGpu(shadowed), without = renderGpu(unshadowed);
    int darker = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) darker += withShadow.at(x, y).g < 0.5f * without.at(x, y).g;
    EXPECT_GT(darker, 200);
    const auto agreement = test::compareWithReference(unshadowed, without);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
}

// The maps are drawn again only when a shadowed light or an object changes, not for the camera,
// materials, biases or filter (which are read when the maps are sampled).
TEST(GpuShadows, MapsAreRenderedOnlyWhenLightsOrGeometryChange) {
    Renderer& renderer = test::sharedHeadless().renderer();
    Scene scene = test::loadTestScene("scenes/shadows.json");
    (void)renderGpu(scene);
    const long long first = renderer.shadowMapRenders();
    (void)renderGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first);
    scene.camera.position.x += 0.5f;
    scene.materials[1].values[0] = 0.3f;
    scene.lights[0].shadow.filterRadius = 3.0f;
    scene.lights[1].shadow.depthBias = 2.0f;
    (void)renderGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first);
    scene.lights[2].position.y += 0.1f;
    (void)renderGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 1);
    std::get<SphereShape>(scene.objects[0].shape).radius = 0.6f;
    (void)renderGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 2);
    scene.lights[0].shadow.mapResolution = 512;
    (void)renderGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 3);
}

}  // namespace
}  // namespace glint
