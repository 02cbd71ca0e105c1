// libFuzzer target for the export mesher (issue 20, every mesh printable):
// any grid of values is meshed closed, 2-manifold (every edge used by
// exactly two triangles, once each way), outward-facing and free of
// degenerate triangles, as validateMesh checks; there is a mesh exactly when
// some voxel is inside.
//
// Input: nx, ny, nz (cells, 1 + byte % 24 each), flags, then one byte a
// voxel for voxels 0..n on each axis, k fastest, then j, then i, read again
// from the start where the input runs out. Flags bit 0: bytes are signs
// (byte % 3: out, exactly zero, in) instead of values ((byte - 128) / 16, so
// 128 is exactly zero); bit 1: the margin around them, out to the index
// box's faces, is read the same way (solids cut by the box, capped there),
// else it is outside.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "polygonizer/export/export_mesher.h"
#include "polygonizer/export/mesh_validation.h"
#include "tests/polygonizer/dense_grid.h"

using namespace hg;

namespace {

constexpr std::size_t kHeader = 4;

struct Input {
    const std::uint8_t* data;
    std::size_t size;
    std::array<int, 3> cells;
    bool signs, margin;

    float value(std::size_t n) const {
        const std::uint8_t b = data[kHeader + n];
        if (signs) return static_cast<float>(b % 3) - 1.0f;
        return static_cast<float>(static_cast<int>(b) - 128) / 16.0f;
    }
    float at(int i, int j, int k) const {
        const std::size_t values = size - kHeader;
        const bool inner = i >= 0 && j >= 0 && k >= 0 && i <= cells[0] && j <= cells[1] && k <= cells[2];
        if (values == 0 || (!inner && !margin)) return -1.0f;
        // The inner voxels in order, then the margin's in its own; each
        // reads the input again from its start where it runs out, so a short
        // input still fills the grid with a pattern.
        const auto w = [](int v) { return static_cast<std::size_t>(v + 8); };  // margins reach 4 below 0
        const std::size_t n = inner ? (static_cast<std::size_t>(i) * static_cast<std::size_t>(cells[1] + 1) +
                                       static_cast<std::size_t>(j)) * static_cast<std::size_t>(cells[2] + 1) +
                                          static_cast<std::size_t>(k)
                                    : (w(i) * 64 + w(j)) * 64 + w(k);
        return value(n % values);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < kHeader) return 0;
    Input in{data, size, {1 + data[0] % 24, 1 + data[1] % 24, 1 + data[2] % 24}, (data[3] & 1) != 0, (data[3] & 2) != 0};
    const voxel::Volume volume = poly::test::denseVolume(in.cells, [&in](int i, int j, int k) { return in.at(i, j, k); });

    bool anyInside = false;
    const voxel::IndexBox& b = volume.frame.indexBox;
    for (int i = b.lo[0]; i <= b.hi[0] && !anyInside; ++i)
        for (int j = b.lo[1]; j <= b.hi[1] && !anyInside; ++j)
            for (int k = b.lo[2]; k <= b.hi[2] && !anyInside; ++k) anyInside = volume.value(i, j, k) > 0.0f;

    const poly::Mesh mesh = poly::meshVolume(volume);
    if (mesh.empty() == anyInside) std::abort();  // a surface lost, or one made from nothing
    if (mesh.normals.size() != mesh.positions.size()) std::abort();
    if (mesh.empty()) return 0;
    const poly::MeshReport r = poly::validateMesh(mesh);
    if (!r.ok()) std::abort();  // open, non-manifold, flipped, inside out or degenerate
    return 0;
}
