// Keeps every chunk's mesh up to date as the grid and the levels of detail
// change, a budget at a time (docs/design.md §5, incremental):
//
//   markChanged(box)  the grid changed there (after LodPyramid::update):
//                     chunks that read it are dirty;
//   setLevels(levels) new levels (selectLevels): chunks whose level or
//                     transition faces change are dirty;
//   process(budget)   meshes dirty chunks on TBB workers, explicit priority
//                     first, then nearest to the viewer, then coarser,
//                     while the next batch is expected to fit the budget
//                     (milliseconds or chunks); one batch (a chunk per
//                     worker) always runs.
//   processInBackground(worker, budget)
//                     the same work off the calling thread: meshes the
//                     worker has finished are taken, complete groups shown,
//                     and the next dirty chunks' samples gathered here and
//                     handed to the worker (meshing_worker.h). Never waits.
//
// A chunk keeps showing its old mesh until its new one is ready, and new
// meshes are shown a group at a time: a group is a set of dirty chunks
// touching each other (faces, edges or corners), shown together once all are
// meshed. Every chunk next to a group is then already up to date, so the
// surface on screen is always one closed surface of one consistent
// configuration: never a hole or a crack, even halfway through an update.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "polygonizer/realtime/chunk_mesher.h"

namespace hg::poly {

class MeshingWorker;
struct MeshingJob;

struct RemeshBudget {
    double milliseconds = 0.0;  // 0: no time limit
    std::size_t chunks = 0;     // 0: no count limit
    // New meshes shown, in bytes (meshBytes; the default: no limit): what
    // a renderer will upload after this call. Complete groups are shown while their
    // bytes fit; a group is never split (that would show a crack), so one
    // larger than the limit is shown alone, when `oversized` allows it (the
    // caller has shown nothing else this frame). The rest stay staged.
    std::size_t showBytes = std::numeric_limits<std::size_t>::max();
    bool oversized = true;
    // processInBackground only: hand the worker new chunks (false: only take
    // back what it has finished, and show).
    bool gather = true;
};

// Bytes of a mesh as uploaded: positions, normals and indices.
std::size_t meshBytes(const Mesh& m);

struct RemeshReport {
    std::size_t meshed = 0;     // chunks meshed in this call
    std::vector<std::size_t> chunks;  // which, in the order they were taken
    std::size_t shown = 0;      // chunks whose new mesh became visible
    std::size_t groupsShown = 0;
    std::size_t bytesShown = 0; // meshBytes of the meshes shown
    std::size_t pending = 0;    // dirty chunks left (meshed or not, not yet shown)
    std::size_t triangles = 0;  // triangles meshed in this call
    double seconds = 0.0;
};

class RemeshQueue {
public:
    // Every chunk starts dirty at `levels`; nothing is shown before the
    // first process(). `pyramid` and `layout` must outlive the queue.
    RemeshQueue(const LodPyramid& pyramid, const ChunkLayout& layout, const std::vector<int>& levels);

    void setLevels(const std::vector<int>& levels);
    void markChanged(const voxel::IndexBox& box);
    void setViewer(const std::array<double, 3>& position) { viewer_ = position; }
    // Higher goes first (the active tool's chunks, say); 0 by default.
    void setPriority(std::size_t chunk, int priority);
    void clearPriorities();

    // Waits for a job under way first (its meshes count as meshed here).
    RemeshReport process(const RemeshBudget& budget);
    // Budget: `milliseconds` bounds the gathering on this thread (one chunk
    // always), `chunks` the chunks per job (0: four per hardware thread);
    // the bytes shown as in process(). One job per queue is under way at a
    // time: a new one is handed over once the last one's meshes are taken.
    RemeshReport processInBackground(MeshingWorker& worker, const RemeshBudget& budget);
    // A job handed to the worker and not yet taken back.
    bool meshing() const { return job_ != nullptr; }
    ~RemeshQueue();
    RemeshQueue(const RemeshQueue&) = delete;
    RemeshQueue& operator=(const RemeshQueue&) = delete;

    // What is on screen: the mesh (null before the chunk's first mesh), the
    // level it was made at, and a counter that grows when it is replaced
    // (what a renderer compares to know it must upload again).
    std::shared_ptr<const Mesh> mesh(std::size_t chunk) const { return slots_[chunk].shown; }
    const ChunkLod& shownLod(std::size_t chunk) const { return slots_[chunk].shownLod; }
    std::uint64_t version(std::size_t chunk) const { return slots_[chunk].version; }
    // Grows whenever any chunk's shown mesh changes: a renderer that saw
    // this value has nothing new to upload.
    std::uint64_t shownGeneration() const { return shownGeneration_; }
    // Grows with each markChanged (the surface itself changed, not its
    // levels): what a picture of the whole sculpture, an impostor, follows.
    std::uint64_t changes() const { return changes_; }
    // Dirty chunks (meshed or not, not yet shown), and the triangles of
    // every shown mesh: counted as they change, so a garden of thousands
    // of chunks asks for them every frame at no cost.
    std::size_t pending() const { return dirty_; }
    std::size_t shownTriangles() const { return shownTriangles_; }
    // Bytes of the meshes held, shown and staged (meshBytes; a walk over
    // the chunks: for reports, not every frame).
    std::size_t meshBytesHeld() const;
    std::size_t count() const { return slots_.size(); }

private:
    struct Slot {
        std::shared_ptr<const Mesh> shown, staged;
        ChunkLod shownLod, target, stagedLod;
        bool dirty = false;
        bool inJob = false;  // its samples are with the worker
        std::uint64_t stamp = 0, stagedStamp = 0;  // staged is current when the stamps agree
        std::uint64_t version = 0;
        int priority = 0;
    };

    void markDirty(std::size_t chunk);
    std::vector<std::size_t> order() const;
    void showCompleteGroups(const RemeshBudget& budget, RemeshReport& report);
    void stage(std::size_t chunk, std::shared_ptr<const Mesh> mesh, const ChunkLod& lod, std::uint64_t stamp,
               RemeshReport& report);
    // Takes the job's meshes if it has finished (or, with `wait`, once it has).
    void takeJob(bool wait, RemeshReport& report);

    const LodPyramid& pyramid_;
    const ChunkLayout& layout_;
    std::vector<Slot> slots_;
    std::array<double, 3> viewer_{};
    std::uint64_t shownGeneration_ = 0;
    std::uint64_t changes_ = 0;
    std::size_t dirty_ = 0;
    std::size_t shownTriangles_ = 0;
    std::shared_ptr<MeshingJob> job_;  // under way on a worker
};

}  // namespace hg::poly
