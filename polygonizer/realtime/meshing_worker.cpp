#include "polygonizer/realtime/meshing_worker.h"

#include <tbb/parallel_for.h>

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
                tbb::parallel_for(std::size_t{0}, j.samples.size(), [&j](std::size_t k) {
                    j.meshes[k] = std::make_shared<const Mesh>(meshChunk(j.samples[k]));
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
