#include "polygonizer/realtime/lod_selection.h"

#include <algorithm>
#include <cmath>

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

namespace {

// Squared distance from p to each slab of chunks along one axis: chunks lie
// on a grid, so a chunk's distance is the three axes' slabs together, in
// the order distanceToChunk adds them (the same doubles).
std::vector<double> slabDistances(const ChunkLayout& layout, int axis, double p) {
    const std::array<int, 3>& n = layout.dims();
    const std::size_t a = static_cast<std::size_t>(axis);
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(n[0]) : static_cast<std::size_t>(n[0] * n[1]);
    std::vector<double> out(static_cast<std::size_t>(n[a]));
    for (std::size_t c = 0; c < out.size(); ++c) {
        double lo[3], hi[3];
        layout.modelBox(c * stride, lo, hi);
        const double d = std::max({lo[a] - p, 0.0, p - hi[a]});
        out[c] = d * d;
    }
    return out;
}

struct ChunkDistances {
    std::vector<double> x, y, z;
    ChunkDistances(const ChunkLayout& layout, const std::array<double, 3>& p)
        : x(slabDistances(layout, 0, p[0])), y(slabDistances(layout, 1, p[1])), z(slabDistances(layout, 2, p[2])) {}
};

}  // namespace

std::vector<int> selectLevelsPerChunk(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings,
                                      const ChunkErrors* errors) {
    const double h = layout.frame().voxelSize;
    const std::array<int, 3>& n = layout.dims();
    const std::size_t nx = static_cast<std::size_t>(n[0]), ny = static_cast<std::size_t>(n[1]),
                      nz = static_cast<std::size_t>(n[2]);
    std::vector<int> level(layout.count());
    const ChunkDistances eye(layout, camera.position);
    std::vector<std::pair<ChunkDistances, double>> spheres;  // detail and tool: level 0 within
    for (const auto* sphere : {&settings.detail, &settings.tool})
        if (*sphere) spheres.emplace_back(ChunkDistances(layout, (*sphere)->center), (*sphere)->radius);
    std::size_t i = 0;
    for (std::size_t z = 0; z < nz; ++z)
        for (std::size_t y = 0; y < ny; ++y)
            for (std::size_t x = 0; x < nx; ++x, ++i) {
                // The nearest point of the chunk decides: its voxels are the largest on screen.
                const double d = std::sqrt(eye.x[x] + eye.y[y] + eye.z[z]);
                int l = errors ? levelAtDistance(camera, h, d, settings, [&](int lv) { return errors->error(i, lv); })
                               : levelAtDistance(camera, h, d, settings);
                for (const auto& [c, radius] : spheres)
                    if (std::sqrt(c.x[x] + c.y[y] + c.z[z]) <= radius) l = 0;
                level[i] = l;
            }
    // Neighbours at most one level apart: each chunk is lowered to its
    // finest neighbour's level + 1, the change spreading. The fixed point
    // is level[i] = min over j of (level[j] + face steps from j to i), a
    // city-block distance transform, which a forward and a backward sweep
    // over the grid compute exactly (on a whole grid, a shortest path's steps
    // can be ordered to go up the axes first, then down).
    const std::size_t sy = nx, sz = nx * ny;
    i = 0;
    for (std::size_t z = 0; z < nz; ++z)
        for (std::size_t y = 0; y < ny; ++y)
            for (std::size_t x = 0; x < nx; ++x, ++i) {
                int& l = level[i];
                if (x > 0) l = std::min(l, level[i - 1] + 1);
                if (y > 0) l = std::min(l, level[i - sy] + 1);
                if (z > 0) l = std::min(l, level[i - sz] + 1);
            }
    for (std::size_t z = nz; z-- > 0;)
        for (std::size_t y = ny; y-- > 0;)
            for (std::size_t x = nx; x-- > 0;) {
                const std::size_t k = --i;
                int& l = level[k];
                if (x + 1 < nx) l = std::min(l, level[k + 1] + 1);
                if (y + 1 < ny) l = std::min(l, level[k + sy] + 1);
                if (z + 1 < nz) l = std::min(l, level[k + sz] + 1);
            }
    return level;
}

}  // namespace hg::poly
