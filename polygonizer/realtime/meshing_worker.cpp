#include "polygonizer/realtime/meshing_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace hg::poly {

void MeshingJob::wait() const {
    std::unique_lock<std::mutex> lock(mutex_);
    finished_.wait(lock, [this] { return done(); });
}

void MeshingJob::finish() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        done_.store(true, std::memory_order_release);
    }
    finished_.notify_all();
}

MeshingWorker::MeshingWorker() : thread_([this] { run(); }) {}

MeshingWorker::~MeshingWorker() {
    std::deque<std::shared_ptr<MeshingJob>> left;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        left.swap(jobs_);
    }
    wake_.notify_all();
    thread_.join();
    for (const auto& job : left) job->finish();  // nobody waits for ever
}

void MeshingWorker::submit(std::shared_ptr<MeshingJob> job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        jobs_.push_back(std::move(job));
    }
    wake_.notify_one();
}

std::size_t MeshingWorker::backlog() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return jobs_.size() + busy_;
}

std::size_t MeshingWorker::queued() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return jobs_.size();
}

void MeshingWorker::run() {
    // The frame comes first: this thread yields the CPU to it (a higher
    // nice value, for this thread only on Linux), and its meshing runs in a
    // low-priority arena, so TBB's workers serve the frame's parallel work
    // (edits, the blend) before a job's chunks. On a machine of two cores
    // the frame's stages would otherwise share their cores with the job.
    ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10);
    tbb::task_arena arena(tbb::task_arena::automatic, 1, tbb::task_arena::priority::low);
    for (;;) {
        std::shared_ptr<MeshingJob> job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
            if (stopping_) return;
            job = std::move(jobs_.front());
            jobs_.pop_front();
            ++busy_;
        }
        if (!job->abandoned_.load(std::memory_order_acquire)) {
            MeshingJob& j = *job;
            j.meshes.resize(j.samples.size());
            try {
                arena.execute([&j] {
                    tbb::parallel_for(std::size_t{0}, j.samples.size(), [&j](std::size_t k) {
                        j.meshes[k] = std::make_shared<const Mesh>(meshChunk(j.samples[k]));
                    });
                });
            } catch (...) {
                j.error = std::current_exception();
            }
        }
        job->samples.clear();
        job->samples.shrink_to_fit();
        {
            std::lock_guard<std::mutex> lock(mutex_);
            --busy_;
        }
        job->finish();
    }
}

}  // namespace hg::poly
