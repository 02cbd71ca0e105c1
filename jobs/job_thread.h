// One thread that runs long work off the frame thread (docs/design.md §5,
// "Meshing off the frame thread" and "The blend off the frame thread"):
// the chunk meshes of the remesh queue (polygonizer/realtime/
// meshing_worker.h) and the morph's blend batches (garden/morph/
// blend_job.h). The frame thread hands a job over and takes
// its result at a later frame boundary, without waiting: a job owns or
// pins everything it reads, and its owner may abandon it (the worker then
// skips it if it has not started).
//
// The frame comes first: the thread runs at a lower priority than the rest
// of the process and its parallel work goes to a low-priority TBB arena, so
// TBB's workers serve the frame's own parallel loops before a job's.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

namespace hg::jobs {

class BackgroundJob {
public:
    BackgroundJob() = default;
    virtual ~BackgroundJob();
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

    bool done() const { return done_.load(std::memory_order_acquire); }
    // Blocks until the worker has finished (or skipped) the job.
    void wait() const;
    // The owner no longer wants the result: a job not started is skipped,
    // and one under way may stop early (run() reads abandoned()).
    void abandon() { abandoned_.store(true, std::memory_order_release); }
    bool abandoned() const { return abandoned_.load(std::memory_order_acquire); }
    // True when run() did: false for a job skipped or dropped.
    bool ran() const { return ran_; }
    // What run() threw (the owner rethrows it when it takes the result).
    std::exception_ptr error;

protected:
    // On the worker thread, inside its low-priority TBB arena.
    virtual void run() = 0;

private:
    friend class JobThread;
    void finish();
    bool ran_ = false;
    std::atomic<bool> done_{false};
    std::atomic<bool> abandoned_{false};
    mutable std::mutex mutex_;
    mutable std::condition_variable finished_;
};

class JobThread {
public:
    JobThread();
    // Finishes the job under way; jobs not started are dropped (marked done
    // without running), so nobody waits for ever.
    virtual ~JobThread();
    JobThread(const JobThread&) = delete;
    JobThread& operator=(const JobThread&) = delete;

    // Queued behind the jobs already handed over (first come, first run).
    void submit(std::shared_ptr<BackgroundJob> job);
    // Jobs handed over and not yet finished, and of those not yet started.
    std::size_t backlog() const;
    std::size_t queued() const;

private:
    void loop();

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::shared_ptr<BackgroundJob>> jobs_;
    std::size_t busy_ = 0;  // jobs taken and under way
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace hg::jobs
