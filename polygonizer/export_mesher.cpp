#include "polygonizer/export_mesher.h"

#include <openvdb/tools/Morphology.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "polygonizer/cell_table.h"
#include "voxel/volume_vdb.h"

namespace hg::poly {

namespace {

using openvdb::Coord;

// Cells (named by their low corner) that can hold surface: every cell with
// an active voxel among its corners, and cells on the index box's faces with
// an inside voxel (where a cut solid is capped).
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
    // A voxel is a corner of the eight cells whose low corners lie at or
    // below it: dilate towards -x, -y, -z (a full 26-neighbour dilation is
    // a superset and keeps it simple).
    openvdb::tools::dilateActiveValues(mask->tree(), 1, openvdb::tools::NN_FACE_EDGE_VERTEX,
                                       openvdb::tools::IGNORE_TILES);
    return mask;
}

struct EdgeKey {
    std::int64_t packed;
    bool operator==(const EdgeKey& o) const { return packed == o.packed; }
};
struct EdgeKeyHash {
    std::size_t operator()(const EdgeKey& k) const { return std::hash<std::int64_t>()(k.packed); }
};

EdgeKey edgeKey(const Coord& lowCorner, int axis) {
    // 20 bits per coordinate (offset to be non-negative), 2 for the axis.
    auto f = [](int v) { return static_cast<std::int64_t>(v + (1 << 19)) & 0xFFFFF; };
    return {(f(lowCorner.x()) << 42) | (f(lowCorner.y()) << 22) | (f(lowCorner.z()) << 2) | axis};
}

}  // namespace

Mesh meshVolume(const voxel::Volume& volume, ExportStats* stats) {
    auto start = std::chrono::steady_clock::now();
    Mesh mesh;
    ExportStats st;
    const openvdb::FloatGrid& grid = voxel::vdb(volume);
    const voxel::VolumeFrame& frame = volume.frame;
    const auto& table = cellTable();
    openvdb::FloatGrid::ConstAccessor acc = grid.getConstAccessor();
    std::unordered_map<EdgeKey, std::uint32_t, EdgeKeyHash> vertexOf;
    const double h = frame.voxelSize;

    auto gradient = [&](const Coord& c) {
        openvdb::Vec3d g;
        for (int a = 0; a < 3; ++a) {
            Coord d(0, 0, 0);
            d[a] = 1;
            g[a] = 0.5 * (static_cast<double>(acc.getValue(c + d)) - static_cast<double>(acc.getValue(c - d)));
        }
        return g;
    };
    auto vertex = [&](const Coord& cell, int e, const float* values) -> std::uint32_t {
        const auto& ec = kEdgeCorners[static_cast<size_t>(e)];
        const int axis = kEdgeAxis[static_cast<size_t>(e)];
        Coord c0 = cell + Coord(ec[0] & 1, (ec[0] >> 1) & 1, (ec[0] >> 2) & 1);
        EdgeKey key = edgeKey(c0, axis);
        auto it = vertexOf.find(key);
        if (it != vertexOf.end()) return it->second;
        const double v0 = values[ec[0]], v1 = values[ec[1]];
        // Clamped away from the ends: a vertex exactly on a grid point would
        // give zero-area triangles that printers' slicers flag.
        const double t = std::clamp(v0 / (v0 - v1), 1e-3, 1.0 - 1e-3);
        auto p = frame.position(c0.x(), c0.y(), c0.z());
        p[static_cast<size_t>(axis)] += t * h;
        Coord c1 = c0;
        c1[axis] += 1;
        openvdb::Vec3d g = gradient(c0) * (1.0 - t) + gradient(c1) * t;
        double len = g.length();
        openvdb::Vec3d n = len > 0 ? -g / len : openvdb::Vec3d(0, 0, 0);  // f grows inwards
        auto index = static_cast<std::uint32_t>(mesh.positions.size() / 3);
        for (int a = 0; a < 3; ++a) {
            mesh.positions.push_back(static_cast<float>(p[static_cast<size_t>(a)]));
            mesh.normals.push_back(static_cast<float>(n[a]));
        }
        vertexOf.emplace(key, index);
        return index;
    };

    openvdb::MaskGrid::Ptr cells = candidateCells(volume);
    for (auto it = cells->cbeginValueOn(); it; ++it) {
        const Coord cell = it.getCoord();
        ++st.cells;
        float values[8];
        int mask = 0;
        for (int c = 0; c < 8; ++c) {
            values[c] = acc.getValue(cell + Coord(c & 1, (c >> 1) & 1, (c >> 2) & 1));
            if (values[c] > 0.0f) mask |= 1 << c;
        }
        if (mask == 0 || mask == 255) continue;
        ++st.surfaceCells;
        const CellCase& cc = table[static_cast<size_t>(mask)];
        for (int t = 0; t < 3 * cc.triangleCount; ++t) mesh.indices.push_back(vertex(cell, cc.edges[static_cast<size_t>(t)], values));
    }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats) *stats = st;
    return mesh;
}

}  // namespace hg::poly
