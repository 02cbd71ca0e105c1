// Level-of-detail benchmark for the chunked polygonizer, on our key
// sculptures at 256^3 (model units are metres):
//
//  1. Triangles with view-dependent LOD (1 px error, 1080 px viewport, 60°
//     vertical field of view) against every chunk at level 0, for a camera
//     at three distances from the sculpture (4, 20, 60 m) and for a garden
//     view (four sculptures at 4, 12, 25 and 40 m at once).
//  2. Milliseconds per chunk remesh at 16^3 and 32^3 (chunks the surface
//     passes through, level 0, one thread), against the export mesher's
//     time for the whole grid spread over the same chunks.
//
// Prints Markdown tables; --json FILE writes the rows too.
//
//   ./build/release/bench/bench_lod [--json out.json] [--filter NAME] [--repeat N]
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"

#include "frep/language/parser.h"
#include "polygonizer/realtime/chunk_mesher.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/realtime/lod_selection.h"
#include "voxel/sampler.h"

namespace {

using namespace hg;
namespace fs = std::filesystem;

struct Sculpture {
    std::string name;
    voxel::Volume volume;
    std::unique_ptr<poly::LodPyramid> pyramid;
    std::unique_ptr<poly::ChunkLayout> layout;
};

std::size_t meshTriangles(const Sculpture& s, const std::vector<int>& levels) {
    const std::vector<poly::ChunkLod> lods = poly::chunkLods(*s.layout, levels);
    std::size_t n = 0;
    for (std::size_t i = 0; i < lods.size(); ++i) n += poly::meshChunk(*s.pyramid, *s.layout, i, lods[i]).triangleCount();
    return n;
}

std::array<double, 3> centre(const voxel::VolumeFrame& f) {
    return {0.5 * (f.modelBox.lo[0] + f.modelBox.hi[0]), 0.5 * (f.modelBox.lo[1] + f.modelBox.hi[1]),
            0.5 * (f.modelBox.lo[2] + f.modelBox.hi[2])};
}

// The camera `distance` metres in front of the sculpture (along -z), at its
// centre's height.
poly::Camera cameraAt(const voxel::VolumeFrame& f, double distance) {
    poly::Camera cam;
    std::array<double, 3> c = centre(f);
    cam.position = {c[0], c[1], f.modelBox.lo[2] - distance};
    cam.fovY = 60.0 * 3.14159265358979323846 / 180.0;
    cam.viewportHeight = 1080;
    return cam;
}

std::string histogram(const std::vector<int>& levels) {
    std::map<int, int> h;
    for (int l : levels) ++h[l];
    std::string s;
    for (const auto& [l, n] : h) s += (s.empty() ? "" : " ") + std::to_string(l) + ":" + std::to_string(n);
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    const int res = 256;
    std::vector<std::unique_ptr<Sculpture>> sculptures;  // the pyramid points at its volume: never moved
    for (const char* n : {"key_dryad", "key_orant", "key_knot"}) {
        if (!args.matches(n)) continue;
        frep::ParseResult r = frep::parseFile((fs::path(HG_SOURCE_DIR) / "content" / "hyperfun" / (std::string(n) + ".hf")).string());
        if (!r.ok()) continue;
        auto program = std::make_shared<const frep::Program>(std::move(*r.program));
        frep::Model model(program, program->defaultBody());
        voxel::VolumeRequest req;
        req.resolution = res;
        voxel::VoxelizeResult v = voxel::voxelize(model, req);
        if (!v.volume) continue;
        auto s = std::make_unique<Sculpture>(Sculpture{n, std::move(*v.volume), nullptr, nullptr});
        s->pyramid = std::make_unique<poly::LodPyramid>(s->volume, 4);
        s->layout = std::make_unique<poly::ChunkLayout>(s->volume.frame, 32);
        sculptures.push_back(std::move(s));
    }
    nlohmann::json json = {{"lod", nlohmann::json::array()}, {"remesh", nlohmann::json::array()}};

    std::printf("LOD at 1 px (1080 px, 60 deg), 32^3 chunks, %d^3:\n\n", res);
    std::printf("| model | camera (m) | levels (level:chunks) | triangles (LOD) | triangles (level 0) | level 0 / LOD |\n");
    std::printf("|---|---:|---|---:|---:|---:|\n");
    poly::LodSettings settings;  // 1 px, up to level 3
    for (auto& owned : sculptures) {
        Sculpture& s = *owned;
        const std::size_t full = meshTriangles(s, std::vector<int>(s.layout->count(), 0));
        for (double d : {4.0, 20.0, 60.0}) {
            std::vector<int> levels = poly::selectLevels(*s.layout, cameraAt(s.volume.frame, d), settings);
            const std::size_t lod = meshTriangles(s, levels);
            std::printf("| %s | %.0f | %s | %zu | %zu | %.1fx |\n", s.name.c_str(), d, histogram(levels).c_str(), lod,
                        full, static_cast<double>(full) / static_cast<double>(std::max<std::size_t>(lod, 1)));
            std::fflush(stdout);
            json["lod"].push_back({{"model", s.name}, {"distance_m", d}, {"triangles_lod", lod}, {"triangles_level0", full}});
        }
    }
    if (sculptures.size() == 3) {
        // A garden view: four sculptures (the dryad twice) at 4, 12, 25 and
        // 40 m at once, as a visitor standing next to one of them sees them.
        std::size_t lod = 0, full = 0;
        const double at[4] = {4.0, 12.0, 25.0, 40.0};
        for (std::size_t k = 0; k < 4; ++k) {
            const Sculpture& s = *sculptures[k % 3];
            lod += meshTriangles(s, poly::selectLevels(*s.layout, cameraAt(s.volume.frame, at[k]), settings));
            full += meshTriangles(s, std::vector<int>(s.layout->count(), 0));
        }
        std::printf("| garden view: 4 sculptures at 4, 12, 25, 40 | | | %zu | %zu | %.1fx |\n", lod, full,
                    static_cast<double>(full) / static_cast<double>(std::max<std::size_t>(lod, 1)));
        json["lod"].push_back({{"model", "garden"}, {"triangles_lod", lod}, {"triangles_level0", full}});
    }

    std::printf("\nChunk remesh, level 0, one thread (chunks the surface passes through):\n\n");
    std::printf("| model | chunk | surface chunks | ms per chunk (mean) | ms per chunk (max) | export mesher per chunk (ms) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|\n");
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    for (auto& owned : sculptures) {
        Sculpture& s = *owned;
        const double exportSeconds = bench::bestOf(args.repeat, [&] { (void)poly::meshVolume(s.volume); });
        for (int size : {16, 32}) {
            poly::ChunkLayout layout(s.volume.frame, size);
            double total = 0.0, worst = 0.0;
            std::size_t surface = 0;
            for (std::size_t i = 0; i < layout.count(); ++i) {
                poly::Mesh m;
                const double t = bench::bestOf(args.repeat, [&] { m = poly::meshChunk(*s.pyramid, layout, i, poly::ChunkLod{}); });
                if (m.empty()) continue;
                ++surface;
                total += t;
                worst = std::max(worst, t);
            }
            const double mean = surface ? total / static_cast<double>(surface) : 0.0;
            std::printf("| %s | %d^3 | %zu | %.2f | %.2f | %.2f |\n", s.name.c_str(), size, surface, mean * 1e3,
                        worst * 1e3, surface ? exportSeconds / static_cast<double>(surface) * 1e3 : 0.0);
            std::fflush(stdout);
            json["remesh"].push_back({{"model", s.name}, {"chunk", size}, {"surface_chunks", surface},
                                      {"mean_ms", mean * 1e3}, {"max_ms", worst * 1e3}});
        }
    }
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << json.dump(2) << "\n";
    return 0;
}
