// validateMesh on TBB against the serial validation it replaced: the same
// counts, box and verdict on meshes with every kind of defect, large enough
// for many chunks of triangles and vertices; the same report to the last
// bit on any number of threads; and the serial loop's box rules kept where
// they are subtle (a NaN first coordinate, -0 against +0).
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "mesh_validation_reference.h"
#include "polygonizer/export/mesh_validation.h"

namespace hg::poly {
namespace {

using test::latLongSphere;
using test::referenceValidate;
using test::withDefects;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Counts and box exactly; volume and area to rounding (summed per chunk of
// triangles, then the chunks in order, where the serial loop went one
// triangle at a time), exactly when `exactSums`.
void expectSameReport(const MeshReport& r, const MeshReport& ref, bool exactSums, const std::string& what) {
    EXPECT_EQ(r.triangles, ref.triangles) << what;
    EXPECT_EQ(r.vertices, ref.vertices) << what;
    EXPECT_EQ(r.boundaryEdges, ref.boundaryEdges) << what;
    EXPECT_EQ(r.nonManifoldEdges, ref.nonManifoldEdges) << what;
    EXPECT_EQ(r.inconsistentEdges, ref.inconsistentEdges) << what;
    EXPECT_EQ(r.degenerateTriangles, ref.degenerateTriangles) << what;
    EXPECT_EQ(r.invalidTriangles, ref.invalidTriangles) << what;
    EXPECT_EQ(r.components, ref.components) << what;
    for (int a = 0; a < 3; ++a) {
        EXPECT_TRUE(sameBits(r.boxMin[a], ref.boxMin[a])) << what << ": " << r.boxMin[a] << " " << ref.boxMin[a];
        EXPECT_TRUE(sameBits(r.boxMax[a], ref.boxMax[a])) << what << ": " << r.boxMax[a] << " " << ref.boxMax[a];
    }
    if (std::isnan(ref.volume) || std::isnan(ref.area)) {
        EXPECT_EQ(std::isnan(r.volume), std::isnan(ref.volume)) << what;
        EXPECT_EQ(std::isnan(r.area), std::isnan(ref.area)) << what;
    } else if (exactSums) {
        EXPECT_EQ(r.volume, ref.volume) << what;
        EXPECT_EQ(r.area, ref.area) << what;
    } else {
        EXPECT_NEAR(r.volume, ref.volume, 1e-12 * std::fabs(ref.volume) + 1e-15) << what;
        EXPECT_NEAR(r.area, ref.area, 1e-12 * ref.area) << what;
    }
    EXPECT_EQ(r.ok(), ref.ok()) << what;
    EXPECT_EQ(describe(r), describe(ref)) << what;
}

TEST(ParallelValidation, MatchesTheSerialReportOnDefectiveMeshes) {
    // 159,200 triangles and 79,602 vertices: several chunks of each.
    const Mesh sphere = latLongSphere(200, 400, 1.0);
    ASSERT_GT(sphere.triangleCount(), 4u << 15);
    ASSERT_GT(sphere.vertexCount(), 1u << 16);
    const MeshReport closed = validateMesh(sphere);
    EXPECT_TRUE(closed.ok()) << describe(closed);
    expectSameReport(closed, referenceValidate(sphere), false, "closed sphere");
    for (unsigned seed : {1u, 2u, 3u}) {
        const Mesh m = withDefects(sphere, seed, seed != 1);
        const MeshReport r = validateMesh(m);
        EXPECT_FALSE(r.ok());
        expectSameReport(r, referenceValidate(m), false, "seed " + std::to_string(seed));
    }
}

TEST(ParallelValidation, SmallMeshesGiveTheSerialSumsExactly) {
    // One chunk: the same additions in the same order.
    for (unsigned seed : {4u, 5u}) {
        const Mesh m = withDefects(latLongSphere(30, 60, 2.0), seed);
        expectSameReport(validateMesh(m), referenceValidate(m), true, "seed " + std::to_string(seed));
    }
}

TEST(ParallelValidation, SameReportOnAnyNumberOfThreads) {
    const Mesh m = withDefects(latLongSphere(200, 400, 1.0), 6);
    MeshReport one, many;
    tbb::task_arena(1).execute([&] { one = validateMesh(m); });
    tbb::task_arena(4).execute([&] { many = validateMesh(m); });
    expectSameReport(many, one, true, "one thread against four");
}

TEST(ParallelValidation, BoxKeepsTheSerialRulesForNaNAndSignedZero) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Mesh m = latLongSphere(200, 400, 1.0);
    // -0 and +0 both minimal on an axis: the first one stays.
    for (std::size_t v = 0; v < m.vertexCount(); ++v)
        if (m.positions[3 * v] < 0.5f) m.positions[3 * v] = (v % 2) ? 0.0f : -0.0f;
    // A NaN where a later chunk of vertices starts is ignored by the box...
    m.positions[3 * (std::size_t{1} << 16) + 1] = nan;
    expectSameReport(validateMesh(m), referenceValidate(m), false, "NaN in a later chunk");
    // ...but a NaN in the first used vertex is the box.
    m.positions[2] = nan;
    const MeshReport r = validateMesh(m);
    EXPECT_TRUE(std::isnan(r.boxMin[2]));
    expectSameReport(r, referenceValidate(m), false, "NaN first");
}

}  // namespace
}  // namespace hg::poly
