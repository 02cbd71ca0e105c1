// Copies of a grid's leaves (values and active states) over boxes, to put
// back exactly: what an edit's undo restores instead of recomputing its box
// from the unedited grid and every edit that reaches it (slow where
// thousands of edits crowd the box).
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "voxel/index_box.h"
#include "voxel/volume.h"

namespace hg::voxel {

class LeafSnapshot {
public:
    LeafSnapshot();
    ~LeafSnapshot();
    LeafSnapshot(LeafSnapshot&&) noexcept;
    LeafSnapshot& operator=(LeafSnapshot&&) noexcept;

    // Copies the leaves that hold voxels of `box` (clipped to the frame),
    // except those copied already: the first copy of a leaf wins, so a box
    // that grows (a live stroke) keeps the state before its first part.
    void capture(const Volume& volume, const IndexBox& box);
    // Writes every copied leaf back into `volume`.
    void restore(Volume& volume) const;
    std::size_t bytes() const;

private:
    struct Leaf;
    std::vector<Leaf> leaves_;
    std::unordered_map<std::uint64_t, std::size_t> index_;
};

}  // namespace hg::voxel
