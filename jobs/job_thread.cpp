#include "jobs/job_thread.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <tbb/task_arena.h>

namespace hg::jobs {

BackgroundJob::~BackgroundJob() = default;

void BackgroundJob::wait() const {
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, [this] { return done(); });
}

void BackgroundJob::finish() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        done_.store(true, std::memory_order_release);
    }
    finished_.notify_all();
}

JobThread::JobThread() : thread_([this] { loop(); }) {}

JobThread::~JobThread() {
    std::deque<std::shared_ptr<BackgroundJob>> left;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        left.swap(jobs_);
    }
    wake_.notify_all();
    thread_.join();
    for (const auto& job : left) job->finish();
}

void JobThread::submit(std::shared_ptr<BackgroundJob> job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        jobs_.push_back(std::move(job));
    }
    wake_.notify_one();
}

std::size_t JobThread::backlog() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return jobs_.size() + busy_;
}

std::size_t JobThread::queued() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return jobs_.size();
}

void JobThread::loop() {
    // A higher nice value, for this thread only on Linux: on a machine of
    // two cores the frame's stages would otherwise share their cores with
    // the job.
    ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10);
    tbb::task_arena arena(tbb::task_arena::automatic, 1, tbb::task_arena::priority::low);
    for (;;) {
        std::shared_ptr<BackgroundJob> job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
            if (stopping_) return;
            job = std::move(jobs_.front());
            jobs_.pop_front();
            ++busy_;
        }
        if (!job->abandoned()) {
            try {
                arena.execute([&job] { job->run(); });
            } catch (...) {
                job->error = std::current_exception();
            }
            job->ran_ = true;
        }
        // Finished and out of the backlog in one step, under the lock that
        // backlog() takes: a backlog of 0 means every job handed over reports
        // done, and a job that reports done is out of the backlog. (With the
        // two apart, BlendJobTest.NewWeightsDropTheJobUnderWay failed once:
        // it saw the backlog empty and the job not yet done.)
        {
            std::lock_guard<std::mutex> lock(mutex_);
            job->finish();
            --busy_;
        }
    }
}

}  // namespace hg::jobs
