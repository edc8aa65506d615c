// MERL .binary: header and size validation (truncated, lying dimensions, trailing data, NaN),
// the half/difference-angle coordinates, and a synthetic Lambertian file whose lookups give the
// Lambert model's ρ/π (nearest and trilinear). Also times loading a full-size file.
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include "brdf/lambert.h"
#include "interchange/merl.h"
#include "math/constants.h"
#include "test_support.h"

namespace glint {
namespace {

glm::vec3 direction(float theta, float phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(Merl, LambertianFileLooksUpAsTheLambertModel) {
    const glm::vec3 albedo(0.8f, 0.5f, 0.2f);
    auto table = parseMerl(makeConstantMerl(albedo / kPi), "lambert.binary");
    ASSERT_TRUE(table.ok()) << table.error().format();
    EXPECT_EQ(table->negativeSamples, 0u);
    const ShadingFrame frame;
    const LambertParams lambert{albedo};
    for (float thetaIn : {0.05f, 0.4f, 0.9f, 1.4f})
        for (float thetaOut : {0.1f, 0.7f, 1.2f, 1.55f})
            for (float phi : {0.0f, 1.0f, 2.5f, 4.0f}) {
                const glm::vec3 wi = direction(thetaIn, 0.3f), wo = direction(thetaOut, 0.3f + phi);
                const glm::vec3 expected = evalLambert(lambert, wi, wo, frame);
                const glm::vec3 nearest = lookupMerlNearest(*table, wi, wo, frame);
                const glm::vec3 trilinear = lookupMerlTrilinear(*table, wi, wo, frame);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(nearest[c], expected[c], 1e-6f);
                    EXPECT_NEAR(trilinear[c], expected[c], 1e-6f);
                }
            }
    EXPECT_EQ(lookupMerlTrilinear(*table, direction(1.0f, 0), -direction(1.0f, 0), frame), glm::vec3(0.0f));  // below
    const glm::vec3 nan(std::nanf(""));
    EXPECT_EQ(lookupMerlTrilinear(*table, nan, nan, frame), glm::vec3(0.0f));
}

// A table whose value encodes its bin shows the lookup reads the bin the reference code reads.
TEST(Merl, BinCoordinatesFollowTheReferenceParametrisation) {
    // Specular configuration: wi mirrored about the normal → θ_h = 0, θ_d = θ_i.
    const ShadingFrame frame;
    const float theta = 0.6f;
    const HalfDifference angles = toHalfDifference(direction(theta, 0.0f), direction(theta, kPi), frame);
    EXPECT_NEAR(angles.thetaHalf, 0.0f, 1e-3f);
    EXPECT_NEAR(angles.thetaDifference, theta, 1e-4f);
    // θ_h bins are non-linear: θ_h = π/8 is index 90·√(1/4) = 45.
    const glm::vec3 bins = merlBinCoordinates({kPi / 8, kPi / 4, kPi / 2});
    EXPECT_NEAR(bins.x, 45.0f, 1e-4f);
    EXPECT_NEAR(bins.y, 45.0f, 1e-4f);
    EXPECT_NEAR(bins.z, 90.0f, 1e-4f);
    // Reciprocity: swapping wi and wo gives the same value on a non-constant table.
    std::string bytes = makeConstantMerl(glm::vec3(0.1f));
    for (size_t i = 0; i < kMerlSamplesPerChannel; ++i) {
        const double value = double(i % 977) + 1.0;  // distinct values across bins
        std::memcpy(bytes.data() + 12 + i * 8, &value, 8);
    }
    auto table = parseMerl(bytes, "ramp.binary");
    ASSERT_TRUE(table.ok());
    const glm::vec3 wi = direction(0.7f, 0.2f), wo = direction(1.1f, 2.0f);
    EXPECT_NEAR(lookupMerlTrilinear(*table, wi, wo, frame).r, lookupMerlTrilinear(*table, wo, wi, frame).r, 1e-4f);
    EXPECT_EQ(lookupMerlNearest(*table, wi, wo, frame).r, lookupMerlNearest(*table, wo, wi, frame).r);
}

TEST(Merl, MalformedFilesAreRefusedWithAClearMessage) {
    const std::string good = makeConstantMerl(glm::vec3(0.1f));
    auto refused = [](const std::string& bytes, const std::string& expected) {
        auto table = parseMerl(bytes, "bad.binary");
        ASSERT_FALSE(table.ok()) << expected;
        EXPECT_NE(table.error().format().find(expected), std::string::npos) << table.error().format();
        EXPECT_EQ(table.error().format().rfind("bad.binary", 0), 0u);
    };
    refused("", "too short for the header");
    refused("MERL", "too short for the header");
    refused(good.substr(0, good.size() - 1), "(truncated)");
    refused(good.substr(0, 12), "(truncated)");
    refused(good + "extra", "(trailing data)");
    // What a checkout without git-lfs leaves in place of the file.
    refused("version https://git-lfs.github.com/spec/v1\n"
            "oid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\nsize 33030156\n",
            "a Git LFS pointer");
    refused("version https://git-lfs.github.com/spec/v1\n", "git lfs pull");
    std::string dimensions = good;
    const int32_t lying[3] = {90, 90, 360};  // the full φ_d range some tools write: not MERL's layout
    std::memcpy(dimensions.data(), lying, 12);
    refused(dimensions, "90×90×360");
    const int32_t huge[3] = {2147483647, 2147483647, 2147483647};
    std::memcpy(dimensions.data(), huge, 12);
    refused(dimensions, "MERL files are 90×90×180");
    std::string nan = good;
    const double notANumber = std::nan("");
    std::memcpy(nan.data() + 12 + 8 * (kMerlSamplesPerChannel + 5), &notANumber, 8);
    refused(nan, "sample 5 of channel 1 is not a finite number");
    std::string negative = good;
    const double minusOne = -1.0;
    std::memcpy(negative.data() + 12, &minusOne, 8);
    auto withNegative = parseMerl(negative, "negative.binary");
    ASSERT_TRUE(withNegative.ok());
    EXPECT_EQ(withNegative->negativeSamples, 1u);
    EXPECT_EQ(withNegative->at(0, 0, 0).r, 0.0f);
}

TEST(Merl, LoadsAFullSizeFileFromDisk) {
    const std::string path = test::outputDirectory("merl") + "/lambert.binary";
    {
        std::ofstream out(path, std::ios::binary);
        const std::string bytes = makeConstantMerl(glm::vec3(0.5f / kPi));
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    const auto start = std::chrono::steady_clock::now();
    auto table = loadMerl(path);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(table.ok()) << table.error().format();
    std::printf("MERL load (%zu bytes): %.3f s\n", kMerlFileBytes, seconds);
    EXPECT_NEAR(table->at(89, 89, 179).g, 0.5f / kPi, 1e-7f);
    EXPECT_FALSE(loadMerl(path + ".missing").ok());
}

}  // namespace
}  // namespace glint
