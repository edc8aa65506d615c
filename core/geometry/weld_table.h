// WeldTable: an open-addressing hash table of indices into the caller's own array (linear
// probing, grows at half load), for sharing equal vertices in one pass; and the hash of a run of
// 32-bit words. It stores no elements and knows nothing of vertices: the caller hashes and compares.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace glint {

// A 64-bit hash of `count` 32-bit words: a multiply-xor per word, then SplitMix64's finaliser
// (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014).
inline uint64_t hashWords(const uint32_t* words, size_t count) {
    uint64_t hash = 0x9E3779B97F4A7C15ull ^ count;
    for (size_t i = 0; i < count; ++i) hash = (hash ^ words[i]) * 0xBF58476D1CE4E5B9ull;
    hash = (hash ^ (hash >> 30)) * 0xBF58476D1CE4E5B9ull;
    hash = (hash ^ (hash >> 27)) * 0x94D049BB133111EBull;
    return hash ^ (hash >> 31);
}

// The bits of a float with −0 taken as +0, so that equal coordinates hash and compare equal.
inline uint32_t floatKey(float value) {
    uint32_t bits;
    std::memcpy(&bits, &value, 4);
    return bits == 0x80000000u ? 0u : bits;
}

class WeldTable {
public:
    explicit WeldTable(size_t expectedElements = 0) { resize(expectedElements); }

    // The stored index whose element equals the candidate's (`equals(storedIndex)` says), or
    // else `candidate`, which is stored now. `hash` must be equal for equal elements.
    template <class Equals>
    uint32_t findOrAdd(uint64_t hash, uint32_t candidate, const Equals& equals) {
        if (2 * (count_ + 1) > slots_.size()) resize(slots_.size());  // doubles
        const auto fragment = static_cast<uint32_t>(hash ^ (hash >> 32));
        const size_t mask = slots_.size() - 1;
        for (size_t at = fragment & mask;; at = (at + 1) & mask) {
            Slot& slot = slots_[at];
            if (slot.index == kEmpty) {
                slot = {fragment, candidate};
                ++count_;
                return candidate;
            }
            if (slot.hash == fragment && equals(slot.index)) return slot.index;
        }
    }

private:
    static constexpr uint32_t kEmpty = UINT32_MAX;
    struct Slot {
        uint32_t hash = 0;  // the 32 bits of the hash that place the slot (kept for regrowing)
        uint32_t index = kEmpty;
    };

    // Room for `elements` at half load.
    void resize(size_t elements) {
        size_t capacity = 16;
        while (capacity < 2 * elements) capacity *= 2;
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(capacity, Slot{});
        const size_t mask = capacity - 1;
        for (const Slot& slot : old) {
            if (slot.index == kEmpty) continue;
            size_t at = slot.hash & mask;
            while (slots_[at].index != kEmpty) at = (at + 1) & mask;
            slots_[at] = slot;
        }
    }

    std::vector<Slot> slots_;
    size_t count_ = 0;
};

}  // namespace glint
