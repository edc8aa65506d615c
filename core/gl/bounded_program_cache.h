// BoundedProgramCache: the one eviction policy of the renderer's compiled programs (built-in
// models, backgrounds, .brdf files, MERL). Specialised programs multiply with the scene's choices
// (lights, enums, display), so each cache holds at most `capacity` entries: the least recently
// used goes when a new one needs room, but never one the frame being drawn has used (a frame
// that needs more grows the cache past its capacity until a later frame). An evicted value is
// destroyed, which deletes its GL objects: the context must be current. It builds nothing itself.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>

namespace glint {

template <class Key, class Value>
class BoundedProgramCache {
public:
    explicit BoundedProgramCache(size_t capacity) : capacity_(capacity) {}

    // The value under `key`, marked as used by `frame`; null when absent.
    Value* use(const Key& key, std::uint64_t frame) {
        const auto found = entries_.find(key);
        if (found == entries_.end()) return nullptr;
        found->second.lastUsed = std::max(found->second.lastUsed, frame);
        return &found->second.value;
    }
    // The value under `key`, not marked; null when absent.
    Value* find(const Key& key) {
        const auto found = entries_.find(key);
        return found == entries_.end() ? nullptr : &found->second.value;
    }
    bool contains(const Key& key) const { return entries_.count(key) > 0; }

    // Stores `value` under `key` (replacing any), used by `frame`, after evicting the least
    // recently used entries that `frame` has not used until there is room.
    Value& insert(const Key& key, Value value, std::uint64_t frame) {
        entries_.erase(key);
        while (entries_.size() >= capacity_) {
            const auto oldest = std::min_element(entries_.begin(), entries_.end(), [](const auto& a, const auto& b) {
                return a.second.lastUsed < b.second.lastUsed;
            });
            if (oldest->second.lastUsed >= frame) break;
            entries_.erase(oldest);
        }
        return entries_.insert_or_assign(key, Entry{std::move(value), frame}).first->second.value;
    }

    // Calls visit(key, value) for every entry (to rebuild programs whose files changed, to read them).
    template <class Visit>
    void forEach(Visit&& visit) {
        for (auto& [key, entry] : entries_) visit(key, entry.value);
    }
    template <class Visit>
    void forEach(Visit&& visit) const {
        for (const auto& [key, entry] : entries_) visit(key, entry.value);
    }
    size_t size() const { return entries_.size(); }
    size_t capacity() const { return capacity_; }

private:
    struct Entry {
        Value value;
        std::uint64_t lastUsed = 0;
    };
    size_t capacity_;
    std::map<Key, Entry> entries_;
};

}  // namespace glint
