// ProgramCompiler: a worker thread whose GL context shares objects with the renderer's
// (GlPlatform::createWorkerContext), where the renderer builds new specialised programs
// (gl/shader_specialisation.h) so that they do not stall the editor: it draws with what it has
// meanwhile and adopts a program once it is linked (gl/renderer.h). Jobs run in order, urgent
// ones before the rest; each ends with glFinish on the worker, so that the program is complete
// before the renderer's context sees it.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include "gl/platform.h"

namespace glint {

class ProgramCompiler {
public:
    enum class Priority { Urgent, Later };
    // `loader`: the renderer's platform's (the same GL functions); `finished` is called on the
    // worker after each job (the editor wakes its event loop with it).
    ProgramCompiler(std::unique_ptr<GlWorkerContext> context, GetProcAddress loader, std::function<void()> finished);
    ~ProgramCompiler();  // finishes the running job, drops the others
    ProgramCompiler(const ProgramCompiler&) = delete;
    ProgramCompiler& operator=(const ProgramCompiler&) = delete;

    // `job` runs on the worker, handed the worker's context as a platform (current throughout);
    // it hands its result over itself.
    using Job = std::function<void(GlPlatform& worker)>;
    void submit(Job job, Priority priority);
    // Run on the worker when it stops, before its context is released (to delete what jobs made there).
    void atStop(std::function<void()> last);

private:
    // The worker's context as a GlPlatform, for renderer code run in jobs.
    class WorkerPlatform final : public GlPlatform {
    public:
        explicit WorkerPlatform(GetProcAddress loader) : loader_(loader) {}
        GetProcAddress procAddressLoader() const override { return loader_; }
        void makeCurrent() override {}  // current on the worker from start to stop
        glm::ivec2 framebufferSize() const override { return {1, 1}; }
        void present() override {}
        const char* name() const override { return "program compiler's context"; }

    private:
        GetProcAddress loader_;
    };
    void run();

    std::unique_ptr<GlWorkerContext> context_;
    WorkerPlatform platform_;
    std::function<void()> last_;
    std::function<void()> finished_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Job> urgent_, later_;
    bool stopping_ = false;
    std::thread worker_;
};

}  // namespace glint
