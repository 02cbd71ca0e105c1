#include "garden/morph/blend_block_vdb.h"

#include <algorithm>
#include <cmath>

namespace hg::garden::blend {

namespace {

// The blend of one block's 512 values. Restrict parameters (GCC ignores
// restrict on local pointers) let -O2 vectorize it without alias checks.
void blendRun(const float* __restrict a, const float* __restrict b, const float* __restrict c, float* __restrict v,
              float w0, float w1, float w2, float band) {
    for (int i = 0; i < kBlockVoxels; ++i) v[i] = blendValue(a[i], b[i], c[i], w0, w1, w2, band);
}

void activeBytes(const float* __restrict v, std::uint8_t* __restrict on, float band) {
    for (int i = 0; i < kBlockVoxels; ++i) on[i] = std::fabs(v[i]) < band;
}

}  // namespace

Lattice itemLattice(const std::array<int, 3>& origin, BlendPass pass, const voxel::IndexBox& indexBox) {
    Lattice l;
    l.stride = pass == BlendPass::Coarse ? kCoarseStride : 1;
    for (int a = 0; a < 3; ++a) {
        int lo = std::max(origin[static_cast<std::size_t>(a)], indexBox.lo[a]);
        int hi = std::min(origin[static_cast<std::size_t>(a)] + kBlendBlock - 1, indexBox.hi[a]);
        if (pass == BlendPass::Coarse) {
            lo = ceilMultiple(lo, kCoarseStride);
            hi = floorMultiple(hi, kCoarseStride);
        }
        l.start[a] = lo;
        l.count[a] = hi >= lo ? (hi - lo) / l.stride + 1 : 0;
    }
    return l;
}

BlendInputs inputs(const MorphSources& s, const MorphWeights& weights) {
    BlendInputs in{};
    for (std::size_t i = 0; i < 3; ++i) {
        in.f[i] = &s.fields[i];
        in.w[i] = static_cast<float>(weights.w[i]);
    }
    in.band = s.frame.band;
    in.box = s.frame.indexBox;
    return in;
}

void sampleValues(const BlendItem& item, std::uint32_t s0, std::uint32_t s1, const BlendInputs& in, float* out) {
    const auto& o = item.origin;
    const bool coarse = item.pass == BlendPass::Coarse;
    const float* src[3];
    for (std::size_t f = 0; f < 3; ++f) src[f] = coarse ? in.f[f]->coarse(o) : in.f[f]->block(o);
    std::size_t n = 0;
    forSamples(itemLattice(o, item.pass, in.box), o, s0, s1, [&](int i, int j, int k, int off) {
        const int at = coarse ? coarseOffset(i - o[0], j - o[1], k - o[2]) : off;
        out[n++] = blendValue(src[0][at], src[1][at], src[2][at], in.w[0], in.w[1], in.w[2], in.band);
    });
}

void diffBytes(const std::uint32_t* __restrict oldBits, const std::uint32_t* __restrict newBits,
               const std::uint8_t* __restrict oldOn, const std::uint8_t* __restrict newOn, std::uint8_t* __restrict diff) {
    for (int i = 0; i < kBlockVoxels; ++i)
        diff[i] = static_cast<std::uint8_t>((oldBits[i] != newBits[i]) | (oldOn[i] != newOn[i]));
}

void blendBlock(const std::array<int, 3>& o, const BlendInputs& in, BlockValues& out) {
    const float band = in.band;
    // Edge blocks hold 0 beyond the box in the sources: blended like the
    // rest, then replaced.
    blendRun(in.f[0]->block(o), in.f[1]->block(o), in.f[2]->block(o), out.v, in.w[0], in.w[1], in.w[2], band);
    const bool whole = in.box.contains(o[0], o[1], o[2]) &&
                       in.box.contains(o[0] + kBlendBlock - 1, o[1] + kBlendBlock - 1, o[2] + kBlendBlock - 1);
    if (!whole) {
        // The block's voxels inside the box, per axis, in block coordinates.
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(0, in.box.lo[a] - o[static_cast<std::size_t>(a)]);
            hi[a] = std::min(kBlendBlock - 1, in.box.hi[a] - o[static_cast<std::size_t>(a)]);
        }
        for (int x = 0; x < kBlendBlock; ++x)
            for (int y = 0; y < kBlendBlock; ++y) {
                float* row = out.v + blockOffset(x, y, 0);
                if (x < lo[0] || x > hi[0] || y < lo[1] || y > hi[1]) {
                    std::fill(row, row + kBlendBlock, -band);
                    continue;
                }
                for (int z = 0; z < lo[2]; ++z) row[z] = -band;
                for (int z = hi[2] + 1; z < kBlendBlock; ++z) row[z] = -band;
            }
    }
    activeBytes(out.v, out.on, band);
    // The leaf mask: word w holds voxels 64w .. 64w+63, bit i voxel 64w+i.
    for (openvdb::Index w = 0; w < FloatLeaf::NodeMaskType::WORD_COUNT; ++w) {
        std::uint64_t word = 0;
        for (openvdb::Index byte = 0; byte < 8; ++byte) word |= packBits(out.on + 64 * w + 8 * byte) << (8 * byte);
        out.mask.getWord<std::uint64_t>(w) = word;
    }
}

BlockChange summarize(const std::uint8_t* diff, const std::array<int, 3>& o) {
    BlockChange c;
    std::uint64_t rows[64];
    std::memcpy(rows, diff, sizeof rows);
    std::uint64_t anyZ = 0;
    unsigned anyX = 0, anyY = 0;
    for (unsigned x = 0; x < 8; ++x)
        for (unsigned y = 0; y < 8; ++y) {
            const std::uint64_t r = rows[x * 8 + y];
            anyZ |= r;
            if (r) { anyX |= 1u << x; anyY |= 1u << y; }
        }
    if (!anyZ) return c;
    for (int i = 0; i < kBlockVoxels; ++i) c.count += diff[i];
    unsigned anyZbits = 0;
    for (unsigned z = 0; z < 8; ++z)
        if ((anyZ >> (8 * z)) & 0xff) anyZbits |= 1u << z;
    const unsigned masks[3] = {anyX, anyY, anyZbits};
    for (int a = 0; a < 3; ++a) {
        c.lo[a] = o[static_cast<std::size_t>(a)] + __builtin_ctz(masks[a]);
        c.hi[a] = o[static_cast<std::size_t>(a)] + 31 - __builtin_clz(masks[a]);
    }
    return c;
}

bool uniformClamped(const float* v, const FloatLeaf::NodeMaskType& on, float band, float& value) {
    if (!on.isOff()) return false;
    const std::uint32_t first = bits(v[0]);
    if (first != bits(band) && first != bits(-band)) return false;
    for (int i = 1; i < kBlockVoxels; ++i)
        if (bits(v[i]) != first) return false;
    value = v[0];
    return true;
}

bool uniformClamped(const FloatLeaf& leaf, float band, float& value) {
    return uniformClamped(leaf.buffer().data(), leaf.getValueMask(), band, value);
}

void storeBlock(FloatLeaf& leaf, const BlockValues& b) {
    std::memcpy(leaf.buffer().data(), b.v, sizeof b.v);
    leaf.setValueMask(b.mask);
}

}  // namespace hg::garden::blend
