#include "garden/deform/selection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

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
openvdb::Vec3d refinedCentre(const openvdb::FloatGrid::ConstAccessor& accessor, const openvdb::Coord& ijk) {
    openvdb::Vec3d at = ijk.asVec3d();
    const double here = -static_cast<double>(accessor.getValue(ijk));
    for (int axis = 0; axis < 3; ++axis) {
        openvdb::Coord step(0, 0, 0);
        step[axis] = 1;
        const double below = -static_cast<double>(accessor.getValue(ijk - step));
        const double above = -static_cast<double>(accessor.getValue(ijk + step));
        const double curvature = below - 2.0 * here + above;
        if (curvature < 0.0) at[axis] += std::clamp(0.5 * (below - above) / curvature, -0.5, 0.5);
    }
    return at;
}

}  // namespace

std::vector<SelectionBall> selectionBalls(const DeformMesh& mesh, double voxelSize, int maxBalls, double uncovered) {
    std::vector<SelectionBall> balls;
    if (mesh.triangles.empty() || !(voxelSize > 0.0) || maxBalls <= 0 || !checkClosedManifold(mesh).empty())
        return balls;
    voxel::ensureOpenVdbInitialized();
    // The signed distance to the mesh (negative inside) over the whole
    // interior: OpenVDB's exact distance near the surface, then grown
    // inward by its sweeps.
    const openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(voxelSize);
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.vertices.size());
    for (const glm::dvec3& v : mesh.vertices)
        points.emplace_back(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    const openvdb::FloatGrid::Ptr distance = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(
        *transform, points, triangles, {}, 1.0f, std::numeric_limits<float>::max());

    // The interior voxels, deepest first (ties by position: deterministic).
    struct Inside {
        openvdb::Coord ijk;
        float depth;
    };
    std::vector<Inside> inside;
    for (auto it = distance->cbeginValueOn(); it; ++it)
        if (*it < 0.0f) inside.push_back({it.getCoord(), -*it});
    if (inside.empty()) return balls;
    std::sort(inside.begin(), inside.end(), [](const Inside& a, const Inside& b) {
        if (a.depth != b.depth) return a.depth > b.depth;
        return a.ijk < b.ijk;
    });
    openvdb::CoordBBox box;
    for (const Inside& i : inside) box.expand(i.ijk);
    const openvdb::Coord dim = box.dim();
    const auto cell = [&](const openvdb::Coord& c) {
        const openvdb::Coord d = c - box.min();
        return (static_cast<std::size_t>(d.z()) * static_cast<std::size_t>(dim.y()) + static_cast<std::size_t>(d.y())) *
                   static_cast<std::size_t>(dim.x()) +
               static_cast<std::size_t>(d.x());
    };
    // 0: outside, 1: inside and not covered, 2: covered.
    std::vector<unsigned char> state(static_cast<std::size_t>(dim.x()) * dim.y() * dim.z(), 0);
    for (const Inside& i : inside) state[cell(i.ijk)] = 1;
    const std::size_t goal =
        inside.size() - static_cast<std::size_t>(uncovered * static_cast<double>(inside.size()));
    std::size_t covered = 0;
    const openvdb::FloatGrid::ConstAccessor accessor = distance->getConstAccessor();
    const auto toGlm = [](const openvdb::Vec3d& v) { return glm::dvec3(v.x(), v.y(), v.z()); };
    for (const Inside& candidate : inside) {
        if (covered >= goal || static_cast<int>(balls.size()) >= maxBalls) break;
        if (state[cell(candidate.ijk)] != 1) continue;
        // Refined only where the move (under a voxel) cannot leave the mesh.
        openvdb::Vec3d centreIndex = static_cast<double>(candidate.depth) > voxelSize ? refinedCentre(accessor, candidate.ijk)
                                                                 : candidate.ijk.asVec3d();
        glm::dvec3 centre = toGlm(transform->indexToWorld(centreIndex));
        double depth = distanceToMesh(mesh, centre);
        if (depth < static_cast<double>(candidate.depth)) {  // the voxel's own ball was larger after all
            centreIndex = candidate.ijk.asVec3d();
            centre = toGlm(transform->indexToWorld(centreIndex));
            depth = static_cast<double>(candidate.depth);
        }
        const double radiusVoxels = depth / voxelSize;
        balls.push_back({centre, depth});
        const int reach = static_cast<int>(std::ceil(radiusVoxels));
        const openvdb::Coord c = openvdb::Coord::round(centreIndex);
        for (int k = std::max(c.z() - reach, box.min().z()); k <= std::min(c.z() + reach, box.max().z()); ++k)
            for (int j = std::max(c.y() - reach, box.min().y()); j <= std::min(c.y() + reach, box.max().y()); ++j)
                for (int i = std::max(c.x() - reach, box.min().x()); i <= std::min(c.x() + reach, box.max().x()); ++i) {
                    const double dx = i - centreIndex.x(), dy = j - centreIndex.y(), dz = k - centreIndex.z();
                    if (dx * dx + dy * dy + dz * dz > radiusVoxels * radiusVoxels) continue;
                    unsigned char& s = state[cell(openvdb::Coord(i, j, k))];
                    if (s == 1) {
                        s = 2;
                        ++covered;
                    }
                }
    }
    return balls;
}

}  // namespace hg::garden::deform
