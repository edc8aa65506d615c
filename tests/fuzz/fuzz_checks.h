// What the libFuzzer targets share: the input as text, and the rule every reader keeps on any
// bytes: a read that fails says why.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace glint::fuzz {

inline std::string text(const uint8_t* data, size_t size) { return {reinterpret_cast<const char*>(data), size}; }

// Whether `read` succeeded; traps when it failed without a message.
template <class Read>
bool readOrExplained(const Read& read) {
    if (!read && read.error().message.empty()) __builtin_trap();
    return static_cast<bool>(read);
}

}  // namespace glint::fuzz
