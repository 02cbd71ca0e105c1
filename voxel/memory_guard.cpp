#include "voxel/memory_guard.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace hg::voxel {

std::uint64_t availableMemoryBytes() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    std::uint64_t value = 0;
    std::string unit;
    while (in >> key >> value >> unit)
        if (key == "MemAvailable:") return value * 1024;
    return 0;
}

std::uint64_t memoryLimit(std::uint64_t requested) {
    if (requested) return requested;
    std::uint64_t avail = availableMemoryBytes();
    if (!avail) return std::uint64_t{4} << 30;
    return avail / 10 * 8;
}

std::string formatBytes(std::uint64_t bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    double v = static_cast<double>(bytes);
    int u = 0;
    while (v >= 1024.0 && u < 4) {
        v /= 1024.0;
        ++u;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", v, units[u]);
    return buf;
}

std::string refuseIfTooBig(const std::string& what, int resolution, std::uint64_t needed, std::uint64_t limit,
                           double growth) {
    if (needed <= limit) return "";
    double ratio = static_cast<double>(limit) / static_cast<double>(needed);
    int fits = static_cast<int>(std::floor(resolution * std::pow(ratio, 1.0 / growth) * 0.95));
    std::ostringstream m;
    m << what << " at resolution " << resolution << " needs about " << formatBytes(needed) << " but only "
      << formatBytes(limit) << " may be used";
    if (fits >= 4) m << "; resolution " << fits << " or less would fit";
    return m.str();
}

}  // namespace hg::voxel
