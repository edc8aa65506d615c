// Whole-file reads and atomic writes, with user-facing errors. Saves never leave a half-written
// file behind: they write a temporary file beside the target, then rename it over the target.
#pragma once

#include <string>

#include "util/diagnostic.h"

namespace glint {

Result<std::string> readTextFile(const std::string& path);
Status writeFileAtomically(const std::string& path, const std::string& contents);

// `parse(text, path)` of the file at `path`, or why the file could not be read.
template <class Parse>
auto parseTextFile(const std::string& path, Parse parse) -> decltype(parse(std::string(), path)) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parse(*text, path);
}

}  // namespace glint
