#include "garden/deform/deformable_model.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "garden/deform/remesh.h"
#include "voxel/volume_vdb.h"

namespace hg::garden::deform {

namespace {

// The grid's value and gradient at a model point by trilinear
// interpolation of the eight voxels around it (index units: stored value
// per voxel), and whether all eight are inside the band: clamped voxels and
// tiles (|value| == band) carry no gradient.
struct GridSample {
    double value = 0.0;
    glm::dvec3 gradient{0.0};
    bool inBand = false;
};

// A vertex this far (voxels) on the far side of the surface holds its
// place; nearer, it is a step that went a little past f = 0 and is brought
// back like any other.
constexpr double kFarSideVoxels = 0.5;

class GridProbe {
public:
    explicit GridProbe(const voxel::Volume& volume)
        : accessor_(voxel::vdb(volume).getConstAccessor()),
          lo_(volume.frame.modelBox.lo[0], volume.frame.modelBox.lo[1], volume.frame.modelBox.lo[2]),
          inverseVoxel_(1.0 / volume.frame.voxelSize),
          band_(static_cast<double>(volume.frame.band)) {}

    GridSample at(const glm::dvec3& p) {
        const glm::dvec3 x = (p - lo_) * inverseVoxel_;
        const glm::dvec3 base = glm::floor(x);
        const glm::dvec3 t = x - base;
        const int i = static_cast<int>(base.x), j = static_cast<int>(base.y), k = static_cast<int>(base.z);
        double c[2][2][2];
        double largest = 0.0;
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b)
                for (int d = 0; d < 2; ++d) {
                    c[a][b][d] = static_cast<double>(accessor_.getValue(openvdb::Coord(i + a, j + b, k + d)));
                    largest = std::max(largest, std::fabs(c[a][b][d]));
                }
        // Along x first, then y, then z; the gradient from the same lerps.
        const auto lerp = [](double p0, double p1, double s) { return p0 + s * (p1 - p0); };
        double cx[2][2], dx[2][2];
        for (int b = 0; b < 2; ++b)
            for (int d = 0; d < 2; ++d) {
                cx[b][d] = lerp(c[0][b][d], c[1][b][d], t.x);
                dx[b][d] = c[1][b][d] - c[0][b][d];
            }
        const double cxy0 = lerp(cx[0][0], cx[1][0], t.y), cxy1 = lerp(cx[0][1], cx[1][1], t.y);
        GridSample s;
        s.value = lerp(cxy0, cxy1, t.z);
        s.gradient.x = lerp(lerp(dx[0][0], dx[1][0], t.y), lerp(dx[0][1], dx[1][1], t.y), t.z);
        s.gradient.y = lerp(cx[1][0] - cx[0][0], cx[1][1] - cx[0][1], t.z);
        s.gradient.z = cxy1 - cxy0;
        s.inBand = largest < band_ * (1.0 - 1e-6);
        return s;
    }

private:
    openvdb::FloatGrid::ConstAccessor accessor_;
    glm::dvec3 lo_;
    double inverseVoxel_;
    double band_;
};

// Gradients shorter than this (stored units per voxel; about 1 near the
// surface) are no gradient.
constexpr double kNoGradient = 0.05;
// The seed's second stop rule: the magnitude falls below this share of
// what it was.
constexpr double kMagnitudeDrop = 0.25;

template <class Body>
void overVertices(std::size_t count, bool parallel, const Body& body) {
    if (parallel && count > 256)
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 128),
                          [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    else
        body(0, count);
}

}  // namespace

DeformableModel::DeformableModel(DeformMesh mesh, double edgeLength, DeformOptions options)
    : mesh_(std::move(mesh)), edgeLength_(edgeLength), options_(options) {
    rebuildTopology();
}

void DeformableModel::rebuildTopology() {
    edges_ = meshEdges(mesh_);
    ring_ = vertexNeighbours(edges_, mesh_.vertices.size());
    fan_ = vertexTriangles(mesh_);
}

void DeformableModel::deform(const voxel::Volume& volume, DeformMode mode, int iterations) {
    if (!(volume.frame.voxelSize > 0.0)) return;  // an empty volume has no frame to step in
    for (int i = 0; i < iterations; ++i) step(volume, mode);
}

void DeformableModel::step(const voxel::Volume& volume, DeformMode mode) {
    const std::size_t n = mesh_.vertices.size();
    const double voxel = volume.frame.voxelSize;
    const double stepLength = options_.stepVoxels * voxel;
    const double towardNormal = mode == DeformMode::Grow ? 1.0 : -1.0;

    // Normals from the old positions (face normals, then per vertex in its
    // fan's order).
    std::vector<glm::dvec3> faceNormal(mesh_.triangles.size());
    overVertices(mesh_.triangles.size(), options_.parallel, [&](std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t < end; ++t) {
            const auto& tri = mesh_.triangles[t];
            faceNormal[t] = glm::cross(mesh_.vertices[tri[1]] - mesh_.vertices[tri[0]],
                                       mesh_.vertices[tri[2]] - mesh_.vertices[tri[0]]);
        }
    });
    double edgeSum = 0.0;
    for (const MeshEdge& e : edges_) edgeSum += glm::length(mesh_.vertices[e.a] - mesh_.vertices[e.b]);
    const double runOff = options_.runOffEdges * edgeSum / static_cast<double>(std::max<std::size_t>(1, edges_.size()));

    // Which side of the surface is the far one: inside the material while
    // shrinking (a shrink-wrap starts outside); while growing, the side
    // fewer of the vertices are on (a blow-up starts inside an object, or
    // in a cavity or empty space, and most of it stays there).
    double farSideSign = 1.0;
    if (mode == DeformMode::Grow) {
        GridProbe probe(volume);
        std::size_t inside = 0;
        for (const glm::dvec3& p : mesh_.vertices)
            if (probe.at(p).value > 0.0) ++inside;
        farSideSign = 2 * inside > n ? -1.0 : 1.0;
    }
    std::vector<glm::dvec3> moved(n);
    std::vector<double> moveLength(n);
    overVertices(n, options_.parallel, [&](std::size_t begin, std::size_t end) {
        GridProbe probe(volume);
        for (std::size_t v = begin; v < end; ++v) {
            const glm::dvec3 p = mesh_.vertices[v];
            glm::dvec3 normal(0.0);
            for (std::uint32_t i = fan_.offsets[v]; i < fan_.offsets[v + 1]; ++i) normal += faceNormal[fan_.items[i]];
            const double normalLength = glm::length(normal);
            if (normalLength > 0.0) normal /= normalLength;

            // The force: along the normal where there is no gradient, else a
            // Newton step toward f = 0 along the gradient, no longer than a
            // step, cut short by the seed's stop rules.
            glm::dvec3 force = towardNormal * stepLength * normal;
            const GridSample here = probe.at(p);
            const double g2 = glm::dot(here.gradient, here.gradient);
            // A vertex on the far side of the surface (inside the material
            // while shrinking, outside it while growing) began there: the
            // model was drawn through the sculpture, and the vertex is on
            // the cut that bounds the selection. It holds its place, or the
            // cut would travel along the material (a model around a
            // column's capital crawled down the shaft).
            const bool farSide = farSideSign * here.value > kFarSideVoxels;
            if (farSide) {
                force = glm::dvec3(0.0);
            } else if (here.inBand && g2 > kNoGradient * kNoGradient) {
                force = (-here.value / g2) * voxel * here.gradient;
                const double length = glm::length(force);
                if (length > stepLength) force *= stepLength / length;
                const GridSample there = probe.at(p + force);
                if (there.inBand) {
                    const double turned = glm::dot(here.gradient, there.gradient);
                    if (turned < 0.0 || glm::dot(there.gradient, there.gradient) < kMagnitudeDrop * kMagnitudeDrop * g2)
                        force = glm::dvec3(0.0);  // the gradient turned or fell: stop here
                    else if ((here.value > 0.0) != (there.value > 0.0) && here.value != there.value)
                        force *= here.value / (here.value - there.value);  // stop on f = 0
                }
            }

            // The neighbourhood: a vertex far from its neighbours' centroid
            // ran off (caught on something they passed) and goes back onto
            // the centroid; else tangential smoothing keeps the vertices
            // spread evenly.
            glm::dvec3 centroid(0.0);
            for (std::uint32_t i = ring_.offsets[v]; i < ring_.offsets[v + 1]; ++i)
                centroid += mesh_.vertices[ring_.items[i]];
            centroid /= static_cast<double>(std::max<std::size_t>(1, ring_.count(v)));
            const glm::dvec3 toCentroid = centroid - p;
            glm::dvec3 next;
            if (glm::length(toCentroid) > runOff)
                next = centroid;
            else
                next = p + force +
                       options_.tangentialSmoothing * (toCentroid - glm::dot(toCentroid, normal) * normal);
            moved[v] = next;
            moveLength[v] = glm::length(next - p);
        }
    });
    mesh_.vertices = std::move(moved);
    lastMove_ = 0.0;
    for (double m : moveLength) lastMove_ = std::max(lastMove_, m);
    ++iterations_;
    int changed = 0;
    if (options_.remeshEvery > 0 && iterations_ % options_.remeshEvery == 0) {
        changed = remeshRound(mesh_, edgeLength_);
        if (changed > 0) rebuildTopology();
    }
    settled_ = changed == 0 && lastMove_ < options_.settledVoxels * voxel;
}

}  // namespace hg::garden::deform
