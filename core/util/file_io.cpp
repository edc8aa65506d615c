// File reads and atomic writes (see file_io.h).
#include "util/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace glint {

Result<std::string> readTextFile(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0)
        return makeError(std::string("cannot open: ") + std::strerror(errno), {path});
    if (S_ISDIR(info.st_mode)) return makeError("is a directory, not a file", {path});
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError(std::string("cannot open: ") + std::strerror(errno), {path});
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) return makeError("read error", {path});
    return buffer.str();
}

Status writeFileAtomically(const std::string& path, const std::string& contents) {
    const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
    FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) return makeError(std::string("cannot write: ") + std::strerror(errno), {path});
    const bool written = std::fwrite(contents.data(), 1, contents.size(), file) == contents.size();
    const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
    const bool closed = std::fclose(file) == 0;
    if (!written || !flushed || !closed) {
        std::remove(temporary.c_str());
        return makeError("write failed (disk full?)", {path});
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        return makeError("cannot replace the file: " + reason, {path});
    }
    return success();
}

}  // namespace glint
