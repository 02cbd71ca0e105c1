// Estimates what a sampling request needs before any of it is allocated,
// and refuses one that would not fit with a message saying what would.
#pragma once

#include <cstdint>
#include <string>

namespace hg::voxel {

// MemAvailable from /proc/meminfo (0 when unknown).
std::uint64_t availableMemoryBytes();

// The limit a request must fit in: `requested` when non-zero, otherwise
// 80% of the available memory (or 4 GiB when that is unknown).
std::uint64_t memoryLimit(std::uint64_t requested);

// "1.5 GiB", "320 MiB", ...
std::string formatBytes(std::uint64_t bytes);

// "" when `needed` fits in `limit`; otherwise a message naming `what`, the
// sizes, and the largest resolution that would fit, given that memory grows
// as resolution^growth (3 for a dense box, about 2 for a narrow band).
std::string refuseIfTooBig(const std::string& what, int resolution, std::uint64_t needed, std::uint64_t limit,
                           double growth);

}  // namespace hg::voxel
