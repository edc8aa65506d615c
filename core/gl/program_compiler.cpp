// Programs built on a worker thread (see program_compiler.h).
#include "gl/program_compiler.h"

#include <glad/gl.h>

namespace glint {

ProgramCompiler::ProgramCompiler(std::unique_ptr<GlWorkerContext> context, GetProcAddress loader, std::function<void()> finished)
    : context_(std::move(context)), platform_(loader), finished_(std::move(finished)), worker_([this] { run(); }) {}

ProgramCompiler::~ProgramCompiler() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

void ProgramCompiler::atStop(std::function<void()> last) {
    std::lock_guard lock(mutex_);
    last_ = std::move(last);
}

void ProgramCompiler::submit(Job job, Priority priority) {
    {
        std::lock_guard lock(mutex_);
        (priority == Priority::Urgent ? urgent_ : later_).push_back(std::move(job));
    }
    wake_.notify_all();
}

void ProgramCompiler::run() {
    context_->makeCurrent();
    for (;;) {
        Job job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !urgent_.empty() || !later_.empty(); });
            if (stopping_) break;
            auto& queue = urgent_.empty() ? later_ : urgent_;
            job = std::move(queue.front());
            queue.pop_front();
        }
        job(platform_);
        glFinish();  // the program is complete before the renderer's context uses it
        if (finished_) finished_();
    }
    std::function<void()> last;
    {
        std::lock_guard lock(mutex_);
        last = std::move(last_);
    }
    if (last) last();
    context_->release();
}

}  // namespace glint
