// Sculptures' grids for the deformable model's tests and bench: real
// voxel::Volumes sampled from HyperFun programs by voxel::voxelize, and the
// distances the tests measure vertices against.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "garden/deform/deform_mesh.h"
#include "tests/test_models.h"
#include "voxel/sampler.h"

namespace hg::test::deform {

// Distance-like fields (about 1 per model unit), positive inside.
inline std::string sphereSource(double r) {
    return "ball(x[3], a[1]) { ball = " + std::to_string(r) + " - sqrt(x[1]^2 + x[2]^2 + x[3]^2); }";
}
// A box of half-sides 0.4, 0.3, 0.25 about the origin.
constexpr const char* kBox =
    "box(x[3], a[1]) { box = min(min(0.4 - abs(x[1]), 0.3 - abs(x[2])), 0.25 - abs(x[3])); }";
// Two balls of radius 0.3 at x = -0.2 and 0.2: two lobes and a neck.
constexpr const char* kTwoLobes =
    "lobes(x[3], a[1]) { lobes = max(0.3 - sqrt((x[1] + 0.2)^2 + x[2]^2 + x[3]^2),"
    " 0.3 - sqrt((x[1] - 0.2)^2 + x[2]^2 + x[3]^2)); }";

// The program's grid over the cube [-half, half]^3 at `voxel` model units.
inline voxel::Volume gridOf(const std::string& source, double half, double voxel) {
    voxel::VolumeRequest request;
    frep::Box3 box;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = -half;
        box.hi[a] = half;
    }
    request.box = box;
    request.resolution = static_cast<int>(std::lround(2.0 * half / voxel));
    voxel::VoxelizeResult r = voxel::voxelize(modelFromSource(source), request);
    EXPECT_TRUE(r.volume) << r.error;
    return r.volume ? std::move(*r.volume) : voxel::Volume();
}

inline double sphereDistance(glm::dvec3 p, double r) { return std::fabs(glm::length(p) - r); }

// Unsigned distance to the box's surface.
inline double boxDistance(glm::dvec3 p) {
    const glm::dvec3 h(0.4, 0.3, 0.25);
    const glm::dvec3 q = glm::abs(p) - h;
    const double outside = glm::length(glm::max(q, glm::dvec3(0.0)));
    const double inside = std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
    return outside > 0.0 ? outside : -inside;
}

inline double twoLobesDistance(glm::dvec3 p) {
    const double f = std::max(0.3 - glm::length(p + glm::dvec3(0.2, 0, 0)), 0.3 - glm::length(p - glm::dvec3(0.2, 0, 0)));
    return std::fabs(f);
}

// The farthest any vertex lies from its neighbours' centroid.
inline double farthestFromNeighbours(const garden::deform::DeformMesh& mesh) {
    using namespace garden::deform;
    const VertexLists ring = vertexNeighbours(meshEdges(mesh), mesh.vertices.size());
    double worst = 0.0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        glm::dvec3 c(0.0);
        for (std::uint32_t i = ring.offsets[v]; i < ring.offsets[v + 1]; ++i) c += mesh.vertices[ring.items[i]];
        c /= static_cast<double>(ring.count(v));
        worst = std::max(worst, glm::length(c - mesh.vertices[v]));
    }
    return worst;
}

}  // namespace hg::test::deform
