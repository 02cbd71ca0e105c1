// Scanned volumes (docs/volumes.md, "Scanned volumes"): the committed
// phantom (content/volumes/phantom.raw, 64^3 u8) read, and its iso-surface
// rebuilt as a sculpture's level set (`voxel::levelSetFromScalar`) at
// 64, 128 and 256 voxels along the solid, for the bone (iso 128) and the
// skin (iso 32); against the peer measured in the same run, a HyperFun
// sculpture of the garden (path_column.hf) sampled by `voxel::voxelize` at
// the same resolution. Prints a Markdown table; --json FILE writes the rows.
//
//   ./build/release/bench/bench_scan [--json out.json] [--repeat N]
#include <tbb/info.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"

#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "voxel/scalar_volume.h"
#include "voxel/sampler.h"

namespace {

using namespace hg;

struct Row {
    std::string surface;
    int resolution = 0;
    double scanSeconds = 0, peerSeconds = 0;
    std::size_t activeVoxels = 0, leaves = 0;
};

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    const std::string root = HG_SOURCE_DIR;
    voxel::RawVolumeLayout layout;
    layout.dims = {64, 64, 64};
    layout.spacing = {0.02, 0.02, 0.02};
    voxel::ScalarVolume scan;
    const double readSeconds = bench::bestOf(args.repeat, [&] {
        if (std::string why = voxel::readRawVolume(root + "/content/volumes/phantom.raw", layout, scan); !why.empty()) {
            std::fprintf(stderr, "error: %s\n", why.c_str());
            std::exit(1);
        }
    });
    std::ifstream in(root + "/content/hyperfun/path_column.hf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    frep::ParseResult parsed = frep::parseProgram(text, "path_column.hf");
    if (!parsed.ok()) return 1;
    auto program = std::make_shared<const frep::Program>(std::move(*parsed.program));
    const frep::Model column(program, 0, {0.0});
    voxel::ModelBox columnBox;
    if (!voxel::resolveModelBox(column, std::nullopt, columnBox).empty()) return 1;

    std::vector<Row> rows;
    for (const auto& [name, iso] : std::vector<std::pair<std::string, double>>{{"bone (iso 128)", 128.0}, {"skin (iso 32)", 32.0}})
        for (int res : {64, 128, 256}) {
            if (!args.matches(name)) continue;
            Row row;
            row.surface = name;
            row.resolution = res;
            voxel::IsoSurfaceRequest req;
            req.iso = iso;
            req.resolution = res;
            voxel::VoxelizeResult r;
            row.scanSeconds = bench::bestOf(args.repeat, [&] { r = voxel::levelSetFromScalar(scan, req); });
            if (!r.volume) {
                std::fprintf(stderr, "error: %s\n", r.error.c_str());
                return 1;
            }
            row.activeVoxels = r.volume->activeVoxelCount();
            row.leaves = r.volume->leafCount();
            voxel::VolumeRequest peer;
            peer.box = columnBox.box;
            peer.resolution = res;
            row.peerSeconds = bench::bestOf(args.repeat, [&] { (void)voxel::voxelize(column, peer); });
            rows.push_back(row);
        }

    std::printf("Threads: %d. Reading the phantom (256 KiB): %.4f s. Scan: `voxel::levelSetFromScalar` (the inside\n"
                "samples' box, the memory estimate, OpenVDB's levelSetRebuild at the sculpture's voxel size, our\n"
                "sign, clamp and invariants). Peer: `voxel::voxelize` of path_column.hf on its box at the same\n"
                "resolution. Best of %d.\n\n",
                tbb::info::default_concurrency(), readSeconds, args.repeat);
    std::printf("| surface | resolution | scan (s) | active voxels | leaves | peer: column voxelize (s) | scan / peer |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (const Row& r : rows)
        std::printf("| %s | %d | %.3f | %zu | %zu | %.3f | %.2fx |\n", r.surface.c_str(), r.resolution, r.scanSeconds,
                    r.activeVoxels, r.leaves, r.peerSeconds, r.scanSeconds / r.peerSeconds);
    if (!args.jsonPath.empty()) {
        nlohmann::json j = nlohmann::json::array();
        for (const Row& r : rows)
            j.push_back({{"surface", r.surface}, {"resolution", r.resolution}, {"scan_s", r.scanSeconds},
                         {"active_voxels", r.activeVoxels}, {"leaves", r.leaves}, {"peer_voxelize_s", r.peerSeconds}});
        std::ofstream(args.jsonPath) << j.dump(2) << "\n";
    }
    return 0;
}
