// Crash guard (see crash_guard.h). Publication protocol: a new buffer is filled completely, then
// its pointer is stored atomically; the buffer it replaced is freed only at the next
// publication, so a handler that loaded the old pointer an instant earlier still reads valid
// memory (the handler never runs longer than the time between two edits).
#include "editor/crash_guard.h"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace glint {
namespace {

struct CrashCopy {
    size_t size;
    char text[1];  // `size` bytes follow
};

constexpr int kGuardedSignals[] = {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL, SIGTERM, SIGINT, SIGHUP};
constexpr size_t kMaxPath = 4096;

char gRecoveryPath[kMaxPath];
char gTemporaryPath[kMaxPath + 16];
std::atomic<CrashCopy*> gPublished{nullptr};
CrashCopy* gRetired = nullptr;  // the copy before gPublished, freed at the next publication
std::atomic<bool> gHandling{false};

void writeAll(int descriptor, const char* data, size_t size) {
    while (size > 0) {
        const ssize_t written = ::write(descriptor, data, size);
        if (written <= 0) return;
        data += written;
        size -= static_cast<size_t>(written);
    }
}

extern "C" void onFatalSignal(int signalNumber) {
    if (!gHandling.exchange(true)) {
        if (const CrashCopy* copy = gPublished.load(); copy && copy->size > 0) {
            const int descriptor = ::open(gTemporaryPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (descriptor >= 0) {
                writeAll(descriptor, copy->text, copy->size);
                ::fsync(descriptor);
                ::close(descriptor);
                ::rename(gTemporaryPath, gRecoveryPath);
            }
        }
    }
    std::signal(signalNumber, SIG_DFL);
    std::raise(signalNumber);
}

}  // namespace

void installCrashGuard(const std::string& recoveryPath) {
    const size_t length = std::min(recoveryPath.size(), kMaxPath - 1);
    std::memcpy(gRecoveryPath, recoveryPath.data(), length);
    gRecoveryPath[length] = '\0';
    std::memcpy(gTemporaryPath, gRecoveryPath, length);
    std::memcpy(gTemporaryPath + length, ".crash", 7);
    for (int signalNumber : kGuardedSignals) std::signal(signalNumber, onFatalSignal);
}

void publishCrashCopy(const std::string& text) {
    auto* copy = static_cast<CrashCopy*>(std::malloc(sizeof(CrashCopy) + text.size()));
    if (!copy) return;
    copy->size = text.size();
    std::memcpy(copy->text, text.data(), text.size());
    CrashCopy* previous = gPublished.exchange(copy);
    std::free(gRetired);
    gRetired = previous;
}

void uninstallCrashGuard() {
    for (int signalNumber : kGuardedSignals) std::signal(signalNumber, SIG_DFL);
    std::free(gPublished.exchange(nullptr));
    std::free(gRetired);
    gRetired = nullptr;
}

}  // namespace glint
