// Turns a sculpture's program into its volume: the model box, the
// normalization, then the culled narrow-band sampling (box_walker.h) on TBB
// workers. The grid is the same whatever the number of threads: every piece
// of work is a pure function of its box, and pieces are put into the tree in
// a fixed order.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "frep/eval/model.h"
#include "frep/language/domain_error.h"
#include "io/progress.h"
#include "voxel/model_box.h"
#include "voxel/normalization.h"
#include "voxel/volume.h"

namespace hg::voxel {

struct SampleOptions {
    // Told the fraction done (0..1) from the TBB workers, at most a few
    // hundred times, and asked for a cancel before each box (io/progress.h);
    // null: nobody watches.
    io::Progress* progress = nullptr;
    // Bytes the grid may take; 0: 80% of the memory available now.
    std::uint64_t memoryLimit = 0;
};

struct SampleStats {
    std::uint64_t boxesTested = 0;    // interval evaluations
    std::uint64_t boxesCulled = 0;    // proven inside or outside the band
    std::uint64_t samples = 0;        // points batch-evaluated
    std::uint64_t voxels = 0;         // voxels in the sampled box
    std::uint64_t leaves = 0;         // leaves that hold evaluated voxels
    std::uint64_t estimatedBytes = 0; // the memory guard's estimate
    // The tape each evaluated leaf ran, specialized to its box
    // (frep/eval/tape_specializer.h): mean and longest, against the full tape.
    double leafTapeMean = 0.0;
    std::uint64_t leafTapeMax = 0;
    std::uint64_t leafTapes = 0;      // leaves batch-evaluated with a tape (the mean's count)
    double pointTapeMean = 0.0;       // HG_PROBE_POINT_TAPES=1: voxels' own tapes (box_walker.h)
    double seconds = 0.0;
    frep::ErrorReport errors;         // domain errors at sampled points

    double evaluatedFraction() const { return voxels ? static_cast<double>(samples) / static_cast<double>(voxels) : 0.0; }
};

struct VolumeRequest {
    std::optional<frep::Box3> box;  // none: found as resolveModelBox() says (model_box.h)
    int resolution = 256;
    float band = 3.0f;
    VolumeSource source;            // recorded in the volume's metadata
};

struct VoxelizeResult {
    std::optional<Volume> volume;
    std::string error;              // why there is no volume
    bool cancelled = false;         // options.progress was cancelled: no volume (error is io::kCancelled)
    ModelBox modelBox;              // the box used and how it was found
    Normalization normalization;
    SampleStats stats;
};

VoxelizeResult voxelize(const frep::Model& model, const VolumeRequest& request, const SampleOptions& options = {});

// A fresh volume in `frame` that holds only `region` (index space, clipped
// to the frame) of what voxelize() stores with normalization `scale`; every
// other voxel reads the background (outside). Built as voxelize() builds
// its grid (leaves on the workers, pruned), without its memory guard: the
// caller bounds the region (polygonizer/export/tiled_mesher.h). `progress` (may be
// null) is told and asked as voxelize()'s; once it is cancelled the volume
// is incomplete and the caller must drop it.
Volume sampleRegion(const frep::Model& model, const VolumeFrame& frame, double scale, const IndexBox& region,
                    SampleStats* stats = nullptr, io::Progress* progress = nullptr);

// Recomputes the voxels of `region` (index space, clipped to the frame) from
// `model` with the volume's normalization, touching nothing else. Bit-identical
// to what a full sampling of `model` stores there.
SampleStats resampleRegion(Volume& volume, const frep::Model& model, const IndexBox& region);

}  // namespace hg::voxel
