// The disk cache of computed tables (core/util/disk_cache.h) and the built-in environments'
// lighting kept in it (core/environment/environment_cache.h): a stored entry reads back, a damaged
// or truncated one reads as a miss and is computed again, a cached map equals the computed one.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "environment/environment_cache.h"
#include "environment/environment_source.h"
#include "util/disk_cache.h"

namespace glint {
namespace {

// The file of the entry `name` (each test its own names: the shards share the folder).
std::string entryFile(const std::string& name) {
    std::error_code error;
    for (const auto& file : std::filesystem::directory_iterator(cacheFolder(), error))
        if (file.path().filename().string().rfind(name + "-", 0) == 0) return file.path().string();
    return {};
}

TEST(DiskCache, StoresReadsAndRefusesDamagedEntries) {
    ASSERT_FALSE(cacheFolder().empty()) << "the test executable has a build ID";
    { std::error_code error; std::filesystem::remove(entryFile("test-values"), error); }
    int computed = 0;
    const auto compute = [&] {
        ++computed;
        return std::vector<float>{1.0f, 2.5f, -3.0f};
    };
    EXPECT_EQ(cachedValues<float>("test-values", 3, compute), (std::vector<float>{1.0f, 2.5f, -3.0f}));
    EXPECT_EQ(cachedValues<float>("test-values", 3, compute), (std::vector<float>{1.0f, 2.5f, -3.0f}));
    EXPECT_EQ(computed, 1) << "the second call reads the entry";
    const std::string file = entryFile("test-values");
    ASSERT_FALSE(file.empty());
    {  // one byte of the values flipped: the checksum no longer matches
        std::fstream stream(file, std::ios::in | std::ios::out | std::ios::binary);
        stream.seekp(-2, std::ios::end);
        stream.put('\x7f');
    }
    EXPECT_FALSE(readCacheEntry("test-values"));
    EXPECT_EQ(cachedValues<float>("test-values", 3, compute)[1], 2.5f);
    EXPECT_EQ(computed, 2);
    std::filesystem::resize_file(file, 20);  // truncated
    EXPECT_FALSE(readCacheEntry("test-values"));
    EXPECT_EQ(cachedValues<float>("test-values", 4, compute).size(), 3u) << "a count that differs is computed";
    EXPECT_EQ(computed, 3);
    std::ofstream(cacheFolder() + "/test-values-0123.bin") << "another build's entry";
    writeCacheEntry("test-values", "x");
    EXPECT_FALSE(std::filesystem::exists(cacheFolder() + "/test-values-0123.bin")) << "entries of other builds are removed";
}

TEST(DiskCache, CachedEnvironmentEqualsTheComputedOne) {
    { std::error_code error; std::filesystem::remove(entryFile("test-sky"), error); }
    const auto computed = makeEnvironmentMap(bakeBuiltinEnvironment(EnvironmentKind::Sky));
    ASSERT_TRUE(cachedEnvironmentMap("test-sky", bakeBuiltinEnvironment(EnvironmentKind::Sky), {}));  // stores
    int offers = 0;
    const auto cached = cachedEnvironmentMap("test-sky", bakeBuiltinEnvironment(EnvironmentKind::Sky), [&](float fraction) {
        ++offers;
        return fraction == 1.0f;
    });
    ASSERT_TRUE(cached);
    EXPECT_EQ(offers, 1) << "read, not computed";
    EXPECT_EQ(cached->irradiance.texels, computed->irradiance.texels);
    ASSERT_EQ(cached->prefiltered.size(), computed->prefiltered.size());
    for (size_t level = 0; level < computed->prefiltered.size(); ++level) {
        EXPECT_EQ(cached->prefiltered[level].texels, computed->prefiltered[level].texels) << level;
        EXPECT_EQ(cached->residualPrefiltered[level].texels, computed->residualPrefiltered[level].texels) << level;
    }
    EXPECT_EQ(cached->peaks.size(), computed->peaks.size());
    EXPECT_EQ(cached->peakMinimumAlpha, computed->peakMinimumAlpha);
    EXPECT_EQ(cached->radiance.texels, computed->radiance.texels);
    // Cancelled at the offer, as the computation would be; another radiance is not served the entry.
    EXPECT_FALSE(cachedEnvironmentMap("test-sky", bakeBuiltinEnvironment(EnvironmentKind::Sky), [](float) { return false; }));
    EquirectImage other = bakeBuiltinEnvironment(EnvironmentKind::Sky);
    other.texels[0] *= 2.0f;
    offers = 0;
    ASSERT_TRUE(cachedEnvironmentMap("test-sky", std::move(other), [&](float) { return ++offers > 0; }));
    EXPECT_GT(offers, 1) << "a changed radiance is computed";
}

}  // namespace
}  // namespace glint
