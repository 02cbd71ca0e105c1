#include "garden/sculpt/surface_ray.h"

#include <algorithm>
#include <cmath>

namespace hg::garden {

std::optional<double> marchToSurface(const voxel::Volume& volume, const ModelPoint& o, const ModelPoint& d) {
    return marchToSurface(volume.frame, 0, [&volume](int i, int j, int k) { return volume.value(i, j, k); }, o, d);
}

std::optional<double> marchToSurface(const voxel::VolumeFrame& f, int level,
                                     const std::function<float(int, int, int)>& value, const ModelPoint& o,
                                     const ModelPoint& d) {
    const double voxel = std::ldexp(f.voxelSize, level);
    // A ray from a NaN pose (a singular placement, a lost controller) meets
    // nothing; left in, NaN passes the box test and the march never ends.
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(o[a]) || !std::isfinite(d[a])) return std::nullopt;
    double t0 = 0.0, t1 = 1e300;
    for (int a = 0; a < 3; ++a) {
        const double lo = f.modelBox.lo[a], hi = f.modelBox.hi[a];
        if (std::fabs(d[a]) < 1e-300) {
            if (o[a] < lo || o[a] > hi) return std::nullopt;
            continue;
        }
        double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t1 >= t0)) return std::nullopt;
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(length > 0.0)) return std::nullopt;
    const double step = 0.5 * voxel / length;
    // Trilinear: the surface between voxels, not at the nearest one (a
    // half-voxel error is most of a small impact's depth).
    const auto sample = [&](double t) {
        double g[3];
        int i[3];
        for (int a = 0; a < 3; ++a) {
            g[a] = (o[a] + d[a] * t - f.modelBox.lo[a]) / voxel;
            i[a] = static_cast<int>(std::floor(g[a]));
            g[a] -= i[a];
        }
        double v = 0.0;
        for (int c = 0; c < 8; ++c) {
            const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
            const double w = (dx ? g[0] : 1.0 - g[0]) * (dy ? g[1] : 1.0 - g[1]) * (dz ? g[2] : 1.0 - g[2]);
            v += w * static_cast<double>(value(i[0] + dx, i[1] + dy, i[2] + dz));
        }
        return v;
    };
    double prevT = t0, prev = sample(t0);
    if (prev >= 0.0) return t0;
    for (double t = t0 + step; t <= t1 + step; t += step) {
        const double v = sample(t);
        if (v >= 0.0) return prevT + (t - prevT) * (prev / (prev - v));  // zero between the samples
        prevT = t;
        prev = v;
    }
    return std::nullopt;
}

}  // namespace hg::garden
