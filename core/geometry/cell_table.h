// CellTable: an open-addressing hash map from 64-bit keys (packed grid cells, packed edges) to
// 32-bit indices, for the mesh analyses that touch every vertex of a million-triangle mesh
// (mesh_topology.cpp, mesh_simplify.cpp), where std::unordered_map's node per entry costs several
// times more. Insert and find only; no erase, no iteration.
#pragma once

#include <cstdint>
#include <vector>

namespace glint {

class CellTable {
public:
    static constexpr uint32_t kAbsent = 0xffffffffu;

    // Room for `expectedEntries` at a load factor of at most 1/2 (it never grows).
    explicit CellTable(size_t expectedEntries) {
        size_t capacity = 16;
        while (capacity < 2 * expectedEntries) capacity *= 2;
        keys_.assign(capacity, kEmptyKey);
        values_.assign(capacity, kAbsent);
        mask_ = capacity - 1;
    }

    uint32_t find(uint64_t key) const {
        for (size_t slot = hash(key) & mask_;; slot = (slot + 1) & mask_) {
            if (keys_[slot] == key) return values_[slot];
            if (keys_[slot] == kEmptyKey) return kAbsent;
        }
    }

    // The value stored under `key`, or `value` after storing it there when there was none. At
    // most `expectedEntries` distinct keys may be inserted.
    uint32_t findOrInsert(uint64_t key, uint32_t value) {
        for (size_t slot = hash(key) & mask_;; slot = (slot + 1) & mask_) {
            if (keys_[slot] == key) return values_[slot];
            if (keys_[slot] == kEmptyKey) {
                keys_[slot] = key;
                values_[slot] = value;
                return value;
            }
        }
    }

private:
    static constexpr uint64_t kEmptyKey = ~0ull;  // callers' keys never have all 64 bits set
    // The finaliser of MurmurHash3 (Appleby): neighbouring cells land far apart.
    static uint64_t hash(uint64_t key) {
        key ^= key >> 33;
        key *= 0xff51afd7ed558ccdull;
        key ^= key >> 33;
        key *= 0xc4ceb9fe1a85ec53ull;
        return key ^ (key >> 33);
    }

    std::vector<uint64_t> keys_;
    std::vector<uint32_t> values_;
    size_t mask_ = 0;
};

}  // namespace glint
