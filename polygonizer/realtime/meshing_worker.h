// Meshes chunks off the frame thread (docs/design.md §5, "Work off the frame
// thread"). The remesh queue gathers a batch of chunks' samples on the frame
// thread (ChunkSamples: a copy, so the grid may change at once) and hands
// them to the worker as a job; the worker meshes the job's chunks on its own
// thread (with TBB's workers) and marks it done; the queue takes the meshes
// at a later frame boundary, without waiting. A job owns everything it
// reads, so a queue may go away with its job under way: the job is marked
// abandoned and skipped or dropped.
#pragma once

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "polygonizer/realtime/chunk_mesher.h"

namespace hg::poly {

struct MeshingJob {
    std::vector<std::size_t> chunks;        // which chunk each sample set is
    std::vector<ChunkLod> lods;             // the level each was gathered at
    std::vector<std::uint64_t> stamps;      // the chunk's dirty stamp when gathered
    std::vector<ChunkSamples> samples;      // released once meshed
    std::vector<std::shared_ptr<const Mesh>> meshes;  // filled by the worker
    std::exception_ptr error;               // what meshing threw (the queue rethrows it)

    bool done() const { return done_.load(std::memory_order_acquire); }
    // Blocks until the worker has finished (or skipped) the job.
    void wait() const;
    // The queue no longer wants the meshes: the worker skips a job it has
    // not started.
    void abandon() { abandoned_.store(true, std::memory_order_release); }

private:
    friend class MeshingWorker;
    void finish();
    std::atomic<bool> done_{false};
    std::atomic<bool> abandoned_{false};
    mutable std::mutex mutex_;
    mutable std::condition_variable finished_;
};

class MeshingWorker {
public:
    MeshingWorker();
    // Finishes the job under way; jobs not started are dropped (marked done,
    // without meshes).
    ~MeshingWorker();
    MeshingWorker(const MeshingWorker&) = delete;
    MeshingWorker& operator=(const MeshingWorker&) = delete;

    // Queued behind the jobs already handed over (first come, first meshed).
    void submit(std::shared_ptr<MeshingJob> job);
    // Jobs handed over and not yet finished, and of those not yet started.
    std::size_t backlog() const;
    std::size_t queued() const;

private:
    void run();

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::shared_ptr<MeshingJob>> jobs_;
    std::size_t busy_ = 0;  // jobs taken and under way
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace hg::poly
