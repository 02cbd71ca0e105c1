#include "polygonizer/export_mesher.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>

#include "polygonizer/cell_table.h"
#include "polygonizer/export_mesher_blocks.h"
#include "voxel/volume_vdb.h"

// How the work goes (block = one OpenVDB leaf of cells, 8^3, named by its
// cells' low corner; a block's corners run 0..8 and so reach one voxel into
// its +x, +y and +z neighbours):
//
//   0. candidates: the grid's leaves, the blocks just below them (whose
//      cells reach into a leaf) and the inside blocks on the index box's
//      faces; each gets its 512 inside bits (one compare per voxel);
//   1. per candidate, from its own bits and its seven upper neighbours': the
//      9^3 corner signs as bit rows, the edges it owns that cross (low end in
//      the block), and how many vertices and triangles it will make. Nothing
//      but bits is read, so the many blocks with no crossing cost ~100 ops;
//   2. one serial prefix sum gives each block its first vertex and first
//      triangle, so the output is allocated once and written in place,
//      in the same order whatever the number of threads;
//   3. per block with a crossing: the values around it (an 11^3 halo), one
//      vertex per owned crossing edge with its gradient normal, then its
//      cells' triangles. A vertex's index in its owner block is a popcount
//      over the owner's crossing bits, so neighbours need no shared map:
//      the mesh is welded by construction.

namespace hg::poly {

namespace {

using openvdb::Coord;
using Tree = openvdb::FloatTree;
using Leaf = Tree::LeafNodeType;
// Not registered with the tree: cheap to make per task, and the tree is not
// changed while we read it.
using Accessor = openvdb::tree::ValueAccessor<const Tree, false>;

constexpr int kB = kBlockSize;
constexpr int kHalo = kB + 3;  // voxels -1 .. 9 of a block: its corners and their gradients
constexpr int kStride[3] = {kHalo * kHalo, kHalo, 1};  // a halo step along x, y, z

Coord blockOf(const Coord& origin) { return Coord(origin.x() >> 3, origin.y() >> 3, origin.z() >> 3); }
Coord originOf(const Coord& block) { return Coord(block.x() * kB, block.y() * kB, block.z() * kB); }
Coord offset(int d) { return Coord(d & 1, (d >> 1) & 1, (d >> 2) & 1); }  // d in 0..7: the upper neighbours
std::int32_t find(const BlockTable& table, const Coord& block) { return table.find(block.x(), block.y(), block.z()); }

struct Candidate {
    Coord origin;
    const Leaf* leaf = nullptr;  // or a tile of value `tile`
    float tile = 0.0f;
    SignMask inside;
    BlockCounts counts;
    std::uint32_t firstVertex = 0;
    std::size_t firstTriangle = 0;
    std::uint32_t written = 0;  // triangles phase 3 wrote (fewer only where an edge has no owner)
};

// The index box's faces, an 8x8 patch at a time: blocks holding an inside
// voxel on a face, where a solid cut by the box is capped. A tile answers
// for its whole patch, a leaf's voxels are read from its buffer.
template <class Mark>
void markCappedFaces(const voxel::IndexBox& b, Accessor& acc, Mark mark) {
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        for (int side = 0; side < 2; ++side)
            for (int i0 = b.lo[u] & ~(kB - 1); i0 <= b.hi[u]; i0 += kB)
                for (int j0 = b.lo[v] & ~(kB - 1); j0 <= b.hi[v]; j0 += kB) {
                    Coord c;
                    c[a] = side ? b.hi[a] : b.lo[a];
                    c[u] = i0;
                    c[v] = j0;
                    const Coord block = c & ~(kB - 1);
                    const Leaf* leaf = acc.probeConstLeaf(block);
                    bool inside = false;
                    if (!leaf) {
                        inside = acc.getValue(block) > 0.0f;
                    } else {
                        for (int i = std::max(i0, b.lo[u]); i <= std::min(i0 + kB - 1, b.hi[u]) && !inside; ++i)
                            for (int j = std::max(j0, b.lo[v]); j <= std::min(j0 + kB - 1, b.hi[v]) && !inside; ++j) {
                                c[u] = i;
                                c[v] = j;
                                inside = leaf->getValue(c) > 0.0f;
                            }
                    }
                    if (inside) mark(block);
                }
    }
}

// Phase 0: candidates in a fixed order (BlockTable's), so the mesh does not
// depend on the thread count.
std::vector<Candidate> findCandidates(const voxel::Volume& volume, BlockTable& table,
                                      std::vector<const Leaf*>& leaves) {
    const Tree& tree = voxel::vdb(volume).tree();
    auto markWithLowerNeighbours = [&table](const Coord& origin) {
        const Coord b = blockOf(origin);
        for (int d = 0; d < 8; ++d) {
            const Coord n = b - offset(d);
            table.mark(n.x(), n.y(), n.z());
        }
    };
    for (const Leaf* leaf : leaves) markWithLowerNeighbours(leaf->origin());
    Accessor acc(tree);
    markCappedFaces(volume.frame.indexBox, acc, markWithLowerNeighbours);

    std::vector<Candidate> out;
    out.reserve(table.marked());
    table.number([&out](int x, int y, int z) {
        out.emplace_back();
        out.back().origin = originOf(Coord(x, y, z));
    });
    for (const Leaf* leaf : leaves) out[static_cast<std::size_t>(find(table, blockOf(leaf->origin())))].leaf = leaf;
    return out;
}

// The table's extent in blocks: every leaf, the index box, one block below.
BlockTable makeTable(const voxel::IndexBox& box, const std::vector<const Leaf*>& leaves) {
    Coord lo(box.lo[0], box.lo[1], box.lo[2]), hi(box.hi[0], box.hi[1], box.hi[2]);
    if (box.empty()) lo = hi = Coord(0, 0, 0);
    for (const Leaf* leaf : leaves) {
        lo.minComponent(leaf->origin());
        hi.maxComponent(leaf->origin());
    }
    const Coord blo = blockOf(lo) - Coord(1, 1, 1), bhi = blockOf(hi);
    return BlockTable({blo.x(), blo.y(), blo.z()}, {bhi.x(), bhi.y(), bhi.z()});
}

struct Context {
    const voxel::VolumeFrame* frame;
    const BlockTable* table;
    std::vector<Candidate>* candidates;
    BlockEdges* edges;  // one per candidate, written where the block is not uniform
};

// The inside bits of the block at `block`: a candidate's, else its tile's.
const SignMask& maskAt(const Context& ctx, const Coord& block, Accessor& acc, SignMask& scratch) {
    const std::int32_t i = find(*ctx.table, block);
    if (i >= 0) return (*ctx.candidates)[static_cast<std::size_t>(i)].inside;
    scratch = uniformMask(acc.getValue(originOf(block)));
    return scratch;
}

// Phase 1.
void classify(const Context& ctx, std::size_t i, Accessor& acc) {
    Candidate& c = (*ctx.candidates)[i];
    const Coord b = blockOf(c.origin);
    std::array<SignMask, 8> scratch;
    std::array<const SignMask*, 8> m;
    m[0] = &c.inside;
    for (int d = 1; d < 8; ++d)
        m[static_cast<std::size_t>(d)] = &maskAt(ctx, b + offset(d), acc, scratch[static_cast<std::size_t>(d)]);
    c.counts = analyseBlock(m, ctx.edges[i]);
}

// The values of the block's 27 neighbours (itself included): leaf buffers
// or tile values.
struct Neighbourhood {
    std::array<const float*, 27> data;
    std::array<float, 27> tile;
};

Neighbourhood neighbourhood(const Context& ctx, const Coord& origin, Accessor& acc) {
    Neighbourhood n;
    const Coord b = blockOf(origin);
    for (int k = 0; k < 27; ++k) {
        const Coord d(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1);
        const std::int32_t i = find(*ctx.table, b + d);
        const Candidate* c = i >= 0 ? &(*ctx.candidates)[static_cast<std::size_t>(i)] : nullptr;
        const auto s = static_cast<std::size_t>(k);
        n.data[s] = c && c->leaf ? c->leaf->buffer().data() : nullptr;
        n.tile[s] = c ? c->tile : (n.data[s] ? 0.0f : acc.getValue(originOf(b + d)));
    }
    return n;
}

// The grid's values around one block (voxels -1 .. 9 in each axis), copied
// once from the leaves and tiles it overlaps: the vertex loop then indexes
// an array.
struct Halo {
    std::array<float, kHalo * kHalo * kHalo> v;
    static constexpr int index(int x, int y, int z) { return ((x + 1) * kHalo + (y + 1)) * kHalo + (z + 1); }

    void fill(const Neighbourhood& n) {
        const int lo[3] = {-1, 0, kB}, hi[3] = {-1, kB - 1, kB + 1};
        for (int k = 0; k < 27; ++k) {
            const int px = k % 3, py = k / 3 % 3, pz = k / 9;
            const float* data = n.data[static_cast<std::size_t>(k)];
            const int count = hi[pz] - lo[pz] + 1;
            for (int x = lo[px]; x <= hi[px]; ++x)
                for (int y = lo[py]; y <= hi[py]; ++y) {
                    float* dst = &v[static_cast<std::size_t>(index(x, y, lo[pz]))];
                    if (!data) {
                        std::fill(dst, dst + count, n.tile[static_cast<std::size_t>(k)]);
                        continue;
                    }
                    // Leaf offsets are x-major, z fastest, like the halo.
                    const int lx = x & (kB - 1), ly = y & (kB - 1), lz = lo[pz] & (kB - 1);
                    std::memcpy(dst, data + (lx * kB + ly) * kB + lz, sizeof(float) * static_cast<std::size_t>(count));
                }
        }
    }
};

struct Output {
    float* positions;
    float* normals;
    std::uint32_t* indices;
};

// Phase 3a: one vertex per owned crossing edge, in the order BlockEdges
// numbers them (axis, then row, then z).
void placeVertices(const Candidate& c, const BlockEdges& e, const Halo& h, const voxel::VolumeFrame& frame,
                   const Output& out) {
    const float* v = h.v.data();
    auto grad = [v](int p) {
        return openvdb::Vec3d(0.5 * static_cast<double>(v[p + kStride[0]] - v[p - kStride[0]]),
                              0.5 * static_cast<double>(v[p + kStride[1]] - v[p - kStride[1]]),
                              0.5 * static_cast<double>(v[p + kStride[2]] - v[p - kStride[2]]));
    };
    const double step = frame.voxelSize;
    std::size_t k = 3 * static_cast<std::size_t>(c.firstVertex);
    for (int axis = 0; axis < 3; ++axis)
        for (int row = 0; row < kB * kB; ++row) {
            unsigned bits = e.cross[static_cast<std::size_t>(axis)][static_cast<std::size_t>(row)];
            const int x = row / kB, y = row % kB;
            while (bits) {
                const int z = lowestBit(bits);
                bits &= bits - 1;
                const int p = Halo::index(x, y, z), q = p + kStride[axis];
                // Clamped away from the ends: a vertex exactly on a grid point
                // gives zero-area triangles that slicers flag.
                const double d0 = v[p], d1 = v[q];
                const double t = std::clamp(d0 / (d0 - d1), 1e-3, 1.0 - 1e-3);
                auto pos = frame.position(c.origin.x() + x, c.origin.y() + y, c.origin.z() + z);
                pos[static_cast<std::size_t>(axis)] += t * step;
                const openvdb::Vec3d g = grad(p) * (1.0 - t) + grad(q) * t;
                const double len = g.length();
                const openvdb::Vec3d n = len > 0 ? -g / len : openvdb::Vec3d(0, 0, 0);  // f grows inwards
                for (std::size_t a = 0; a < 3; ++a) {
                    out.positions[k + a] = static_cast<float>(pos[a]);
                    out.normals[k + a] = static_cast<float>(n[static_cast<int>(a)]);
                }
                k += 3;
            }
        }
}

// Phase 3 for one block.
void meshBlock(const Context& ctx, std::size_t i, Accessor& acc, const Output& out) {
    Candidate& c = (*ctx.candidates)[i];
    const BlockEdges& e = ctx.edges[i];
    if (c.counts.vertices > 0) {
        Halo h;
        h.fill(neighbourhood(ctx, c.origin, acc));
        placeVertices(c, e, h, *ctx.frame, out);
    }
    // The blocks that own this block's cells' edges: itself and its upper
    // neighbours (those without a crossing own no vertex).
    std::array<EdgeOwner, 8> owners{};
    const Coord b = blockOf(c.origin);
    for (int d = 0; d < 8; ++d) {
        const std::int32_t j = find(*ctx.table, b + offset(d));
        if (j < 0) continue;
        const Candidate& o = (*ctx.candidates)[static_cast<std::size_t>(j)];
        if (o.counts.vertices == 0) continue;
        owners[static_cast<std::size_t>(d)] = {&ctx.edges[static_cast<std::size_t>(j)], o.firstVertex};
    }
    c.written = triangulateBlock(e, owners, out.indices + 3 * c.firstTriangle);
}

// Blocks whose triangles lost an edge without an owner (only a sign change
// between two tiles, a program discontinuous across its own surface, has
// none) wrote fewer than they reserved: close the gaps.
void compact(const std::vector<Candidate>& candidates, std::vector<std::uint32_t>& indices) {
    std::size_t to = 0;
    for (const Candidate& c : candidates) {
        const std::size_t from = 3 * c.firstTriangle, n = 3 * static_cast<std::size_t>(c.written);
        if (from != to) std::memmove(indices.data() + to, indices.data() + from, n * sizeof(std::uint32_t));
        to += n;
    }
    indices.resize(to);
}

template <class Body>
void forEach(std::size_t n, const Tree& tree, Body body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
        Accessor acc(tree);
        for (std::size_t i = r.begin(); i != r.end(); ++i) body(i, acc);
    });
}

}  // namespace

Mesh meshVolume(const voxel::Volume& volume, ExportStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    const Tree& tree = voxel::vdb(volume).tree();
    std::vector<const Leaf*> leaves;
    leaves.reserve(tree.leafCount());
    tree.getNodes(leaves);

    // Phase 0.
    BlockTable table = makeTable(volume.frame.indexBox, leaves);
    std::vector<Candidate> candidates = findCandidates(volume, table, leaves);
    forEach(candidates.size(), tree, [&](std::size_t i, Accessor& acc) {
        Candidate& c = candidates[i];
        if (c.leaf) {
            c.inside = leafMask(c.leaf->buffer().data());
        } else {
            c.tile = acc.getValue(c.origin);
            c.inside = uniformMask(c.tile);
        }
    });

    // Phase 1. Edge data is left uninitialized: only non-uniform blocks
    // write theirs, and only those are read.
    std::unique_ptr<BlockEdges[]> edges(new BlockEdges[candidates.size()]);
    const Context ctx{&volume.frame, &table, &candidates, edges.get()};
    forEach(candidates.size(), tree, [&](std::size_t i, Accessor& acc) { classify(ctx, i, acc); });

    // Phase 2.
    std::uint32_t vertices = 0;
    std::size_t triangles = 0;
    ExportStats st;
    std::vector<std::uint32_t> active;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        Candidate& c = candidates[i];
        c.firstVertex = vertices;
        c.firstTriangle = triangles;
        vertices += c.counts.vertices;
        triangles += c.counts.triangles;
        st.surfaceCells += c.counts.surfaceCells;
        if (c.counts.vertices > 0 || c.counts.triangles > 0) active.push_back(static_cast<std::uint32_t>(i));
    }
    Mesh mesh;
    // Zero-filling the output is a large share of the serial time: split it.
    tbb::parallel_invoke([&] { mesh.positions.resize(3 * static_cast<std::size_t>(vertices)); },
                         [&] { mesh.normals.resize(3 * static_cast<std::size_t>(vertices)); },
                         [&] { mesh.indices.resize(3 * triangles); });

    // Phase 3.
    const Output out{mesh.positions.data(), mesh.normals.data(), mesh.indices.data()};
    forEach(active.size(), tree, [&](std::size_t k, Accessor& acc) { meshBlock(ctx, active[k], acc, out); });
    bool complete = true;
    for (std::uint32_t i : active) complete = complete && candidates[i].written == candidates[i].counts.triangles;
    if (!complete) compact(candidates, mesh.indices);

    st.cells = candidates.size() * static_cast<std::size_t>(kB * kB * kB);
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = st;
    return mesh;
}

}  // namespace hg::poly
