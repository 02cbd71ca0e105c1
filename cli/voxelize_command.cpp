// `hypergarden voxelize FILE.hf --res N [--band B] [--dense] -o OUT.vdb
// [--levelset] [--stats]`: samples a body into an OpenVDB grid and writes
// it. The output is checked for writability before any work and written
// atomically, so a failure leaves no file behind.
#include <tbb/global_control.h>

#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/load_model.h"
#include "cli/progress_bar.h"
#include "voxel/dense_field.h"
#include "voxel/grid_stats.h"
#include "voxel/memory_guard.h"
#include "voxel/sampler.h"
#include "voxel/vdb_io.h"

namespace hg::garden::cli {

namespace {

void printErrors(const std::string& file, const frep::ErrorReport& e) {
    if (!e.count) return;
    std::fprintf(stderr, "%s:%d:%d: warning: %llu sample%s failed (%s); treated as outside\n", file.c_str(),
                 e.firstLoc.line, e.firstLoc.column, static_cast<unsigned long long>(e.count),
                 e.count == 1 ? "" : "s", frep::describe(e.first));
}

int fail(const std::string& file, const std::string& why) {
    std::cerr << file << ": error: " << why << "\n";
    return 1;
}

voxel::VolumeRequest makeRequest(const VoxelizeOptions& o, const frep::Model& model) {
    voxel::VolumeRequest r;
    r.resolution = o.resolution;
    r.band = o.band;
    r.source.file = o.model.file;
    r.source.body = model.body().spelling;
    r.source.parameters = o.model.parameters;
    return r;
}

int runDense(const VoxelizeOptions& o, const frep::Model& model, const voxel::VolumeRequest& request) {
    if (std::string why = voxel::checkResolutionAndBand(request.resolution, request.band); !why.empty())
        return fail(o.model.file, why);
    voxel::ModelBox box;
    if (std::string why = voxel::resolveModelBox(model, request.box, box); !why.empty())
        return fail(o.model.file, why);
    voxel::VolumeFrame frame;
    if (std::string why = voxel::makeFrame(box.box, request.resolution, request.band, frame); !why.empty())
        return fail(o.model.file, why);
    std::printf("model box: %s\n", voxel::describeModelBox(box).c_str());
    voxel::Normalization norm = voxel::estimateNormalization(model, frame);
    voxel::DenseResult dense = voxel::sampleDense(model, frame, norm.scale, frame.indexBox,
                                                  static_cast<std::uint64_t>(o.memoryLimitMiB * 1048576.0));
    if (!dense.error.empty()) return fail(o.model.file, dense.error);
    printErrors(o.model.file, dense.errors);
    std::printf("dense source cache: %d x %d x %d voxels, %s, %.3f s\n", frame.indexBox.extent(0),
                frame.indexBox.extent(1), frame.indexBox.extent(2), voxel::formatBytes(dense.bytes).c_str(),
                dense.seconds);
    voxel::Volume volume = voxel::volumeFromDense(std::move(dense.field), frame, norm.scale, request.source);
    volume.boxOrigin = box.origin;
    if (std::string why = voxel::writeVolume(volume, o.output); !why.empty()) return fail(o.model.file, why);
    std::printf("wrote %s (unclamped, every voxel active)\n", o.output.c_str());
    return 0;
}

}  // namespace

int runVoxelize(const VoxelizeOptions& o) {
    if (o.dense && o.levelset) {
        std::cerr << "error: --dense writes an unclamped source cache; --levelset needs the narrow band\n";
        return 2;
    }
    std::optional<frep::Box3> box;
    if (!boxOption(o.box, box)) return 2;
    if (!outputWritable(o.output)) return 1;
    std::unique_ptr<tbb::global_control> threads;
    if (o.threads > 0)
        threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        static_cast<size_t>(o.threads));
    auto loaded = loadModel(o.model);
    if (!loaded) return 1;
    const frep::Model& model = *loaded->model;
    voxel::VolumeRequest request = makeRequest(o, model);
    request.box = box;
    std::printf("body: %s, path: %s\n", request.source.body.c_str(), model.pathDescription().c_str());
    if (o.dense) return runDense(o, model, request);

    voxel::SampleOptions options;
    options.memoryLimit = static_cast<std::uint64_t>(o.memoryLimitMiB * 1048576.0);
    voxel::VoxelizeResult result;
    {
        ProgressBar bar("voxelize");
        options.progress = &bar;
        result = voxel::voxelize(model, request, options);
    }
    if (!result.volume) return fail(o.model.file, result.error);
    const voxel::Volume& volume = *result.volume;
    const voxel::VolumeFrame& f = volume.frame;
    const voxel::SampleStats& s = result.stats;
    printErrors(o.model.file, s.errors);
    std::printf("model box: %s\n", voxel::describeModelBox(result.modelBox).c_str());
    std::printf("grid: %d voxels along the longest side, voxel %.4g, index box %d x %d x %d, band %g voxels\n",
                f.resolution, f.voxelSize, f.indexBox.extent(0), f.indexBox.extent(1), f.indexBox.extent(2),
                static_cast<double>(f.band));
    std::printf("normalization: stored = f * %.6g (median |grad f| %.4g per unit at %zu surface samples)\n",
                volume.normalization, result.normalization.medianGradient, result.normalization.surfaceSamples);
    std::printf("sampled: %.3f s, %llu samples (%.2f%% of %llu voxels), %llu of %llu boxes culled, %zu active voxels\n",
                s.seconds, static_cast<unsigned long long>(s.samples), 100.0 * s.evaluatedFraction(),
                static_cast<unsigned long long>(s.voxels), static_cast<unsigned long long>(s.boxesCulled),
                static_cast<unsigned long long>(s.boxesTested), volume.activeVoxelCount());
    if (o.stats && model.tape() && s.leafTapeMean > 0.0)
        std::printf("stats: the tape specialized to each leaf's box ran %.0f instructions on average, %llu at most, of %zu\n",
                    s.leafTapeMean, static_cast<unsigned long long>(s.leafTapeMax), model.tape()->size());
    if (o.stats && s.pointTapeMean > 0.0)
        std::printf("stats: specialized to single voxels of those leaves (HG_PROBE_POINT_TAPES=1), %.0f on average\n",
                    s.pointTapeMean);
    if (o.stats) {
        voxel::GridStats g = voxel::measureGrid(volume);
        std::printf("stats: |grad| of the stored field at %zu surface voxels: median %.3f, 90th percentile %.3f "
                    "(target about 1 per voxel)\n",
                    g.surfaceVoxels, g.medianGradient, g.p90Gradient);
        std::printf("stats: %zu leaves, %zu inside tiles, %zu outside tiles, %s in memory (estimate was %s)\n",
                    g.leaves, g.tilesInside, g.tilesOutside, voxel::formatBytes(g.memoryBytes).c_str(),
                    voxel::formatBytes(s.estimatedBytes).c_str());
    }
    std::string why = o.levelset ? voxel::writeLevelSet(volume, o.output) : voxel::writeVolume(volume, o.output);
    if (!why.empty()) return fail(o.model.file, why);
    std::printf("wrote %s (%s)\n", o.output.c_str(),
                o.levelset ? "OpenVDB level set: negative inside, model units" : "Hypergarden grid: positive inside, voxel units");
    return 0;
}

}  // namespace hg::garden::cli
