// Every mesh is printable (issue 20). Thin, box-aligned sculptures meshed
// with edges of four triangles where a cell's fan drew a chord across a
// face that the cell beyond drew too (polygonizer/loop_fan.h). Checked here:
//
// - the tables: no chord of any case lies on a cell face, and every pair of
//   face neighbours (each axis, all 4096 sign patterns) uses each edge at
//   most twice, the edges on the shared face exactly twice, once each way;
// - the export mesher over fields chosen to break a cell table (white
//   noise, thin slabs and rods on grid planes, spheres touching at a grid
//   point, values exactly zero on grid points): closed, 2-manifold (every
//   edge used by exactly two triangles, once in each direction), outward and
//   free of degenerate and zero-area triangles, one fan around every vertex;
// - the chunk mesher's union at one level (as strict), and at mixed levels
//   (closed, consistently oriented; only the known pinches on chunk edge
//   lines);
// - the tiled export across many tile seams, on HyperFun noise, values
//   exactly zero and a plate with a pit and a rod one voxel thick at
//   --res 96, 128 and 256 (which meshed with four such edges), written to
//   STL, OBJ and glTF;
// - every file in tests/data/bounded and content/hyperfun at several
//   resolutions.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "polygonizer/cell_table.h"
#include "polygonizer/realtime/chunk_layout.h"
#include "polygonizer/realtime/chunk_mesher.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "polygonizer/export/mesh_export.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/tiled_mesher.h"
#include "polygonizer/realtime/transition_table.h"
#include "tests/polygonizer/chunk_union.h"
#include "tests/polygonizer/dense_grid.h"
#include "tests/test_models.h"
#include "voxel/model_box.h"
#include "voxel/sampler.h"

namespace hg::poly {
namespace {

using Field = std::function<float(int, int, int)>;

// A number in [0, 1) for each voxel and seed (splitmix64 of both), so a
// field is a pure function of its voxel.
double hashUnit(std::uint64_t seed, int i, int j, int k) {
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 42 ^
                                                      static_cast<std::uint64_t>(static_cast<std::uint32_t>(j)) << 21 ^
                                                      static_cast<std::uint64_t>(static_cast<std::uint32_t>(k)));
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

// White noise in [-1, 1] plus `bias`, a share of it exactly zero.
Field whiteNoise(std::uint64_t seed, double zeroShare, double bias) {
    return [=](int i, int j, int k) {
        if (hashUnit(seed ^ 0x5A5A, i, j, k) < zeroShare) return 0.0f;
        return static_cast<float>(2.0 * hashUnit(seed, i, j, k) - 1.0 + bias);
    };
}

// Only -1, 0 and +1: a third of the grid points exactly on the surface.
Field ternary(std::uint64_t seed) {
    return [=](int i, int j, int k) { return static_cast<float>(std::floor(3.0 * hashUnit(seed, i, j, k)) - 1.0); };
}

// Lattice noise of period `p` voxels, trilinear between lattice points,
// rounded to quarters: smooth blobs with many exact zeros.
Field smoothNoise(std::uint64_t seed, int p) {
    return [=](int i, int j, int k) {
        auto floorDiv = [p](int a) { return a >= 0 ? a / p : -((-a + p - 1) / p); };
        const int gi = floorDiv(i), gj = floorDiv(j), gk = floorDiv(k);
        const double fi = static_cast<double>(i - gi * p) / p, fj = static_cast<double>(j - gj * p) / p,
                     fk = static_cast<double>(k - gk * p) / p;
        double v = 0.0;
        for (int c = 0; c < 8; ++c) {
            const double w = ((c & 1) ? fi : 1 - fi) * ((c & 2) ? fj : 1 - fj) * ((c & 4) ? fk : 1 - fk);
            v += w * (2.0 * hashUnit(seed, gi + (c & 1), gj + ((c >> 1) & 1), gk + ((c >> 2) & 1)) - 1.0);
        }
        return static_cast<float>(std::round(4.0 * v) / 4.0);
    };
}

struct GridBox {
    std::array<int, 3> lo, hi;  // faces on grid planes (voxel indices)
};

// Inside distance to the box's nearest face along the axes: exactly zero on
// its faces, so a box one voxel thick has no grid point inside and one two
// voxels thick has one plane of them.
double boxField(const GridBox& b, int i, int j, int k) {
    const int p[3] = {i, j, k};
    double f = 1e9;
    for (std::size_t a = 0; a < 3; ++a) f = std::min(f, static_cast<double>(std::min(p[a] - b.lo[a], b.hi[a] - p[a])));
    return f;
}

// Slabs, rods and small cubes on grid planes, 0 to 3 voxels thick, some
// carved out of the others and a last few added on top (a cube at least 2
// voxels wide among them, so the field is never empty), shifted by
// `offset` (0: grid points on faces are exactly zero; 0.5: inside).
Field gridBoxes(std::uint64_t seed, const std::array<int, 3>& cells, double offset) {
    std::mt19937 rng(static_cast<std::uint32_t>(seed));
    auto below = [&rng](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    std::vector<GridBox> add, carve, top;
    const int count = 6 + below(10);
    for (int n = 0; n <= count; ++n) {
        GridBox b;
        const int longAxis = n == count ? 3 : below(4);  // 3: no long axis (a small cube)
        const bool flat = below(2) == 1;                 // a slab: two long axes
        for (std::size_t a = 0; a < 3; ++a) {
            const int ia = static_cast<int>(a);
            const bool isLong = ia == longAxis || (flat && longAxis < 3 && ia == (longAxis + 1) % 3);
            const int extent = isLong ? 4 + below(cells[a]) : (n == count ? 2 : 0) + below(n == count ? 2 : 4);
            b.lo[a] = below(cells[a]) - 2;
            b.hi[a] = b.lo[a] + extent;
        }
        const int kind = n == count ? 2 : below(6);
        (kind == 0 ? carve : kind == 1 ? top : add).push_back(b);
    }
    return [=](int i, int j, int k) {
        double f = -1e9;
        for (const GridBox& b : add) f = std::max(f, boxField(b, i, j, k));
        for (const GridBox& b : carve) f = std::min(f, -boxField(b, i, j, k));
        for (const GridBox& b : top) f = std::max(f, boxField(b, i, j, k));
        return static_cast<float>(f + offset);
    };
}

// Pairs of spheres touching at a grid point (centres on grid points, along
// an axis or along (3, 4, 0) and its turns, radii summing to the distance),
// and some overlapping or apart by a hair.
Field touchingSpheres(std::uint64_t seed, const std::array<int, 3>& cells) {
    std::mt19937 rng(static_cast<std::uint32_t>(seed));
    struct Sphere {
        double c[3], r;
    };
    std::vector<Sphere> spheres;
    for (int n = 0; n < 3; ++n) {
        Sphere s;
        for (std::size_t a = 0; a < 3; ++a) s.c[a] = 3 + static_cast<int>(rng() % static_cast<unsigned>(cells[a] - 6));
        // Centres on grid points, the contact point c + r1 * d / |d| too:
        // along an axis any whole r1, along (3, 4, 0) k a multiple of 5.
        const bool diagonal = rng() % 2;
        const auto axis = static_cast<std::size_t>(rng() % 3);
        double d[3] = {0, 0, 0}, dist = 0, r1 = 0;
        if (diagonal) {
            const int k = 2 + static_cast<int>(rng() % 2);
            d[axis] = 3.0 * k;
            d[(axis + 1) % 3] = 4.0 * k;
            dist = 5.0 * k;
            r1 = 5.0 * (1 + static_cast<int>(rng() % static_cast<unsigned>(k - 1)));
        } else {
            dist = d[axis] = 2.0 + static_cast<double>(rng() % 6);
            r1 = 1.0 + static_cast<double>(rng() % static_cast<unsigned>(dist - 1));
        }
        const double slack[3] = {0.0, 1e-6, -1e-6};  // touching, overlapping, apart
        s.r = r1;
        Sphere t;
        for (std::size_t a = 0; a < 3; ++a) t.c[a] = s.c[a] + d[a];
        t.r = dist - r1 + slack[rng() % 3];
        spheres.push_back(s);
        spheres.push_back(t);
    }
    return [=](int i, int j, int k) {
        double f = -1e9;
        for (const Sphere& s : spheres) {
            const double dx = i - s.c[0], dy = j - s.c[1], dz = k - s.c[2];
            f = std::max(f, s.r - std::sqrt(dx * dx + dy * dy + dz * dz));
        }
        return static_cast<float>(f);
    };
}

// Vertices whose triangles do not make one fan around them (a closed,
// oriented cycle of link edges): two surfaces touching at a point. Each
// triangle (a, b, c) gives a the link edge b -> c; a vertex's link edges
// are gathered by counting (no sort: this runs on every mesh, sanitizers
// included) and followed from the first until they close.
std::size_t pinchedVertices(const Mesh& mesh) {
    const std::size_t n = mesh.vertexCount();
    std::vector<std::uint32_t> first(n + 1, 0);
    for (std::uint32_t v : mesh.indices) ++first[v + 1];
    for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links(mesh.indices.size());
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (std::size_t k = 0; k < 3; ++k)
            links[fill[mesh.indices[3 * t + k]]++] = {mesh.indices[3 * t + (k + 1) % 3], mesh.indices[3 * t + (k + 2) % 3]};
    std::size_t pinched = 0;
    for (std::size_t v = 0; v < n; ++v) {
        const std::size_t lo = first[v], hi = first[v + 1];
        if (lo == hi) continue;
        std::size_t at = lo, steps = 0;
        do {
            std::size_t next = hi;
            for (std::size_t j = lo; j < hi && next == hi; ++j)
                if (links[j].first == links[at].second) next = j;
            at = next;
            ++steps;
        } while (at != hi && at != lo && steps <= hi - lo);
        pinched += !(at == lo && steps == hi - lo);
    }
    return pinched;
}

// Triangles of zero area: their corners' float positions, crossed in double.
std::size_t flatTriangles(const Mesh& mesh) {
    std::size_t flat = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        double p[3][3];
        for (std::size_t c = 0; c < 3; ++c)
            for (std::size_t a = 0; a < 3; ++a) p[c][a] = mesh.positions[3 * mesh.indices[3 * t + c] + a];
        const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        flat += n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0;
    }
    return flat;
}

// What printing needs, by the project's validation (closed, every edge used
// by exactly two triangles, consistently oriented, positive volume, no
// degenerate triangle), plus one fan of triangles around every vertex and
// no triangle of zero area.
void expectPrintable(const Mesh& mesh, const std::string& what) {
    const MeshReport r = validateMesh(mesh);
    EXPECT_TRUE(r.ok()) << what << "\n" << describe(r);
    if (r.ok()) {
        EXPECT_EQ(pinchedVertices(mesh), 0u) << what;
    }
    EXPECT_EQ(flatTriangles(mesh), 0u) << what << ": triangles of zero area";
}

struct NamedField {
    std::string name;
    Field field;
};

// The fields of one seed on a grid of `cells`.
std::vector<NamedField> fieldsFor(std::uint64_t seed, const std::array<int, 3>& cells) {
    return {
        {"white noise", whiteNoise(seed, 0.0, 0.0)},
        {"white noise, a fifth exactly zero", whiteNoise(seed, 0.2, 0.1)},
        {"-1, 0, +1", ternary(seed)},
        {"smooth noise in quarters", smoothNoise(seed, 2 + static_cast<int>(seed % 4))},
        {"boxes on grid planes", gridBoxes(seed, cells, 0.0)},
        {"boxes on grid planes, faces inside", gridBoxes(seed, cells, 0.5)},
        {"touching spheres", touchingSpheres(seed, cells)},
    };
}

std::string context(const std::string& field, std::uint64_t seed, const std::array<int, 3>& cells) {
    std::ostringstream s;
    s << field << ", seed " << seed << ", " << cells[0] << "x" << cells[1] << "x" << cells[2] << " cells";
    return s.str();
}

TEST(ManifoldProperty, TheChecksSeeTwoSolidsTouchingAtAPointAndAFlatTriangle) {
    // Two tetrahedra sharing a corner: every edge used twice, once each
    // way, outward; only the shared corner has two fans.
    Mesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1};
    m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5};
    ASSERT_TRUE(validateMesh(m).ok()) << describe(validateMesh(m));
    EXPECT_EQ(pinchedVertices(m), 1u);
    m.indices.resize(12);
    EXPECT_EQ(pinchedVertices(m), 0u);
    EXPECT_EQ(flatTriangles(m), 0u);
    // The tip pulled down onto the middle of edge 1-2: triangle 1 2 3 is a
    // segment, the others lie flat but keep their area.
    m.positions[9] = 0.5f, m.positions[10] = 0.5f, m.positions[11] = 0.0f;
    EXPECT_EQ(flatTriangles(m), 1u);
}

// --- the tables ------------------------------------------------------------

// Crossings a and b (edge numbers) of a cell lie on one of its faces.
bool cubeEdgesShareFace(int a, int b) {
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            auto on = [&](int e) {
                for (int c : kEdgeCorners[static_cast<std::size_t>(e)])
                    if (((c >> axis) & 1) != side) return false;
                return true;
            };
            if (on(a) && on(b)) return true;
        }
    return false;
}

// Uses of each triangle edge of one case, by its (smaller, larger) crossings.
template <class Case>
std::map<std::pair<int, int>, int> edgeUses(const Case& c) {
    std::map<std::pair<int, int>, int> uses;
    for (std::size_t t = 0; t < c.triangleCount; ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const int a = c.edges[3 * t + k], b = c.edges[3 * t + (k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    return uses;
}

TEST(ManifoldProperty, NoChordOfAnyCaseLiesOnACellFace) {
    // Two crossings on one face are joined only by the face's segment (one
    // triangle of the cell); a chord (two triangles) there could be the
    // neighbour's chord too.
    for (std::size_t m = 0; m < 256; ++m)
        for (const auto& [edge, n] : edgeUses(cellTable()[m]))
            if (cubeEdgesShareFace(edge.first, edge.second)) {
                EXPECT_EQ(n, 1) << "cell case " << m;
            }
    const TransitionGeometry& g = transitionGeometry();
    std::vector<unsigned> faces(g.edges.size(), 0u);
    for (std::size_t f = 0; f < g.faces.size(); ++f)
        for (std::size_t i = 0; i < g.faces[f].size(); ++i)
            faces[static_cast<std::size_t>(g.edgeIndex(g.faces[f][i], g.faces[f][(i + 1) % g.faces[f].size()]))] |= 1u << f;
    for (std::size_t c = 0; c < 512; ++c)
        for (const auto& [edge, n] : edgeUses(transitionTable()[c]))
            if (faces[static_cast<std::size_t>(edge.first)] & faces[static_cast<std::size_t>(edge.second)]) {
                EXPECT_EQ(n, 1) << "transition case " << c;
            }
}

TEST(ManifoldProperty, FaceNeighboursShareEachEdgeOfTheirFaceExactlyTwiceOnceEachWay) {
    // Two cells along `axis`, 12 corners, every sign pattern: vertices are
    // numbered by grid edge, as the meshers weld them.
    for (int axis = 0; axis < 3; ++axis) {
        int dims[3] = {2, 2, 2};
        dims[axis] = 3;
        for (int m = 0; m < 4096; ++m) {
            std::map<std::pair<int, int>, int> forward, backward;
            std::map<int, bool> onSharedFace;
            for (int cell = 0; cell < 2; ++cell) {
                int origin[3] = {0, 0, 0};
                origin[axis] = cell;
                auto corner = [&](int c, int p[3]) {
                    for (int a = 0; a < 3; ++a) p[a] = origin[a] + ((c >> a) & 1);
                };
                int mask = 0;
                for (int c = 0; c < 8; ++c) {
                    int p[3];
                    corner(c, p);
                    mask |= ((m >> ((p[0] * dims[1] + p[1]) * dims[2] + p[2])) & 1) << c;
                }
                auto vertex = [&](int e) {
                    int p[3];
                    corner(kEdgeCorners[static_cast<std::size_t>(e)][0], p);
                    const int key = ((kEdgeAxis[static_cast<std::size_t>(e)] * 3 + p[0]) * 3 + p[1]) * 3 + p[2];
                    int q[3];
                    corner(kEdgeCorners[static_cast<std::size_t>(e)][1], q);
                    onSharedFace[key] = p[axis] == 1 && q[axis] == 1;
                    return key;
                };
                const CellCase& cc = cellTable()[static_cast<std::size_t>(mask)];
                for (std::size_t t = 0; t < cc.triangleCount; ++t)
                    for (std::size_t k = 0; k < 3; ++k) {
                        const int a = vertex(cc.edges[3 * t + k]), b = vertex(cc.edges[3 * t + (k + 1) % 3]);
                        ++(a < b ? forward : backward)[{std::min(a, b), std::max(a, b)}];
                    }
            }
            std::map<std::pair<int, int>, int> all = forward;
            for (const auto& [e, n] : backward) all[e] += n;
            for (const auto& [e, n] : all) {
                ASSERT_LE(n, 2) << "axis " << axis << " signs " << m;
                if (onSharedFace[e.first] && onSharedFace[e.second]) {
                    EXPECT_EQ(forward[e], 1) << "axis " << axis << " signs " << m;
                    EXPECT_EQ(backward[e], 1) << "axis " << axis << " signs " << m;
                }
            }
        }
    }
}

// --- the export mesher and the chunk mesher on fields of voxels ----------

// Grids of sizes that are and are not whole leaves, so blocks, their upper
// neighbours and the index box's faces all meet the surface.
const std::array<std::array<int, 3>, 3> kSizes = {{{12, 12, 12}, {21, 13, 17}, {28, 9, 24}}};

TEST(ManifoldProperty, ExportMesherOnRandomFieldsIsClosedManifoldAndOutward) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const auto& cells = kSizes[seed % kSizes.size()];
        for (const NamedField& f : fieldsFor(seed, cells)) {
            expectPrintable(meshVolume(test::denseVolume(cells, f.field)), context(f.name, seed, cells));
            if (HasFailure()) return;
        }
    }
}

// The chunk mesher with one level everywhere (no transition cells): the
// union of its chunks, welded by position, is as printable as the export
// mesh. At mixed levels (a checkerboard: a seam on every chunk face) it is
// closed and consistently oriented with no edge used other than twice but
// the pinches on chunk edge lines that chunk_mesher_test.cpp describes.
TEST(ManifoldProperty, ChunkMesherOnRandomFieldsIsClosedAndManifold) {
    const std::array<int, 3> cells = {36, 25, 33};
    for (std::uint64_t seed = 1; seed <= 4; ++seed)
        for (const NamedField& f : fieldsFor(seed, cells)) {
            const std::string what = context(f.name, seed, cells);
            const voxel::Volume v = test::denseVolume(cells, f.field);
            const LodPyramid pyramid(v, 2);
            const ChunkLayout layout(v.frame, 16);
            for (int level = 0; level < 2; ++level) {
                const std::vector<int> levels(layout.count(), level);
                expectPrintable(weldByPosition(test::unionOf(pyramid, layout, levels)),
                                what + ", every chunk at level " + std::to_string(level));
            }
            std::vector<int> checkerboard(layout.count());
            for (std::size_t i = 0; i < layout.count(); ++i) {
                const ChunkKey k = layout.key(i);
                checkerboard[i] = (k.x + k.y + k.z) & 1;
            }
            const Mesh welded = weldByPosition(test::unionOf(pyramid, layout, checkerboard));
            const MeshReport r = validateMesh(welded);
            const test::EdgeUse e = test::edgeUse(welded, layout);
            EXPECT_TRUE(r.closed()) << what << ", levels 0 and 1\n" << describe(r);
            EXPECT_EQ(e.other, 0u) << what << ", levels 0 and 1";
            EXPECT_EQ(r.inconsistentEdges, 0u) << what << ", levels 0 and 1";
            EXPECT_EQ(r.degenerateTriangles, 0u) << what << ", levels 0 and 1";
            if (HasFailure()) return;
        }
}

// --- the export path: models, tiles, files ----------------------------------

frep::Box3 cube(double lo, double hi) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = lo;
        b.hi[a] = hi;
    }
    return b;
}

// The tiled mesh of `model` is printable and is the untiled mesh.
void expectPrintableTiled(const frep::Model& model, const frep::Box3& box, int res, int tile, const std::string& what) {
    TiledMeshOptions o;
    o.resolution = res;
    o.tileSize = tile;
    const TiledMeshResult tiled = meshModelTiled(model, box, o);
    ASSERT_EQ(tiled.error, "") << what;
    const std::string where = what + " at " + std::to_string(res) + ", tiles of " + std::to_string(tile);
    expectPrintable(tiled.mesh, where);
    if (tile > 0) {
        EXPECT_GT(tiled.stats.sharedVertices, 0u) << where << ": the surface crosses tile seams";
        voxel::VolumeRequest req;
        req.box = box;
        req.resolution = res;
        const voxel::VoxelizeResult v = voxel::voxelize(model, req);
        ASSERT_TRUE(v.volume) << v.error;
        EXPECT_EQ(tiled.mesh.triangleCount(), meshVolume(*v.volume).triangleCount()) << where << ": as untiled";
    }
}

// Pseudo-random per voxel (the shader hash), in HyperFun: white noise, and
// -1, 0, +1 (a third of the points exactly on the surface).
constexpr const char* kHashNoise =
    "q(x[3], a[1]) { q = frac(abs(sin(12.9898 * x[1] + 78.233 * x[2] + 37.719 * x[3])) * 43758.5453) - 0.5; }";
constexpr const char* kHashTernary =
    "q(x[3], a[1]) { q = floor(3 * frac(abs(sin(12.9898 * x[1] + 78.233 * x[2] + 37.719 * x[3])) * 43758.5453)) - 1; }";

TEST(ManifoldProperty, TiledExportOfNoiseAndExactZerosIsPrintableAcrossTileSeams) {
    expectPrintableTiled(::hg::test::modelFromSource(kHashNoise), cube(0, 1), 29, 8, "hash noise");
    expectPrintableTiled(::hg::test::modelFromSource(kHashTernary), cube(0, 1), 29, 8, "hash -1, 0, +1");
    expectPrintableTiled(::hg::test::modelFromSource(kHashTernary), cube(0, 1), 40, 16, "hash -1, 0, +1");
}

// A plate one voxel thick with a pit one voxel wide in it, and a rod one
// voxel thick lying on the plate across the pit: a[1] is the voxel size,
// in the box [-1, 1]^3 the plate is the grid plane z = 0 (even
// resolutions), the pit the grid point (0, v, 0), the rod the grid line
// x = 0, z = v. The saddle at the pit is a checkerboard face between two
// cells that both loop through it: before loop_fan.h's fix, four edges of
// four triangles at every resolution.
constexpr const char* kPlatePitRod =
    "plate(x[3], a[1]) {\n"
    "  array p[3], h[3], r[3];\n"
    "  v = a[1];\n"
    "  p[1] = -0.3; p[2] = -0.3; p[3] = -0.5 * v;\n"
    "  h[1] = -0.5 * v; h[2] = 0.5 * v; h[3] = -v;\n"
    "  r[1] = -0.5 * v; r[2] = -0.3; r[3] = 0.5 * v;\n"
    "  plate = (hfBlock(x, p, 0.6, 0.6, v) \\ hfBlock(x, h, v, v, 2 * v)) | hfBlock(x, r, v, 0.6, v);\n"
    "}\n";

TEST(ManifoldProperty, ThinBoxAlignedPlatePitAndRodExportAtEveryResolution) {
    for (int res : {96, 128, 256}) {
        const frep::Model plate = ::hg::test::modelFromSource(kPlatePitRod, {2.0 / res});
        expectPrintableTiled(plate, cube(-1, 1), res, 0, "plate, pit and rod");
        if (res == 96) expectPrintableTiled(plate, cube(-1, 1), res, 16, "plate, pit and rod");
    }
    // And written: STL, OBJ and glTF are not refused.
    const frep::Model plate = ::hg::test::modelFromSource(kPlatePitRod, {2.0 / 96});
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hg_manifold_property_plate";
    std::filesystem::create_directories(dir);
    for (const char* name : {"plate.stl", "plate.obj", "plate.glb"}) {
        MeshExportOptions o;
        o.resolution = 96;
        MeshExportReport report;
        const std::string path = (dir / name).string();
        EXPECT_EQ(exportMesh(plate, cube(-1, 1), o, path, report), "") << name;
        EXPECT_TRUE(std::filesystem::exists(path)) << name;
        EXPECT_GT(report.triangles, 0u) << name;
    }
    std::filesystem::remove_all(dir);
}

TEST(ManifoldProperty, EveryBoundedAndContentFileIsPrintableAtSeveralResolutions) {
    std::vector<std::filesystem::path> files;
    for (const auto& dir : {std::filesystem::path(HG_TEST_DATA_DIR) / "bounded",
                            std::filesystem::path(HG_SOURCE_DIR) / "content" / "hyperfun"})
        for (const auto& entry : std::filesystem::directory_iterator(dir))
            if (entry.path().extension() == ".hf") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 10u);
    for (const auto& file : files) {
        const frep::Model model = ::hg::test::modelFromFile(file.string());
        voxel::ModelBox box;
        ASSERT_EQ(voxel::resolveModelBox(model, std::nullopt, box), "") << file;
        for (int res : {37, 64, 96}) expectPrintableTiled(model, box.box, res, res == 64 ? 32 : 0, file.filename().string());
    }
}

}  // namespace
}  // namespace hg::poly
