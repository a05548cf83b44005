#pragma once
// Chapter 27's worker threads: a fixed crew that sleeps between frames. Each
// frame, run(job) wakes them, calls job(i) once for every index i from 0 to
// count - 1 (index 0 on the calling thread, the others each on its own
// worker) and returns when all have returned: the fork and the join. Plain
// C++, no Vulkan: what the job records, and into which command buffer, is
// main.cpp's business.
//
// Why a crew and not new threads each frame: starting a thread costs tens of
// microseconds, which at thousands of frames a second is a frame's budget.

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace ch27 {

// [workers]
class Workers {
public:
    explicit Workers(uint32_t count) {
        errors_.resize(count);
        for (uint32_t i = 1; i < count; ++i) threads_.emplace_back([this, i] { work(i); });
    }
    ~Workers() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        for (std::thread& t : threads_) t.join();
    }
    Workers(const Workers&) = delete;
    Workers& operator=(const Workers&) = delete;

    uint32_t count() const { return uint32_t(errors_.size()); }

    // job(i) for every i, at the same time; returns once every call has
    // returned. Everything a call wrote is then visible to this thread (the
    // mutex orders it), and an exception thrown by any call is thrown here.
    void run(const std::function<void(uint32_t)>& job) {
        {
            std::lock_guard lock(mutex_);
            job_ = &job;
            pending_ = count() - 1;
            ++generation_;  // the workers wait for this to change
        }
        wake_.notify_all();
        attempt(job, 0);  // this thread's share, while the others do theirs
        std::unique_lock lock(mutex_);
        done_.wait(lock, [this] { return pending_ == 0; });
        job_ = nullptr;
        for (std::exception_ptr& error : errors_)
            if (error) std::rethrow_exception(std::exchange(error, nullptr));
    }
    // [/workers]

private:
    void attempt(const std::function<void(uint32_t)>& job, uint32_t index) {
        try {
            job(index);
        } catch (...) {
            errors_[index] = std::current_exception();  // index's own slot: no race
        }
    }

    void work(uint32_t index) {
        uint64_t seen = 0;
        for (;;) {
            const std::function<void(uint32_t)>* job = nullptr;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
                if (stop_) return;
                seen = generation_;
                job = job_;
            }
            attempt(*job, index);
            {
                std::lock_guard lock(mutex_);
                --pending_;
            }
            done_.notify_one();
        }
    }

    std::mutex mutex_;
    std::condition_variable wake_;  // a new frame's job, or stop
    std::condition_variable done_;  // a worker finished its share
    const std::function<void(uint32_t)>* job_ = nullptr;
    uint64_t generation_ = 0;
    uint32_t pending_ = 0;
    bool stop_ = false;
    std::vector<std::exception_ptr> errors_;  // one per index, read after the join
    std::vector<std::thread> threads_;
};

}  // namespace ch27
