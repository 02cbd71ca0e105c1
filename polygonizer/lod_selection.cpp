#include "polygonizer/lod_selection.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace hg::poly {

double projectedVoxelPixels(const Camera& camera, double voxelSize, int level, double distance) {
    const double size = voxelSize * std::ldexp(1.0, level);
    const double d = std::max(distance, 1e-9);
    return size * camera.viewportHeight / (2.0 * d * std::tan(0.5 * camera.fovY));
}

double distanceToChunk(const ChunkLayout& layout, std::size_t chunk, const std::array<double, 3>& p) {
    double lo[3], hi[3];
    layout.modelBox(chunk, lo, hi);
    double s = 0.0;
    for (int a = 0; a < 3; ++a) {
        double d = std::max({lo[a] - p[static_cast<size_t>(a)], 0.0, p[static_cast<size_t>(a)] - hi[a]});
        s += d * d;
    }
    return std::sqrt(s);
}

std::vector<int> selectLevels(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings) {
    const double h = layout.frame().voxelSize;
    const int maxLevel = std::max(0, settings.maxLevel);
    std::vector<int> level(layout.count());
    for (std::size_t i = 0; i < level.size(); ++i) {
        // The nearest point of the chunk decides: its voxels are the largest on screen.
        const double d = distanceToChunk(layout, i, camera.position);
        int l = 0;
        while (l < maxLevel && projectedVoxelPixels(camera, h, l + 1, d) <= settings.pixelError) ++l;
        for (const auto& s : {settings.detail, settings.tool})
            if (s && distanceToChunk(layout, i, s->center) <= s->radius) l = 0;
        level[i] = l;
    }
    // Neighbours at most one level apart: a chunk is lowered to its finest
    // neighbour's level + 1, and the change spreads (a breadth-first pass).
    std::deque<std::size_t> queue;
    for (std::size_t i = 0; i < level.size(); ++i) queue.push_back(i);
    while (!queue.empty()) {
        const std::size_t i = queue.front();
        queue.pop_front();
        for (std::size_t n : layout.faceNeighbours(i))
            if (level[n] > level[i] + 1) {
                level[n] = level[i] + 1;
                queue.push_back(n);
            }
    }
    return level;
}

}  // namespace hg::poly
