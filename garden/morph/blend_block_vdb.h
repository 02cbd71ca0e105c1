// The block kernel the morph blend is built from, shared by blendMorph()
// and MorphBlender (internal to garden/morph; includes OpenVDB). A block is
// one OpenVDB leaf of 8^3 voxels; its values go in leaf order.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "garden/morph/morph_blend.h"
#include "voxel/volume_vdb.h"

namespace hg::garden::blend {

using voxel::FloatLeaf;
static_assert(FloatLeaf::DIM == kBlendBlock && kBlockEdge == kBlendBlock, "blocks are OpenVDB leaves");

// The one formula both paths use, so that they agree bit for bit (the build
// never contracts a*b+c into a fused multiply-add, and vector and scalar
// IEEE arithmetic round alike).
inline float blendValue(float a, float b, float c, float w0, float w1, float w2, float band) {
    float v = w0 * a + w1 * b + w2 * c;
    return std::min(std::max(v, -band), band);
}

inline std::uint32_t bits(float v) {
    std::uint32_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}

// Eight 0/1 bytes (the first in the lowest byte) to eight bits: each byte's
// bit lands in the top byte of the product at its own place, with no carry.
inline std::uint64_t packBits(const std::uint8_t* bytes) {
    std::uint64_t x;
    std::memcpy(&x, bytes, sizeof x);
    return (x * 0x0102040810204080ULL) >> 56;
}

// The inverse: bit i of `b` to byte i (0 or 1). Byte i of the repeated
// word keeps only bit i; adding 0x7f carries any set bit into the byte's top
// bit, never into the next byte.
inline void unpackBits(std::uint64_t b, std::uint8_t* bytes) {
    const std::uint64_t x = ((((b * 0x0101010101010101ULL) & 0x8040201008040201ULL) + 0x7f7f7f7f7f7f7f7fULL) >> 7) &
                            0x0101010101010101ULL;
    std::memcpy(bytes, &x, sizeof x);
}
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "packBits and unpackBits read bytes little-endian");

// The voxels an item blends: start + stride * (x, y, z) for x < count[0], ...
// numbered x fastest.
struct Lattice {
    int start[3] = {0, 0, 0};
    int count[3] = {0, 0, 0};
    int stride = 1;
    std::uint32_t size() const {
        return static_cast<std::uint32_t>(count[0]) * static_cast<std::uint32_t>(count[1]) *
               static_cast<std::uint32_t>(count[2]);
    }
};

// The voxels of the block at `origin` that `pass` blends, clipped to the box.
Lattice itemLattice(const std::array<int, 3>& origin, BlendPass pass, const voxel::IndexBox& indexBox);

// Calls visit(i, j, k, leafOffset) for samples [s0, s1) of the lattice of
// the block at `o`.
template <class Visit>
void forSamples(const Lattice& l, const std::array<int, 3>& o, std::uint32_t s0, std::uint32_t s1, Visit&& visit) {
    const std::uint32_t nx = static_cast<std::uint32_t>(l.count[0]), ny = static_cast<std::uint32_t>(l.count[1]);
    for (std::uint32_t r = s0; r < s1; ++r) {
        const int i = l.start[0] + l.stride * static_cast<int>(r % nx);
        const int j = l.start[1] + l.stride * static_cast<int>((r / nx) % ny);
        const int k = l.start[2] + l.stride * static_cast<int>(r / (nx * ny));
        visit(i, j, k, blockOffset(i - o[0], j - o[1], k - o[2]));
    }
}

struct BlendInputs {
    const BlockedField* f[3];
    float w[3];
    float band;
    voxel::IndexBox box;
};

BlendInputs inputs(const MorphSources& s, const MorphWeights& weights);

// One block's stored values in leaf order, which of them are active
// (inside the band) as bytes, and the same as a leaf's mask.
struct BlockValues {
    float v[kBlockVoxels];
    std::uint8_t on[kBlockVoxels];
    FloatLeaf::NodeMaskType mask;
};

// The blended values of samples [s0, s1) of `item`, in order, into `out`
// (s1 - s0 floats). The coarse lattice reads the sources' compact copies
// (the same floats as their blocks).
void sampleValues(const BlendItem& item, std::uint32_t s0, std::uint32_t s1, const BlendInputs& in, float* out);

// The whole block at `o`: every voxel of it inside the index box blended,
// the rest the background (outside, inactive).
void blendBlock(const std::array<int, 3>& o, const BlendInputs& in, BlockValues& out);

// Per voxel: 1 where the value's bits or the active state differ.
void diffBytes(const std::uint32_t* __restrict oldBits, const std::uint32_t* __restrict newBits,
               const std::uint8_t* __restrict oldOn, const std::uint8_t* __restrict newOn, std::uint8_t* __restrict diff);

// Which voxels of a block differ, summed up: how many, and their bounding box.
struct BlockChange {
    std::uint64_t count = 0;
    int lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};
};

BlockChange summarize(const std::uint8_t* diff, const std::array<int, 3>& o);

// A block whose 512 stored values all clamp alike (and so are inactive)
// becomes a tile of that value: the narrow band's rule, as in the sampler.
bool uniformClamped(const float* v, const FloatLeaf::NodeMaskType& on, float band, float& value);
bool uniformClamped(const FloatLeaf& leaf, float band, float& value);

void storeBlock(FloatLeaf& leaf, const BlockValues& b);

}  // namespace hg::garden::blend
