// The export mesher at any resolution in bounded memory: a model's cells
// are cut into cubic tiles; each tile's voxels (its cells' corners and one
// voxel more on every side, for the gradients) are sampled on their own,
// meshed by the export mesher restricted to the tile's cells
// (export_mesher.h's CellWindow), and welded onto the mesh so far by grid
// edge. Only one tile's grid is alive at a time, so memory is the mesh plus
// one tile, whatever the resolution.
//
// Every voxel is sampled exactly as a full sampling of the same frame
// samples it (voxel/box_walker.h) and every vertex is placed from the same
// values by the same arithmetic, so the welded mesh is the untiled export
// mesher's mesh over voxelize() at that resolution, triangle for triangle;
// only the order of vertices and triangles differs. See docs/mesh-export.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "frep/eval/model.h"
#include "frep/kernels/box.h"
#include "io/progress.h"
#include "polygonizer/mesh.h"
#include "voxel/volume_frame.h"

namespace hg::poly {

struct TiledMeshOptions {
    int resolution = 256;           // voxels along the model box's longest side
    int tileSize = 0;               // cells per tile side, a multiple of 8; 0: the largest of 256, 128, 64, 32 that fits
    std::uint64_t memoryLimit = 0;  // bytes; 0: voxel::memoryLimit(0), 80% of what is available
    std::uint64_t bytesPerTriangle = 96;  // the guard's count per expected triangle: kMeshBytesPerTriangle or kSimplifyBytesPerTriangle
    // Told the fraction done (the plan's coarse sampling the first
    // kPlanShare, then tile by tile, from the sampler's workers too) and
    // asked for a cancel inside and between tiles (io/progress.h); may be null.
    io::Progress* progress = nullptr;
};

// What the memory guard decided before any tile is sampled.
struct TiledMeshPlan {
    voxel::VolumeFrame frame;
    double normalization = 1.0;          // stored value = f * this (voxel/normalization.h)
    int tileSize = 0;
    int tileCounts[3] = {0, 0, 0};       // tiles along x, y, z
    std::uint64_t tileBytes = 0;         // bound on one tile's grid and samples (every leaf evaluated)
    std::uint64_t expectedTriangles = 0; // from a coarse meshing, scaled by area
    std::uint64_t meshBytes = 0;         // that mesh with its validation or simplification
    std::uint64_t estimatedBytes = 0;    // tileBytes + meshBytes
    std::uint64_t limit = 0;             // bytes the export may use

    std::size_t tiles() const {
        return static_cast<std::size_t>(tileCounts[0]) * static_cast<std::size_t>(tileCounts[1]) *
               static_cast<std::size_t>(tileCounts[2]);
    }
};

// Bytes per expected triangle that the guard counts: the finished mesh
// (positions, normals, indices, about 24 bytes) and validation's edge census
// or a writer's buffers; with simplification, meshoptimizer's working set
// and the passes' index buffers too. Measured peaks (docs/benchmarks.md):
// about 45 and 160 bytes a triangle, tile and process included.
constexpr std::uint64_t kMeshBytesPerTriangle = 96;
constexpr std::uint64_t kSimplifyBytesPerTriangle = 192;

// The memory guard: checks the resolution, builds the frame over `box`,
// estimates the mesh from a coarse meshing (at most 128 voxels along the
// longest side) and picks the tile size. "" when the export fits in the
// limit; otherwise why not, with the largest resolution that would fit.
std::string planTiledMesh(const frep::Model& model, const frep::Box3& box, const TiledMeshOptions& options,
                          TiledMeshPlan& plan);

struct TiledMeshStats {
    std::size_t tiles = 0;            // tiles sampled
    std::size_t tilesWithSurface = 0;
    std::uint64_t peakTileBytes = 0;  // the largest tile grid, as OpenVDB counts it
    std::uint64_t samples = 0;        // points evaluated
    std::size_t sharedVertices = 0;   // vertices welded to an earlier tile's
    // The tape each evaluated leaf ran (voxel::SampleStats), over all tiles.
    double leafTapeMean = 0.0;
    std::uint64_t leafTapeMax = 0;
    double seconds = 0.0;             // all of it, planning included
    double planSeconds = 0.0;         // of which the plan: coarse sampling and normalization
    double sampleSeconds = 0.0;       // of which sampling tiles
    double meshSeconds = 0.0;         // meshing them
    double weldSeconds = 0.0;         // welding them on
};

// The share of the progress the plan takes (its coarse sampling).
constexpr double kPlanShare = 0.05;

struct TiledMeshResult {
    Mesh mesh;           // positions in model units, outward normals, welded
    std::string error;   // "" on success
    bool cancelled = false;  // options.progress was cancelled: no mesh (error is io::kCancelled)
    TiledMeshPlan plan;
    TiledMeshStats stats;
};

// Plans (refusing what does not fit) and meshes. An empty mesh with an
// error when the model has no surface in the box or the work was cancelled.
TiledMeshResult meshModelTiled(const frep::Model& model, const frep::Box3& box, const TiledMeshOptions& options);

}  // namespace hg::poly
