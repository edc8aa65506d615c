// The classroom surface probe against the radiometry worked by hand and against the CPU reference
// it breaks down: the lambert_sun centre (E = π, f_r = 0.5/π, L = 0.5), a Blinn-Phong point
// under a point light (L, H, R), glass (Snell's law and total internal reflection), a miss.
#include <gtest/gtest.h>

#include <cmath>

#include "classroom/probe_text.h"
#include "classroom/surface_probe.h"
#include "math/constants.h"
#include "render/reference_renderer.h"
#include "test_support.h"

namespace glint {
namespace {

void expectProbeVectorNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// One sphere of radius 1 at the origin seen by the default camera (perspective, from (0, 0, 4)).
Scene probeSphereScene(BrdfModel model) {
    Scene scene;
    scene.materials.push_back(Material::withDefaults("probed", model));
    scene.objects.push_back(SceneObject{"ball", SphereShape{}, 0, SurfaceInterpolation::Exact});
    return scene;
}

// The probe hits a surface that refracts the view ray from index etaIncident into etaTransmitted.
void expectViewRefraction(const ProbeResult& probe, float etaIncident, float etaTransmitted) {
    ASSERT_TRUE(probe.hitSurface);
    ASSERT_TRUE(probe.viewTransmitted.has_value());
    EXPECT_FLOAT_EQ(probe.viewTransmitted->etaIncident, etaIncident);
    EXPECT_FLOAT_EQ(probe.viewTransmitted->etaTransmitted, etaTransmitted);
}

TEST(SurfaceProbe, LambertSunCentreIsTheWorkedExample) {
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    // 255×255: pixel 127's centre is the image centre, whose ray meets the sphere's apex.
    const ProbeResult probe = probeSurface(scene, 127, 127, 255, 255);
    ASSERT_TRUE(probe.hitSurface);
    EXPECT_EQ(probe.objectName, "unit sphere");
    EXPECT_EQ(probe.materialName, "half grey");
    expectProbeVectorNear(probe.normal, {0, 0, 1}, 1e-6f);
    expectProbeVectorNear(probe.towardsViewer, {0, 0, 1}, 1e-6f);
    ASSERT_EQ(probe.lights.size(), 1u);
    const ProbeLight& sun = probe.lights[0];
    EXPECT_STREQ(sun.source.symbol, "M");
    EXPECT_NEAR(sun.source.amount, kPi, 1e-6f);
    EXPECT_NEAR(sun.source.photometric, 683.0f * kPi, 1e-2f);  // lx of white light
    EXPECT_NEAR(sun.cosTheta, 1.0f, 1e-6f);
    EXPECT_NEAR(sun.incidentDegrees, 0.0f, 0.05f);
    EXPECT_NEAR(sun.irradiance.g, kPi, 1e-5f);           // E = π W/m²
    EXPECT_NEAR(sun.brdf.g, 0.5f / kPi, 1e-6f);          // f_r = ρ/π
    EXPECT_NEAR(sun.radiance.g, 0.5f, 1e-5f);            // L = 0.5 W/(sr·m²)
    EXPECT_NEAR(probe.radiance.g, 0.5f, 1e-5f);
    // sRGB(0.5) = 0.7354 → 188.
    EXPECT_NEAR(probe.display[1].encoded, 0.7354f, 1e-3f);
    EXPECT_EQ(probe.display[1].value8, 188);
    const std::vector<std::string> equation = probeLightEquation(sun);
    ASSERT_EQ(equation.size(), 3u);
    EXPECT_EQ(equation[0], "E⊥ = M = 3.142 W/m²");
    EXPECT_EQ(equation[1], "E = E⊥·cos θ = 3.142 W/m² × 1.000 = 3.142 W/m²");
    EXPECT_EQ(equation[2], "L = f_r·E = 0.159 1/sr × 3.142 W/m² = 0.500 W/(sr·m²)");
    EXPECT_EQ(probeTotalEquation(probe), "L = Σ f_r·E = 0.500 W/(sr·m²)");
}

TEST(SurfaceProbe, RadianceIsTheReferencePixel) {
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    const RadianceImage image = renderReference(scene, 32, 24);
    for (const auto& [x, y] : {std::pair{16, 12}, std::pair{10, 7}, std::pair{20, 18}})
        EXPECT_EQ(probeSurface(scene, x, y, 32, 24).radiance, image.at(x, y)) << x << "," << y;
}

TEST(SurfaceProbe, BlinnPhongPointUnderAPointLight) {
    Scene scene = probeSphereScene(BrdfModel::BlinnPhong);
    Light bulb;
    bulb.name = "bulb";
    bulb.type = LightType::Point;
    bulb.power = 100.0f;
    bulb.position = {2, 2, 2};
    scene.lights.push_back(bulb);
    const ProbeResult probe = probeSurface(scene, 32, 32, 65, 65);  // the view axis: hits (0, 0, 1)
    ASSERT_TRUE(probe.hitSurface);
    expectProbeVectorNear(probe.position, {0, 0, 1}, 1e-5f);
    ASSERT_EQ(probe.lights.size(), 1u);
    const ProbeLight& light = probe.lights[0];
    const glm::vec3 towardsLight = glm::vec3(2, 2, 1) / 3.0f;
    expectProbeVectorNear(light.towardsLight, towardsLight, 1e-5f);
    expectProbeVectorNear(light.halfVector, glm::normalize(towardsLight + glm::vec3(0, 0, 1)), 1e-5f);
    expectProbeVectorNear(light.mirror, {-2.0f / 3, -2.0f / 3, 1.0f / 3}, 1e-5f);  // 2(N·L)N − L
    EXPECT_NEAR(light.distance, 3.0f, 1e-5f);
    EXPECT_NEAR(light.cosTheta, 1.0f / 3, 1e-5f);
    EXPECT_NEAR(light.halfDegrees, glm::degrees(std::acos(glm::normalize(towardsLight + glm::vec3(0, 0, 1)).z)), 1e-3f);
    EXPECT_NEAR(light.mirrorViewDegrees, glm::degrees(std::acos(1.0f / 3)), 1e-3f);
    EXPECT_NEAR(light.normalIrradiance.r, 100.0f / (4 * kPi * 9), 1e-5f);  // Φ/(4π d²)
    EXPECT_NEAR(light.irradiance.r, 100.0f / (4 * kPi * 9) / 3, 1e-5f);
    const glm::vec3 expectedBrdf = evalBrdf(BrdfModel::BlinnPhong, scene.materials[0].analytic()->values, towardsLight,
                                            glm::vec3(0, 0, 1), ShadingFrame::fromNormalAndTangent({0, 0, 1}, {1, 0, 0}));
    expectProbeVectorNear(light.brdf, expectedBrdf, 1e-4f);
    expectProbeVectorNear(light.radiance, light.brdf * light.irradiance, 1e-6f);
    EXPECT_FALSE(light.transmitted.has_value());  // not refractive
    EXPECT_EQ(probe.radiance, renderReference(scene, 65, 65).at(32, 32));
}

TEST(SurfaceProbe, GlassRefractsBySnellsLaw) {
    const Scene scene = probeSphereScene(BrdfModel::Glass);  // η = 1.5
    const ProbeResult probe = probeSurface(scene, 44, 40, 65, 65);
    ASSERT_NO_FATAL_FAILURE(expectViewRefraction(probe, 1.0f, 1.5f));
    const ProbeRefraction& refraction = *probe.viewTransmitted;
    EXPECT_FALSE(refraction.totalInternalReflection);
    EXPECT_GT(refraction.incidentDegrees, 10.0f);
    const float sinIncident = std::sin(glm::radians(refraction.incidentDegrees));
    const float sinTransmitted = std::sin(glm::radians(refraction.transmittedDegrees));
    EXPECT_NEAR(1.0f * sinIncident, 1.5f * sinTransmitted, 1e-4f);  // η_i sin θ_i = η_t sin θ_t
    // T leaves into the glass, in the plane of incidence, at θ_t from −N.
    EXPECT_NEAR(glm::dot(refraction.direction, -probe.normal), std::cos(glm::radians(refraction.transmittedDegrees)), 1e-4f);
    EXPECT_NEAR(glm::dot(refraction.direction, glm::cross(probe.normal, probe.towardsViewer)), 0.0f, 1e-5f);
}

TEST(SurfaceProbe, GlassSeenFromInsideReflectsTotallyBeyondTheCriticalAngle) {
    Scene scene = probeSphereScene(BrdfModel::Glass);
    std::get<SphereShape>(scene.objects[0].shape).radius = 2.0f;
    scene.camera.position = {0, 0, 1.5f};  // inside the glass, looking along +x at the wall
    scene.camera.target = {1, 0, 1.5f};
    const ProbeResult probe = probeSurface(scene, 32, 32, 65, 65);
    ASSERT_NO_FATAL_FAILURE(expectViewRefraction(probe, 1.5f, 1.0f));
    const ProbeRefraction& refraction = *probe.viewTransmitted;
    ASSERT_TRUE(refraction.criticalDegrees.has_value());
    EXPECT_NEAR(*refraction.criticalDegrees, glm::degrees(std::asin(1.0f / 1.5f)), 1e-3f);  // 41.8°
    // cos θ_i = x/r at x = √(4 − 1.5²): θ_i ≈ 48.6° > 41.8°.
    EXPECT_NEAR(refraction.incidentDegrees, glm::degrees(std::acos(std::sqrt(4.0f - 2.25f) / 2.0f)), 1e-2f);
    EXPECT_TRUE(refraction.totalInternalReflection);
    EXPECT_NE(probeReport(probe).find("total internal reflection"), std::string::npos);
}

TEST(SurfaceProbe, AMissSaysNoSurface) {
    const Scene scene = test::loadTestScene("scenes/lambert_sun.json");
    const ProbeResult probe = probeSurface(scene, 0, 0, 64, 64);
    EXPECT_FALSE(probe.hitSurface);
    EXPECT_TRUE(probe.lights.empty());
    EXPECT_EQ(probe.radiance, glm::vec3(0.0f));  // the black background
    EXPECT_EQ(probe.display[0].value8, 0);
    EXPECT_NE(probeReport(probe).find("no surface"), std::string::npos);
}

}  // namespace
}  // namespace glint
