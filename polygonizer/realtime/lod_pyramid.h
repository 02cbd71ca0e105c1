// The volume at every level of detail: level L holds the level-0 value at
// every 2^L-th voxel (point sampling, as Transvoxel expects: a coarse
// sample is a fine sample, so the surfaces of neighbouring levels meet at
// the shared samples). Kept up to date locally: after the grid changes in a
// box, update(box) recomputes exactly the coarse voxels that sample it.
#pragma once

#include <memory>

#include "voxel/volume.h"

namespace hg::poly {

class LodPyramid {
public:
    // `volume` must outlive the pyramid; level 0 is its grid, not a copy.
    LodPyramid(const voxel::Volume& volume, int levels);
    // A deep copy of `source`'s coarse levels over `volume`, which must
    // hold the same grid as source's (a copy of one sculpture: the loader
    // gives copies of one source their own grids).
    LodPyramid(const LodPyramid& source, const voxel::Volume& volume);
    ~LodPyramid();
    LodPyramid(const LodPyramid&) = delete;
    LodPyramid& operator=(const LodPyramid&) = delete;

    int levels() const;
    const voxel::Volume& volume() const;
    // Memory of the coarse levels (level 0 is the volume's, not counted).
    std::size_t memoryBytes() const;
    // Level-L voxel (i, j, k): the level-0 value at (i, j, k) * 2^L.
    float value(int level, int i, int j, int k) const;
    // The level-L voxels of `box` (level-L indices) into `out`, x fastest,
    // then y, then z. Voxels whose level-0 position lies outside the frame's
    // index box read the background (outside), as the export mesher sees
    // them, so a solid cut by the box is capped the same way.
    void gather(int level, const voxel::IndexBox& box, float* out) const;
    // The level-L voxels that sample the level-0 `box`, recomputed.
    // Returns how many voxels were written (over all coarse levels).
    std::size_t update(const voxel::IndexBox& box);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace hg::poly
