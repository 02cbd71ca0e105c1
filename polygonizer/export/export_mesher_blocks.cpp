#include "polygonizer/export/export_mesher_blocks.h"

#include <algorithm>

#include "polygonizer/cell_table.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hg::poly {

namespace {

constexpr int kB = kBlockSize;
constexpr int kRow = kB + 1;  // corners per row of a block
constexpr std::uint16_t kAllInside = (1u << kRow) - 1;

// popcount of a byte. (The x86-64 baseline has no popcount instruction, and
// the library call is far slower than a table.)
struct ByteCounts {
    std::array<std::uint8_t, 256> n{};
    constexpr ByteCounts() {
        for (int i = 1; i < 256; ++i) n[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>((i & 1) + n[static_cast<std::size_t>(i >> 1)]);
    }
};
constexpr ByteCounts kByteCounts;
unsigned bitCount(unsigned byte) { return kByteCounts.n[byte]; }

// Bits 0..63 of one leaf row: value > 0 (false for NaN, as the compare is).
std::uint64_t insideBits(const float* v) {
    std::uint64_t w = 0;
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps();
    for (int i = 0; i < 64; i += 4)
        w |= static_cast<std::uint64_t>(_mm_movemask_ps(_mm_cmpgt_ps(_mm_loadu_ps(v + i), zero))) << i;
#else
    for (int i = 0; i < 64; ++i) w |= static_cast<std::uint64_t>(v[i] > 0.0f) << i;
#endif
    return w;
}

// Case index of cell (x, y, z): bit c set when corner c is inside.
inline unsigned cellCase(const CornerRows& rows, int x, int y, int z) {
    const unsigned r00 = rows[static_cast<std::size_t>(x * kRow + y)] >> z;
    const unsigned r10 = rows[static_cast<std::size_t>((x + 1) * kRow + y)] >> z;
    const unsigned r01 = rows[static_cast<std::size_t>(x * kRow + y + 1)] >> z;
    const unsigned r11 = rows[static_cast<std::size_t>((x + 1) * kRow + y + 1)] >> z;
    return (r00 & 1) | (r10 & 1) << 1 | (r01 & 1) << 2 | (r11 & 1) << 3 | (r00 & 2) << 3 | (r10 & 2) << 4 |
           (r01 & 2) << 5 | (r11 & 2) << 6;
}

// Bit z set when cell (x, y, z) has corners of both signs.
inline unsigned surfaceCellsOfColumn(const CornerRows& rows, int x, int y) {
    const unsigned r00 = rows[static_cast<std::size_t>(x * kRow + y)];
    const unsigned r10 = rows[static_cast<std::size_t>((x + 1) * kRow + y)];
    const unsigned r01 = rows[static_cast<std::size_t>(x * kRow + y + 1)];
    const unsigned r11 = rows[static_cast<std::size_t>((x + 1) * kRow + y + 1)];
    const unsigned any = r00 | r10 | r01 | r11, all = r00 & r10 & r01 & r11;
    return ((any | any >> 1) & ~(all & all >> 1)) & 0xFFu;
}

// The vertex of every crossing edge a block's cells use, by the edge's low
// end: [((axis * 9 + x) * 9 + y) * 9 + z], x, y, z in 0..8. Only crossing
// edges' entries are written (and only they are read).
using EdgeIndices = std::array<std::uint32_t, 3 * kRow * kRow * kRow>;

// The cell table with each triangle corner's edge replaced by that edge's
// entry in EdgeIndices relative to the cell's low corner's: one load fewer
// per corner in the triangle loop.
struct CaseOffsets {
    std::uint8_t corners = 0;  // 3 per triangle
    std::array<std::int16_t, 36> offset{};
};

std::array<CaseOffsets, 256> makeCaseOffsets() {
    std::array<int, 12> edge{};
    for (std::size_t e = 0; e < 12; ++e) {
        const int c0 = kEdgeCorners[e][0];
        edge[e] = ((kEdgeAxis[e] * kRow + (c0 & 1)) * kRow + ((c0 >> 1) & 1)) * kRow + ((c0 >> 2) & 1);
    }
    std::array<CaseOffsets, 256> out{};
    const auto& table = cellTable();
    for (std::size_t c = 0; c < 256; ++c) {
        out[c].corners = static_cast<std::uint8_t>(3 * table[c].triangleCount);
        for (std::size_t k = 0; k < out[c].corners; ++k)
            out[c].offset[k] = static_cast<std::int16_t>(edge[table[c].edges[k]]);
    }
    return out;
}

constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;

// Fills `vertex` for the crossing edges of the block's cells, row by row:
// an owner numbers a row's crossings consecutively from its base, so each
// row costs one look-up in its owner (the block or an upper neighbour).
// False when some crossing has no owner (its entry is kNoVertex).
bool edgeIndices(const BlockEdges& e, const std::array<EdgeOwner, 8>& owners, EdgeIndices& vertex) {
    bool complete = true;
    // The block's own rows come in its numbering's order: count, not look up.
    std::uint32_t own = owners[0].firstVertex;
    for (int axis = 0; axis < 3; ++axis)
        for (int x = 0; x < (axis == 0 ? kB : kRow); ++x)
            for (int y = 0; y < (axis == 1 ? kB : kRow); ++y) {
                const unsigned c = crossings(e.rows, axis, x, y);
                if (!c) continue;
                const auto d = static_cast<std::size_t>((x >> 3) | (y >> 3) << 1);
                const auto row = static_cast<std::size_t>((x & (kB - 1)) * kB + (y & (kB - 1)));
                std::uint32_t* dst = vertex.data() + ((axis * kRow + x) * kRow + y) * kRow;
                // z 0..7 belong to owner d, z = 8 to the one above it (its z = 0).
                const EdgeOwner& low = owners[d];
                std::uint32_t next = kNoVertex;
                if (d == 0) {
                    next = own;
                    own += bitCount(c & 0xFFu);
                } else if (low.edges) {
                    next = low.firstVertex + low.edges->base[static_cast<std::size_t>(axis)][row];
                }
                for (unsigned bits = c & 0xFFu; bits; bits &= bits - 1) {
                    dst[lowestBit(bits)] = next;
                    if (next != kNoVertex) ++next;
                }
                complete = complete && (low.edges || !(c & 0xFFu));
                if (!(c & 0x100u)) continue;
                const EdgeOwner& high = owners[d + 4];
                dst[kB] = high.edges ? high.firstVertex + high.edges->base[static_cast<std::size_t>(axis)][row] : kNoVertex;
                complete = complete && high.edges;
            }
    return complete;
}

}  // namespace

SignMask leafMask(const float* values) {
    SignMask m;
    for (std::size_t x = 0; x < 8; ++x) m.w[x] = insideBits(values + 64 * x);
    return m;
}

SignMask uniformMask(float value) {
    SignMask m;
    m.w.fill(value > 0.0f ? ~std::uint64_t{0} : 0);
    return m;
}

bool cornerRows(const std::array<const SignMask*, 8>& m, CornerRows& rows) {
    // z 0..7 from the block's (or its +x / +y neighbours') bits, z = 8 from
    // the +z neighbours' first voxel in the row.
    unsigned any = 0, all = kAllInside;
    for (int x = 0; x <= kB; ++x)
        for (int y = 0; y <= kB; ++y) {
            const std::size_t d = static_cast<std::size_t>((x >> 3) | (y >> 3) << 1);
            const auto word = static_cast<std::size_t>(x & (kB - 1));
            const unsigned shift = 8u * static_cast<unsigned>(y & (kB - 1));
            const auto low = static_cast<unsigned>((m[d]->w[word] >> shift) & 0xFFu);
            const auto top = static_cast<unsigned>((m[d + 4]->w[word] >> shift) & 1u);
            const unsigned r = low | top << 8;
            rows[static_cast<std::size_t>(x * kRow + y)] = static_cast<std::uint16_t>(r);
            any |= r;
            all &= r;
        }
    return any != 0 && all != kAllInside;
}

BlockCounts analyseBlock(const CornerRows& rows, BlockEdges& edges) {
    BlockCounts counts;
    edges.rows = rows;
    for (int axis = 0; axis < 3; ++axis)
        for (int x = 0; x < kB; ++x)
            for (int y = 0; y < kB; ++y) {
                const auto row = static_cast<std::size_t>(x * kB + y);
                const unsigned c = crossings(rows, axis, x, y) & 0xFFu;
                edges.base[static_cast<std::size_t>(axis)][row] = static_cast<std::uint16_t>(counts.vertices);
                counts.vertices += bitCount(c);
            }
    const auto& table = cellTable();
    for (int x = 0; x < kB; ++x)
        for (int y = 0; y < kB; ++y)
            for (unsigned cells = surfaceCellsOfColumn(rows, x, y); cells; cells &= cells - 1) {
                counts.triangles += table[cellCase(rows, x, y, lowestBit(cells))].triangleCount;
                ++counts.surfaceCells;
            }
    return counts;
}

std::uint32_t triangulateBlock(const BlockEdges& e, const std::array<EdgeOwner, 8>& owners, std::uint32_t* out) {
    static const std::array<CaseOffsets, 256> cases = makeCaseOffsets();
    EdgeIndices vertex;
    const bool complete = edgeIndices(e, owners, vertex);
    std::uint32_t* const first = out;
    for (int x = 0; x < kB; ++x)
        for (int y = 0; y < kB; ++y)
            for (unsigned cells = surfaceCellsOfColumn(e.rows, x, y); cells; cells &= cells - 1) {
                const int z = lowestBit(cells);
                const std::uint32_t* v = vertex.data() + ((x * kRow + y) * kRow + z);
                const CaseOffsets& cc = cases[cellCase(e.rows, x, y, z)];
                if (complete) {
                    for (std::size_t k = 0; k < cc.corners; ++k) out[k] = v[cc.offset[k]];
                    out += cc.corners;
                    continue;
                }
                for (std::size_t k = 0; k < cc.corners; k += 3) {
                    const std::uint32_t a = v[cc.offset[k]], b = v[cc.offset[k + 1]], d = v[cc.offset[k + 2]];
                    if (a == kNoVertex || b == kNoVertex || d == kNoVertex) continue;
                    *out++ = a;
                    *out++ = b;
                    *out++ = d;
                }
            }
    return static_cast<std::uint32_t>((out - first) / 3);
}

BlockTable::BlockTable(const std::array<int, 3>& lo, const std::array<int, 3>& hi) : lo_(lo) {
    for (std::size_t a = 0; a < 3; ++a) {
        size_[a] = hi[a] < lo[a] ? 0u : static_cast<unsigned>(static_cast<long long>(hi[a]) - lo[a] + 1);
        bricks_[a] = (size_[a] + kSide - 1) / kSide;
    }
    // Compared by division: the product may not fit.
    useMap_ = bricks_[0] && bricks_[1] && bricks_[2] && bricks_[1] * bricks_[2] > kMaxDense / bricks_[0];
    if (!useMap_) dense_.resize(bricks_[0] * bricks_[1] * bricks_[2]);
}

void BlockTable::mark(int x, int y, int z) {
    const unsigned ux = static_cast<unsigned>(x - lo_[0]), uy = static_cast<unsigned>(y - lo_[1]),
                   uz = static_cast<unsigned>(z - lo_[2]);
    const BrickKey k{ux >> kLog, uy >> kLog, uz >> kLog};
    std::int32_t*& brick = useMap_ ? map_[k] : dense_[(k[0] * bricks_[1] + k[1]) * bricks_[2] + k[2]];
    if (!brick) {
        storage_.emplace_back(new std::int32_t[kCells]);
        brick = storage_.back().get();
        std::fill(brick, brick + kCells, -1);
    }
    std::int32_t& slot = brick[cellIndex(ux, uy, uz)];
    marked_ += slot < 0;
    slot = 0;
}

}  // namespace hg::poly
