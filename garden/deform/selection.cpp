#include "garden/deform/selection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "garden/sketch/inflation_field.h"
#include "voxel/volume_vdb.h"

namespace hg::garden::deform {

namespace {

// The point of triangle abc nearest p (Ericson, "Real-Time Collision
// Detection", 5.1.5).
glm::dvec3 nearestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double denominator = 1.0 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

// The exact distance from p to the mesh (min over its triangles; the min
// is exact, so the split over workers does not change it).
double distanceToMesh(const DeformMesh& mesh, const glm::dvec3& p) {
    return std::sqrt(tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), 1024), 1e300,
        [&](const tbb::blocked_range<std::size_t>& r, double nearest) {
            for (std::size_t t = r.begin(); t < r.end(); ++t) {
                const auto& tri = mesh.triangles[t];
                const glm::dvec3 q = nearestOnTriangle(p, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
                nearest = std::min(nearest, glm::dot(p - q, p - q));
            }
            return nearest;
        },
        [](double x, double y) { return std::min(x, y); }));
}

// Where the inscribed ball around a voxel is largest, to a fraction of a
// voxel: the peak of a parabola through the depth at the voxel and its two
// neighbours, per axis, no farther than half a voxel. The voxel's own ball
// can be most of a voxel smaller than the largest near it.
template <class Depth>
openvdb::Vec3d refinedCentre(const Depth& depth, const openvdb::Coord& ijk) {
    openvdb::Vec3d at = ijk.asVec3d();
    const double here = depth(ijk);
    for (int axis = 0; axis < 3; ++axis) {
        openvdb::Coord step(0, 0, 0);
        step[axis] = 1;
        const double below = depth(ijk - step), above = depth(ijk + step);
        const double curvature = below - 2.0 * here + above;
        if (below >= 0.0 && above >= 0.0 && curvature < 0.0)
            at[axis] += std::clamp(0.5 * (below - above) / curvature, -0.5, 0.5);
    }
    return at;
}

// The depth (voxels to the mesh) of every voxel in the mesh's index box,
// -1 outside: exact within the narrow band OpenVDB's meshToLevelSet
// computes, then carried inward by a chamfer distance transform (two
// sweeps each way over the 26 neighbours, steps 1, sqrt 2, sqrt 3). The
// chamfer only orders the candidates; every ball's radius is measured
// exactly against the triangles.
struct DepthField {
    openvdb::CoordBBox box;
    openvdb::Coord dim;
    std::vector<float> depth;

    std::size_t cell(const openvdb::Coord& c) const {
        const openvdb::Coord d = c - box.min();
        return (static_cast<std::size_t>(d.z()) * static_cast<std::size_t>(dim.y()) + static_cast<std::size_t>(d.y())) *
                   static_cast<std::size_t>(dim.x()) +
               static_cast<std::size_t>(d.x());
    }
    double at(const openvdb::Coord& c) const { return box.isInside(c) ? static_cast<double>(depth[cell(c)]) : -1.0; }
};

DepthField depthField(const openvdb::FloatGrid& levelSet, const openvdb::CoordBBox& box, double voxelSize,
                      float halfWidth) {
    DepthField f;
    f.box = box;
    f.dim = box.dim();
    f.depth.assign(static_cast<std::size_t>(f.dim.x()) * f.dim.y() * f.dim.z(), -1.0f);
    constexpr float kUnknown = 1e30f;
    const auto accessor = levelSet.getConstAccessor();
    const auto exactBelow = static_cast<float>((static_cast<double>(halfWidth) - 0.5) * voxelSize);
    for (auto it = box.begin(); it; ++it) {
        const float v = accessor.getValue(*it);
        if (v >= 0.0f) continue;
        f.depth[f.cell(*it)] = v > -exactBelow ? static_cast<float>(-static_cast<double>(v) / voxelSize) : kUnknown;
    }
    std::vector<std::pair<openvdb::Coord, float>> before;  // the 13 neighbours a forward sweep has visited
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int order = dz * 9 + dy * 3 + dx;
                if (order < 0)
                    before.emplace_back(openvdb::Coord(dx, dy, dz), std::sqrt(static_cast<float>(dx * dx + dy * dy + dz * dz)));
            }
    const auto sweep = [&](int direction) {
        const openvdb::Coord lo = box.min(), hi = box.max();
        for (int k0 = 0; k0 < f.dim.z(); ++k0)
            for (int j0 = 0; j0 < f.dim.y(); ++j0)
                for (int i0 = 0; i0 < f.dim.x(); ++i0) {
                    const openvdb::Coord c = direction > 0 ? openvdb::Coord(lo.x() + i0, lo.y() + j0, lo.z() + k0)
                                                           : openvdb::Coord(hi.x() - i0, hi.y() - j0, hi.z() - k0);
                    float& d = f.depth[f.cell(c)];
                    if (d < 0.0f) continue;
                    for (const auto& [offset, step] : before) {
                        const openvdb::Coord n = direction > 0 ? c + offset : c - offset;
                        if (!box.isInside(n)) continue;
                        const float dn = f.depth[f.cell(n)];
                        if (dn >= 0.0f && dn + step < d) d = dn + step;
                    }
                }
    };
    for (int round = 0; round < 2; ++round) {
        sweep(1);
        sweep(-1);
    }
    return f;
}

}  // namespace

std::vector<SelectionBall> selectionBalls(const DeformMesh& mesh, double voxelSize, int maxBalls, double uncovered) {
    std::vector<SelectionBall> balls;
    if (mesh.triangles.empty() || !(voxelSize > 0.0) || maxBalls <= 0 || !checkClosedManifold(mesh).empty())
        return balls;
    voxel::ensureOpenVdbInitialized();
    const openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(voxelSize);
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.vertices.size());
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& v : mesh.vertices) {
        points.emplace_back(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    constexpr float kHalfWidth = 3.0f;
    // Points in index space (the transform is a plain scale). No
    // renormalization, trimming or removal of voxels where the surface
    // crosses itself: the band only seeds the chamfer and orders the
    // candidates (the balls' radii are exact), and they cost most of the
    // conversion's time.
    std::vector<openvdb::Vec3s> indexPoints(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) indexPoints[i] = points[i] * static_cast<float>(1.0 / voxelSize);
    const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(indexPoints, triangles);
    const openvdb::FloatGrid::Ptr levelSet = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        adapter, *transform, kHalfWidth, kHalfWidth,
        openvdb::tools::DISABLE_INTERSECTING_VOXEL_REMOVAL | openvdb::tools::DISABLE_RENORMALIZATION |
            openvdb::tools::DISABLE_NARROW_BAND_TRIMMING);
    const openvdb::CoordBBox box(
        openvdb::Coord(static_cast<int>(std::floor(lo.x / voxelSize)) - 1, static_cast<int>(std::floor(lo.y / voxelSize)) - 1,
                       static_cast<int>(std::floor(lo.z / voxelSize)) - 1),
        openvdb::Coord(static_cast<int>(std::ceil(hi.x / voxelSize)) + 1, static_cast<int>(std::ceil(hi.y / voxelSize)) + 1,
                       static_cast<int>(std::ceil(hi.z / voxelSize)) + 1));
    const DepthField field = depthField(*levelSet, box, voxelSize, kHalfWidth);

    // The interior voxels, deepest first (ties by position: deterministic).
    struct Inside {
        openvdb::Coord ijk;
        float depth;  // voxels
    };
    std::vector<Inside> inside;
    for (auto it = box.begin(); it; ++it) {
        const float d = field.depth[field.cell(*it)];
        if (d >= 0.0f) inside.push_back({*it, d});
    }
    if (inside.empty()) return balls;
    std::sort(inside.begin(), inside.end(), [](const Inside& a, const Inside& b) {
        if (a.depth != b.depth) return a.depth > b.depth;
        return a.ijk < b.ijk;
    });
    // 0: outside, 1: inside and not covered, 2: covered.
    std::vector<unsigned char> state(field.depth.size(), 0);
    for (const Inside& i : inside) state[field.cell(i.ijk)] = 1;
    const std::size_t goal =
        inside.size() - static_cast<std::size_t>(uncovered * static_cast<double>(inside.size()));
    std::size_t covered = 0;
    const auto toGlm = [](const openvdb::Vec3d& v) { return glm::dvec3(v.x(), v.y(), v.z()); };
    const auto depthAt = [&](const openvdb::Coord& c) { return field.at(c); };
    for (const Inside& candidate : inside) {
        if (covered >= goal || static_cast<int>(balls.size()) >= maxBalls) break;
        if (state[field.cell(candidate.ijk)] != 1) continue;
        // The voxel's own ball, or one a fraction of a voxel away if larger
        // (refined only where the move, under a voxel, cannot leave the mesh).
        openvdb::Vec3d centreIndex = candidate.ijk.asVec3d();
        glm::dvec3 centre = toGlm(transform->indexToWorld(centreIndex));
        double depth = distanceToMesh(mesh, centre);
        if (candidate.depth > 1.0f) {
            const openvdb::Vec3d refined = refinedCentre(depthAt, candidate.ijk);
            const glm::dvec3 refinedWorld = toGlm(transform->indexToWorld(refined));
            const double refinedDepth = distanceToMesh(mesh, refinedWorld);
            if (refinedDepth > depth) {
                centreIndex = refined;
                centre = refinedWorld;
                depth = refinedDepth;
            }
        }
        const double radiusVoxels = depth / voxelSize;
        // Stored as the values HyperFun's lexer reads back from their
        // 12-decimal text (sketch::hfDecimal), so the exported selection
        // and selectionField agree bit for bit.
        balls.push_back({glm::dvec3(sketch::hfConstant(centre.x), sketch::hfConstant(centre.y), sketch::hfConstant(centre.z)),
                         sketch::hfConstant(depth)});
        const int reach = static_cast<int>(std::ceil(radiusVoxels));
        const openvdb::Coord c = openvdb::Coord::round(centreIndex);
        for (int k = std::max(c.z() - reach, box.min().z()); k <= std::min(c.z() + reach, box.max().z()); ++k)
            for (int j = std::max(c.y() - reach, box.min().y()); j <= std::min(c.y() + reach, box.max().y()); ++j)
                for (int i = std::max(c.x() - reach, box.min().x()); i <= std::min(c.x() + reach, box.max().x()); ++i) {
                    const double dx = i - centreIndex.x(), dy = j - centreIndex.y(), dz = k - centreIndex.z();
                    if (dx * dx + dy * dy + dz * dz > radiusVoxels * radiusVoxels) continue;
                    unsigned char& s = state[field.cell(openvdb::Coord(i, j, k))];
                    if (s == 1) {
                        s = 2;
                        ++covered;
                    }
                }
    }
    return balls;
}

}  // namespace hg::garden::deform
