// File reads and atomic writes (see file_io.h).
#include "util/file_io.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <fcntl.h>
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

long long fileModificationTime(const std::string& path) {
    std::error_code error;
    const auto time = std::filesystem::last_write_time(path, error);
    return error ? 0 : std::chrono::duration_cast<std::chrono::nanoseconds>(time.time_since_epoch()).count();
}

namespace {

// "DIR/.NAME.partial-PID.EXT" beside "DIR/NAME.EXT": hidden, unique to this process, same extension.
std::string temporaryBeside(const std::string& path) {
    const std::filesystem::path target(path);
    return (target.parent_path() /
            ("." + target.stem().string() + ".partial-" + std::to_string(::getpid()) + target.extension().string()))
        .string();
}

// The system's reason for the last failure, or `otherwise` when errno holds none.
std::string reason(int error, const char* otherwise) { return error != 0 ? std::strerror(error) : otherwise; }

}  // namespace

Status replaceFileAtomically(const std::string& path, const std::function<Status(const std::string& temporary)>& write) {
    const std::string temporary = temporaryBeside(path);
    const auto failed = [&](const std::string& message) {
        std::remove(temporary.c_str());
        return makeError(message + "; the file is unchanged", {path});
    };
    errno = 0;
    if (Status written = write(temporary); !written) return failed(written.error().message);
    // Flushed to the disk before the rename, so that a crash cannot leave a renamed, empty file.
    const int descriptor = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
    if (descriptor < 0 || ::fsync(descriptor) != 0) {
        const int error = errno;
        if (descriptor >= 0) ::close(descriptor);
        return failed("cannot flush the file to the disk: " + reason(error, "unknown error"));
    }
    ::close(descriptor);
    if (std::rename(temporary.c_str(), path.c_str()) != 0) return failed("cannot replace the file: " + reason(errno, "unknown error"));
    return success();
}

Status writeFileAtomically(const std::string& path, const std::string& contents) {
    return replaceFileAtomically(path, [&](const std::string& temporary) -> Status {
        FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file) return makeError("cannot write: " + reason(errno, "unknown error"));
        const bool written = std::fwrite(contents.data(), 1, contents.size(), file) == contents.size();
        const int writeError = errno;
        const bool closed = std::fclose(file) == 0;
        if (!written || !closed) return makeError("write failed: " + reason(written ? errno : writeError, "unknown error"));
        return success();
    });
}

}  // namespace glint
