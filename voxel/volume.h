// A sculpture's volume: one OpenVDB FloatGrid in the sculpture's model frame
// holding f scaled to about one unit per voxel near the surface, clamped to
// +-band voxels, positive inside (HyperFun's sign). Tiles and inactive voxels
// hold the clamped value with the right sign; active voxels are those inside
// the band.
//
// This header does not include OpenVDB: code that works on the grid itself
// includes voxel/volume_vdb.h.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "voxel/volume_frame.h"

namespace hg::voxel {

// Where a volume came from: written into .vdb metadata so that a grid can be
// traced back to (and re-sampled from) its program.
struct VolumeSource {
    std::string file;
    std::string body;
    std::vector<double> parameters;  // a[1], a[2], ...
};

struct VolumeGrid;  // defined in voxel/volume_vdb.h

// How a volume's model box was found (voxel/model_box.h).
enum class BoxOrigin {
    Given,             // by the caller (--box, the garden file)
    IntervalEstimate,  // by interval subdivision (frep::estimateBounds)
    Sampled,           // by sampling the default box when the estimate failed
};

// "given", "interval estimate", "sampled": the .vdb metadata's words.
const char* boxOriginName(BoxOrigin origin);

enum class VolumeKind {
    NarrowBand,   // clamped to +-band, tiles beyond it (what the garden draws)
    DenseSource,  // every voxel active, unclamped (a morph source cache)
};

class Volume {
public:
    Volume();  // an empty grid (every voxel outside)
    ~Volume();
    Volume(Volume&&) noexcept;
    Volume& operator=(Volume&&) noexcept;
    Volume(const Volume&) = delete;
    Volume& operator=(const Volume&) = delete;
    Volume clone() const;  // deep copy of the grid

    VolumeFrame frame;
    // Stored value = f * normalization (then clamped): voxels per unit of f.
    double normalization = 1.0;
    BoxOrigin boxOrigin = BoxOrigin::Given;
    VolumeKind kind = VolumeKind::NarrowBand;
    VolumeSource source;

    // The stored value at voxel (i, j, k) (background outside the grid).
    float value(int i, int j, int k) const;
    bool active(int i, int j, int k) const;
    std::size_t activeVoxelCount() const;
    std::size_t leafCount() const;
    std::size_t memoryBytes() const;

    VolumeGrid& grid() { return *grid_; }
    const VolumeGrid& grid() const { return *grid_; }

private:
    std::unique_ptr<VolumeGrid> grid_;
};

}  // namespace hg::voxel
