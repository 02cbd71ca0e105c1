#include "voxel/mesh_volume.h"

#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "voxel/memory_guard.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

namespace {

using Clock = std::chrono::steady_clock;

// What mesh-to-volume holds per band voxel beside our grid: its distance
// grid, the closest-triangle index grid and a mask, in whole leaves.
constexpr double kBytesPerBandVoxel = 16.0;

// Vertices equal by position get one id (a facet soup's corners, an OBJ's
// seams), so edges are compared by where they are.
std::vector<std::uint32_t> positionIds(const std::vector<float>& positions) {
    std::map<std::array<float, 3>, std::uint32_t> ids;
    std::vector<std::uint32_t> out(positions.size() / 3);
    for (std::size_t v = 0; v < out.size(); ++v) {
        const std::array<float, 3> p{positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
        out[v] = ids.emplace(p, static_cast<std::uint32_t>(ids.size())).first->second;
    }
    return out;
}

}  // namespace

frep::Box3 meshBounds(const std::vector<float>& positions) {
    frep::Box3 box;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = std::numeric_limits<double>::max();
        box.hi[a] = std::numeric_limits<double>::lowest();
    }
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3)
        for (int a = 0; a < 3; ++a) {
            box.lo[a] = std::min(box.lo[a], static_cast<double>(positions[i + static_cast<std::size_t>(a)]));
            box.hi[a] = std::max(box.hi[a], static_cast<double>(positions[i + static_cast<std::size_t>(a)]));
        }
    return box;
}

frep::Box3 meshModelBox(const std::vector<float>& positions) {
    frep::Box3 box = meshBounds(positions);
    if (positions.size() < 3) return box;
    double longest = 0.0;
    for (int a = 0; a < 3; ++a) longest = std::max(longest, box.hi[a] - box.lo[a]);
    const double margin = kMeshBoxMargin * longest;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] -= margin;
        box.hi[a] += margin;
    }
    return box;
}

bool meshIsClosed(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices) {
    const std::vector<std::uint32_t> id = positionIds(positions);
    std::unordered_map<std::uint64_t, int> uses;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t c[3] = {id[indices[t]], id[indices[t + 1]], id[indices[t + 2]]};
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;  // degenerate: no edges of its own
        for (int e = 0; e < 3; ++e) {
            const std::uint64_t a = std::min(c[e], c[(e + 1) % 3]), b = std::max(c[e], c[(e + 1) % 3]);
            ++uses[(a << 32) | b];
        }
    }
    if (uses.empty()) return false;
    for (const auto& [edge, n] : uses)
        if (n != 2) return false;
    return true;
}

VoxelizeResult levelSetFromMesh(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices,
                                const MeshLevelSetRequest& request) {
    VoxelizeResult result;
    const auto start = Clock::now();
    if (std::string why = checkResolutionAndBand(request.resolution, request.band); !why.empty()) {
        result.error = why;
        return result;
    }
    if (indices.size() < 3 || indices.size() % 3 != 0) {
        result.error = "the mesh has no triangles";
        return result;
    }
    const std::size_t vertices = positions.size() / 3;
    for (std::uint32_t i : indices)
        if (i >= vertices) {
            result.error = "the mesh has a triangle corner " + std::to_string(i) + " past its " +
                           std::to_string(vertices) + " vertices";
            return result;
        }
    for (float x : positions)
        if (!std::isfinite(x)) {
            result.error = "the mesh has a vertex that is not finite";
            return result;
        }
    result.modelBox.origin = request.box ? BoxOrigin::Given : BoxOrigin::Sampled;
    result.modelBox.box = request.box ? *request.box : meshModelBox(positions);
    VolumeFrame frame;
    if (std::string why = makeFrame(result.modelBox.box, request.resolution, request.band, frame); !why.empty()) {
        result.error = "the mesh's box: " + why;
        return result;
    }
    // The band's voxels: the surface's area in voxels times the band's
    // thickness, by whole 8^3 leaves (the guard of levelSetFromScalar).
    std::vector<openvdb::Vec3s> points(vertices);
    for (std::size_t v = 0; v < vertices; ++v)
        points[v] = openvdb::Vec3s(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    std::vector<openvdb::Vec3I> triangles(indices.size() / 3);
    double area = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        triangles[t] = openvdb::Vec3I(indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]);
        const openvdb::Vec3d a(points[triangles[t][0]]), b(points[triangles[t][1]]), c(points[triangles[t][2]]);
        area += 0.5 * (b - a).cross(c - a).length();
    }
    const double areaVoxels = area / (frame.voxelSize * frame.voxelSize);
    const double leaves = areaVoxels / 64.0 * (std::ceil(2.0 * (static_cast<double>(frame.band) + 1.0) / 8.0) + 1.0);
    const auto needed = static_cast<std::uint64_t>(leaves * 512.0 * kBytesPerBandVoxel);
    result.stats.estimatedBytes = needed;
    if (std::string why = refuseIfTooBig("the level set of the mesh", request.resolution, needed,
                                         memoryLimit(request.memoryLimit), 2.0);
        !why.empty()) {
        result.error = why;
        return result;
    }
    ensureOpenVdbInitialized();
    const openvdb::math::Transform::Ptr xform = frameTransform(frame);
    const bool closed = meshIsClosed(positions, indices);
    // A voxel beyond the band on each side, so that the clamp, not the
    // conversion, ends it.
    const float width = frame.band + 1.0f;
    openvdb::FloatGrid::Ptr distance;
    try {
        if (closed) {
            distance = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*xform, points, triangles, width);
        } else {
            // No inside: the points within the shell's half-thickness of the
            // surface are the solid, their distance to the shell's faces
            // the unsigned distance less that half-thickness.
            const double shell = kMeshShellVoxels * frame.voxelSize;
            const std::vector<openvdb::Vec4I> noQuads;
            distance = openvdb::tools::meshToUnsignedDistanceField<openvdb::FloatGrid>(
                *xform, points, triangles, noQuads, width + static_cast<float>(kMeshShellVoxels));
            for (auto it = distance->beginValueAll(); it; ++it)
                it.setValue(static_cast<float>(static_cast<double>(*it) - shell));
            distance->tree().root().setBackground(
                static_cast<float>(static_cast<double>(distance->background()) - shell), false);
        }
    } catch (const std::exception& e) {
        result.error = std::string("the mesh could not be turned into a level set: ") + e.what();
        return result;
    }
    adoptLevelSet(*distance, frame, request.source, std::chrono::duration<double>(Clock::now() - start).count(), result);
    return result;
}

}  // namespace hg::voxel
