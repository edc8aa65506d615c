// Specular transport on the CPU: mirror Fresnel, glass Fresnel splitting with Beer-Lambert
// absorption, the classic transparency, total internal reflection from inside a sphere, the
// thin pane, and the registry's ambient-reflectance hook. No GL.
#include <gtest/gtest.h>

#include "brdf/glass.h"
#include "brdf/lambert.h"
#include "brdf/mirror.h"
#include "render/specular_transport.h"

namespace glint {
namespace {

const Background kGrey{BackgroundKind::Constant, glm::vec3(2.0f)};
const SphereGeometry kUnitSphere{{0, 0, 0}, 1.0f};

// Glass seen straight on at the front of the unit sphere (viewer on +z).
glm::vec3 centralRay(const GlassInterface& glass, glm::vec3 absorption, const Background& background = kGrey) {
    return traceGlass(glass, absorption, background, &kUnitSphere, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 3.0f);
}

TEST(MirrorTransport, ReflectsTheBackgroundWeightedByConductorFresnel) {
    const glm::vec3 eta{1.66f, 0.88f, 0.52f}, kappa{9.22f, 6.27f, 4.84f};
    const glm::vec3 normal{0, 0, 1};
    const glm::vec3 straight = traceMirror(eta, kappa, kGrey, normal, normal);
    const glm::vec3 f0 = fresnelF0(eta, kappa);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(straight[c], 2.0f * f0[c], 1e-5f);
    // The sky seen in the reflected direction: the viewer looks down at 45°, the mirror shows up.
    const Background sky{BackgroundKind::Sky, {}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    const glm::vec3 towardsViewer = glm::normalize(glm::vec3(0, 1, 1));
    const glm::vec3 seen = traceMirror(glm::vec3(1.5f), glm::vec3(0.0f), sky, {0, 1, 0}, towardsViewer);
    const float fresnel = fresnelDielectric(std::sqrt(0.5f), 1.5f);
    EXPECT_NEAR(seen.b, fresnel * std::sqrt(0.5f), 1e-5f);  // zenith weight = elevation sin 45°
    EXPECT_NEAR(seen.r, 0.0f, 1e-6f);                       // no ground in an upward reflection
}

TEST(GlassTransport, NonAbsorbingSphereInAUniformBackgroundIsInvisible) {
    // Energy conservation (a white furnace): R + T·Σ R^k·T = 1 up to the last bounce; the
    // (η_t/η_i)² factors cancel on every path from air to air.
    const GlassInterface glass{1.5f, false, 0.0f};
    for (float angle : {0.0f, 0.4f, 0.8f, 1.2f}) {
        const glm::vec3 normal{std::sin(angle), 0.0f, std::cos(angle)};
        const glm::vec3 radiance = traceGlass(glass, glm::vec3(0.0f), kGrey, &kUnitSphere, normal, normal, {0, 0, 1}, 3.0f);
        EXPECT_NEAR(radiance.g, 2.0f, 2e-4f) << "angle " << angle;
    }
}

TEST(GlassTransport, BeerLambertAlongEachChord) {
    const GlassInterface glass{1.5f, false, 0.0f};
    const glm::vec3 absorption{0.0f, 0.5f, 3.0f};
    const glm::vec3 radiance = centralRay(glass, absorption);
    const float reflectance = 0.04f;  // ((1.5 − 1)/(1.5 + 1))²
    for (int c = 0; c < 3; ++c) {
        const float chordTransmittance = std::exp(-absorption[c] * 2.0f);  // diameter 2 m
        float expected = reflectance;
        for (int k = 0; k < kMaxInternalBounces; ++k)
            expected += (1 - reflectance) * (1 - reflectance) * std::pow(reflectance, float(k)) * std::pow(chordTransmittance, float(k + 1));
        EXPECT_NEAR(radiance[c], 2.0f * expected, 1e-5f) << "channel " << c;
    }
    EXPECT_LT(radiance.b, 0.2f) << "strong absorption colours the glass";
}

TEST(GlassTransport, ClassicTransparencyUsesKt) {
    const GlassInterface classic{1.5f, true, 0.7f};
    const glm::vec3 radiance = centralRay(classic, glm::vec3(0.0f));
    float expected = 0.3f;  // (1 − k_t)·I_refl
    for (int k = 0; k < kMaxInternalBounces; ++k) expected += 0.7f * 0.7f * std::pow(0.3f, float(k));
    EXPECT_NEAR(radiance.r, 2.0f * expected, 1e-5f);
}

TEST(GlassTransport, TotalInternalReflectionFromInside) {
    // From inside, a wall hit beyond the critical angle (sin θ_c = 1/η) reflects everything, and
    // in a sphere every later wall is hit at the same angle: no light ever leaves, so black.
    const GlassInterface water{1.33f, false, 0.0f};
    const float critical = std::asin(1.0f / 1.33f);
    for (float offset : {-0.1f, 0.1f}) {
        const float angle = critical + offset;  // angle between the ray and the outward normal
        const glm::vec3 wallPoint{0, 0, -1};
        const glm::vec3 direction{std::sin(angle), 0.0f, -std::cos(angle)};
        const glm::vec3 inwardNormal{0, 0, 1};
        const glm::vec3 radiance =
            traceGlass(water, glm::vec3(0.0f), kGrey, &kUnitSphere, wallPoint, inwardNormal, -direction, 0.5f);
        if (offset > 0) EXPECT_EQ(radiance, glm::vec3(0.0f)) << "total internal reflection";
        else EXPECT_GT(radiance.r, 1.0f) << "below the critical angle most light leaves";
    }
    EXPECT_EQ(glassReflectance(water, std::cos(critical + 0.01f), 1.0f / 1.33f), 1.0f);
}

TEST(GlassTransport, ThinPaneOnAPlane) {
    const GlassInterface glass{1.5f, false, 0.0f};
    const Background sky{BackgroundKind::Sky, {}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    // Looking straight down through a horizontal pane: the ground, weighted (1 − R)², plus the
    // zenith reflected with R.
    const glm::vec3 radiance = traceGlass(glass, glm::vec3(5.0f), sky, nullptr, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 1.0f);
    EXPECT_NEAR(radiance.r, 0.96f * 0.96f, 1e-5f);
    EXPECT_NEAR(radiance.b, 0.04f, 1e-5f);
}

TEST(AmbientHook, LambertIsItsAlbedoAndModelsWithoutTheHookReflectNone) {
    const ShadingFrame frame;
    const std::vector<float> lambert = {0.2f, 0.5f, 0.9f};
    EXPECT_EQ(ambientReflectance(BrdfModel::Lambert, lambert, {0, 0, 1}, frame), glm::vec3(0.2f, 0.5f, 0.9f));
    std::vector<float> mirror = defaultValues(kMirrorTable);
    mirror[6] = mirror[7] = mirror[8] = 0.1f;
    EXPECT_EQ(ambientReflectance(BrdfModel::Mirror, mirror, {0, 0, 1}, frame), glm::vec3(0.1f));
    EXPECT_EQ(modelInfo(BrdfModel::Glass).glslAmbient, nullptr);
    EXPECT_EQ(ambientReflectance(BrdfModel::Glass, defaultValues(kGlassTable), {0, 0, 1}, frame), glm::vec3(0.0f));
    EXPECT_EQ(evalBrdf(BrdfModel::Glass, defaultValues(kGlassTable), {0, 0, 1}, {0, 0, 1}, frame), glm::vec3(0.0f));
}

}  // namespace
}  // namespace glint
