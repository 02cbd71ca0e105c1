// The edge census behind validateMesh: the same boundary, non-manifold and
// inconsistent edges and the same parts as the serial sort it replaced, on
// meshes with every kind of defect, however the work is cut into chunks
// and buckets, with 32- or 64-bit numbers, on one thread or many.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <cstdint>
#include <string>
#include <vector>

#include "mesh_validation_reference.h"
#include "polygonizer/export/mesh_validation_edges.h"

namespace hg::poly {
namespace {

using test::concatenate;
using test::latLongSphere;
using test::referenceValidate;
using test::soup;
using test::withDefects;

// What validateMesh hands the census: in range and three different corners.
std::vector<std::uint8_t> liveTriangles(const Mesh& m) {
    std::vector<std::uint8_t> live(m.triangleCount(), 0);
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
        const std::uint32_t* i = &m.indices[3 * t];
        const bool inRange = i[0] < m.vertexCount() && i[1] < m.vertexCount() && i[2] < m.vertexCount();
        live[t] = inRange && i[0] != i[1] && i[1] != i[2] && i[0] != i[2];
    }
    return live;
}

void expectSame(const EdgeCensus& c, const MeshReport& ref, const std::string& what) {
    EXPECT_EQ(c.boundaryEdges, ref.boundaryEdges) << what;
    EXPECT_EQ(c.nonManifoldEdges, ref.nonManifoldEdges) << what;
    EXPECT_EQ(c.inconsistentEdges, ref.inconsistentEdges) << what;
    EXPECT_EQ(c.components, ref.components) << what;
}



struct Case {
    std::string name;
    Mesh mesh;
};

std::vector<Case> meshes() {
    const Mesh sphere = latLongSphere(40, 80, 1.0);
    return {
        {"closed sphere", sphere},
        {"defects in place", withDefects(sphere, 1, false)},
        {"defects, vertices shuffled", withDefects(sphere, 2)},
        {"three spheres, defects", withDefects(concatenate(concatenate(sphere, latLongSphere(10, 20, 1.0, 3)),
                                                           latLongSphere(12, 16, 0.5, -3)),
                                               3)},
        {"soup", soup(latLongSphere(8, 16, 1.0))},
        {"wide fans at the poles", withDefects(latLongSphere(3, 2000, 1.0), 4, false)},
        {"empty", Mesh{}},
    };
}

std::vector<EdgeLayout> layouts(const Mesh& m) {
    return {
        defaultEdgeLayout(m.triangleCount(), m.vertexCount()),
        {1, 6, false},      // a chunk per triangle
        {997, 0, false},    // a bucket per vertex
        {7, 3, false},
        {100, 2, true},     // 64-bit numbers
        {5000, 12, false},  // one bucket
        {13, 4, true},
    };
}

TEST(EdgeCensus, MatchesTheSerialSortOnDefectiveMeshes) {
    for (const Case& c : meshes()) {
        const MeshReport ref = referenceValidate(c.mesh);
        const std::vector<std::uint8_t> live = liveTriangles(c.mesh);
        for (const EdgeLayout& layout : layouts(c.mesh)) {
            const std::string what = c.name + ", chunks of " + std::to_string(layout.chunkTriangles) +
                                     ", buckets of 2^" + std::to_string(layout.bucketShift) +
                                     (layout.wideIds ? ", 64-bit" : "");
            expectSame(censusEdges(c.mesh, live, layout), ref, what);
        }
    }
}

TEST(EdgeCensus, TheDefectiveMeshesHaveEveryKindOfEdge) {
    // Otherwise the test above would prove less than it says.
    const MeshReport r = referenceValidate(withDefects(latLongSphere(40, 80, 1.0), 2));
    EXPECT_GT(r.boundaryEdges, 0u);
    EXPECT_GT(r.nonManifoldEdges, 0u);
    EXPECT_GT(r.inconsistentEdges, 0u);
    EXPECT_GT(r.degenerateTriangles, 0u);
    EXPECT_GT(r.invalidTriangles, 0u);
    EXPECT_GT(r.components, 1u);
}

TEST(EdgeCensus, SameOnOneThreadAndMany) {
    const Mesh m = withDefects(latLongSphere(60, 120, 1.0), 5);
    const std::vector<std::uint8_t> live = liveTriangles(m);
    const EdgeLayout layout{64, 2, false};
    EdgeCensus one, many;
    tbb::task_arena(1).execute([&] { one = censusEdges(m, live, layout); });
    tbb::task_arena(4).execute([&] { many = censusEdges(m, live, layout); });
    EXPECT_EQ(one.boundaryEdges, many.boundaryEdges);
    EXPECT_EQ(one.nonManifoldEdges, many.nonManifoldEdges);
    EXPECT_EQ(one.inconsistentEdges, many.inconsistentEdges);
    EXPECT_EQ(one.components, many.components);
    expectSame(many, referenceValidate(m), "four threads");
}

TEST(EdgeCensus, CountsEachKindOfEdge) {
    Mesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1};
    auto census = [](const Mesh& mesh) {
        return censusEdges(mesh, liveTriangles(mesh), defaultEdgeLayout(mesh.triangleCount(), mesh.vertexCount()));
    };

    m.indices = {0, 1, 2};
    EdgeCensus c = census(m);
    EXPECT_EQ(c.boundaryEdges, 3u);
    EXPECT_EQ(c.components, 1u);

    m.indices = {0, 1, 2, 1, 3, 2};  // two triangles sharing edge 1-2, the same way round
    c = census(m);
    EXPECT_EQ(c.boundaryEdges, 4u);
    EXPECT_EQ(c.inconsistentEdges, 0u);
    EXPECT_EQ(c.components, 1u);

    m.indices = {0, 1, 2, 1, 2, 3};  // the second one flipped
    c = census(m);
    EXPECT_EQ(c.inconsistentEdges, 1u);

    m.indices = {0, 1, 2, 0, 1, 2, 0, 1, 2};  // three times over
    c = census(m);
    EXPECT_EQ(c.nonManifoldEdges, 3u);
    EXPECT_EQ(c.boundaryEdges, 0u);
    EXPECT_EQ(c.inconsistentEdges, 0u);
    EXPECT_EQ(c.components, 1u);

    m.indices = {0, 1, 2, 0, 1, 3};  // on either side of edge 0-1, both running from 0 to 1
    c = census(m);
    EXPECT_EQ(c.components, 1u);
    EXPECT_EQ(c.inconsistentEdges, 1u);

    m.indices = {0, 1, 2, 0, 3, 4};  // sharing a corner only: two parts
    c = census(m);
    EXPECT_EQ(c.components, 2u);
    EXPECT_EQ(c.boundaryEdges, 6u);

    m.indices = {0, 1, 2, 3, 2, 1, 0, 0, 1};  // the last one degenerate: not counted
    std::vector<std::uint8_t> live = liveTriangles(m);
    c = censusEdges(m, live, {1, 0, false});
    EXPECT_EQ(c.boundaryEdges, 4u);
    EXPECT_EQ(c.components, 1u);
}

}  // namespace
}  // namespace hg::poly
