// The synthetic "scanned" head that content/volumes/phantom.raw holds
// (docs/volumes.md, "Scanned volumes"): 64^3 u8 samples 0.02 model units
// apart, like a CT of a skull: air near 0, soft tissue about 60, bone about
// 200 (a cranial shell with eye sockets, a jaw arch, five vertebrae down
// to the ground inside a neck), blurred over a sample and a half at every edge
// (the partial-volume effect) and with a few units of noise. Its bone
// surface is at 128. Written by hg_scan_phantom and checked byte for byte
// by a test, so the committed file is always what this makes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hg::tools {

constexpr int kPhantomSize = 64;
constexpr double kPhantomSpacing = 0.02;

namespace phantom {

struct P {
    double x, y, z;
};

inline double length(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); }

// About the distance to an ellipsoid's surface, negative inside.
inline double ellipsoid(const P& p, const P& c, const P& r) {
    const double k = length((p.x - c.x) / r.x, (p.y - c.y) / r.y, (p.z - c.z) / r.z);
    return (k - 1.0) * std::min({r.x, r.y, r.z});
}

inline double sphere(const P& p, const P& c, double r) { return length(p.x - c.x, p.y - c.y, p.z - c.z) - r; }

// 0 outside, 1 inside, a ramp across 1.5 samples: a voxel's share of the solid.
inline double share(double distance) {
    return std::clamp(0.5 - distance / (1.5 * kPhantomSpacing), 0.0, 1.0);
}

// Noise in [-1, 1) from the sample's index alone (a fixed integer hash, the
// same on every machine).
inline double noise(int i, int j, int k) {
    std::uint32_t h = static_cast<std::uint32_t>(i) * 73856093u ^ static_cast<std::uint32_t>(j) * 19349663u ^
                      static_cast<std::uint32_t>(k) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return static_cast<double>(h % 2048u) / 1024.0 - 1.0;
}

// Distance to the bone, negative inside.
inline double bone(const P& p) {
    const P head{0.64, 0.80, 0.62};
    // The cranium: a shell 0.06 thick around an ellipsoid.
    double d = std::fabs(ellipsoid(p, head, {0.36, 0.40, 0.44})) - 0.03;
    // Eye sockets cut it.
    for (double side : {-1.0, 1.0}) d = std::max(d, -sphere(p, {0.64 + 0.15 * side, 0.74, 1.02}, 0.1));
    // The jaw: the front half of a ring of tube under the face, meeting the shell.
    const double rx = p.x - 0.64, rz = p.z - 0.66;
    const double ring = length(std::hypot(rx, rz) - 0.26, p.y - 0.50, 0.0) - 0.045;
    d = std::min(d, std::max(ring, 0.62 - p.z));
    // Five vertebrae from the ground up to the skull's base, each touching the next.
    for (int v = 0; v < 5; ++v) d = std::min(d, ellipsoid(p, {0.64, 0.06 + 0.08 * v, 0.56}, {0.08, 0.05, 0.07}));
    return d;
}

// Distance to the soft tissue's surface (head and neck), negative inside.
inline double tissue(const P& p) {
    const double head = ellipsoid(p, {0.64, 0.80, 0.62}, {0.42, 0.46, 0.50});
    const double neck = std::max(std::hypot(p.x - 0.64, p.z - 0.58) - 0.17, p.y - 0.7);
    return std::min(head, neck);
}

}  // namespace phantom

// The samples, x fastest, then y (up), then z (towards the face).
inline std::vector<std::uint8_t> makePhantom() {
    using namespace phantom;
    std::vector<std::uint8_t> out;
    out.reserve(static_cast<std::size_t>(kPhantomSize) * kPhantomSize * kPhantomSize);
    for (int k = 0; k < kPhantomSize; ++k)
        for (int j = 0; j < kPhantomSize; ++j)
            for (int i = 0; i < kPhantomSize; ++i) {
                const P p{i * kPhantomSpacing, j * kPhantomSpacing, k * kPhantomSpacing};
                const double v = 60.0 * share(tissue(p)) + 140.0 * share(bone(p)) + 6.0 * noise(i, j, k) + 4.0;
                out.push_back(static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0))));
            }
    return out;
}

}  // namespace hg::tools
