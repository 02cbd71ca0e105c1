// Meshes chunks off the frame thread (docs/design.md §5, "Meshing off the frame
// thread"). The remesh queue gathers a batch of chunks' samples on the frame
// thread (ChunkSamples: a copy, so the grid may change at once) and hands
// them to the worker as a job; the worker meshes the job's chunks on its own
// thread (with TBB's workers) and marks it done; the queue takes the meshes
// at a later frame boundary, without waiting. A job owns everything it
// reads, so a queue may go away with its job under way: the job is marked
// abandoned and skipped or dropped.
#pragma once

#include <memory>
#include <vector>

#include "jobs/job_thread.h"
#include "polygonizer/realtime/chunk_mesher.h"

namespace hg::poly {

struct MeshingJob final : jobs::BackgroundJob {
    std::vector<std::size_t> chunks;        // which chunk each sample set is
    std::vector<ChunkLod> lods;             // the level each was gathered at
    std::vector<std::uint64_t> stamps;      // the chunk's dirty stamp when gathered
    std::vector<ChunkSamples> samples;      // released once meshed
    // Filled by the worker; empty for a job dropped by a worker that stopped.
    std::vector<std::shared_ptr<const Mesh>> meshes;

private:
    void run() override;
};

// The thread the queue's jobs run on (one per garden session).
class MeshingWorker final : public jobs::JobThread {};

}  // namespace hg::poly
