// Synthetic scanned volumes for the tests (docs/volumes.md, "Scanned
// volumes"): a ball whose density falls linearly with the distance from its
// centre, written as raw u8 or u16 samples, so that its iso-surface at the
// ramp's middle value is a sphere of known radius.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace hg::test {

struct ScanBall {
    int n = 40;                  // samples along each axis
    double spacing = 0.05;       // model units between samples
    std::array<double, 3> centre{1.0, 1.0, 1.0};
    double radius = 0.6;
    double iso = 128.0;          // the sample value at the radius
    double slope = 40.0;         // sample units per spacing, rising inwards
    double top = 255.0;          // the largest sample (255 for u8, 65535 for u16)
    bool inverted = false;       // dense outside instead ("inside": "below")

    // The sample at (i, j, k) before rounding.
    double value(int i, int j, int k) const {
        const double dx = i * spacing - centre[0], dy = j * spacing - centre[1], dz = k * spacing - centre[2];
        const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
        const double v = std::clamp(iso + slope * (radius - r) / spacing, 0.0, top);
        return inverted ? top - v : v;
    }
    // Raw samples, x fastest; u16 little-endian.
    std::string bytes(bool sixteen) const {
        std::string out;
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const auto v = static_cast<std::uint32_t>(std::lround(value(i, j, k)));
                    out.push_back(static_cast<char>(v & 0xff));
                    if (sixteen) out.push_back(static_cast<char>((v >> 8) & 0xff));
                }
        return out;
    }
    void write(const std::string& path, bool sixteen) const { std::ofstream(path, std::ios::binary) << bytes(sixteen); }
};

}  // namespace hg::test
