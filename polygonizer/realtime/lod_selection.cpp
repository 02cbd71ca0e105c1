#include "polygonizer/realtime/lod_selection.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "polygonizer/realtime/chunk_errors.h"

namespace hg::poly {

double pixelsPerUnit(const Camera& camera, double distance) {
    return camera.viewportHeight / (2.0 * std::max(distance, 1e-9) * std::tan(0.5 * camera.fovY));
}

double projectedVoxelPixels(const Camera& camera, double voxelSize, int level, double distance) {
    return voxelSize * std::ldexp(1.0, level) * pixelsPerUnit(camera, distance);
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

int levelAtDistance(const Camera& camera, double voxelSize, double distance, const LodSettings& settings) {
    const int maxLevel = std::max(0, settings.maxLevel);
    int l = 0;
    while (l < maxLevel && projectedVoxelPixels(camera, voxelSize, l + 1, distance) <= settings.pixelError) ++l;
    return l;
}

namespace {

// Nearest and farthest distance from p to the box [lo, hi].
std::pair<double, double> boxDistances(const double lo[3], const double hi[3], const std::array<double, 3>& p) {
    double nearSq = 0.0, farSq = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
        const double below = lo[a] - p[a], above = p[a] - hi[a];
        const double n = std::max({below, 0.0, above});
        const double f = std::max(std::abs(p[a] - lo[a]), std::abs(p[a] - hi[a]));
        nearSq += n * n;
        farSq += f * f;
    }
    return {std::sqrt(nearSq), std::sqrt(farSq)};
}

}  // namespace

std::optional<int> uniformLevel(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings,
                                const ChunkErrors* errors) {
    if (layout.count() == 0) return std::nullopt;
    double lo[3], hi[3];
    layout.modelBounds(lo, hi);
    for (const auto& s : {settings.detail, settings.tool})
        if (s && boxDistances(lo, hi, s->center).first <= s->radius) return std::nullopt;
    const double h = layout.frame().voxelSize;
    // Every chunk's nearest point lies between the bound's nearest and
    // farthest points, and the level never falls with distance.
    const auto [nearest, farthest] = boxDistances(lo, hi, camera.position);
    if (errors) {
        // And no chunk errs more than the largest error, nor less than the
        // smallest: the finest any chunk may take is the nearest point's
        // with the largest errors, the coarsest the farthest point's with
        // the smallest.
        const int l = levelAtDistance(camera, h, nearest, settings, [&](int level) { return errors->largest(level); });
        if (levelAtDistance(camera, h, farthest, settings, [&](int level) { return errors->smallest(level); }) != l)
            return std::nullopt;
        return l;
    }
    const int l = levelAtDistance(camera, h, nearest, settings);
    if (levelAtDistance(camera, h, farthest, settings) != l) return std::nullopt;
    return l;
}

std::vector<int> selectLevels(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings,
                              const ChunkErrors* errors) {
    if (const std::optional<int> l = uniformLevel(layout, camera, settings, errors))
        return std::vector<int>(layout.count(), *l);
    return selectLevelsPerChunk(layout, camera, settings, errors);
}

std::vector<int> selectLevelsPerChunk(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings,
                                      const ChunkErrors* errors) {
    const double h = layout.frame().voxelSize;
    std::vector<int> level(layout.count());
    for (std::size_t i = 0; i < level.size(); ++i) {
        // The nearest point of the chunk decides: its voxels are the largest on screen.
        const double d = distanceToChunk(layout, i, camera.position);
        int l = errors ? levelAtDistance(camera, h, d, settings, [&](int lv) { return errors->error(i, lv); })
                       : levelAtDistance(camera, h, d, settings);
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
        layout.forEachFaceNeighbour(i, [&](std::size_t n) {
            if (level[n] > level[i] + 1) {
                level[n] = level[i] + 1;
                queue.push_back(n);
            }
        });
    }
    return level;
}

}  // namespace hg::poly
