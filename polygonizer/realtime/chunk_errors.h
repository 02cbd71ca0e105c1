// How far each chunk's surface at each coarser level strays from its
// level-0 surface (docs/polygonizer.md, "Levels by measured error"). A
// coarse level holds every 2^L-th level-0 sample (lod_pyramid.h), and its
// surface is where the trilinear blend of those samples crosses zero; so at
// every level-0 voxel near either surface, |level-0 value - coarse blend|
// is how far apart the two surfaces lie there, in level-0 voxels (the
// stored field is about one unit per voxel near the surface, voxel/volume.h).
// A chunk's error at level L is the largest of these over its voxels and
// every level up to L (so it never falls as the level grows). After an
// edit the changed chunks are measured again a few at a time (refresh).
//
// Where a sculpture is smooth the coarse levels stray by a small part of a
// voxel, and level selection (lod_selection.h) may take them much nearer
// than a voxel-size rule would; a carved groove, a thin rod or a sharp edge
// strays by voxels and keeps its fine levels.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "polygonizer/realtime/chunk_layout.h"

namespace hg::poly {

class LodPyramid;

class ChunkErrors {
public:
    // Every chunk of `layout` at levels 1..levels-1 of `pyramid` (TBB).
    ChunkErrors(const LodPyramid& pyramid, const ChunkLayout& layout);
    // `source`'s errors (unknown chunks stay unknown) for a pyramid and
    // layout equal to source's: a copy of one sculpture's grid errs alike.
    ChunkErrors(const ChunkErrors& source, const LodPyramid& pyramid, const ChunkLayout& layout);

    int levels() const { return levels_; }
    std::size_t count() const { return count_; }
    // Chunk `chunk`'s error at `level`, in level-0 voxels: 0 at level 0,
    // never smaller at a coarser level.
    float error(std::size_t chunk, int level) const {
        return level <= 0 ? 0.0f : errors_[chunk * static_cast<std::size_t>(levels_ - 1) + static_cast<std::size_t>(level - 1)];
    }
    // The largest and smallest chunk error at `level` (over every chunk).
    float largest(int level) const { return level <= 0 ? 0.0f : largest_[static_cast<std::size_t>(level - 1)]; }
    float smallest(int level) const { return level <= 0 ? 0.0f : smallest_[static_cast<std::size_t>(level - 1)]; }

    // The level-0 `box` changed (after LodPyramid::update): every chunk
    // whose error may have changed is unknown until refresh() measures it
    // again, and meanwhile errs without bound (so it takes the voxel-size
    // rule's level: an edit is never drawn coarser than before). Measuring
    // is left to refresh so that a stroke, which changes a box every
    // frame, does not measure its chunks every frame. Returns how many.
    std::size_t update(const voxel::IndexBox& box);
    // Measures unknown chunks, nearest to `viewer` (model frame) first, a
    // batch at a time while `milliseconds` last (0: all); at least one
    // batch when any is unknown. Returns how many were measured.
    std::size_t refresh(const std::array<double, 3>& viewer, double milliseconds);
    std::size_t unknown() const { return unknown_.size(); }
    // Grows whenever an error changes (levels chosen from older errors are stale).
    std::uint64_t version() const { return version_; }

private:
    void measure(const std::vector<std::size_t>& chunks);
    void summarize();

    const LodPyramid& pyramid_;
    const ChunkLayout& layout_;
    int levels_ = 1;
    std::size_t count_ = 0;
    std::uint64_t version_ = 0;
    std::vector<float> errors_;  // count x (levels - 1)
    std::vector<float> largest_, smallest_;
    std::vector<std::size_t> unknown_;  // changed, not measured since
    std::vector<bool> isUnknown_;
};

}  // namespace hg::poly
