// Built-in environments' lighting through the disk cache (see environment_cache.h).
#include "environment/environment_cache.h"

#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>

#include "util/disk_cache.h"

namespace glint {
namespace {

// The precomputed parts of a map, after a header naming the radiance they were made from (its
// size and a hash of its texels): the irradiance, the prefiltered and residual levels, the peaks, the residual's mean.
class Writer {
public:
    template <class T>
    void put(const T& value) { bytes.append(reinterpret_cast<const char*>(&value), sizeof value); }
    void put(const EquirectImage& image) {
        put(static_cast<std::int32_t>(image.width)), put(static_cast<std::int32_t>(image.height));
        bytes.append(reinterpret_cast<const char*>(image.texels.data()), image.texels.size() * sizeof(glm::vec3));
    }
    std::string bytes;
};

class Reader {
public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}
    template <class T>
    bool get(T& value) {
        if (bytes_.size() - offset_ < sizeof value) return false;
        std::memcpy(&value, bytes_.data() + offset_, sizeof value);
        offset_ += sizeof value;
        return true;
    }
    bool get(EquirectImage& image) {
        std::int32_t width = 0, height = 0;
        if (!get(width) || !get(height) || width <= 0 || height <= 0 || width > 1 << 14 || height > 1 << 14) return false;
        const size_t size = static_cast<size_t>(width) * height * sizeof(glm::vec3);
        if (bytes_.size() - offset_ < size) return false;
        image = EquirectImage(width, height);
        std::memcpy(image.texels.data(), bytes_.data() + offset_, size);
        offset_ += size;
        return true;
    }
    bool atEnd() const { return offset_ == bytes_.size(); }

private:
    const std::string& bytes_;
    size_t offset_ = 0;
};

std::uint64_t radianceHash(const EquirectImage& radiance) {
    return cacheChecksum(radiance.texels.data(), radiance.texels.size() * sizeof(glm::vec3));
}

std::string lightingBytes(const EnvironmentMap& map) {
    Writer out;
    out.put(static_cast<std::int32_t>(map.radiance.width)), out.put(static_cast<std::int32_t>(map.radiance.height));
    out.put(radianceHash(map.radiance));
    out.put(map.irradiance);
    for (const EquirectImage& level : map.prefiltered) out.put(level);
    for (const EquirectImage& level : map.residualPrefiltered) out.put(level);
    out.put(static_cast<std::uint32_t>(map.peaks.size()));
    for (const EnvironmentPeakLight& peak : map.peaks) out.put(peak);
    out.put(map.peakMinimumAlpha);
    out.put(map.residualMean);
    return out.bytes;
}

// The map of `radiance` with the lighting in `bytes`; nothing when they do not belong together.
std::optional<EnvironmentMap> mapFromBytes(const std::string& bytes, EquirectImage& radiance) {
    Reader in(bytes);
    EnvironmentMap map;
    std::int32_t width = 0, height = 0;
    std::uint64_t hash = 0;
    if (!in.get(width) || !in.get(height) || !in.get(hash) || width != radiance.width || height != radiance.height ||
        hash != radianceHash(radiance) || !in.get(map.irradiance))
        return std::nullopt;
    map.prefiltered.resize(kPrefilteredLevels);
    map.residualPrefiltered.resize(kPrefilteredLevels);
    for (EquirectImage& level : map.prefiltered)
        if (!in.get(level)) return std::nullopt;
    for (EquirectImage& level : map.residualPrefiltered)
        if (!in.get(level)) return std::nullopt;
    std::uint32_t peaks = 0;
    if (!in.get(peaks) || peaks > static_cast<std::uint32_t>(kMaxPeakLights)) return std::nullopt;
    map.peaks.resize(peaks);
    for (EnvironmentPeakLight& peak : map.peaks)
        if (!in.get(peak)) return std::nullopt;
    if (!in.get(map.peakMinimumAlpha) || !in.get(map.residualMean) || !in.atEnd()) return std::nullopt;
    map.distribution = EnvironmentDistribution(radiance);
    map.radiance = std::move(radiance);
    return map;
}

}  // namespace

std::shared_ptr<const EnvironmentMap> cachedEnvironmentMap(const std::string& name, EquirectImage radiance,
                                                           const EnvironmentProgress& progress) {
    if (const std::optional<std::string> bytes = readCacheEntry(name)) {
        if (std::optional<EnvironmentMap> map = mapFromBytes(*bytes, radiance)) {
            if (progress && !progress(1.0f)) return nullptr;  // cancelled, as makeEnvironmentMap would be
            return std::make_shared<const EnvironmentMap>(std::move(*map));
        }
    }
    std::shared_ptr<const EnvironmentMap> map = makeEnvironmentMap(std::move(radiance), progress);
    if (map) writeCacheEntry(name, lightingBytes(*map));
    return map;
}

}  // namespace glint
