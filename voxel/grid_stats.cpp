#include "voxel/grid_stats.h"

#include <cmath>
#include <vector>

#include "voxel/normalization.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

GridStats measureGrid(const Volume& volume) {
    GridStats s;
    const openvdb::FloatGrid& grid = vdb(volume);
    const float band = volume.frame.band;
    s.activeVoxels = static_cast<std::size_t>(grid.activeVoxelCount());
    s.leaves = static_cast<std::size_t>(grid.tree().leafCount());
    s.memoryBytes = static_cast<std::size_t>(grid.memUsage());
    for (auto it = grid.tree().cbeginValueAll(); it; ++it) {
        if (it.isVoxelValue()) continue;
        if (*it == band) ++s.tilesInside;
        else if (*it == -band) ++s.tilesOutside;
    }
    std::vector<double> mags;
    openvdb::FloatGrid::ConstAccessor acc = grid.getConstAccessor();
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        if (!it.isVoxelValue() || std::fabs(*it) >= 0.5f) continue;
        const openvdb::Coord c = it.getCoord();
        float n[6];
        bool inside = true;
        for (int a = 0; a < 3 && inside; ++a) {
            openvdb::Coord d(0, 0, 0);
            d[a] = 1;
            n[2 * a] = acc.getValue(c + d);
            n[2 * a + 1] = acc.getValue(c - d);
            inside = std::fabs(n[2 * a]) < band && std::fabs(n[2 * a + 1]) < band;
        }
        if (!inside) continue;
        double gx = 0.5 * static_cast<double>(n[0] - n[1]);
        double gy = 0.5 * static_cast<double>(n[2] - n[3]);
        double gz = 0.5 * static_cast<double>(n[4] - n[5]);
        mags.push_back(std::sqrt(gx * gx + gy * gy + gz * gz));
    }
    s.surfaceVoxels = mags.size();
    medianAndP90(mags.data(), mags.size(), s.medianGradient, s.p90Gradient);
    return s;
}

}  // namespace hg::voxel
