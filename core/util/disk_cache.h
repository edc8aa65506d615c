// A cache on disk for what Glint computes the same way in every process: the built-in
// environments' precomputed lighting and the directional-albedo tables (about 1.3 s of CPU at
// every start otherwise). Entries live in $GLINT_CACHE_DIR, else $XDG_CACHE_HOME/glint, else
// ~/.cache/glint; an empty GLINT_CACHE_DIR turns the cache off. Each entry is tied to the
// executable that wrote it (its GNU build ID): a rebuilt Glint computes afresh and replaces the
// entry, so a changed computation never meets old numbers. An entry that is missing, truncated
// or damaged (checksum) reads as a miss; a write that fails is ignored.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace glint {

// The bytes stored under `name` (letters, digits, '-') by this executable, if any.
std::optional<std::string> readCacheEntry(const std::string& name);
// Stores `bytes` under `name` (atomically) and removes the entries of other builds under it.
void writeCacheEntry(const std::string& name, const std::string& bytes);

// FNV-1a over `size` bytes: the entries' checksum, and a key for what an entry was made from.
std::uint64_t cacheChecksum(const void* data, size_t size);

// The folder entries go to; empty when the cache is off or this executable has no build ID.
std::string cacheFolder();

// `compute()`'s values (trivially copyable), read from the entry `name` when it holds `count` of
// them, else computed and stored.
template <class T, class Compute>
std::vector<T> cachedValues(const std::string& name, size_t count, Compute compute) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (const std::optional<std::string> bytes = readCacheEntry(name); bytes && bytes->size() == count * sizeof(T)) {
        std::vector<T> values(count);
        std::copy(bytes->begin(), bytes->end(), reinterpret_cast<char*>(values.data()));
        return values;
    }
    std::vector<T> values = compute();
    if (values.size() == count)
        writeCacheEntry(name, std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
    return values;
}

}  // namespace glint
