// Lights and photometry: spot cone (inside, outside, falloff, smooth edge), the classic
// attenuation option, ambient radiance and the photometric equivalents. No GL.
#include <gtest/gtest.h>

#include "light/light.h"
#include "light/photometry.h"

namespace glint {
namespace {

// A spot at the origin pointing down −y; the point is 2 m away at `degrees` off its axis.
Light spotDown(float halfAngle, float edge, float exponent) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 0, 0};
    spot.direction = {0, -1, 0};
    spot.power = 4.0f * kPi;  // I = Φ/4π = 1 W/sr
    spot.coneHalfAngleDegrees = halfAngle;
    spot.edgeWidthDegrees = edge;
    spot.falloffExponent = exponent;
    return spot;
}

glm::vec3 pointOffAxis(float degrees) {
    const float angle = glm::radians(degrees);
    return 2.0f * glm::vec3(std::sin(angle), -std::cos(angle), 0.0f);
}

TEST(SpotLight, OnItsAxisItIsThePointLight) {
    const Light spot = spotDown(30, 5, 3);
    Light point = spot;
    point.type = LightType::Point;
    const LightArrival fromSpot = lightArrival(spot, pointOffAxis(0));
    const LightArrival fromPoint = lightArrival(point, pointOffAxis(0));
    EXPECT_NEAR(fromSpot.normalIrradiance.r, 0.25f, 1e-6f);  // I/d² = 1/4 W/m²
    EXPECT_EQ(fromSpot.normalIrradiance, fromPoint.normalIrradiance);
    EXPECT_NEAR(fromSpot.towardsLight.y, 1.0f, 1e-6f);
}

TEST(SpotLight, NothingOutsideTheCone) {
    const Light spot = spotDown(30, 5, 0);
    EXPECT_EQ(lightArrival(spot, pointOffAxis(30.5f)).normalIrradiance, glm::vec3(0.0f));
    EXPECT_EQ(lightArrival(spot, pointOffAxis(90)).normalIrradiance, glm::vec3(0.0f));
    EXPECT_EQ(lightArrival(spot, pointOffAxis(150)).normalIrradiance, glm::vec3(0.0f));  // behind it
    EXPECT_NEAR(lightArrival(spot, pointOffAxis(24)).normalIrradiance.g, 0.25f, 1e-6f);   // inside the edge
}

TEST(SpotLight, HearnBakerFalloffIsCosineToTheA) {
    const Light spot = spotDown(60, 0, 4);
    for (float degrees : {0.0f, 20.0f, 45.0f}) {
        const float expected = 0.25f * std::pow(std::cos(glm::radians(degrees)), 4.0f);
        EXPECT_NEAR(lightArrival(spot, pointOffAxis(degrees)).normalIrradiance.r, expected, 1e-6f) << degrees;
    }
}

TEST(SpotLight, SmoothEdgeRisesMonotonicallyAcrossItsWidth) {
    const Light spot = spotDown(30, 10, 0);
    float previous = 0.0f;
    for (float degrees = 30.0f; degrees >= 20.0f; degrees -= 0.5f) {
        const float value = lightArrival(spot, pointOffAxis(degrees)).normalIrradiance.r;
        EXPECT_GE(value, previous) << degrees;
        previous = value;
    }
    EXPECT_NEAR(previous, 0.25f, 1e-6f);
    // Halfway across the edge in cos α, smoothstep gives exactly one half.
    const float cosMiddle = 0.5f * (std::cos(glm::radians(30.0f)) + std::cos(glm::radians(20.0f)));
    EXPECT_NEAR(spotFactor(cosMiddle, std::cos(glm::radians(30.0f)), std::cos(glm::radians(20.0f)), 0.0f), 0.5f, 1e-5f);
    // A zero edge is a hard cut.
    const Light hard = spotDown(30, 0, 0);
    EXPECT_NEAR(lightArrival(hard, pointOffAxis(29.9f)).normalIrradiance.r, 0.25f, 1e-6f);
    EXPECT_EQ(lightArrival(hard, pointOffAxis(30.1f)).normalIrradiance.r, 0.0f);
}

TEST(ClassicAttenuation, ReplacesTheInverseSquareLawOnlyWhenEnabled) {
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {0, 0, 0};
    bulb.power = 4.0f * kPi;
    const glm::vec3 point{0, 0, 3};
    EXPECT_NEAR(lightArrival(bulb, point).normalIrradiance.r, 1.0f / 9.0f, 1e-7f);
    bulb.attenuation.enabled = true;
    bulb.attenuation.coefficients = {1.0f, 0.5f, 0.25f};
    EXPECT_NEAR(lightArrival(bulb, point).normalIrradiance.r, 1.0f / (1.0f + 1.5f + 2.25f), 1e-7f);
    bulb.attenuation.coefficients = {0, 0, 1};  // the physical law again
    EXPECT_NEAR(lightArrival(bulb, point).normalIrradiance.r, 1.0f / 9.0f, 1e-7f);
    Light spot = spotDown(30, 0, 0);
    spot.attenuation = {true, {2.0f, 0.0f, 0.0f}};  // constant: no distance dependence
    EXPECT_NEAR(lightArrival(spot, pointOffAxis(0)).normalIrradiance.r, 0.5f, 1e-7f);
}

TEST(AmbientLight, IsUniformRadianceAndNoDeltaLight) {
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambientRadiance = 0.3f;
    ambient.color = {1.0f, 0.5f, 0.0f};
    EXPECT_EQ(ambientRadiance(ambient), glm::vec3(0.3f, 0.15f, 0.0f));
    EXPECT_EQ(lightArrival(ambient, {1, 2, 3}).normalIrradiance, glm::vec3(0.0f));
    ambient.enabled = false;
    EXPECT_EQ(ambientRadiance(ambient), glm::vec3(0.0f));
    Light point;
    point.type = LightType::Point;
    EXPECT_EQ(ambientRadiance(point), glm::vec3(0.0f));
}

TEST(Photometry, OneWattOfWhiteIs683Lumens) {
    EXPECT_FLOAT_EQ(relativeLuminance({1, 1, 1}), 1.0f);
    EXPECT_FLOAT_EQ(luminousFlux({1, 1, 1}), 683.0f);
    EXPECT_NEAR(luminousFlux({0, 1, 0}), 683.0f * 0.7152f, 1e-3f);  // pure green
    EXPECT_NEAR(luminousFlux({0, 0, 1}), 683.0f * 0.0722f, 1e-3f);  // pure blue
    EXPECT_NEAR(illuminance({2, 2, 2}), 1366.0f, 1e-3f);
    EXPECT_NEAR(luminousIntensity({1, 0, 0}), 683.0f * 0.2126f, 1e-3f);
    EXPECT_NEAR(luminance({0.5f, 0.5f, 0.5f}), 341.5f, 1e-3f);
}

TEST(Photometry, PerLightType) {
    Light bulb;
    bulb.type = LightType::Point;
    bulb.power = 100.0f;
    bulb.color = {1, 1, 1};
    const LightPhotometry point = lightPhotometry(bulb);
    EXPECT_NEAR(point.lumens, 68300.0f, 0.5f);
    EXPECT_NEAR(point.candelas, 68300.0f / (4.0f * kPi), 0.05f);  // lm / 4π sr
    EXPECT_EQ(point.lux, 0.0f);
    Light sun;
    sun.irradiance = 1000.0f;
    sun.color = {1, 1, 1};
    EXPECT_NEAR(lightPhotometry(sun).lux, 683000.0f, 1.0f);
    Light sky;
    sky.type = LightType::Ambient;
    sky.ambientRadiance = 1.0f;
    sky.color = {0, 1, 0};
    EXPECT_NEAR(lightPhotometry(sky).nits, 683.0f * 0.7152f, 1e-3f);
}

}  // namespace
}  // namespace glint
