// Whole-file reads and atomic writes, with user-facing errors. Saves never leave a half-written
// file behind: they write a temporary file beside the target, flush it to the disk, then rename it
// over the target; on any error the temporary is removed and the target is as it was.
#pragma once

#include <functional>
#include <string>

#include "util/diagnostic.h"

namespace glint {

Result<std::string> readTextFile(const std::string& path);

// When the file at `path` was last written [ns since the file clock's epoch], or 0 when it cannot
// be read; for caches that must notice an edited file.
long long fileModificationTime(const std::string& path);
Status writeFileAtomically(const std::string& path, const std::string& contents);

// Replaces `path` with what `write(temporary)` writes to a temporary file in the same folder (with
// the same extension, for writers that choose the format by it, such as OpenImageIO's). Errors:
// write()'s, or the flush or rename's, naming `path` and the system's reason.
Status replaceFileAtomically(const std::string& path, const std::function<Status(const std::string& temporary)>& write);

// `parse(text, path)` of the file at `path`, or why the file could not be read.
template <class Parse>
auto parseTextFile(const std::string& path, Parse parse) -> decltype(parse(std::string(), path)) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parse(*text, path);
}

}  // namespace glint
