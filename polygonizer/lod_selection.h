// View-dependent level of detail: for each chunk, the coarsest level whose
// voxels project to at most `pixelError` pixels from the camera (level L has
// voxels 2^L times the grid's), forced to level 0 inside the detail sphere
// and around the tool, then refined until face neighbours differ by at most
// one level (what transition cells can stitch). Refining only ever lowers a
// level, so every chunk still meets the pixel error.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "polygonizer/chunk_layout.h"

namespace hg::poly {

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
    std::optional<Sphere> detail;  // the movable detail sphere (seed 004)
    std::optional<Sphere> tool;    // around the active tool
};

// Projected size, in pixels, of a voxel of `level` at `distance` (model units).
double projectedVoxelPixels(const Camera& camera, double voxelSize, int level, double distance);

// One level per chunk, in the layout's order.
std::vector<int> selectLevels(const ChunkLayout& layout, const Camera& camera, const LodSettings& settings);

// Distance from a point to a chunk's model box (0 inside).
double distanceToChunk(const ChunkLayout& layout, std::size_t chunk, const std::array<double, 3>& p);

}  // namespace hg::poly
