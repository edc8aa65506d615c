// Renders many independent jobs headless on N threads, each thread with its own OSMesa context
// and Renderer (created once, reused for all its jobs). Jobs are handed out by index; the
// caller stores results by index, so the outcome does not depend on the number of threads.
#pragma once

#include <cstddef>
#include <functional>

#include "runtime/headless.h"

namespace glint {

// Calls job(renderer, index) once for every index in [0, count), on min(threads, count)
// threads (threads = 1: on the calling thread). Fails only when a context cannot be created;
// then no further jobs start.
Status renderInParallel(int threads, size_t count, const std::function<void(HeadlessRenderer&, size_t)>& job);

}  // namespace glint
