#include "polygonizer/export_mesher.h"

#include <openvdb/tools/Morphology.h>
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

// Cells (named by their low corner) that can hold surface: every cell with
// an active voxel among its corners, and cells on the index box's faces with
// an inside voxel (where a cut solid is capped). Blocks are this mask's
// leaves.
openvdb::MaskGrid::Ptr candidateCells(const voxel::Volume& volume) {
    const openvdb::FloatGrid& grid = voxel::vdb(volume);
    auto mask = openvdb::MaskGrid::create();
    mask->tree().topologyUnion(grid.tree());
    const voxel::IndexBox& b = volume.frame.indexBox;
    openvdb::FloatGrid::ConstAccessor acc = grid.getConstAccessor();
    openvdb::MaskGrid::Accessor m = mask->getAccessor();
    for (int a = 0; a < 3; ++a) {
        int u = (a + 1) % 3, v = (a + 2) % 3;
        for (int side = 0; side < 2; ++side)
            for (int i = b.lo[u]; i <= b.hi[u]; ++i)
                for (int j = b.lo[v]; j <= b.hi[v]; ++j) {
                    Coord c;
                    c[a] = side ? b.hi[a] : b.lo[a];
                    c[u] = i;
                    c[v] = j;
                    if (acc.getValue(c) > 0.0f) m.setValueOn(c);
                }
    }
    // A voxel is a corner of the cells whose low corners lie one step below
    // it; the 26-neighbour dilation is a superset that keeps it simple.
    openvdb::tools::dilateActiveValues(mask->tree(), 1, openvdb::tools::NN_FACE_EDGE_VERTEX,
                                       openvdb::tools::IGNORE_TILES);
    return mask;
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
    const openvdb::MaskTree::LeafNodeType* cells = nullptr;
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
    const auto& table = cellTable();
    for (auto it = b.cells->cbeginValueOn(); it; ++it) {
        const Coord cell = it.getCoord() - b.origin;
        const int cx = cell.x(), cy = cell.y(), cz = cell.z();
        int mask = 0;
        for (int c = 0; c < 8; ++c)
            if (b.inside[cornerSlot(cx + (c & 1), cy + ((c >> 1) & 1), cz + ((c >> 2) & 1))]) mask |= 1 << c;
        if (mask == 0 || mask == 255) continue;
        ++b.surfaceCells;
        const CellCase& cc = table[static_cast<size_t>(mask)];
        for (int t = 0; t < 3 * cc.triangleCount; ++t) {
            const int e = cc.edges[static_cast<size_t>(t)];
            const int c0 = kEdgeCorners[static_cast<size_t>(e)][0];
            int ex = cx + (c0 & 1), ey = cy + ((c0 >> 1) & 1), ez = cz + ((c0 >> 2) & 1);
            int nb = (ex >= kB) + 2 * (ey >= kB) + 4 * (ez >= kB);
            const Block& owner = blocks[static_cast<size_t>(b.neighbour[static_cast<size_t>(nb)])];
            std::int32_t local = owner.edgeVertex[edgeSlot(kEdgeAxis[static_cast<size_t>(e)], ex % kB, ey % kB, ez % kB)];
            b.indices.push_back(owner.firstVertex + static_cast<std::uint32_t>(local));
        }
    }
}

}  // namespace

Mesh meshVolume(const voxel::Volume& volume, ExportStats* stats) {
    auto start = std::chrono::steady_clock::now();
    const openvdb::FloatTree& tree = voxel::vdb(volume).tree();
    openvdb::MaskGrid::Ptr cells = candidateCells(volume);

    std::vector<Block> blocks;
    blocks.reserve(cells->tree().leafCount());
    std::unordered_map<Coord, std::int32_t> indexOf;
    for (auto leaf = cells->tree().cbeginLeaf(); leaf; ++leaf) {
        indexOf.emplace(leaf->origin(), static_cast<std::int32_t>(blocks.size()));
        blocks.emplace_back();
        blocks.back().cells = leaf.getLeaf();
        blocks.back().origin = leaf->origin();
    }
    // Every edge a candidate cell uses starts at a corner next to an active
    // voxel, whose block is a candidate block too (the mask is dilated).
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
        st.cells += b.cells->onVoxelCount();
        st.surfaceCells += b.surfaceCells;
    }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = st;
    return mesh;
}

}  // namespace hg::poly
