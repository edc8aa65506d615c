// Shadows on the GPU (OSMesa) against the CPU reference's shadow rays: a sphere over a plane under
// a directional, a spot and a point light, compared per pixel outside silhouettes and penumbrae;
// the umbra equals the ambient-only picture exactly; linearity; a golden; and the shadow maps are
// re-rendered only when shadowed lights or geometry change.
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test_support.h"
#include "math/constants.h"
#include "render/shadow_projection.h"
#include "render/shadow_rays.h"
#include "test_support.h"

namespace glint {
namespace {

constexpr int kWidth = 160, kHeight = 120;

// The shadows scene's images are kWidth×kHeight unless a test says otherwise.
RadianceImage renderShadowsGpu(const Scene& scene, int width = kWidth, int height = kHeight) {
    return test::renderGpu(scene, width, height);
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

// World size [m] of one texel of `light`'s shadow map at `point`: the formula of shadows.glsl.
float texelWorldSize(const Scene& scene, const Light& light, glm::vec3 point) {
    const ShadowProjection projection = *shadowProjection(light, sceneBounds(scene));
    const float resolution = static_cast<float>(light.shadow.mapResolution);
    const glm::vec3 fromLight = point - projection.lightPosition;
    switch (projection.kind) {
        case ShadowMapKind::Orthographic: return projection.sideScale / resolution;
        case ShadowMapKind::Perspective:
            return projection.sideScale * glm::dot(fromLight, glm::normalize(light.direction)) / resolution;
        case ShadowMapKind::Cube: break;
    }
    const glm::vec3 magnitude = glm::abs(fromLight);
    return projection.sideScale * std::max({magnitude.x, magnitude.y, magnitude.z}) / resolution;
}

// Whether `light` reaches `hit`: cos θ > 0, inside a spot's cone, and the CPU shadow ray is free.
bool reaches(const Scene& scene, const Light& light, const SurfaceHit& hit) {
    const LightArrival arrival = lightArrival(light, hit.position);
    const glm::vec3& irradiance = arrival.normalIrradiance;
    return glm::dot(arrival.towardsLight, hit.normal) > 0.0f && std::max({irradiance.r, irradiance.g, irradiance.b}) > 0.0f &&
           lightVisibility(scene, light, hit, arrival) > 0.0f;
}

// Per pixel: which lights reach the primary hit (one bit per light; −1 for the background), and
// whether a shadow edge lies within the GPU's filter footprint of it: the CPU shadow rays from 8
// points on a ring around the hit, in its tangent plane, disagree with the centre's. The ring's
// radius is what moves or blurs the GPU's edge: the PCF radius, plus one texel for the bilinear
// taps, plus the normal offset and depth bias, in shadow-map texels at the point, stretched by
// 1/cos θ where the light grazes the surface.
struct LitMask {
    std::vector<int> lights;
    std::vector<bool> nearShadowEdge;
};

LitMask cpuLitMask(const Scene& scene, int width, int height) {
    const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(static_cast<float>(width) / height));
    LitMask mask{std::vector<int>(static_cast<size_t>(width) * height, -1), std::vector<bool>(static_cast<size_t>(width) * height)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto hit = intersectScene(scene, primaryRay(inverse, x + 0.5f, y + 0.5f, width, height));
            if (!hit) continue;
            int bits = 0;
            bool nearEdge = false;
            const glm::vec3 bitangent = glm::cross(hit->normal, hit->tangent);
            for (size_t i = 0; i < scene.lights.size(); ++i) {
                const Light& light = scene.lights[i];
                if (!light.enabled || light.type == LightType::Ambient) continue;
                const bool centre = reaches(scene, light, *hit);
                bits |= centre ? 1 << i : 0;
                if (!light.castsShadows) continue;
                const ShadowSettings& settings = light.shadow;
                const float cosTheta = std::abs(glm::dot(lightArrival(light, hit->position).towardsLight, hit->normal));
                const float ringRadius = (settings.filterRadius + 1.0f + settings.normalOffset + settings.depthBias) *
                                         texelWorldSize(scene, light, hit->position) / std::max(cosTheta, 0.25f);
                for (int k = 0; k < 8 && !nearEdge; ++k) {
                    const float angle = k * kPi / 4.0f;
                    SurfaceHit moved = *hit;
                    moved.position += ringRadius * (std::cos(angle) * hit->tangent + std::sin(angle) * bitangent);
                    nearEdge = reaches(scene, light, moved) != centre;
                }
            }
            mask.lights[y * width + x] = bits;
            mask.nearShadowEdge[y * width + x] = nearEdge;
        }
    return mask;
}

// The pixels left out of the per-pixel comparison: a shadow edge within the filter footprint
// (above), or a 5×5 pixel neighbourhood that does not agree on which lights reach it (the
// terminator on the sphere, where the map sees the sphere shadow itself; a spot's cone edge;
// where a shadow edge meets a silhouette).
std::vector<bool> penumbraBand(const LitMask& mask, int width, int height) {
    std::vector<bool> band = mask.nearShadowEdge;
    const std::vector<int>& lights = mask.lights;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
                    band[y * width + x] = band[y * width + x] || lights[ny * width + nx] != lights[y * width + x];
                }
    return band;
}

void expectShadowedAgreement(const Scene& scene, int width = kWidth, int height = kHeight) {
    const auto band = penumbraBand(cpuLitMask(scene, width, height), width, height);
    const auto agreement = test::compareWithReference(scene, renderShadowsGpu(scene, width, height), 1e-3f, 1e-5f, band);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative " << agreement.worstRelative << ")";
    EXPECT_GT(agreement.compared, width * height * 3 / 4);
}

TEST(GpuShadows, DirectionalLightMatchesTheCpuShadowRays) { expectShadowedAgreement(sceneWithLight(0)); }
TEST(GpuShadows, SpotLightMatchesTheCpuShadowRays) { expectShadowedAgreement(sceneWithLight(1)); }
TEST(GpuShadows, PointLightMatchesTheCpuShadowRays) { expectShadowedAgreement(sceneWithLight(2)); }
TEST(GpuShadows, ThreeShadowedLightsTogetherMatchTheCpuShadowRays) {
    expectShadowedAgreement(test::loadTestScene("scenes/shadows.json"));
}

// A mesh object placed away from the origin and scaled (its vertices are in the unit sphere,
// placed by center and scale) casts its shadow where it stands, under all three light kinds; the
// torus is closed, so its back faces are culled in the maps and in the picture.
TEST(GpuShadows, PlacedMeshCastsItsShadowWhereItStands) {
    Scene scene = test::loadTestScene("scenes/shadows.json");
    MeshShape torus;
    torus.mesh = std::make_shared<const Mesh>(makeTorus({0, 0, 0}, 0.7f, 0.3f, 48, 24));
    torus.center = {0.4f, 0.2f, -0.3f};
    torus.scale = 0.8f;
    scene.objects[0].shape = torus;
    scene.objects[0].interpolation = SurfaceInterpolation::Phong;
    scene.msaaSamples = 1;  // per pixel against the CPU reference, which has no anti-aliasing (the torus's own triangle edges)
    expectShadowedAgreement(scene);
}

// The default scene with its key light's shadow on (default settings): no acne on the lit sphere
// or floor and no gap at the contact, or those pixels would disagree with the shadow rays.
TEST(GpuShadows, DefaultSceneMatchesTheCpuShadowRays) {
    Scene scene = defaultScene();  // its key light casts a shadow
    scene.environment = Environment{};  // compared on its own (environment_gpu_test.cpp)
    expectShadowedAgreement(scene, 320, 240);
}

// The sphere's shadow has its true round silhouette, not the proxy mesh's (which circumscribes
// the sphere and is up to 2.1% wider): under a sun straight above with a fine map, no filter
// and no normal offset (the footprint shrinks to 2 texels, 1.5 mm), every floor pixel away from
// that footprint matches the shadow rays, including pixels in the ring between r and 1.03·r
// around the sphere's axis, where a shadow of the proxy would fall.
TEST(GpuShadows, SphereCastsItsTrueSilhouette) {
    constexpr int width = 256, height = 192;
    Scene scene = sceneWithLight(0);
    scene.lights[0].direction = {0.0f, -1.0f, 0.0f};
    scene.lights[0].shadow = {4096, 1.0f, 0.0f, 0.0f};
    const auto& sphere = std::get<SphereShape>(scene.objects[0].shape);
    const RadianceImage gpu = renderShadowsGpu(scene, width, height);
    const RadianceImage cpu = renderReference(scene, width, height);
    const LitMask mask = cpuLitMask(scene, width, height);
    const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(static_cast<float>(width) / height));
    int comparedInRing = 0, disagreeing = 0;
    for (int y = 1; y < height - 1; ++y)
        for (int x = 1; x < width - 1; ++x) {
            bool onFloorOnly = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const auto hit = intersectScene(scene, primaryRay(inverse, x + dx + 0.5f, y + dy + 0.5f, width, height));
                    onFloorOnly = onFloorOnly && hit && hit->objectIndex == 1;
                }
            if (!onFloorOnly || mask.nearShadowEdge[y * width + x]) continue;
            const auto hit = intersectScene(scene, primaryRay(inverse, x + 0.5f, y + 0.5f, width, height));
            const glm::vec2 offAxis(hit->position.x - sphere.center.x, hit->position.z - sphere.center.z);
            const float distance = glm::length(offAxis) / sphere.radius;
            comparedInRing += distance > 1.0f && distance < 1.03f;
            if (std::abs(gpu.at(x, y).g - cpu.at(x, y).g) > 1e-3f * cpu.at(x, y).g) {
                if (disagreeing++ == 0) ADD_FAILURE() << "floor pixel " << x << "," << y << " at " << distance << " r off the axis";
            }
        }
    EXPECT_EQ(disagreeing, 0);
    EXPECT_GE(comparedInRing, 20);
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
        const RadianceImage gpu = renderShadowsGpu(scene), gpuAmbient = renderShadowsGpu(ambientOnly);
        const RadianceImage cpu = renderReference(scene, kWidth, kHeight);
        const RadianceImage cpuAmbient = renderReference(ambientOnly, kWidth, kHeight);
        const LitMask mask = cpuLitMask(scene, kWidth, kHeight);
        const auto band = penumbraBand(mask, kWidth, kHeight);
        const glm::mat4 inverse = glm::inverse(scene.camera.viewProjection(static_cast<float>(kWidth) / kHeight));
        int umbraPixels = 0, litFloorPixels = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const auto hit = intersectScene(scene, primaryRay(inverse, x + 0.5f, y + 0.5f, kWidth, kHeight));
                if (!hit || hit->objectIndex != 1 || band[y * kWidth + x]) continue;  // the floor, away from edges
                if (mask.lights[y * kWidth + x] != 0) {
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
    RadianceImage sum = renderShadowsGpu(all);
    float worst = 0.0f, brightest = 0.0f;
    std::vector<RadianceImage> parts;
    for (int light = 0; light < 3; ++light) {
        Scene alone = sceneWithLight(light, false);
        alone.background.color = glm::vec3(0.0f);
        parts.push_back(renderShadowsGpu(alone));
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
    const RadianceImage withShadow = renderShadowsGpu(shadowed), without = renderShadowsGpu(unshadowed);
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
    (void)renderShadowsGpu(scene);
    const long long first = renderer.shadowMapRenders();
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first);
    scene.camera.position.x += 0.5f;
    scene.materials[1].analytic()->values[0] = 0.3f;
    scene.lights[0].shadow.filterRadius = 3.0f;
    scene.lights[1].shadow.depthBias = 2.0f;
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first);
    scene.lights[2].position.y += 0.1f;
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 1);
    std::get<SphereShape>(scene.objects[0].shape).radius = 0.6f;
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 2);
    scene.lights[0].shadow.mapResolution = 512;
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapRenders(), first + 3);
}

// Moving one shadowed light draws its map alone; an object change draws them all; a light
// without shadows draws none.
TEST(GpuShadows, OnlyTheMapOfTheLightThatMovedIsDrawn) {
    Renderer& renderer = test::sharedHeadless().renderer();
    Scene scene = test::loadTestScene("scenes/shadows.json");  // three shadowed lights
    Light fill;
    fill.type = LightType::Point;
    fill.position = {2.0f, 1.0f, 2.0f};
    scene.lights.push_back(fill);  // no shadows
    (void)renderShadowsGpu(scene);
    const long long first = renderer.shadowMapsDrawn();
    scene.lights[1].position.x += 0.2f;
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapsDrawn(), first + 1);
    scene.lights.back().position.y += 0.5f;
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapsDrawn(), first + 1);
    std::get<PlaneShape>(scene.objects[1].shape).size.x = 5.0f;
    (void)renderShadowsGpu(scene);
    EXPECT_EQ(renderer.shadowMapsDrawn(), first + 4);
}

}  // namespace
}  // namespace glint
