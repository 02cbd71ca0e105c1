#include "garden/sculpt/impacts.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "garden/sculpt/surface_ray.h"

namespace hg::garden {

namespace {

constexpr double kPi = 3.14159265358979323846;

ModelPoint cross(const ModelPoint& a, const ModelPoint& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
ModelPoint normalized(const ModelPoint& v) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / l, v[1] / l, v[2] / l};
}
// Two unit vectors across a unit direction.
void basis(const ModelPoint& d, ModelPoint& u, ModelPoint& v) {
    const ModelPoint helper = std::fabs(d[1]) < 0.9 ? ModelPoint{0, 1, 0} : ModelPoint{1, 0, 0};
    u = normalized(cross(helper, d));
    v = cross(d, u);
}

// Uniform in [0, 1) from the engine's bits: the same on every platform
// (the standard distributions' algorithms are not specified).
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0); }

}  // namespace

std::string checkImpactTool(const ImpactTool& t, double voxelSize) {
    if (!(std::isfinite(t.size) && t.size >= voxelSize && t.size <= 4096 * voxelSize))
        return "the impact tool's size must be between one voxel and 4096 voxels";
    if (!(std::isfinite(t.volume) && t.volume > 0.0)) return "the compaction volume must be a positive number";
    if (!(std::isfinite(t.spreadSize) && t.spreadSize >= 0.0)) return "the spread must be a number >= 0";
    if (t.spread == ImpactSpread::Cone && t.spreadSize >= 0.5 * kPi) return "a cone's half-angle must be under 90 degrees";
    if (t.count < 1 || t.count > 100000) return "impacts per pull must be 1 to 100000";
    return "";
}

std::vector<ImpactRay> drawImpactRays(const ImpactRay& aim, const ImpactTool& tool) {
    std::mt19937_64 rng(tool.seed);
    ModelPoint u, v;
    const ModelPoint d = normalized(aim.direction);
    basis(d, u, v);
    std::vector<ImpactRay> rays;
    rays.reserve(static_cast<std::size_t>(tool.count));
    for (int i = 0; i < tool.count; ++i) {
        ImpactRay r{aim.origin, d};
        const double a = 2.0 * kPi * unit(rng);
        if (tool.spread == ImpactSpread::Cone) {
            // Uniform over the cone's solid angle.
            const double cosMax = std::cos(tool.spreadSize);
            const double c = 1.0 - unit(rng) * (1.0 - cosMax), s = std::sqrt(std::max(0.0, 1.0 - c * c));
            for (int k = 0; k < 3; ++k) r.direction[k] = c * d[k] + s * (std::cos(a) * u[k] + std::sin(a) * v[k]);
        } else {
            // A disc across the aim: uniform over its area, or gaussian (Box-Muller).
            const double radius = tool.spread == ImpactSpread::Uniform
                                      ? tool.spreadSize * std::sqrt(unit(rng))
                                      : tool.spreadSize * std::sqrt(-2.0 * std::log(1.0 - unit(rng)));
            for (int k = 0; k < 3; ++k) r.origin[k] += radius * (std::cos(a) * u[k] + std::sin(a) * v[k]);
        }
        rays.push_back(r);
    }
    return rays;
}

double impactDepth(ImpactShape shape, double size, double volume) {
    switch (shape) {
        case ImpactShape::Sphere: {
            // A spherical cap: pi d^2 (3r - d) / 3, increasing on [0, 2r].
            const double r = size;
            double lo = 0.0, hi = 2.0 * r;
            if (kPi * hi * hi * (3.0 * r - hi) / 3.0 <= volume) return hi;
            for (int i = 0; i < 60; ++i) {
                const double m = 0.5 * (lo + hi);
                (kPi * m * m * (3.0 * r - m) / 3.0 < volume ? lo : hi) = m;
            }
            return 0.5 * (lo + hi);
        }
        case ImpactShape::Chisel:
            // A 90-degree V of edge length L: a triangle of area d^2 along L.
            return std::min(std::sqrt(volume / size), size);
        case ImpactShape::Square:
            return std::min(volume / (size * size), size);
    }
    return 0.0;
}

frep::Box3 impactReach(const Impact& m, const FieldUnits& units) {
    // The tool's solid lies within `size` of the tip (the sphere within its
    // diameter), and its clamped field is -band beyond band voxels of it.
    const double extent = (m.shape == ImpactShape::Sphere ? 2.0 : 1.5) * m.size + (units.band + 1.0) * units.voxelSize;
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = m.tip[a] - extent;
        b.hi[a] = m.tip[a] + extent;
    }
    return b;
}

std::optional<Impact> castImpact(const voxel::Volume& grid, const ImpactRay& ray, const ImpactTool& tool,
                                 const FieldUnits& units) {
    const auto t = marchToSurface(grid, ray.origin, ray.direction);
    if (!t) return std::nullopt;
    Impact m;
    m.shape = tool.shape;
    m.size = tool.size;
    m.direction = normalized(ray.direction);
    ModelPoint v;
    basis(m.direction, m.across, v);
    m.depth = impactDepth(tool.shape, tool.size, tool.volume);
    for (int a = 0; a < 3; ++a) m.tip[a] = ray.origin[a] + ray.direction[a] * *t + m.direction[a] * m.depth;
    m.reach = impactReach(m, units);
    return m;
}

std::vector<ImpactRay> raysInBox(const std::vector<ImpactRay>& rays, const frep::Box3& box) {
    std::vector<ImpactRay> out = rays;
    for (ImpactRay& r : out)
        for (int a = 0; a < 3; ++a) r.origin[a] = (r.origin[a] - box.lo[a]) / (box.hi[a] - box.lo[a]);
    return out;
}

std::vector<ImpactRay> raysFromBox(const std::vector<ImpactRay>& relative, const frep::Box3& box) {
    std::vector<ImpactRay> out = relative;
    for (ImpactRay& r : out)
        for (int a = 0; a < 3; ++a) r.origin[a] = box.lo[a] + r.origin[a] * (box.hi[a] - box.lo[a]);
    return out;
}

}  // namespace hg::garden
