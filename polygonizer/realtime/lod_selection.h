// View-dependent level of detail: for each chunk, the coarsest level whose
// voxels project to at most `pixelError` pixels from the camera (level L has
// voxels 2^L times the grid's), forced to level 0 inside the detail sphere
// and around the tool, then refined until face neighbours differ by at most
// one level (what transition cells can stitch). Refining only ever lowers a
// level, so every chunk still meets the pixel error.
//
// Hierarchical (docs/design.md §5, "Level of detail for many sculptures"):
// the whole layout is tested first. The level only grows with distance, so
// when the nearest and the farthest points of the layout's bound give the
// same level and no detail or tool sphere reaches it, every chunk takes that
// level, neighbours are equal (nothing to stitch), and the per-chunk pass
// would give exactly the same levels: it is skipped. A garden's far
// sculptures cost one box test each; only those that straddle a level's
// distance, or hold a sphere, visit their chunks.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "polygonizer/realtime/chunk_layout.h"

namespace hg::poly {

class ChunkErrors;

struct Camera {
    std::array<double, 3> position{};  // model frame
    double fovY = 1.0;                 // vertical field of view, radians
    int viewportHeight = 1080;         // pixels
};

struct Sphere {
    std::array<double, 3> center{};
    double radius = 0.0;
};

struct LodSettings {
    double pixelError = 1.0;       // the largest projected voxel, pixels
    int maxLevel = 3;              // 32^3 chunks: 32, 16, 8, 4 cells a side
    // With measured errors (chunk_errors.h): a coarser level is also taken
    // where its surface strays from level 0's by at most `errorPixels` on
    // screen and its voxels project to at most `coarsePixels` (so shading,
    // which follows the level's samples, keeps its detail within a few pixels).
    double errorPixels = 0.5;
    double coarsePixels = 4.0;
    std::optional<Sphere> detail;  // the movable detail sphere (seed 004)
    std::optional<Sphere> tool;    // around the active tool
};

// Projected size, in pixels, of a voxel of `level` at `distance` (model units).
double projectedVoxelPixels(const Camera& camera, double voxelSize, int level, double distance);

// The level of a voxel of `voxelSize` seen from `distance`: the coarsest
// that meets the pixel error, at most settings.maxLevel.
int levelAtDistance(const Camera& camera, double voxelSize, double distance, const LodSettings& settings);
// Pixels a model unit spans at `distance` (one tangent: the per-chunk pass
// asks this once a chunk).
double pixelsPerUnit(const Camera& camera, double distance);
// The same, where level L's surface is known to stray by at most
// errorOf(L) level-0 voxels (non-decreasing in L): also the coarsest level
// whose error projects within settings.errorPixels and whose voxels within
// settings.coarsePixels. Never finer than the level above.
template <class ErrorOf>
int levelAtDistance(const Camera& camera, double voxelSize, double distance, const LodSettings& settings,
                    ErrorOf errorOf) {
    const int maxLevel = settings.maxLevel < 0 ? 0 : settings.maxLevel;
    const double voxelPixels = voxelSize * pixelsPerUnit(camera, distance);  // level 0's
    int l = 0;
    while (l < maxLevel) {
        const double voxel = voxelPixels * static_cast<double>(2 << l);  // level l + 1's
        const bool small = voxel <= settings.pixelError;
        const bool close =
            voxel <= settings.coarsePixels && voxelPixels * static_cast<double>(errorOf(l + 1)) <= settings.errorPixels;
        if (!small && !close) break;
        ++l;
    }
    return l;
}

// The one level every chunk of the layout takes, when the layout's bound
// shows that they all take the same (see above); none when they may differ.
// With `errors` (of this layout), levels by measured error as above.
std::optional<int> uniformLevel(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings,
                                const ChunkErrors* errors = nullptr);

// One level per chunk, in the layout's order: uniformLevel's when it has
// one, else each chunk's (selectLevelsPerChunk). The two always agree.
std::vector<int> selectLevels(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings,
                              const ChunkErrors* errors = nullptr);
// Every chunk tested (the flat selection the hierarchical one must equal).
std::vector<int> selectLevelsPerChunk(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings,
                                      const ChunkErrors* errors = nullptr);

// Distance from a point to a chunk's model box (0 inside).
double distanceToChunk(const ChunkLayout& layout, std::size_t chunk, const std::array<double, 3>& p);

}  // namespace hg::poly
