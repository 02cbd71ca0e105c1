// A dense field stored block by block: 8^3 blocks aligned like OpenVDB
// leaves, each in leaf order (x slowest, z fastest). The morph blend reads
// one block of each source and writes one leaf, so this layout turns it
// into three contiguous 2 KiB reads and one write per block; the sampler's
// x-fastest layout (voxel::DenseField) costs a cache miss per row of 8
// instead, which made the blend memory-latency bound (about 15x slower).
// A second, compact copy of every fourth voxel serves the coarse pass.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "voxel/dense_field.h"
#include "voxel/index_box.h"

namespace hg::garden {

constexpr int kBlockEdge = 8;
constexpr int kBlockVoxels = kBlockEdge * kBlockEdge * kBlockEdge;
constexpr int kCoarseVoxels = 8;  // per block, at local coordinates 0 and 4

inline int coarseOffset(int x, int y, int z) { return ((x >> 2) << 2) | ((y >> 2) << 1) | (z >> 2); }

// Offset of voxel (x, y, z) of a block in leaf order (OpenVDB's
// LeafNode<float, 3>::coordToOffset of the local coordinates).
inline int blockOffset(int x, int y, int z) { return (x << 6) | (y << 3) | z; }

class BlockedField {
public:
    BlockedField() = default;
    // Re-lays `dense` out; voxels of edge blocks outside its box hold 0.
    explicit BlockedField(const voxel::DenseField& dense);

    const voxel::IndexBox& box() const { return box_; }
    // The block whose low corner is `origin` (multiples of 8, covering box()).
    const float* block(const std::array<int, 3>& origin) const {
        return values_.data() + blockIndex(origin) * static_cast<std::size_t>(kBlockVoxels);
    }
    // The block's 8 voxels whose local coordinates are 0 or 4 on every
    // axis (the coarse pass's lattice), index (x/4) * 4 + (y/4) * 2 + z/4: a
    // copy in one cache line, where the block holds them in four.
    const float* coarse(const std::array<int, 3>& origin) const {
        return coarse_.data() + blockIndex(origin) * static_cast<std::size_t>(kCoarseVoxels);
    }
    float value(int i, int j, int k) const;
    // Every block, one after another (edge blocks padded).
    const float* data() const { return values_.data(); }
    std::size_t size() const { return values_.size(); }
    // Memory held: the blocks and the coarse copy.
    std::size_t bytes() const { return (values_.capacity() + coarse_.capacity()) * sizeof(float); }

private:
    std::size_t blockIndex(const std::array<int, 3>& origin) const {
        return (static_cast<std::size_t>((origin[2] - first_[2]) / kBlockEdge) * static_cast<std::size_t>(count_[1]) +
                static_cast<std::size_t>((origin[1] - first_[1]) / kBlockEdge)) * static_cast<std::size_t>(count_[0]) +
               static_cast<std::size_t>((origin[0] - first_[0]) / kBlockEdge);
    }

    voxel::IndexBox box_;
    std::array<int, 3> first_{};  // origin of the block at box_.lo
    std::array<int, 3> count_{};  // blocks along x, y, z
    std::vector<float> values_;
    std::vector<float> coarse_;
};

using voxel::ceilMultiple;
using voxel::floorMultiple;

}  // namespace hg::garden
