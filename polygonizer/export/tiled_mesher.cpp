#include "polygonizer/export/tiled_mesher.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <unordered_map>
#include <vector>

#include "polygonizer/export/export_mesher.h"
#include "voxel/memory_guard.h"
#include "voxel/normalization.h"
#include "voxel/sampler.h"

namespace hg::poly {

namespace {

using Clock = std::chrono::steady_clock;

constexpr float kBand = 3.0f;  // the sampler's default: what voxelize() would store
constexpr int kTileSizes[] = {256, 128, 64, 32};
constexpr int kCoarseResolution = 128;
// A leaf of the tile's tree (values, mask, node) and the walk's samples of
// it (values, evaluated bits), which resampleRegion holds at the same time.
constexpr std::uint64_t kLeafBytes = 4400;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A tile's region: its cells, one voxel below (gradients) and above them
// the upper neighbours' blocks and one voxel more. The cells alone need
// only two voxels above; with fewer than the whole neighbour blocks, the
// background beyond the region meets the true values inside them, and
// wherever the solid is inside there the mesher would place a face of
// vertices that no triangle uses.
constexpr int kReach = 1 + 8 + 1;

// t + 1 + kReach voxels, which may straddle one more leaf than they fill.
std::uint64_t tileBytes(int t) {
    const auto leaves = static_cast<std::uint64_t>((t + 1 + kReach + 7) / 8 + 1);
    return leaves * leaves * leaves * kLeafBytes;
}

// The cells the untiled mesher visits (its candidate blocks are the leaves
// inside the index box and the blocks just below them), and where tiles
// start: on a multiple of the sampler's top box (128) where the tile is
// that large or larger, so that tile faces fall on top box faces and no top
// box is walked through by more than one tile, except for the one or two
// voxels of overlap.
struct CellRange {
    int lo[3];
    int hi[3];
    int origin[3];
};

CellRange cellRange(const voxel::VolumeFrame& frame, int tile) {
    CellRange r{};
    for (int a = 0; a < 3; ++a) {
        r.lo[a] = voxel::floorMultiple(frame.indexBox.lo[a], 8) - 8;
        r.hi[a] = voxel::floorMultiple(frame.indexBox.hi[a], 8) + 7;
        r.origin[a] = voxel::floorMultiple(r.lo[a], std::min(tile, 128));
    }
    return r;
}

// The vertex of this edge is shared with another tile when the edge lies
// on a tile face: a plane across one of the other two axes at a multiple
// of the tile size from the tiles' origin.
bool onTileFace(std::uint64_t key, const CellRange& range, int tile) {
    const int axis = gridEdgeAxis(key);
    for (int b = 0; b < 3; ++b)
        if (b != axis && (gridEdgeIndex(key, b) - range.origin[b]) % tile == 0) return true;
    return false;
}

// Adds a tile's triangles to `out`, with the vertices they use: a vertex on
// a tile face is looked up in `shared` (every tile computes it from the
// same values, so the first one made stands for all); the rest are the
// tile's alone.
void weldTile(const Mesh& tile, const std::vector<std::uint64_t>& edges, const CellRange& range, int tileSize,
              std::unordered_map<std::uint64_t, std::uint32_t>& shared, Mesh& out, std::size_t& sharedVertices) {
    std::vector<std::uint32_t> remap(tile.vertexCount(), kNone);
    auto addVertex = [&](std::uint32_t v) {
        const auto n = static_cast<std::uint32_t>(out.vertexCount());
        for (std::size_t a = 0; a < 3; ++a) {
            out.positions.push_back(tile.positions[3 * std::size_t{v} + a]);
            out.normals.push_back(tile.normals[3 * std::size_t{v} + a]);
        }
        return n;
    };
    for (const std::uint32_t v : tile.indices) {
        std::uint32_t& m = remap[v];
        if (m == kNone) {
            const std::uint64_t key = edges[v];
            if (onTileFace(key, range, tileSize)) {
                const auto [it, inserted] = shared.try_emplace(key, kNone);
                if (inserted) it->second = addVertex(v);
                else ++sharedVertices;
                m = it->second;
            } else {
                m = addVertex(v);
            }
        }
        out.indices.push_back(m);
    }
}

}  // namespace

std::string planTiledMesh(const frep::Model& model, const frep::Box3& box, const TiledMeshOptions& options,
                          TiledMeshPlan& plan) {
    plan = TiledMeshPlan{};
    if (std::string why = voxel::checkResolutionAndBand(options.resolution, kBand); !why.empty()) return why;
    if (options.tileSize != 0 && (options.tileSize < 8 || options.tileSize % 8 != 0))
        return "the tile size must be a positive multiple of 8 (got " + std::to_string(options.tileSize) + ")";
    if (std::string why = voxel::makeFrame(box, options.resolution, kBand, plan.frame); !why.empty()) return why;
    plan.limit = voxel::memoryLimit(options.memoryLimit);

    // The normalization first: the tiles need it, and the coarse pass below
    // takes it too instead of estimating its own (an estimate evaluates
    // the whole model on a lattice and its gradients at the surface, which
    // for an edited sculpture costs as much as the coarse pass itself). A
    // positive scale leaves every sign, so the coarse mesh, as it is.
    plan.normalization = voxel::estimateNormalization(model, plan.frame).scale;

    // How many triangles: a coarse meshing's count, scaled by area (the
    // square of the resolution), with a margin for detail the coarse grid
    // misses. The count needs only the signs, so the coarse grid's band is
    // the narrowest: fewer voxels near the surface to evaluate, and
    // smaller boxes' tapes for them.
    const int coarseResolution = std::min(options.resolution, kCoarseResolution);
    voxel::VolumeFrame coarseFrame;
    if (std::string why = voxel::makeFrame(box, coarseResolution, voxel::kMinBand, coarseFrame); !why.empty())
        return why;
    const double coarseScale = plan.normalization * coarseFrame.voxelSize / plan.frame.voxelSize;
    io::ProgressRange coarseProgress(options.progress, 0.0, kPlanShare);
    const voxel::Volume coarse =
        voxel::sampleRegion(model, coarseFrame, coarseScale, coarseFrame.indexBox, nullptr, &coarseProgress);
    if (coarseProgress.cancelled()) return io::kCancelled;
    const double scale = static_cast<double>(options.resolution) / coarseResolution;
    const double margin = scale > 1.0 ? 1.1 : 1.0;
    plan.expectedTriangles =
        static_cast<std::uint64_t>(static_cast<double>(meshVolume(coarse).triangleCount()) * scale * scale * margin);
    plan.meshBytes = plan.expectedTriangles * options.bytesPerTriangle;

    std::vector<int> sizes(std::begin(kTileSizes), std::end(kTileSizes));
    if (options.tileSize) sizes = {options.tileSize};
    for (int t : sizes) {
        plan.tileSize = t;
        plan.tileBytes = tileBytes(t);
        plan.estimatedBytes = plan.tileBytes + plan.meshBytes;
        if (plan.estimatedBytes <= plan.limit) break;
    }
    if (std::string why = voxel::refuseIfTooBig("the mesh", options.resolution, plan.estimatedBytes, plan.limit, 2.0);
        !why.empty())
        return why;

    const CellRange range = cellRange(plan.frame, plan.tileSize);
    for (int a = 0; a < 3; ++a) plan.tileCounts[a] = (range.hi[a] - range.origin[a] + plan.tileSize) / plan.tileSize;
    return "";
}

TiledMeshResult meshModelTiled(const frep::Model& model, const frep::Box3& box, const TiledMeshOptions& options) {
    const auto start = Clock::now();
    TiledMeshResult r;
    r.error = planTiledMesh(model, box, options, r.plan);
    r.stats.planSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    io::ProgressRange progress(options.progress, kPlanShare, 1.0);  // the tiles
    if (progress.cancelled()) {
        r.cancelled = true;
        r.error = io::kCancelled;
    }
    if (!r.error.empty()) return r;
    const TiledMeshPlan& plan = r.plan;
    const int t = plan.tileSize;
    const CellRange range = cellRange(plan.frame, t);

    Mesh& out = r.mesh;
    // Reserved once: growing by doubling would briefly need twice the mesh.
    out.indices.reserve(3 * plan.expectedTriangles);
    out.positions.reserve(3 * plan.expectedTriangles / 2 + 3);
    out.normals.reserve(3 * plan.expectedTriangles / 2 + 3);
    std::unordered_map<std::uint64_t, std::uint32_t> shared;
    std::vector<std::uint64_t> edges;
    const std::size_t total = plan.tiles();
    std::size_t done = 0;
    double leafTapeSum = 0.0;
    std::uint64_t leafTapes = 0;
    for (int tz = 0; tz < plan.tileCounts[2]; ++tz)
        for (int ty = 0; ty < plan.tileCounts[1]; ++ty)
            for (int tx = 0; tx < plan.tileCounts[0]; ++tx) {
                const int index[3] = {tx, ty, tz};
                CellWindow window;
                voxel::IndexBox region;
                for (int a = 0; a < 3; ++a) {
                    window.cells.lo[a] = std::max(range.origin[a] + index[a] * t, range.lo[a]);
                    window.cells.hi[a] = std::min(range.origin[a] + (index[a] + 1) * t - 1, range.hi[a]);
                    region.lo[a] = window.cells.lo[a] - 1;
                    region.hi[a] = window.cells.hi[a] + kReach;
                }
                window.vertexEdges = &edges;
                auto t0 = Clock::now();
                voxel::SampleStats s;
                // Sampling is most of a tile's share; meshing and welding it, the rest.
                const double share = 1.0 / static_cast<double>(total), at = static_cast<double>(done) * share;
                io::ProgressRange tileProgress(&progress, at, at + 0.8 * share);
                const voxel::Volume volume =
                    voxel::sampleRegion(model, plan.frame, plan.normalization, region, &s, &tileProgress);
                if (tileProgress.cancelled()) {
                    r.cancelled = true;
                    r.error = io::kCancelled;
                    r.mesh = Mesh{};
                    return r;
                }
                r.stats.samples += s.samples;
                leafTapeSum += s.leafTapeMean * static_cast<double>(s.leafTapes);
                leafTapes += s.leafTapes;
                r.stats.leafTapeMax = std::max(r.stats.leafTapeMax, s.leafTapeMax);
                r.stats.peakTileBytes = std::max<std::uint64_t>(r.stats.peakTileBytes, volume.memoryBytes());
                auto t1 = Clock::now();
                const Mesh tile = meshVolume(volume, window);
                auto t2 = Clock::now();
                ++r.stats.tiles;
                if (!tile.empty()) {
                    ++r.stats.tilesWithSurface;
                    weldTile(tile, edges, range, t, shared, out, r.stats.sharedVertices);
                }
                r.stats.sampleSeconds += std::chrono::duration<double>(t1 - t0).count();
                r.stats.meshSeconds += std::chrono::duration<double>(t2 - t1).count();
                r.stats.weldSeconds += std::chrono::duration<double>(Clock::now() - t2).count();
                if (out.vertexCount() >= kNone) {
                    r.error = "the mesh has more vertices than 32-bit indices can number; use a lower resolution";
                    r.mesh = Mesh{};
                    return r;
                }
                progress.interrupted(static_cast<double>(++done) / static_cast<double>(total));
            }
    if (out.empty()) r.error = "the model has no surface inside the box";
    r.stats.leafTapeMean = leafTapes ? leafTapeSum / static_cast<double>(leafTapes) : 0.0;
    r.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return r;
}

}  // namespace hg::poly
