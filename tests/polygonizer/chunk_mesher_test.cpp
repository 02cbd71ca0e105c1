// Chunk meshes at mixed levels of detail: the union of every chunk's mesh,
// welded by position, is closed (no boundary edge), manifold and outward,
// for uniform levels, a checkerboard where levels differ across every chunk
// face, random balanced configurations, the levels a camera selects, and
// our own sculptures. Every edge is used twice, except rare pinches on
// chunk edge lines (see edgeUse). At level 0 everywhere the union is the
// export mesh.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "frep/language/parser.h"
#include "polygonizer/realtime/chunk_mesher.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/realtime/lod_selection.h"
#include "polygonizer/export/mesh_validation.h"
#include "chunk_union.h"
#include "sample_program.h"
#include "voxel/sampler.h"

namespace hg::poly {
namespace {

using test::edgeUse;
using test::EdgeUse;
using test::sampleProgram;
using test::unionOf;

// Thin features (the ring's tube is a few coarse cells wide) so that coarse
// and fine samples disagree often along seams.
const char* kRings =
    "q(x[3], a[1]) { array c[3], d[3]; c = [0, 0, 0]; d = [0.25, 0.1, 0];"
    " q = hfTorusY(x, c, 0.55, 0.12) | hfTorusX(x, d, 0.45, 0.09) | (0.05 - ((x[1]-0.2)^2 + (x[2]+0.3)^2 + (x[3]-0.5)^2)); }";

std::string describeLevels(const ChunkLayout& layout, const std::vector<int>& levels) {
    std::ostringstream s;
    s << "chunks " << layout.dims()[0] << "x" << layout.dims()[1] << "x" << layout.dims()[2] << " levels";
    for (int l : levels) s << ' ' << l;
    return s.str();
}

void expectClosed(const LodPyramid& pyramid, const ChunkLayout& layout, const std::vector<int>& levels) {
    Mesh welded = weldByPosition(unionOf(pyramid, layout, levels));
    MeshReport r = validateMesh(welded);
    ASSERT_GT(r.triangles, 0u);
    EdgeUse e = edgeUse(welded, layout);
    EXPECT_EQ(r.boundaryEdges, 0u) << describeLevels(layout, levels);
    EXPECT_EQ(e.boundary, 0u);
    EXPECT_EQ(e.other, 0u) << describeLevels(layout, levels);
    EXPECT_LE(e.pinches, r.triangles / 1000) << "pinches are rare";
    EXPECT_EQ(r.inconsistentEdges, 0u) << describeLevels(layout, levels);
    EXPECT_GT(r.volume, 0.0);
}

// Lowers levels until face neighbours differ by at most one.
void balance(const ChunkLayout& layout, std::vector<int>& levels) {
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t i = 0; i < levels.size(); ++i)
            for (std::size_t n : layout.faceNeighbours(i))
                if (levels[n] > levels[i] + 1) {
                    levels[n] = levels[i] + 1;
                    changed = true;
                }
    }
}

TEST(ChunkMesher, AtLevelZeroTheUnionIsTheExportMesh) {
    voxel::Volume v = sampleProgram(kRings, 96);
    LodPyramid pyramid(v, 3);
    ChunkLayout layout(v.frame, 16);
    MeshReport chunks = validateMesh(weldByPosition(unionOf(pyramid, layout, std::vector<int>(layout.count(), 0))));
    MeshReport whole = validateMesh(meshVolume(v));
    EXPECT_TRUE(chunks.ok());
    EXPECT_EQ(chunks.triangles, whole.triangles);
    EXPECT_EQ(chunks.vertices, whole.vertices);
    EXPECT_NEAR(chunks.volume, whole.volume, 1e-9 * whole.volume);
}

TEST(ChunkMesher, UniformLevelsAreClosedAndCoarserLevelsHaveFewerTriangles) {
    voxel::Volume v = sampleProgram(kRings, 128);
    LodPyramid pyramid(v, 4);
    ChunkLayout layout(v.frame, 32);
    std::size_t previous = 0;
    for (int level = 0; level < 4; ++level) {
        std::vector<int> levels(layout.count(), level);
        expectClosed(pyramid, layout, levels);
        std::size_t triangles = unionOf(pyramid, layout, levels).triangleCount();
        if (level > 0) {
            EXPECT_LT(3 * triangles, previous) << "level " << level;
        }
        previous = triangles;
    }
}

TEST(ChunkMesher, CheckerboardWithALevelSeamOnEveryChunkFaceIsClosed) {
    voxel::Volume v = sampleProgram(kRings, 128);
    LodPyramid pyramid(v, 4);
    for (int size : {16, 32}) {
        ChunkLayout layout(v.frame, size);
        for (int base : {0, 1, 2}) {
            if (size == 16 && base == 2) continue;  // 16 >> 3 leaves 2 cells: still fine, but slow to no purpose
            std::vector<int> levels(layout.count());
            for (std::size_t i = 0; i < levels.size(); ++i) {
                ChunkKey k = layout.key(i);
                levels[i] = base + ((k.x + k.y + k.z) & 1);
            }
            expectClosed(pyramid, layout, levels);
        }
    }
}

TEST(ChunkMesher, RandomBalancedConfigurationsAreClosed) {
    voxel::Volume v = sampleProgram(kRings, 96);
    LodPyramid pyramid(v, 4);
    std::mt19937 rng(11);
    for (int size : {16, 32}) {
        ChunkLayout layout(v.frame, size);
        const int maxLevel = size == 32 ? 3 : 2;
        for (int trial = 0; trial < 5; ++trial) {
            std::vector<int> levels(layout.count());
            for (int& l : levels) l = static_cast<int>(rng() % static_cast<unsigned>(maxLevel + 1));
            balance(layout, levels);
            expectClosed(pyramid, layout, levels);
        }
        // A single fine chunk in a coarse world, and a single coarse chunk in
        // a fine one: every kind of convex and concave corner, on chunks the
        // surface passes through.
        std::vector<std::size_t> surfaceChunks;
        for (std::size_t i = 0; i < layout.count(); ++i)
            if (!meshChunk(pyramid, layout, i, ChunkLod{}).empty()) surfaceChunks.push_back(i);
        ASSERT_GE(surfaceChunks.size(), 4u);
        for (std::size_t n = 0; n < 4; ++n) {
            const std::size_t i = surfaceChunks[n * surfaceChunks.size() / 4];
            std::vector<int> fineIsland(layout.count(), 1), coarseIsland(layout.count(), 0);
            fineIsland[i] = 0;
            coarseIsland[i] = 1;
            expectClosed(pyramid, layout, fineIsland);
            expectClosed(pyramid, layout, coarseIsland);
        }
    }
}

TEST(ChunkMesher, LevelsSelectedFromCamerasAreClosed) {
    voxel::Volume v = sampleProgram(kRings, 128);
    LodPyramid pyramid(v, 4);
    ChunkLayout layout(v.frame, 16);
    for (double distance : {0.05, 0.4, 1.5}) {
        Camera cam;
        cam.position = {0.3, 0.2, -0.6 - distance};
        cam.viewportHeight = 200;  // a small viewport: more levels within a small model
        LodSettings s;
        s.maxLevel = 2;
        s.detail = Sphere{{0.55, 0.0, 0.0}, 0.1};
        std::vector<int> levels = selectLevels(layout, cam, s);
        expectClosed(pyramid, layout, levels);
    }
}

TEST(ChunkMesher, OurSculpturesAreClosedAtMixedLevels) {
    const std::filesystem::path dir = std::filesystem::path(HG_SOURCE_DIR) / "content" / "hyperfun";
    for (const char* name : {"key_dryad.hf", "key_orant.hf", "key_knot.hf"}) {
        std::ifstream in(dir / name);
        ASSERT_TRUE(in) << name;
        std::stringstream text;
        text << in.rdbuf();
        voxel::Volume v = sampleProgram(text.str(), 96);
        LodPyramid pyramid(v, 3);
        ChunkLayout layout(v.frame, 16);
        std::vector<int> levels(layout.count());
        for (std::size_t i = 0; i < levels.size(); ++i) {
            ChunkKey k = layout.key(i);
            levels[i] = (k.x + 2 * k.y + k.z) % 3 == 0 ? 0 : 1;
        }
        balance(layout, levels);
        SCOPED_TRACE(name);
        expectClosed(pyramid, layout, levels);
    }
}

// Each chunk's transition faces are the faces whose neighbour (by key) is
// one level finer, for levels that vary over a layout of unequal sides.
TEST(ChunkMesher, TransitionFacesAreTheFacesWithAFinerNeighbour) {
    voxel::Volume v = sampleProgram(kRings, 64);
    ChunkLayout layout(v.frame, 16);
    ASSERT_GT(layout.count(), 8u);
    std::vector<int> levels(layout.count());
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const ChunkKey k = layout.key(i);
        levels[i] = (k.x + k.y + 2 * k.z) % 4 == 0 ? 1 : 2;
    }
    const std::vector<ChunkLod> lods = chunkLods(layout, levels);
    int transitions = 0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const ChunkKey k = layout.key(i);
        EXPECT_EQ(lods[i].level, levels[i]);
        for (int f = 0; f < kChunkFaces; ++f) {
            ChunkKey n = k;
            (f / 2 == 0 ? n.x : f / 2 == 1 ? n.y : n.z) += f % 2 ? 1 : -1;
            const bool finer = layout.contains(n) && levels[layout.index(n)] == levels[i] - 1;
            EXPECT_EQ((lods[i].transitionFaces >> f & 1) != 0, finer) << "chunk " << i << " face " << f;
            transitions += finer;
        }
    }
    EXPECT_GT(transitions, 10);
}

TEST(ChunkMesher, RejectsLevelsThatCannotBeStitched) {
    voxel::Volume v = sampleProgram(kRings, 64);
    ChunkLayout layout(v.frame, 16);
    std::vector<int> levels(layout.count(), 0);
    levels[0] = 2;
    EXPECT_THROW(chunkLods(layout, levels), std::invalid_argument);
    LodPyramid pyramid(v, 2);
    ChunkLod tooCoarse;
    tooCoarse.level = 2;
    EXPECT_THROW(meshChunk(pyramid, layout, 0, tooCoarse), std::invalid_argument);
}

}  // namespace
}  // namespace hg::poly
