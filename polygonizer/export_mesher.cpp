#include "polygonizer/export_mesher.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <bitset>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "polygonizer/cell_table.h"
#include "voxel/volume_vdb.h"

namespace hg::poly {

namespace {

using openvdb::Coord;
constexpr int kB = 8;            // block edge: one OpenVDB leaf of cells
constexpr int kHalo = kB + 3;    // voxels origin-1 .. origin+9 (cells, edges and their gradients)

// Blocks (8^3 cells, named by their cells' low corners) that can hold
// surface: every leaf of the grid and the blocks just below it in x, y and z
// (whose cells reach into the leaf), and the blocks of inside voxels on the
// index box's faces (where a cut solid is capped). Sorted, so the mesh does
// not depend on the thread count.
std::vector<Coord> candidateBlocks(const voxel::Volume& volume) {
    const openvdb::FloatGrid& grid = voxel::vdb(volume);
    std::vector<Coord> out;
    auto addWithLowerNeighbours = [&out](const Coord& origin) {
        for (int n = 0; n < 8; ++n)
            out.push_back(origin - Coord((n & 1) * kB, ((n >> 1) & 1) * kB, ((n >> 2) & 1) * kB));
    };
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) addWithLowerNeighbours(leaf->origin());
    // The index box's faces, an 8x8 patch at a time: a tile answers for its
    // whole patch, a leaf's voxels are read from its buffer.
    const voxel::IndexBox& b = volume.frame.indexBox;
    for (int a = 0; a < 3; ++a) {
        int u = (a + 1) % 3, v = (a + 2) % 3;
        for (int side = 0; side < 2; ++side)
            for (int i0 = b.lo[u] & ~(kB - 1); i0 <= b.hi[u]; i0 += kB)
                for (int j0 = b.lo[v] & ~(kB - 1); j0 <= b.hi[v]; j0 += kB) {
                    Coord c;
                    c[a] = side ? b.hi[a] : b.lo[a];
                    c[u] = i0;
                    c[v] = j0;
                    const Coord block = c & ~(kB - 1);
                    const auto* leaf = grid.tree().probeConstLeaf(block);
                    bool inside = false;
                    if (!leaf) {
                        inside = grid.tree().getValue(block) > 0.0f;
                    } else {
                        for (int i = std::max(i0, b.lo[u]); i <= std::min(i0 + kB - 1, b.hi[u]) && !inside; ++i)
                            for (int j = std::max(j0, b.lo[v]); j <= std::min(j0 + kB - 1, b.hi[v]) && !inside; ++j) {
                                c[u] = i;
                                c[v] = j;
                                inside = leaf->getValue(c) > 0.0f;
                            }
                    }
                    if (inside) addWithLowerNeighbours(block);
                }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// The grid's values around one block, copied once from the (up to 27)
// leaves and tiles it overlaps: the inner loops then index an array.
struct Halo {
    std::array<float, kHalo * kHalo * kHalo> v;
    float at(int x, int y, int z) const {  // block-local, -1 .. 9
        return v[static_cast<size_t>(((x + 1) * kHalo + (y + 1)) * kHalo + (z + 1))];
    }
    void fill(const openvdb::FloatTree& tree, const Coord& origin) {
        // Region by region: each of the 27 neighbours is a leaf (copy its
        // overlapping box straight from its buffer) or a tile (one value).
        using Leaf = openvdb::FloatTree::LeafNodeType;
        const int lo[3] = {-1, 0, kB}, hi[3] = {-1, kB - 1, kB + 1};
        for (int n = 0; n < 27; ++n) {
            const int px = n % 3, py = n / 3 % 3, pz = n / 9;
            const Coord o = origin + Coord((px - 1) * kB, (py - 1) * kB, (pz - 1) * kB);
            const Leaf* leaf = tree.probeConstLeaf(o);
            const float tile = leaf ? 0.0f : tree.getValue(o);
            const float* data = leaf ? leaf->buffer().data() : nullptr;
            for (int x = lo[px]; x <= hi[px]; ++x)
                for (int y = lo[py]; y <= hi[py]; ++y) {
                    float* dst = &v[static_cast<size_t>(((x + 1) * kHalo + (y + 1)) * kHalo + (lo[pz] + 1))];
                    const int count = hi[pz] - lo[pz] + 1;
                    if (!data) {
                        std::fill(dst, dst + count, tile);
                        continue;
                    }
                    // Leaf offsets are x-major, z fastest, like the halo.
                    const int lx = x - (px - 1) * kB, ly = y - (py - 1) * kB, lz = lo[pz] - (pz - 1) * kB;
                    std::copy_n(data + (lx * kB + ly) * kB + lz, count, dst);
                }
        }
    }
};

struct Block {
    Coord origin;
    std::array<std::int32_t, 3 * kB * kB * kB> edgeVertex{};  // owned crossings: local index or -1
    std::vector<float> positions, normals;
    std::vector<std::uint32_t> indices;
    std::uint32_t firstVertex = 0;
    std::array<std::int32_t, 8> neighbour{};  // block index at origin + 8 * (dx, dy, dz), dx..dz in {0, 1}
    std::bitset<(kB + 1) * (kB + 1) * (kB + 1)> inside;  // corners 0..8 of the block's cells
    std::size_t surfaceCells = 0;
};


size_t edgeSlot(int axis, int x, int y, int z) { return static_cast<size_t>(((axis * kB + x) * kB + y) * kB + z); }

// Pass 1: the crossings on edges whose low end lies in the block.
size_t cornerSlot(int x, int y, int z) { return static_cast<size_t>((x * (kB + 1) + y) * (kB + 1) + z); }

void placeVertices(Block& b, const Halo& h, const voxel::VolumeFrame& frame) {
    b.edgeVertex.fill(-1);
    for (int x = 0; x <= kB; ++x)
        for (int y = 0; y <= kB; ++y)
            for (int z = 0; z <= kB; ++z) b.inside[cornerSlot(x, y, z)] = h.at(x, y, z) > 0.0f;
    if (b.inside.none() || b.inside.all()) return;  // no edge of the block crosses
    const double step = frame.voxelSize;
    auto grad = [&h](int x, int y, int z) {
        return openvdb::Vec3d(0.5 * static_cast<double>(h.at(x + 1, y, z) - h.at(x - 1, y, z)),
                              0.5 * static_cast<double>(h.at(x, y + 1, z) - h.at(x, y - 1, z)),
                              0.5 * static_cast<double>(h.at(x, y, z + 1) - h.at(x, y, z - 1)));
    };
    for (int x = 0; x < kB; ++x)
        for (int y = 0; y < kB; ++y)
            for (int z = 0; z < kB; ++z) {
                const float v0 = h.at(x, y, z);
                for (int axis = 0; axis < 3; ++axis) {
                    int x1 = x + (axis == 0), y1 = y + (axis == 1), z1 = z + (axis == 2);
                    const float v1 = h.at(x1, y1, z1);
                    if ((v0 > 0.0f) == (v1 > 0.0f)) continue;
                    // Clamped away from the ends: a vertex exactly on a grid point
                    // gives zero-area triangles that slicers flag.
                    const double d0 = v0, d1 = v1;
                    const double t = std::clamp(d0 / (d0 - d1), 1e-3, 1.0 - 1e-3);
                    auto p = frame.position(b.origin.x() + x, b.origin.y() + y, b.origin.z() + z);
                    p[static_cast<size_t>(axis)] += t * step;
                    openvdb::Vec3d g = grad(x, y, z) * (1.0 - t) + grad(x1, y1, z1) * t;
                    double len = g.length();
                    openvdb::Vec3d n = len > 0 ? -g / len : openvdb::Vec3d(0, 0, 0);  // f grows inwards
                    b.edgeVertex[edgeSlot(axis, x, y, z)] = static_cast<std::int32_t>(b.positions.size() / 3);
                    for (int a = 0; a < 3; ++a) {
                        b.positions.push_back(static_cast<float>(p[static_cast<size_t>(a)]));
                        b.normals.push_back(static_cast<float>(n[a]));
                    }
                }
            }
}

// Pass 2: the block's candidate cells, with vertices from the blocks that
// own their edges (this one or its +x/+y/+z neighbours).
void triangulate(Block& b, const std::vector<Block>& blocks) {
    if (b.inside.none() || b.inside.all()) return;
    const auto& table = cellTable();
    for (int cx = 0; cx < kB; ++cx)
        for (int cy = 0; cy < kB; ++cy)
            for (int cz = 0; cz < kB; ++cz) {
                int mask = 0;
                for (int c = 0; c < 8; ++c)
                    if (b.inside[cornerSlot(cx + (c & 1), cy + ((c >> 1) & 1), cz + ((c >> 2) & 1))]) mask |= 1 << c;
                if (mask == 0 || mask == 255) continue;
                ++b.surfaceCells;
                const CellCase& cc = table[static_cast<size_t>(mask)];
                for (int t = 0; t < cc.triangleCount; ++t) {
                    std::uint32_t tri[3];
                    bool found = true;
                    for (int k = 0; k < 3; ++k) {
                        const int e = cc.edges[static_cast<size_t>(3 * t + k)];
                        const int c0 = kEdgeCorners[static_cast<size_t>(e)][0];
                        int ex = cx + (c0 & 1), ey = cy + ((c0 >> 1) & 1), ez = cz + ((c0 >> 2) & 1);
                        int nb = (ex >= kB) + 2 * (ey >= kB) + 4 * (ez >= kB);
                        std::int32_t owner = b.neighbour[static_cast<size_t>(nb)];
                        // Only a sign change between two tiles (a program discontinuous
                        // across its own surface) has no owning block.
                        if (owner < 0) { found = false; break; }
                        const Block& o = blocks[static_cast<size_t>(owner)];
                        std::int32_t local =
                            o.edgeVertex[edgeSlot(kEdgeAxis[static_cast<size_t>(e)], ex % kB, ey % kB, ez % kB)];
                        if (local < 0) { found = false; break; }
                        tri[k] = o.firstVertex + static_cast<std::uint32_t>(local);
                    }
                    if (found) b.indices.insert(b.indices.end(), tri, tri + 3);
                }
            }
}

}  // namespace

Mesh meshVolume(const voxel::Volume& volume, ExportStats* stats) {
    auto start = std::chrono::steady_clock::now();
    const openvdb::FloatTree& tree = voxel::vdb(volume).tree();
    const std::vector<Coord> origins = candidateBlocks(volume);
    std::vector<Block> blocks(origins.size());
    std::unordered_map<Coord, std::int32_t> indexOf;
    for (size_t i = 0; i < origins.size(); ++i) {
        blocks[i].origin = origins[i];
        indexOf.emplace(origins[i], static_cast<std::int32_t>(i));
    }
    // An edge a cell uses starts in the cell's block or one above it; a
    // crossing edge has a leaf voxel (or a capped face voxel) at one end, so
    // its block is a candidate too (leaves and their lower neighbours).
    for (Block& b : blocks)
        for (int n = 0; n < 8; ++n) {
            auto it = indexOf.find(b.origin + Coord((n & 1) * kB, ((n >> 1) & 1) * kB, ((n >> 2) & 1) * kB));
            b.neighbour[static_cast<size_t>(n)] = it == indexOf.end() ? -1 : it->second;
        }

    const voxel::VolumeFrame& frame = volume.frame;
    tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t i) {
        Halo h;
        h.fill(tree, blocks[i].origin);
        placeVertices(blocks[i], h, frame);
    });
    std::uint32_t vertices = 0;
    for (Block& b : blocks) {
        b.firstVertex = vertices;
        vertices += static_cast<std::uint32_t>(b.positions.size() / 3);
    }
    tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t i) { triangulate(blocks[i], blocks); });

    Mesh mesh;
    ExportStats st;
    std::size_t triangles = 0;
    for (const Block& b : blocks) triangles += b.indices.size();
    mesh.positions.reserve(3 * vertices);
    mesh.normals.reserve(3 * vertices);
    mesh.indices.reserve(triangles);
    for (const Block& b : blocks) {
        mesh.positions.insert(mesh.positions.end(), b.positions.begin(), b.positions.end());
        mesh.normals.insert(mesh.normals.end(), b.normals.begin(), b.normals.end());
        mesh.indices.insert(mesh.indices.end(), b.indices.begin(), b.indices.end());
        st.cells += kB * kB * kB;
        st.surfaceCells += b.surfaceCells;
    }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = st;
    return mesh;
}

}  // namespace hg::poly
