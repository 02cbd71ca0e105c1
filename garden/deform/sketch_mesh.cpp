#include "garden/deform/sketch_mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "garden/deform/remesh.h"
#include "garden/sketch/inflation_field.h"
#include "voxel/volume_vdb.h"

namespace hg::garden::deform {

namespace {

// Newton steps onto the solid's surface along the field's gradient (central
// differences): the field is about a distance, so two steps land within
// rounding of it.
glm::dvec3 ontoSurface(const sketch::InflatedSolid& solid, glm::dvec3 p, double h) {
    for (int i = 0; i < 2; ++i) {
        const double f = sketch::inflatedValue(solid, p);
        glm::dvec3 g;
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 e(0.0);
            e[a] = h;
            g[a] = (sketch::inflatedValue(solid, p + e) - sketch::inflatedValue(solid, p - e)) / (2.0 * h);
        }
        const double g2 = glm::dot(g, g);
        if (!(g2 > 1e-12)) break;
        p -= (f / g2) * g;
    }
    return p;
}

}  // namespace

DeformMesh meshOfInflatedSketch(const sketch::InflatedSolid& solid, double edgeLength) {
    DeformMesh mesh;
    if (solid.pieces.empty() || !(edgeLength > 0.0)) return mesh;
    voxel::ensureOpenVdbInitialized();
    // Samples at 3/4 of the edge: volumeToMesh's edges are then mostly a
    // little shorter than the target and the remesher mostly collapses.
    const double h = 0.75 * edgeLength;
    const sketch::Vec3 lo = solid.paddedLo(2.0 * h), hi = solid.paddedHi(2.0 * h);
    const glm::ivec3 size = glm::ivec3(glm::ceil((hi - lo) / h)) + 1;
    std::vector<float> values(static_cast<std::size_t>(size.x) * size.y * size.z);
    tbb::parallel_for(tbb::blocked_range<int>(0, size.z), [&](const tbb::blocked_range<int>& r) {
        for (int k = r.begin(); k < r.end(); ++k)
            for (int j = 0; j < size.y; ++j)
                for (int i = 0; i < size.x; ++i) {
                    const glm::dvec3 p = lo + h * glm::dvec3(i, j, k);
                    // Negative inside: OpenVDB's level-set sign.
                    values[(static_cast<std::size_t>(k) * size.y + j) * size.x + i] =
                        static_cast<float>(-sketch::inflatedValue(solid, p) / h);
                }
    });
    const float background = 3.0f;
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(background);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(h));
    grid->transform().postTranslate(openvdb::Vec3d(lo.x, lo.y, lo.z));
    auto accessor = grid->getAccessor();
    for (int k = 0; k < size.z; ++k)
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const float v = values[(static_cast<std::size_t>(k) * size.y + j) * size.x + i];
                accessor.setValue(openvdb::Coord(i, j, k), std::clamp(v, -background, background));
            }
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, 0.0, false);
    for (const openvdb::Vec3s& p : points)
        mesh.vertices.emplace_back(static_cast<double>(p.x()), static_cast<double>(p.y()), static_cast<double>(p.z()));
    for (const openvdb::Vec3I& t : triangles) mesh.triangles.push_back({t.x(), t.y(), t.z()});
    for (const openvdb::Vec4I& q : quads) {
        // Split along the shorter diagonal.
        const auto d = [&](unsigned a, unsigned b) { return glm::length(mesh.vertices[a] - mesh.vertices[b]); };
        if (d(q[0], q[2]) <= d(q[1], q[3])) {
            mesh.triangles.push_back({q[0], q[1], q[2]});
            mesh.triangles.push_back({q[0], q[2], q[3]});
        } else {
            mesh.triangles.push_back({q[0], q[1], q[3]});
            mesh.triangles.push_back({q[1], q[2], q[3]});
        }
    }
    if (meshVolume(mesh) < 0.0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    const double gradientStep = 1e-4 * edgeLength;
    return remeshUniform(std::move(mesh), edgeLength, 8,
                         [&](const glm::dvec3& p) { return ontoSurface(solid, p, gradientStep); });
}

}  // namespace hg::garden::deform
