// A job that holds its thread until opened: whatever is handed over behind
// it waits, so a test can look at jobs queued and under way.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>

#include "jobs/job_thread.h"

namespace hg::jobs::test {

class Gate final : public BackgroundJob {
public:
    void open() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            open_ = true;
        }
        opened_.notify_all();
    }
    std::atomic<bool> entered{false};

private:
    void run() override {
        entered = true;
        std::unique_lock<std::mutex> lock(mutex_);
        opened_.wait(lock, [this] { return open_; });
    }
    std::mutex mutex_;
    std::condition_variable opened_;
    bool open_ = false;
};

}  // namespace hg::jobs::test
