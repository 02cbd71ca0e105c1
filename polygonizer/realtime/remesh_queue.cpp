#include "polygonizer/realtime/remesh_queue.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <tuple>

#include "polygonizer/realtime/lod_selection.h"
#include "polygonizer/realtime/meshing_worker.h"

namespace hg::poly {

namespace {

// Milliseconds since a call began: both kinds of call spend a budget in ms.
class Stopwatch {
public:
    double ms() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

std::size_t meshBytes(const Mesh& m) {
    return (m.positions.size() + m.normals.size()) * sizeof(float) + m.indices.size() * sizeof(std::uint32_t);
}

std::size_t RemeshQueue::meshBytesHeld() const {
    std::size_t n = 0;
    for (const Slot& s : slots_) {
        if (s.shown) n += meshBytes(*s.shown);
        if (s.staged && s.staged != s.shown) n += meshBytes(*s.staged);
    }
    return n;
}

RemeshQueue::RemeshQueue(const LodPyramid& pyramid, const ChunkLayout& layout, const std::vector<int>& levels)
    : pyramid_(pyramid), layout_(layout), slots_(layout.count()) {
    const std::vector<ChunkLod> lods = chunkLods(layout, levels);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        slots_[i].target = lods[i];
        markDirty(i);
    }
}

RemeshQueue::~RemeshQueue() {
    if (job_) job_->abandon();
}

void RemeshQueue::markDirty(std::size_t chunk) {
    Slot& s = slots_[chunk];
    if (!s.dirty) ++dirty_;
    s.dirty = true;
    ++s.stamp;  // a mesh staged before this no longer counts
}

void RemeshQueue::setLevels(const std::vector<int>& levels) {
    const std::vector<ChunkLod> lods = chunkLods(layout_, levels);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (lods[i] == slots_[i].target) continue;
        slots_[i].target = lods[i];
        markDirty(i);
    }
}

void RemeshQueue::markChanged(const voxel::IndexBox& box) {
    ++changes_;
    // A chunk reads its level's samples from its low corner to one past its
    // high corner, and one more on each side for gradients: at most one
    // cell of the coarsest level beyond its voxels. Only the chunks whose
    // reach can meet the box are looked at (a morph step reports thousands
    // of small boxes).
    const int size = layout_.chunkSize();
    const int reach = 1 << pyramid_.levels();  // more than any level's cell
    const ChunkKey lo = layout_.keyOf(box.lo[0] - reach, box.lo[1] - reach, box.lo[2] - reach);
    const ChunkKey hi = layout_.keyOf(box.hi[0] + reach, box.hi[1] + reach, box.hi[2] + reach);
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                const ChunkKey k{x, y, z};
                if (!layout_.contains(k)) continue;
                const std::size_t i = layout_.index(k);
                const voxel::IndexBox v = layout_.voxels(i);
                const int cell = 1 << std::max(slots_[i].target.level, slots_[i].shownLod.level);
                bool touches = true;
                for (int a = 0; a < 3 && touches; ++a)
                    touches = box.hi[a] >= v.lo[a] - cell && box.lo[a] <= v.lo[a] + size + cell;
                if (touches) markDirty(i);
            }
}

void RemeshQueue::setPriority(std::size_t chunk, int priority) { slots_[chunk].priority = priority; }

void RemeshQueue::clearPriorities() {
    for (Slot& s : slots_) s.priority = 0;
}

// Dirty chunks without a current staged mesh: explicit priority, then
// nearest, then coarser first (cheaper, and it covers more).
std::vector<std::size_t> RemeshQueue::order() const {
    std::vector<std::tuple<int, double, int, std::size_t>> keyed;
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        const Slot& s = slots_[i];
        if (!s.dirty || s.inJob || (s.staged && s.stagedStamp == s.stamp)) continue;
        keyed.emplace_back(-s.priority, distanceToChunk(layout_, i, viewer_), -s.target.level, i);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::size_t> out;
    out.reserve(keyed.size());
    for (const auto& k : keyed) out.push_back(std::get<3>(k));
    return out;
}

// A mesh made from the chunk's samples of `stamp`: staged unless the chunk
// changed since (then it stays dirty and is meshed again).
void RemeshQueue::stage(std::size_t chunk, std::shared_ptr<const Mesh> mesh, const ChunkLod& lod, std::uint64_t stamp,
                        RemeshReport& report) {
    report.chunks.push_back(chunk);
    ++report.meshed;
    report.triangles += mesh->triangleCount();
    Slot& s = slots_[chunk];
    if (stamp != s.stamp) return;
    s.staged = std::move(mesh);
    s.stagedLod = lod;
    s.stagedStamp = stamp;
}

void RemeshQueue::takeJob(bool wait, RemeshReport& report) {
    if (!job_ || (!wait && !job_->done())) return;
    job_->wait();
    const std::shared_ptr<MeshingJob> job = std::move(job_);
    job_.reset();
    for (std::size_t k = 0; k < job->chunks.size(); ++k) slots_[job->chunks[k]].inJob = false;
    if (job->error) std::rethrow_exception(job->error);
    if (job->meshes.size() != job->chunks.size()) return;  // dropped by a worker that stopped: mesh again
    for (std::size_t k = 0; k < job->chunks.size(); ++k)
        stage(job->chunks[k], std::move(job->meshes[k]), job->lods[k], job->stamps[k], report);
}

RemeshReport RemeshQueue::processInBackground(MeshingWorker& worker, const RemeshBudget& budget) {
    const Stopwatch watch;
    RemeshReport report;
    takeJob(false, report);
    showCompleteGroups(budget, report);
    if (report.shown > 0) ++shownGeneration_;
    if (!job_ && budget.gather) {
        const std::vector<std::size_t> todo = order();
        const std::size_t threads = static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
        const std::size_t most = budget.chunks > 0 ? budget.chunks : 4 * threads;
        auto job = std::make_shared<MeshingJob>();
        for (std::size_t i : todo) {
            if (job->chunks.size() >= most) break;
            if (!job->chunks.empty() && budget.milliseconds > 0.0 && watch.ms() > budget.milliseconds) break;
            Slot& s = slots_[i];
            job->samples.push_back(gatherChunk(pyramid_, layout_, i, s.target));
            job->chunks.push_back(i);
            job->lods.push_back(s.target);
            job->stamps.push_back(s.stamp);
            s.inJob = true;
        }
        if (!job->chunks.empty()) {
            job_ = job;
            worker.submit(std::move(job));
        }
    }
    report.pending = pending();
    report.seconds = watch.ms() / 1000.0;
    return report;
}

RemeshReport RemeshQueue::process(const RemeshBudget& budget) {
    const Stopwatch watch;
    RemeshReport report;
    takeJob(true, report);  // a job's meshes are not counted against the budget
    const std::vector<std::size_t> todo = order();
    const std::size_t batch = static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    std::size_t next = 0;
    double lastBatchMs = 0.0;
    while (next < todo.size()) {
        // The first batch always runs, so every call makes progress; the
        // caller decides whether there is time for a call at all. A later
        // batch starts only if one like the last still fits: stopping once
        // the budget is spent would overshoot it by a batch.
        const double before = watch.ms();
        if (next > 0 && budget.milliseconds > 0.0 && before + lastBatchMs > budget.milliseconds) break;
        std::size_t take = std::min(batch, todo.size() - next);
        if (budget.chunks > 0) take = std::min(take, budget.chunks - next);
        if (take == 0) break;
        std::vector<std::shared_ptr<const Mesh>> made(take);
        tbb::parallel_for(std::size_t{0}, take, [&](std::size_t k) {
            const std::size_t i = todo[next + k];
            made[k] = std::make_shared<const Mesh>(meshChunk(pyramid_, layout_, i, slots_[i].target));
        });
        for (std::size_t k = 0; k < take; ++k) {
            const Slot& s = slots_[todo[next + k]];
            stage(todo[next + k], std::move(made[k]), s.target, s.stamp, report);
        }
        next += take;
        lastBatchMs = watch.ms() - before;
    }
    showCompleteGroups(budget, report);
    if (report.shown > 0) ++shownGeneration_;
    report.pending = pending();
    report.seconds = watch.ms() / 1000.0;
    return report;
}

// Groups of dirty chunks touching each other (26 neighbours), shown when
// every member has a current staged mesh and their bytes fit the budget.
void RemeshQueue::showCompleteGroups(const RemeshBudget& budget, RemeshReport& report) {
    std::vector<int> group(slots_.size(), -1);
    std::vector<std::size_t> members, stack;
    int groups = 0;
    for (std::size_t seed = 0; seed < slots_.size(); ++seed) {
        if (!slots_[seed].dirty || group[seed] >= 0) continue;
        members.clear();
        stack.assign(1, seed);
        group[seed] = groups;
        bool complete = true;
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            members.push_back(i);
            const Slot& s = slots_[i];
            complete = complete && s.staged && s.stagedStamp == s.stamp;
            const ChunkKey k = layout_.key(i);
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const ChunkKey m{k.x + dx, k.y + dy, k.z + dz};
                        if (!layout_.contains(m)) continue;
                        const std::size_t j = layout_.index(m);
                        if (!slots_[j].dirty || group[j] >= 0) continue;
                        group[j] = groups;
                        stack.push_back(j);
                    }
        }
        ++groups;
        if (!complete) continue;
        if (budget.showBytes != std::numeric_limits<std::size_t>::max()) {
            std::size_t bytes = 0;
            for (std::size_t i : members) bytes += meshBytes(*slots_[i].staged);
            const bool fits = report.bytesShown + bytes <= budget.showBytes;
            const bool alone = budget.oversized && report.groupsShown == 0;
            if (!fits && !alone) continue;
        }
        ++report.groupsShown;
        for (std::size_t i : members) {
            Slot& s = slots_[i];
            if (s.shown) shownTriangles_ -= s.shown->triangleCount();
            s.shown = std::move(s.staged);
            shownTriangles_ += s.shown->triangleCount();
            report.bytesShown += meshBytes(*s.shown);
            s.shownLod = s.stagedLod;
            s.dirty = false;
            --dirty_;
            ++s.version;
            ++report.shown;
        }
    }
}

}  // namespace hg::poly
