// The headless render pool (see render_pool.h).
#include "cli/render_pool.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace glint {

Status renderInParallel(int threads, size_t count, const std::function<void(HeadlessRenderer&, size_t)>& job) {
    std::atomic<size_t> next{0};
    std::mutex errorMutex;
    std::optional<Diagnostic> firstError;
    auto work = [&] {
        auto headless = HeadlessRenderer::create();  // this thread's own context, current from here on
        if (!headless) {
            const std::lock_guard<std::mutex> lock(errorMutex);
            if (!firstError) firstError = headless.error();
            next = count;  // start nothing more
            return;
        }
        for (size_t index = next++; index < count; index = next++) job(**headless, index);
    };
    const size_t workers = std::min<size_t>(static_cast<size_t>(std::max(threads, 1)), std::max<size_t>(count, 1));
    if (workers <= 1) {
        work();
    } else {
        std::vector<std::thread> pool;
        for (size_t i = 0; i < workers; ++i) pool.emplace_back(work);
        for (std::thread& thread : pool) thread.join();
    }
    if (firstError) return *firstError;
    return success();
}

}  // namespace glint
