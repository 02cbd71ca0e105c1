#include "garden/morph/blocked_field.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace hg::garden {

BlockedField::BlockedField(const voxel::DenseField& dense) : box_(dense.box) {
    if (box_.empty()) return;
    for (int a = 0; a < 3; ++a) {
        first_[static_cast<std::size_t>(a)] = floorMultiple(box_.lo[a], kBlockEdge);
        count_[static_cast<std::size_t>(a)] =
            (floorMultiple(box_.hi[a], kBlockEdge) - first_[static_cast<std::size_t>(a)]) / kBlockEdge + 1;
    }
    values_.assign(static_cast<std::size_t>(count_[0]) * static_cast<std::size_t>(count_[1]) *
                       static_cast<std::size_t>(count_[2]) * static_cast<std::size_t>(kBlockVoxels),
                   0.0f);
    // One z-slab of blocks per task; rows of the dense field are read in order.
    tbb::parallel_for(0, count_[2], [&](int bz) {
        const int z0 = first_[2] + bz * kBlockEdge;
        for (int k = std::max(z0, box_.lo[2]); k <= std::min(z0 + kBlockEdge - 1, box_.hi[2]); ++k)
            for (int j = box_.lo[1]; j <= box_.hi[1]; ++j) {
                const float* row = dense.values.data() + dense.at(box_.lo[0], j, k);
                const int oy = floorMultiple(j, kBlockEdge);
                for (int i = box_.lo[0]; i <= box_.hi[0]; ++i) {
                    const int ox = floorMultiple(i, kBlockEdge);
                    float* b = values_.data() + blockIndex({ox, oy, z0}) * static_cast<std::size_t>(kBlockVoxels);
                    b[blockOffset(i - ox, j - oy, k - z0)] = row[i - box_.lo[0]];
                }
            }
    });
    const std::size_t blocks = values_.size() / static_cast<std::size_t>(kBlockVoxels);
    coarse_.resize(blocks * static_cast<std::size_t>(kCoarseVoxels));
    for (std::size_t b = 0; b < blocks; ++b)
        for (int x = 0; x < kBlockEdge; x += 4)
            for (int y = 0; y < kBlockEdge; y += 4)
                for (int z = 0; z < kBlockEdge; z += 4)
                    coarse_[b * kCoarseVoxels + static_cast<std::size_t>(coarseOffset(x, y, z))] =
                        values_[b * kBlockVoxels + static_cast<std::size_t>(blockOffset(x, y, z))];
}

float BlockedField::value(int i, int j, int k) const {
    const std::array<int, 3> o{floorMultiple(i, kBlockEdge), floorMultiple(j, kBlockEdge), floorMultiple(k, kBlockEdge)};
    return block(o)[blockOffset(i - o[0], j - o[1], k - o[2])];
}

}  // namespace hg::garden
