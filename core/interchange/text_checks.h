// Checks on raw text read from an interchange file before it is parsed: UTF-8 validity, with
// the line of the first bad byte. It does not decode or normalise anything.
#pragma once

#include <optional>
#include <string_view>

namespace glint {

struct TextPosition {
    size_t byteOffset;
    int line;  // 1-based
};

// Where the first byte sequence that is not well-formed UTF-8 (RFC 3629: no overlongs, no
// surrogates, nothing above U+10FFFF) starts, or nothing when all of `text` is UTF-8.
std::optional<TextPosition> findInvalidUtf8(std::string_view text);

}  // namespace glint
