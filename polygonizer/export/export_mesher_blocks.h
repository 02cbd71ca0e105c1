// The export mesher's per-block bit work, apart from the grid (no OpenVDB
// here): which corners of a block of 8^3 cells are inside, which of the
// edges it owns cross the surface and what local number each crossing's
// vertex gets, and its cells' triangles. Plus the block table that finds a
// block's neighbours without a hash map. export_mesher.cpp drives it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace hg::poly {

constexpr int kBlockSize = 8;  // cells per block side: one OpenVDB leaf

// Which of a block's 8^3 voxels are inside (value > 0): word x, bit 8y + z,
// the order of an OpenVDB leaf's buffer.
struct SignMask {
    std::array<std::uint64_t, 8> w;
};

SignMask leafMask(const float* values);  // 512 values, x-major, z fastest
SignMask uniformMask(float value);

// A block's corner signs, 0..8 in each axis: [9x + y], bit z set when
// corner (x, y, z) is inside.
using CornerRows = std::array<std::uint16_t, 81>;

// From the inside bits of the block (m[0]) and its upper neighbours (m[d]
// at offset (d & 1, d >> 1 & 1, d >> 2 & 1)). False when every corner has
// the same sign (no cell of the block touches the surface).
bool cornerRows(const std::array<const SignMask*, 8>& m, CornerRows& rows);

// The crossings of the edges along `axis` (0..2: x, y, z) that start in row
// (x, y) of the corners, bit z: 0..8 along x and y, 0..7 along z. Those
// with x, y and z below 8 are the block's own.
inline unsigned crossings(const CornerRows& rows, int axis, int x, int y) {
    const unsigned r = rows[static_cast<std::size_t>(x * 9 + y)];
    if (axis == 2) return (r ^ r >> 1) & 0xFFu;
    return r ^ rows[static_cast<std::size_t>(axis == 0 ? (x + 1) * 9 + y : x * 9 + y + 1)];
}

// What a block that is not uniform keeps for phase 3: its corners and the
// local number of its own crossings' vertices, axis by axis, row (8x + y) by
// row, z upwards. A vertex's number is then base + the crossings below it in
// its row, which any block can work out for its neighbour's edges.
struct BlockEdges {
    CornerRows rows;
    std::array<std::array<std::uint16_t, 64>, 3> base;  // [axis][8x + y]: the row's first local number
};

struct BlockCounts {
    std::uint32_t vertices = 0;      // owned crossing edges
    std::uint32_t triangles = 0;     // of the block's cells, by the cell table
    std::uint32_t surfaceCells = 0;  // cells with both inside and outside corners
};

// For a block that is not uniform: fills `edges` and counts what the block
// will make.
BlockCounts analyseBlock(const CornerRows& rows, BlockEdges& edges);

// Where the vertices of the edges a block owns are: owners[d] in
// triangulateBlock is the block itself (d = 0) or its upper neighbour at
// offset (d & 1, d >> 1 & 1, d >> 2 & 1).
struct EdgeOwner {
    const BlockEdges* edges = nullptr;  // none: no vertex there
    std::uint32_t firstVertex = 0;
};

// Writes the triangles of the block's surface cells (three vertex indices
// each, counter-clockwise from outside) and returns how many. A triangle
// with an edge that has no owner is left out.
std::uint32_t triangulateBlock(const BlockEdges& e, const std::array<EdgeOwner, 8>& owners, std::uint32_t* out);

inline int lowestBit(unsigned bits) { return __builtin_ctz(bits); }  // bits != 0

// Candidate number by block coordinates (a block's origin / 8), -1 where
// there is none: 16^3-block bricks over a fixed extent, each allocated when
// a block in it is first marked, found through a dense directory (a map
// instead where the extent is too large to cover, which only a malformed
// grid with leaves far apart has). Lookups are a few shifts, and blocks are
// numbered in one fixed order.
class BlockTable {
public:
    // Inclusive extent in block coordinates.
    BlockTable(const std::array<int, 3>& lo, const std::array<int, 3>& hi);

    std::int32_t find(int x, int y, int z) const {
        const unsigned ux = static_cast<unsigned>(x - lo_[0]), uy = static_cast<unsigned>(y - lo_[1]),
                       uz = static_cast<unsigned>(z - lo_[2]);
        if (ux >= size_[0] || uy >= size_[1] || uz >= size_[2]) return -1;
        const std::int32_t* brick = brickAt({ux >> kLog, uy >> kLog, uz >> kLog});
        return brick ? brick[cellIndex(ux, uy, uz)] : -1;
    }
    // The block must lie in the extent.
    void mark(int x, int y, int z);
    std::size_t marked() const { return marked_; }
    // Numbers the marked blocks 0, 1, ... brick by brick (x, then y, then z)
    // and calls f(x, y, z) for each in that order.
    template <class F>
    void number(F f);

private:
    using BrickKey = std::array<unsigned, 3>;
    static constexpr unsigned kLog = 4, kSide = 1u << kLog, kCells = kSide * kSide * kSide;
    static constexpr std::size_t kMaxDense = std::size_t{1} << 22;  // directory entries

    const std::int32_t* brickAt(const BrickKey& k) const {
        if (!useMap_) return dense_[(k[0] * bricks_[1] + k[1]) * bricks_[2] + k[2]];
        const auto it = map_.find(k);
        return it == map_.end() ? nullptr : it->second;
    }
    static std::size_t cellIndex(unsigned ux, unsigned uy, unsigned uz) {
        return (((ux & (kSide - 1)) << kLog | (uy & (kSide - 1))) << kLog) | (uz & (kSide - 1));
    }

    std::array<int, 3> lo_;
    std::array<unsigned, 3> size_;        // blocks
    std::array<std::size_t, 3> bricks_;   // bricks
    bool useMap_ = false;
    std::vector<std::int32_t*> dense_;
    std::map<BrickKey, std::int32_t*> map_;  // ordered: numbers blocks as the dense directory does
    std::vector<std::unique_ptr<std::int32_t[]>> storage_;
    std::size_t marked_ = 0;
};

template <class F>
void BlockTable::number(F f) {
    std::int32_t next = 0;
    auto numberBrick = [&](const BrickKey& k, std::int32_t* brick) {
        for (unsigned c = 0; c < kCells; ++c) {
            if (brick[c] < 0) continue;
            brick[c] = next++;
            f(lo_[0] + static_cast<int>(k[0] * kSide + (c >> (2 * kLog))),
              lo_[1] + static_cast<int>(k[1] * kSide + ((c >> kLog) & (kSide - 1))),
              lo_[2] + static_cast<int>(k[2] * kSide + (c & (kSide - 1))));
        }
    };
    if (useMap_) {
        for (const auto& [k, brick] : map_) numberBrick(k, brick);
        return;
    }
    for (unsigned bx = 0; bx < bricks_[0]; ++bx)
        for (unsigned by = 0; by < bricks_[1]; ++by)
            for (unsigned bz = 0; bz < bricks_[2]; ++bz)
                if (std::int32_t* brick = dense_[(bx * bricks_[1] + by) * bricks_[2] + bz]) numberBrick({bx, by, bz}, brick);
}

}  // namespace hg::poly
