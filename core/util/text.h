// Small text helpers shared by Glint's line-based parsers (.brdf, .bparam, .mtl). Nothing here
// knows any file format.
#pragma once

#include <cctype>
#include <string_view>

namespace glint {

// `text` without leading and trailing white space (a view into the same characters).
inline std::string_view trimmed(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    return text;
}

}  // namespace glint
