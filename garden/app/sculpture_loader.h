// Sculptures sampled off the frame (issue 25; docs/design.md §6, "Progressive
// loading"): one background thread voxelizes the sculptures it was given,
// always the one nearest the viewer next, while the garden runs; the frame
// takes the finished grids (GardenSession attaches a coarse mesh at once
// and the finer levels stream in through the remesh queue). A grid sampled
// here is the grid the session would sample at start: voxelize() and a
// scan's rebuild are deterministic. So copies of one HyperFun source (the
// same file, body, a[], box, resolution and band) are sampled once: the
// grid is kept while a copy still waits, and each copy gets a deep copy
// of it, bit for bit what its own sampling would give (and a copy of its
// meshing). The worker keeps at most kAhead finished grids that the frame
// has not taken (a copy is made in milliseconds: without the limit a
// garden of copies would pile up its grids here, outside the memory
// budget's reach), except while wait() wants them all. With a MeshingShape the worker also builds each grid's
// coarse levels, chunks and level errors (sculpture_meshing.h), so the
// frame that takes it only attaches them.
#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "garden/app/sculpture_meshing.h"
#include "garden/scene/garden_file.h"
#include "io/progress.h"
#include "voxel/sampler.h"

namespace hg::garden {

class SculptureLoader {
public:
    struct Job {
        std::size_t sculpture = 0;      // the session's index
        // Shared, not pointed into the garden's load: sculptures added
        // while others load grow that vector (session_adding.cpp).
        std::shared_ptr<const SculptureLoad> source;
        SculptureSpec spec;
        voxel::VolumeRequest request;
        std::array<double, 3> where{};  // world position, for the nearest-first order
    };
    struct Loaded {
        std::size_t sculpture = 0;
        std::unique_ptr<voxel::Volume> volume;  // null: the sampling failed
        std::string error;
        PreparedMeshing meshing;  // built on `volume` when the loader was given a shape
    };

    // Starts sampling at once, nearest to `viewer` first; with `meshing`,
    // each grid comes with its meshing built to that shape.
    SculptureLoader(std::vector<Job> jobs, const std::array<double, 3>& viewer,
                    std::optional<MeshingShape> meshing = std::nullopt);
    // Cancels the sculpture under way (a HyperFun body's sampling stops at
    // its next box; a scan's or a mesh's level set is let finish) and
    // samples no more.
    ~SculptureLoader();
    SculptureLoader(const SculptureLoader&) = delete;
    SculptureLoader& operator=(const SculptureLoader&) = delete;

    // Where the viewer is now: the next sculpture sampled is the nearest.
    void setViewer(const std::array<double, 3>& viewer);
    // Up to `max` finished grids (0: all there are), in the order sampled.
    std::vector<Loaded> take(std::size_t max = 0);
    // Sculptures not yet taken (sampling, waiting or finished).
    std::size_t remaining() const;
    static constexpr std::size_t kAhead = 2;
    // Blocks until every sculpture is sampled (the kAhead limit lifted).
    void wait();
    // Sculptures sampled, and those given a copy of another's grid.
    std::size_t sampled() const;
    std::size_t copied() const;
    // How far the sampling under way has come (0 to 1; 0 before the first
    // report), for the panel.
    double fractionUnderWay() const { return stop_.fraction(); }
    // Cancels the sampling under way and samples no more (what the
    // destructor does); true when a sampling was cut short by it.
    bool close();

private:
    void run();
    // The grid a job would sample, as a key (sampledSourceKey; "" for a
    // scan, a mesh or a source that did not parse: never shared).
    static std::string sourceKey(const Job& job);

    mutable std::mutex mutex_;
    std::vector<Job> waiting_;
    std::vector<Loaded> finished_;
    // Grids sampled whose copies still wait, with their meshing, by
    // sourceKey (worker thread only).
    struct Kept {
        std::unique_ptr<voxel::Volume> volume;
        PreparedMeshing meshing;  // built on `volume`
    };
    std::map<std::string, Kept> kept_;
    std::size_t sampled_ = 0, copied_ = 0;
    std::condition_variable taken_;  // the frame took finished grids, or wait() wants them all
    bool all_ = false;               // wait(): no limit ahead
    std::size_t remaining_ = 0;
    std::array<double, 3> viewer_{};
    const std::optional<MeshingShape> meshing_;
    io::NullProgress stop_;  // cancelled on close; the sampling under way asks it
    bool cutShort_ = false;  // a sampling was cancelled by close (set by the worker before it ends)
    std::thread worker_;  // last: started once everything above is set
};

}  // namespace hg::garden
