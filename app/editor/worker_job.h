// A result computed on a worker thread while the editor keeps drawing: the work is offered a
// progress callback (fraction in [0, 1]; it answers false once cancel() was asked), the fraction is
// published atomically for the frame loop to show, and the result is taken once finished().
// The destructor cancels and waits, so work must offer progress often (every few ms).
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace glint {

template <class T>
class WorkerJob {
public:
    using Progress = std::function<bool(float fraction)>;

    explicit WorkerJob(std::function<T(const Progress&)> work) {
        thread_ = std::thread([this, work = std::move(work)] {
            const Progress progress = [this](float fraction) {
                progress_.store(fraction);
                return !cancelRequested_.load();
            };
            T result = work(progress);
            {
                std::lock_guard lock(resultMutex_);
                result_.emplace(std::move(result));
            }
            finished_.store(true);
        });
    }
    ~WorkerJob() {
        cancel();
        if (thread_.joinable()) thread_.join();
    }
    WorkerJob(const WorkerJob&) = delete;
    WorkerJob& operator=(const WorkerJob&) = delete;

    float progress() const { return progress_.load(); }
    void cancel() { cancelRequested_.store(true); }
    bool cancelRequested() const { return cancelRequested_.load(); }
    bool finished() const { return finished_.load(); }
    // The work's result once finished() (taken once; empty before and after).
    std::optional<T> takeResult() {
        std::lock_guard lock(resultMutex_);
        std::optional<T> taken = std::move(result_);
        result_.reset();
        return taken;
    }

private:
    std::atomic<float> progress_{0.0f};
    std::atomic<bool> cancelRequested_{false};
    std::atomic<bool> finished_{false};
    std::mutex resultMutex_;
    std::optional<T> result_;
    std::thread thread_;  // last: started once the members above exist
};

}  // namespace glint
