#include "voxel/sampler.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>

#include "voxel/box_walker.h"
#include "voxel/memory_guard.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

namespace {

using Clock = std::chrono::steady_clock;

// A leaf node and what a leaf of evaluated voxels costs in the tree.
constexpr std::uint64_t kLeafBytes = sizeof(FloatLeaf) + FloatLeaf::SIZE * sizeof(float) + 64;
constexpr std::uint64_t kLeavesPerTask = (kTaskBoxSize / kLeafSize) * (kTaskBoxSize / kLeafSize) * (kTaskBoxSize / kLeafSize);

// The two phases of a walk over `clip`: top boxes (128^3) down to task boxes
// (32^3), then each task box to its leaves. Between them `beforeTasks` sees
// how many task boxes are left and may stop the walk by returning false.
// Once `stop` (may be null) is cancelled the boxes left are skipped and the
// walk returns false.
struct Walk {
    std::vector<WalkOutput> outputs;  // top boxes, then task boxes, in order
    WalkCounters counters;
    frep::ErrorReport errors;
};

template <class Between, class PerTask>
bool runWalk(const frep::Model& model, const VolumeFrame& frame, double scale, const IndexBox& clip, Walk& walk,
             Between beforeTasks, PerTask afterTask, const io::Progress* stop = nullptr) {
    auto stopped = [stop] { return stop && stop->cancelled(); };
    tbb::enumerable_thread_specific<std::unique_ptr<BoxWalker>> walkers;
    auto walker = [&]() -> BoxWalker& {
        auto& w = walkers.local();
        if (!w) w = std::make_unique<BoxWalker>(model, frame, scale);
        return *w;
    };
    std::vector<std::array<int, 3>> tops = alignedBoxes(clip, kTopBoxSize);
    std::vector<WalkOutput> topOut(tops.size());
    std::vector<std::vector<DeferredBox>> deferred(tops.size());
    tbb::parallel_for(std::size_t{0}, tops.size(), [&](std::size_t i) {
        if (stopped()) return;
        walker().walk(tops[i].data(), kTopBoxSize, clip, topOut[i], kTaskBoxSize, &deferred[i]);
    });
    std::vector<DeferredBox> tasks;
    for (auto& d : deferred) tasks.insert(tasks.end(), d.begin(), d.end());
    if (stopped() || !beforeTasks(tasks.size())) return false;

    std::vector<WalkOutput> taskOut(tasks.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tasks.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            if (stopped()) return;
            walker().walk(tasks[i].origin.data(), kTaskBoxSize, clip, taskOut[i], 0, nullptr, tasks[i].tape);
            afterTask(i, taskOut[i]);
        }
    });
    if (stopped()) return false;
    walk.outputs = std::move(topOut);
    walk.outputs.insert(walk.outputs.end(), std::make_move_iterator(taskOut.begin()),
                        std::make_move_iterator(taskOut.end()));
    for (const WalkOutput& o : walk.outputs) {
        walk.counters.add(o.counters);
        walk.errors.merge(o.errors);
    }
    return true;
}

void copyStats(const Walk& walk, SampleStats& stats) {
    stats.boxesTested = walk.counters.boxesTested;
    stats.boxesCulled = walk.counters.boxesInside + walk.counters.boxesOutside;
    stats.samples = walk.counters.samples;
    stats.leaves = walk.counters.leaves;
    stats.leafTapeMax = walk.counters.leafTapeMax;
    stats.leafTapes = walk.counters.leafTapes;
    stats.leafTapeMean = walk.counters.leafTapes
                             ? static_cast<double>(walk.counters.leafTapeSum) / static_cast<double>(walk.counters.leafTapes)
                             : 0.0;
    stats.pointTapeMean = walk.counters.pointTapes ? static_cast<double>(walk.counters.pointTapeSum) /
                                                         static_cast<double>(walk.counters.pointTapes)
                                                   : 0.0;
    stats.errors = walk.errors;
}

std::unique_ptr<FloatLeaf> makeLeaf(const LeafSamples& s, float background, float band) {
    auto leaf = std::make_unique<FloatLeaf>(openvdb::Coord(s.origin[0], s.origin[1], s.origin[2]), background, false);
    for (openvdb::Index i = 0; i < FloatLeaf::SIZE; ++i) {
        float v = s.values[i];
        if (std::fabs(v) < band) leaf->setValueOn(i, v);
        else leaf->setValueOff(i, v);
    }
    return leaf;
}

// The walk over `clip` and the tree it gives (fills, then the leaves built
// on the workers, pruned): what voxelize() stores there. False, with
// `error`, when the memory guard refuses the walk's task boxes or
// options.progress is cancelled (io::kCancelled).
bool sampleTree(const frep::Model& model, const VolumeFrame& frame, double scale, const IndexBox& clip,
                const SampleOptions& options, SampleStats& stats, std::string& error, openvdb::FloatTree& tree) {
    const std::uint64_t limit = memoryLimit(options.memoryLimit);
    io::ProgressRange progress(options.progress, 0.0, 1.0);  // a flag to ask even when nobody watches
    std::atomic<std::size_t> done{0};
    std::size_t total = 0;
    std::vector<std::vector<std::unique_ptr<FloatLeaf>>> built;
    const float band = frame.band;
    Walk walk;
    bool ran = runWalk(
        model, frame, scale, clip, walk,
        [&](std::size_t tasks) {
            // Every task box could at worst fill all its leaves.
            stats.estimatedBytes = tasks * kLeavesPerTask * kLeafBytes;
            error = refuseIfTooBig("the narrow-band grid", frame.resolution, stats.estimatedBytes, limit, 2.0);
            total = tasks;
            built.resize(tasks);
            return error.empty();
        },
        [&](std::size_t i, WalkOutput& out) {
            // Leaves are built on the workers; the samples are freed at once.
            for (const LeafSamples& s : out.leaves) built[i].push_back(makeLeaf(s, -band, band));
            out.leaves.clear();
            out.leaves.shrink_to_fit();
            std::size_t d = ++done;
            if (d % std::max<std::size_t>(1, total / 200) == 0 || d == total)
                progress.interrupted(static_cast<double>(d) / static_cast<double>(total));
        },
        &progress);
    if (!ran) {
        if (error.empty()) error = io::kCancelled;
        return false;
    }
    copyStats(walk, stats);

    // Top boxes stop at task boxes, so only task outputs hold leaves, and
    // those were built on the workers.
    const std::size_t tops = walk.outputs.size() - built.size();
    for (std::size_t i = 0; i < walk.outputs.size(); ++i) {
        for (const BoxFill& f : walk.outputs[i].fills)
            if (f.value != -band) tree.fill(toCoordBBox(f.box), f.value, false);
        if (i >= tops)
            for (auto& leaf : built[i - tops]) tree.addLeaf(leaf.release());
    }
    tree.prune();
    return true;
}

}  // namespace

VoxelizeResult voxelize(const frep::Model& model, const VolumeRequest& request, const SampleOptions& options) {
    VoxelizeResult result;
    auto start = Clock::now();
    // A bad request is refused before a model box is searched for (which may
    // take two coarse samplings).
    if (std::string why = checkResolutionAndBand(request.resolution, request.band); !why.empty()) {
        result.error = why;
        return result;
    }
    if (std::string why = resolveModelBox(model, request.box, result.modelBox); !why.empty()) {
        result.error = why;
        return result;
    }
    VolumeFrame frame;
    if (std::string why = makeFrame(result.modelBox.box, request.resolution, request.band, frame); !why.empty()) {
        result.error = why;
        return result;
    }
    result.normalization = estimateNormalization(model, frame);
    const double scale = result.normalization.scale;
    SampleStats& stats = result.stats;
    stats.voxels = frame.indexBox.volume();

    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(-frame.band);
    grid->setTransform(frameTransform(frame));
    grid->setName(request.source.body);
    if (!sampleTree(model, frame, scale, frame.indexBox, options, stats, result.error, grid->tree())) {
        result.cancelled = options.progress && options.progress->cancelled();
        if (result.cancelled) result.error = io::kCancelled;
        return result;
    }

    Volume volume;
    volume.frame = frame;
    volume.normalization = scale;
    volume.boxOrigin = result.modelBox.origin;
    volume.source = request.source;
    volume.grid().grid = grid;
    stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.volume = std::move(volume);
    return result;
}

Volume sampleRegion(const frep::Model& model, const VolumeFrame& frame, double scale, const IndexBox& region,
                    SampleStats* stats, io::Progress* progress) {
    auto start = Clock::now();
    Volume volume;
    volume.frame = frame;
    volume.normalization = scale;
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(-frame.band);
    grid->setTransform(frameTransform(frame));
    SampleStats st;
    const IndexBox clip = intersect(region, frame.indexBox);
    st.voxels = clip.volume();
    if (!clip.empty()) {
        SampleOptions unlimited;
        unlimited.memoryLimit = ~std::uint64_t{0};
        unlimited.progress = progress;
        std::string error;
        sampleTree(model, frame, scale, clip, unlimited, st, error, grid->tree());
    }
    volume.grid().grid = grid;
    st.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (stats) *stats = st;
    return volume;
}

SampleStats resampleRegion(Volume& volume, const frep::Model& model, const IndexBox& region) {
    auto start = Clock::now();
    SampleStats stats;
    const VolumeFrame& frame = volume.frame;
    IndexBox clip = intersect(region, frame.indexBox);
    stats.voxels = clip.volume();
    if (clip.empty()) return stats;
    Walk walk;
    runWalk(model, frame, volume.normalization, clip, walk, [](std::size_t) { return true; },
            [](std::size_t, WalkOutput&) {});
    copyStats(walk, stats);

    // Fills, then whole leaves, then single voxels through an accessor made
    // last: replacing a leaf would leave an earlier accessor's cache dangling.
    openvdb::FloatTree& tree = vdb(volume).tree();
    const float band = frame.band;
    for (const WalkOutput& out : walk.outputs)
        for (const BoxFill& f : out.fills) tree.fill(toCoordBBox(f.box), f.value, false);
    for (const WalkOutput& out : walk.outputs)
        for (const LeafSamples& s : out.leaves)
            if (s.evaluated.all()) tree.addLeaf(makeLeaf(s, -band, band).release());
    openvdb::FloatGrid::Accessor acc = vdb(volume).getAccessor();
    for (const WalkOutput& out : walk.outputs)
        for (const LeafSamples& s : out.leaves) {
            if (s.evaluated.all()) continue;
            for (std::size_t i = 0; i < FloatLeaf::SIZE; ++i) {
                if (!s.evaluated.test(i)) continue;
                openvdb::Coord c = FloatLeaf::offsetToLocalCoord(static_cast<openvdb::Index>(i)) +
                                   openvdb::Coord(s.origin[0], s.origin[1], s.origin[2]);
                float v = s.values[i];
                if (std::fabs(v) < band) acc.setValueOn(c, v);
                else acc.setValueOff(c, v);
            }
        }
    stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return stats;
}

}  // namespace hg::voxel
