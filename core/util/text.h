// Small text helpers shared by Glint's line-based parsers (.brdf, .bparam, .mtl, .obj) and its
// file-type checks, identifiers shown as words, and markup escaping. Nothing here knows any file format.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace glint {

// `text` without leading and trailing white space (a view into the same characters).
inline std::string_view trimmed(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    return text;
}

// A number through a printf format: "%g" for people, "%.9g" to read back as the same float.
inline std::string formatNumber(double value, const char* format = "%g") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// A path's extension without the dot, in lower case: "obj" for "Cow.OBJ"; empty when it has none.
inline std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    if (!extension.empty()) extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// An identifier as words for a label: "red_acrylic" → "Red acrylic".
inline std::string readableName(std::string_view identifier) {
    std::string words(identifier);
    std::replace(words.begin(), words.end(), '_', ' ');
    if (!words.empty()) words[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(words[0])));
    return words;
}

// Escapes &, <, >, " and ' for HTML and XML text and attributes; drops control characters
// that XML 1.0 cannot carry.
inline std::string escapeMarkup(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') break;
                out += c;
        }
    }
    return out;
}

}  // namespace glint
