// `hypergarden mesh FILE.hf|FILE.vdb --res N -o OUT.stl [--ascii]
// [--mm-per-unit S]`: the export mesher over a sculpture's volume (sampled
// from a HyperFun file, or read from one of our .vdb grids), validated and
// written as STL for printing.
#include <tbb/parallel_invoke.h>

#include <cstdio>
#include <iostream>

#include "cli/commands.h"
#include "cli/load_model.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"
#include "voxel/sampler.h"
#include "voxel/vdb_io.h"

namespace hg::garden::cli {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

int runMesh(const MeshOptions& o) {
    if (!(o.mmPerUnit > 0.0)) {
        std::cerr << "error: --mm-per-unit must be positive\n";
        return 2;
    }
    voxel::VolumeRequest req;
    if (!boxOption(o.box, req.box)) return 2;
    if (!outputWritable(o.output)) return 1;
    voxel::Volume volume;
    if (endsWith(o.model.file, ".vdb")) {
        if (std::string why = voxel::readVolume(o.model.file, volume); !why.empty()) {
            std::cerr << "error: " << why << "\n";
            return 1;
        }
        std::printf("grid: %s, %d voxels along the longest side\n", o.model.file.c_str(), volume.frame.resolution);
    } else {
        if (o.resolution <= 0) {
            std::cerr << "error: --res N is required when meshing a HyperFun file\n";
            return 2;
        }
        auto loaded = loadModel(o.model);
        if (!loaded) return 1;
        req.resolution = o.resolution;
        req.source = {o.model.file, loaded->model->body().spelling, o.model.parameters};
        voxel::VoxelizeResult r = voxel::voxelize(*loaded->model, req);
        if (!r.volume) {
            std::cerr << o.model.file << ": error: " << r.error << "\n";
            return 1;
        }
        volume = std::move(*r.volume);
        std::printf("model box: %s\n", voxel::describeModelBox(r.modelBox).c_str());
        std::printf("sampled %s at %d voxels along the longest side in %.3f s\n", o.model.file.c_str(),
                    volume.frame.resolution, r.stats.seconds);
    }
    poly::ExportStats stats;
    poly::Mesh mesh = poly::meshVolume(volume, &stats);
    if (mesh.empty()) {
        std::cerr << o.model.file << ": error: the volume has no surface (nothing inside the model box)\n";
        return 1;
    }
    // Validation and writing only read the mesh: side by side, so that one
    // computes while the other waits on the file.
    poly::MeshReport report;
    std::string why;
    tbb::parallel_invoke([&] { report = poly::validateMesh(mesh); },
                         [&] { why = poly::writeStl(mesh, o.output, o.ascii, o.mmPerUnit); });
    std::printf("meshed in %.3f s\n%s", stats.seconds, poly::describe(report, o.mmPerUnit).c_str());
    if (!why.empty()) {
        std::cerr << "error: " << why << "\n";
        return 1;
    }
    std::printf("wrote %s (%s STL in mm, %g mm per model unit%s)\n", o.output.c_str(), o.ascii ? "ASCII" : "binary",
                o.mmPerUnit, o.mmPerUnit == 1000.0 ? ": model units as metres" : "");
    return report.ok() ? 0 : 1;
}

}  // namespace hg::garden::cli
