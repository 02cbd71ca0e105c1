#include "polygonizer/export/export_mesher.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "polygonizer/export/export_mesher_blocks.h"
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
//      the block), and how many vertices and triangles it will make. Only
//      bits are read, so the many blocks without a crossing cost little;
//   2. one serial prefix sum gives each block its first vertex and first
//      triangle, so the output is allocated once and written in place, in
//      the same order whatever the number of threads;
//   3. per block with a crossing: the values around it (an 11^3 halo), one
//      vertex per owned crossing edge with its gradient normal, then its
//      cells' triangles. An edge's vertex number is its owner's first
//      vertex plus the owner's count of crossings before it (kept per row
//      of edges), so neighbours need no shared map: the mesh is welded by
//      construction.

namespace hg::poly {

namespace {

using openvdb::Coord;
using Tree = openvdb::FloatTree;
using Leaf = Tree::LeafNodeType;
// Not registered with the tree: cheap to make per task, and the tree is not
// changed while we read it.
using Accessor = openvdb::tree::ValueAccessor<const Tree, false>;

constexpr int kB = kBlockSize;
constexpr int kHalo = kB + 3;                          // voxels -1 .. 9 of a block: its corners and their gradients
constexpr int kStride[3] = {kHalo * kHalo, kHalo, 1};  // a halo step along x, y, z

Coord blockOf(const Coord& origin) { return Coord(origin.x() >> 3, origin.y() >> 3, origin.z() >> 3); }
Coord originOf(const Coord& block) { return Coord(block.x() * kB, block.y() * kB, block.z() * kB); }
Coord upper(int d) { return Coord(d & 1, (d >> 1) & 1, (d >> 2) & 1); }  // d in 0..7: the block and its upper neighbours

// A candidate's values: its leaf's buffer, or one tile value.
struct Values {
    const float* data = nullptr;
    float tile = 0.0f;
};

struct BlockState {
    BlockCounts counts;
    const BlockEdges* edges = nullptr;  // where the block is not uniform
    std::uint32_t firstVertex = 0;
    std::uint32_t written = 0;  // triangles phase 3 wrote (fewer only where an edge has no owner)
    std::size_t firstTriangle = 0;
};

// Everything per candidate, by candidate number (BlockTable's order).
struct Candidates {
    BlockTable table;
    std::vector<Coord> origins;
    std::vector<Values> values;
    std::vector<SignMask> inside;
    std::vector<BlockState> state;

    std::int32_t find(const Coord& block) const { return table.find(block.x(), block.y(), block.z()); }
};

// The index box's faces, an 8x8 patch at a time: blocks holding an inside
// voxel on a face, where a solid cut by the box is capped. A tile answers
// for its whole patch, a leaf's voxels are read from its buffer. Only the
// patches that reach into `clip` are read (a window's surroundings: a tile
// of a large export need not scan the whole box's faces).
template <class Mark>
void markCappedFaces(const voxel::IndexBox& b, const voxel::IndexBox& clip, Accessor& acc, Mark mark) {
    for (int a = 0; a < 3; ++a) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            const int face = side ? b.hi[a] : b.lo[a];
            if (face < clip.lo[a] || face > clip.hi[a]) continue;
            for (int i0 = std::max(b.lo[u], clip.lo[u]) & ~(kB - 1); i0 <= std::min(b.hi[u], clip.hi[u]); i0 += kB)
                for (int j0 = std::max(b.lo[v], clip.lo[v]) & ~(kB - 1); j0 <= std::min(b.hi[v], clip.hi[v]); j0 += kB) {
                    Coord c;
                    c[a] = face;
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

template <class Body>
void forEach(std::size_t n, const Tree& tree, Body body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
        Accessor acc(tree);
        for (std::size_t i = r.begin(); i != r.end(); ++i) body(i, acc);
    });
}

// Phase 0: candidates numbered in a fixed order (BlockTable's), so the mesh
// does not depend on the thread count; their values and inside bits.
Candidates findCandidates(const voxel::Volume& volume, const voxel::IndexBox& faceClip) {
    const Tree& tree = voxel::vdb(volume).tree();
    std::vector<const Leaf*> leaves;
    leaves.reserve(tree.leafCount());
    tree.getNodes(leaves);
    Candidates c{makeTable(volume.frame.indexBox, leaves), {}, {}, {}, {}};
    auto markWithLowerNeighbours = [&c](const Coord& origin) {
        const Coord b = blockOf(origin);
        for (int d = 0; d < 8; ++d) {
            const Coord n = b - upper(d);
            c.table.mark(n.x(), n.y(), n.z());
        }
    };
    for (const Leaf* leaf : leaves) markWithLowerNeighbours(leaf->origin());
    Accessor acc(tree);
    markCappedFaces(volume.frame.indexBox, faceClip, acc, markWithLowerNeighbours);

    c.origins.reserve(c.table.marked());
    c.table.number([&c](int x, int y, int z) { c.origins.push_back(originOf(Coord(x, y, z))); });
    const std::size_t n = c.origins.size();
    c.values.resize(n);
    c.inside.resize(n);
    c.state.resize(n);
    forEach(n, tree, [&c](std::size_t i, Accessor& a) {
        Values& v = c.values[i];
        if (const Leaf* leaf = a.probeConstLeaf(c.origins[i])) {
            v.data = leaf->buffer().data();
            c.inside[i] = leafMask(v.data);
        } else {
            v.tile = a.getValue(c.origins[i]);
            c.inside[i] = uniformMask(v.tile);
        }
    });
    return c;
}

// Phase 1 for candidate i. Edge data goes to `pool` (in whatever order the
// threads come: only the pointer is kept, so the mesh does not depend on it).
void classify(Candidates& c, std::size_t i, Accessor& acc, BlockEdges* pool, std::atomic<std::size_t>& used) {
    const Coord b = blockOf(c.origins[i]);
    std::array<SignMask, 8> tiles;
    std::array<const SignMask*, 8> m;
    for (std::size_t d = 0; d < 8; ++d) {
        const std::int32_t j = d ? c.find(b + upper(static_cast<int>(d))) : static_cast<std::int32_t>(i);
        if (j >= 0) {
            m[d] = &c.inside[static_cast<std::size_t>(j)];
        } else {
            tiles[d] = uniformMask(acc.getValue(originOf(b + upper(static_cast<int>(d)))));
            m[d] = &tiles[d];
        }
    }
    CornerRows rows;
    if (!cornerRows(m, rows)) return;
    BlockEdges& e = pool[used++];
    c.state[i].counts = analyseBlock(rows, e);
    c.state[i].edges = &e;
}

// The grid's values around one block (voxels -1 .. 9 in each axis), copied
// once from the leaves and tiles it overlaps: the vertex loop then indexes
// an array.
struct Halo {
    std::array<float, kHalo * kHalo * kHalo> v;
    static constexpr int index(int x, int y, int z) { return ((x + 1) * kHalo + (y + 1)) * kHalo + (z + 1); }

    void fill(const Candidates& c, const Coord& origin, Accessor& acc) {
        // The 27 neighbours (offsets -1..1, x fastest), each a leaf buffer or
        // a row of its tile value: `mask` is 0 for a tile, so every voxel of
        // the neighbour reads that row, and the copy below needs no branch.
        std::array<const float*, 27> data;
        std::array<int, 27> mask;
        std::array<std::array<float, kB>, 27> tileRows;
        const Coord b = blockOf(origin);
        for (std::size_t k = 0; k < 27; ++k) {
            const Coord d(static_cast<int>(k % 3) - 1, static_cast<int>(k / 3 % 3) - 1, static_cast<int>(k / 9) - 1);
            const std::int32_t j = c.find(b + d);
            const Values val = j >= 0 ? c.values[static_cast<std::size_t>(j)] : Values{nullptr, acc.getValue(originOf(b + d))};
            mask[k] = val.data ? -1 : 0;
            if (!val.data) tileRows[k].fill(val.tile);
            data[k] = val.data ? val.data : tileRows[k].data();
        }
        // Row (x, y) of the halo: z = -1 from the neighbour below, 0..7 from
        // the block's column, 8..9 from the one above.
        for (int x = -1; x <= kB + 1; ++x)
            for (int y = -1; y <= kB + 1; ++y) {
                const auto s = static_cast<std::size_t>(((x + kB) >> 3) + 3 * ((y + kB) >> 3));
                const int row = ((x & (kB - 1)) * kB + (y & (kB - 1))) * kB;  // leaf offset of (x, y, 0)
                float* dst = &v[static_cast<std::size_t>(index(x, y, -1))];
                dst[0] = data[s][(row + kB - 1) & mask[s]];
                std::memcpy(dst + 1, data[s + 9] + (row & mask[s + 9]), kB * sizeof(float));
                std::memcpy(dst + 1 + kB, data[s + 18] + (row & mask[s + 18]), 2 * sizeof(float));
            }
    }
};

struct Output {
    float* positions;
    float* normals;
    std::uint32_t* indices;
    std::uint64_t* edges;  // gridEdgeKey per vertex, or none
};

// Phase 3a: one vertex per owned crossing edge, in the order BlockEdges
// numbers them (axis, then row, then z).
void placeVertices(const Coord& origin, std::uint32_t firstVertex, const BlockEdges& e, const Halo& h,
                   const voxel::VolumeFrame& frame, const Output& out) {
    const float* v = h.v.data();
    auto grad = [v](int p, int a) { return v[p + kStride[a]] - v[p - kStride[a]]; };  // twice the gradient
    const double step = frame.voxelSize;
    std::size_t k = 3 * static_cast<std::size_t>(firstVertex);
    for (int axis = 0; axis < 3; ++axis)
        for (int row = 0; row < kB * kB; ++row) {
            const int x = row / kB, y = row % kB;
            unsigned bits = crossings(e.rows, axis, x, y) & 0xFFu;
            while (bits) {
                const int z = lowestBit(bits);
                bits &= bits - 1;
                const int p = Halo::index(x, y, z), q = p + kStride[axis];
                // Clamped away from the ends: a vertex exactly on a grid point
                // gives zero-area triangles that slicers flag.
                const double d0 = v[p], d1 = v[q];
                const double t = std::clamp(d0 / (d0 - d1), 1e-3, 1.0 - 1e-3);
                auto pos = frame.position(origin.x() + x, origin.y() + y, origin.z() + z);
                pos[static_cast<std::size_t>(axis)] += t * step;
                const auto tf = static_cast<float>(t);
                float g[3];
                for (int a = 0; a < 3; ++a) g[a] = grad(p, a) * (1.0f - tf) + grad(q, a) * tf;
                const float len2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
                const float scale = len2 > 0.0f ? -1.0f / std::sqrt(len2) : 0.0f;  // f grows inwards
                for (std::size_t a = 0; a < 3; ++a) {
                    out.positions[k + a] = static_cast<float>(pos[a]);
                    out.normals[k + a] = g[a] * scale;
                }
                if (out.edges) out.edges[k / 3] = gridEdgeKey(axis, origin.x() + x, origin.y() + y, origin.z() + z);
                k += 3;
            }
        }
}

// The next block's own leaf, read while this one is meshed: its halo copy
// otherwise waits on memory (leaves were last read in phase 0).
void prefetchValues(const Values& v) {
    if (!v.data) return;
    for (int i = 0; i < kB * kB * kB; i += 16) __builtin_prefetch(v.data + i);
}

// Phase 3 for candidate i.
void meshBlock(Candidates& c, std::size_t i, Accessor& acc, const voxel::VolumeFrame& frame, const Output& out) {
    BlockState& s = c.state[i];
    if (s.counts.vertices > 0) {
        Halo h;
        h.fill(c, c.origins[i], acc);
        placeVertices(c.origins[i], s.firstVertex, *s.edges, h, frame, out);
    }
    if (s.counts.triangles == 0) return;  // a window's neighbour: vertices only
    // The blocks that own this block's cells' edges: itself and its upper
    // neighbours (those without a crossing own no vertex).
    std::array<EdgeOwner, 8> owners{};
    const Coord b = blockOf(c.origins[i]);
    for (int d = 0; d < 8; ++d) {
        const std::int32_t j = d ? c.find(b + upper(d)) : static_cast<std::int32_t>(i);
        if (j < 0) continue;
        const BlockState& o = c.state[static_cast<std::size_t>(j)];
        if (o.counts.vertices > 0) owners[static_cast<std::size_t>(d)] = {o.edges, o.firstVertex};
    }
    s.written = triangulateBlock(*s.edges, owners, out.indices + 3 * s.firstTriangle);
}

// Blocks whose triangles lost an edge without an owner (only a sign change
// between two tiles, a program discontinuous across its own surface, has
// none) wrote fewer than they reserved: close the gaps.
void compact(const std::vector<BlockState>& state, std::vector<std::uint32_t>& indices) {
    std::size_t to = 0;
    for (const BlockState& s : state) {
        const std::size_t from = 3 * s.firstTriangle, n = 3 * static_cast<std::size_t>(s.written);
        if (from != to) std::memmove(indices.data() + to, indices.data() + from, n * sizeof(std::uint32_t));
        to += n;
    }
    indices.resize(to);
}

// Asks for transparent huge pages on the whole 2 MiB pages of a large
// buffer before it is first touched: faulting fresh memory in 4 KiB at a
// time is otherwise a large share of the mesher's time on big meshes. The
// kernel's policy decides; elsewhere this does nothing.
void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t lo = (begin + kHuge - 1) & ~(kHuge - 1), hi = (begin + bytes) & ~(kHuge - 1);
    if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
}

// Sizes an output array, on huge pages where it is large.
template <class T>
void allocate(std::vector<T>& v, std::size_t n) {
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
    v.resize(n);
}

// A block of a window's own cells, or one whose vertices those cells use
// (the block itself and its upper neighbours: origins up to hi + 1).
bool inWindow(const Coord& origin, const voxel::IndexBox& cells, int reach) {
    for (int a = 0; a < 3; ++a)
        if (origin[a] < cells.lo[a] || origin[a] > cells.hi[a] + reach) return false;
    return true;
}

Mesh meshImpl(const voxel::Volume& volume, const CellWindow* window, ExportStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    const Tree& tree = voxel::vdb(volume).tree();

    // A window's cells reach one block beyond it either way.
    voxel::IndexBox faceClip = volume.frame.indexBox;
    if (window)
        for (int a = 0; a < 3; ++a) {
            faceClip.lo[a] = window->cells.lo[a] - kB;
            faceClip.hi[a] = window->cells.hi[a] + kB + 1;
        }
    Candidates c = findCandidates(volume, faceClip);
    const std::size_t n = c.origins.size();

    // Phase 1. The pool is left uninitialized: only the blocks that are not
    // uniform (a minority) write a slot, so only their pages are touched.
    std::unique_ptr<BlockEdges[]> pool(new BlockEdges[n]);
    adviseHugePages(pool.get(), n * sizeof(BlockEdges));
    std::atomic<std::size_t> used{0};
    forEach(n, tree, [&](std::size_t i, Accessor& acc) { classify(c, i, acc, pool.get(), used); });

    // Phase 2.
    std::uint32_t vertices = 0;
    std::size_t triangles = 0;
    ExportStats st;
    std::vector<std::uint32_t> active;
    for (std::size_t i = 0; i < n; ++i) {
        BlockState& s = c.state[i];
        if (window && s.edges) {
            if (!inWindow(c.origins[i], window->cells, 0)) s.counts.triangles = s.counts.surfaceCells = 0;
            if (!inWindow(c.origins[i], window->cells, 1)) s.counts.vertices = 0;
        }
        s.firstVertex = vertices;
        s.firstTriangle = triangles;
        vertices += s.counts.vertices;
        triangles += s.counts.triangles;
        st.surfaceCells += s.counts.surfaceCells;
        if (s.counts.vertices > 0 || s.counts.triangles > 0) active.push_back(static_cast<std::uint32_t>(i));
    }
    Mesh mesh;
    // Zero-filling the output is a large share of the serial time: split it.
    tbb::parallel_invoke([&] { allocate(mesh.positions, 3 * static_cast<std::size_t>(vertices)); },
                         [&] { allocate(mesh.normals, 3 * static_cast<std::size_t>(vertices)); },
                         [&] { allocate(mesh.indices, 3 * triangles); });
    std::uint64_t* edgeKeys = nullptr;
    if (window && window->vertexEdges) {
        window->vertexEdges->assign(vertices, 0);
        edgeKeys = window->vertexEdges->data();
    }

    // Phase 3.
    const Output out{mesh.positions.data(), mesh.normals.data(), mesh.indices.data(), edgeKeys};
    forEach(active.size(), tree, [&](std::size_t k, Accessor& acc) {
        if (k + 1 < active.size()) prefetchValues(c.values[active[k + 1]]);
        meshBlock(c, active[k], acc, volume.frame, out);
    });
    bool complete = true;
    for (std::uint32_t i : active) complete = complete && c.state[i].written == c.state[i].counts.triangles;
    if (!complete) compact(c.state, mesh.indices);

    st.cells = n * static_cast<std::size_t>(kB * kB * kB);
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = st;
    return mesh;
}

}  // namespace

Mesh meshVolume(const voxel::Volume& volume, ExportStats* stats) { return meshImpl(volume, nullptr, stats); }

Mesh meshVolume(const voxel::Volume& volume, const CellWindow& window, ExportStats* stats) {
    return meshImpl(volume, &window, stats);
}

}  // namespace hg::poly
