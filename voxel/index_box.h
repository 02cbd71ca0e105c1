// An axis-aligned box of voxel indices, both corners included. The voxel
// module's own box type, so that headers seen by the whole program need not
// include OpenVDB (whose CoordBBox is the same idea).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace hg::voxel {

struct IndexBox {
    int lo[3] = {0, 0, 0};
    int hi[3] = {-1, -1, -1};  // empty by default

    static IndexBox fromCorners(int x0, int y0, int z0, int x1, int y1, int z1) {
        IndexBox b;
        b.lo[0] = x0; b.lo[1] = y0; b.lo[2] = z0;
        b.hi[0] = x1; b.hi[1] = y1; b.hi[2] = z1;
        return b;
    }
    bool empty() const { return hi[0] < lo[0] || hi[1] < lo[1] || hi[2] < lo[2]; }
    int extent(int axis) const { return hi[axis] - lo[axis] + 1; }
    std::uint64_t volume() const {
        if (empty()) return 0;
        return static_cast<std::uint64_t>(extent(0)) * static_cast<std::uint64_t>(extent(1)) *
               static_cast<std::uint64_t>(extent(2));
    }
    bool contains(int x, int y, int z) const {
        return x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1] && z >= lo[2] && z <= hi[2];
    }
    bool contains(const IndexBox& o) const {
        return o.empty() || (contains(o.lo[0], o.lo[1], o.lo[2]) && contains(o.hi[0], o.hi[1], o.hi[2]));
    }
};

inline IndexBox intersect(const IndexBox& a, const IndexBox& b) {
    IndexBox r;
    for (int i = 0; i < 3; ++i) {
        r.lo[i] = std::max(a.lo[i], b.lo[i]);
        r.hi[i] = std::min(a.hi[i], b.hi[i]);
    }
    return r;
}

inline bool operator==(const IndexBox& a, const IndexBox& b) {
    return std::equal(a.lo, a.lo + 3, b.lo) && std::equal(a.hi, a.hi + 3, b.hi);
}

// The multiple of m (> 0) at or below v, and at or above it (negative v too).
inline int floorMultiple(int v, int m) { return v >= 0 ? v / m * m : -((-v + m - 1) / m) * m; }
inline int ceilMultiple(int v, int m) { return -floorMultiple(-v, m); }

// Origins of the boxes of edge `size`, aligned to multiples of it, that
// cover `box`, in z, y, x order (x fastest).
inline std::vector<std::array<int, 3>> alignedBoxes(const IndexBox& box, int size) {
    std::vector<std::array<int, 3>> out;
    if (box.empty()) return out;
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = floorMultiple(box.lo[a], size);
        hi[a] = floorMultiple(box.hi[a], size);
    }
    for (int z = lo[2]; z <= hi[2]; z += size)
        for (int y = lo[1]; y <= hi[1]; y += size)
            for (int x = lo[0]; x <= hi[0]; x += size) out.push_back({x, y, z});
    return out;
}

}  // namespace hg::voxel
