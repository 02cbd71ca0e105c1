// Volume sampling benchmark: for the shared corpus models and every program
// in content/hyperfun, the culled narrow-band sampler against dense sampling
// of the same box with the same batch evaluator (both on all cores), the
// fraction of the box the culled sampler evaluated, and its times at
// 128^3, 256^3 and 512^3. Prints a Markdown table; --json FILE writes the
// rows too. Times are the best of --repeat runs.
//
//   ./build/release/bench/bench_voxel [--json out.json] [--filter NAME] [--repeat N] [--dense-res N]
#include <tbb/enumerable_thread_specific.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"

#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "voxel/dense_field.h"
#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace {

using namespace hg;
using bench::bestOf;
namespace fs = std::filesystem;

struct Subject {
    std::string name;
    std::shared_ptr<const frep::Program> program;
    std::unique_ptr<frep::Model> model;
    std::optional<frep::Box3> box;  // none: estimated
};

struct Row {
    std::string name;
    std::string path;
    double culledSeconds = 0, denseSeconds = 0;
    double evaluated = 0;           // fraction of the box's voxels evaluated
    double bandVoxels = 0;          // fraction of the box's voxels in the band (active)
    double bandLeaves = 0;          // fraction of the box in leaves that hold band voxels
    double bandOnlySeconds = 0;     // evaluating exactly the band voxels, nothing else
    double boxSeconds = 0;          // model box estimate (0: given)
    double culledByRes[3] = {0, 0, 0};
    std::string note;
};

frep::Box3 cube(double h) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) { b.lo[a] = -h; b.hi[a] = h; }
    return b;
}

// Boxes for programs whose solid is unbounded or whose interval estimate
// fails; HyperFun's own viewer samples [-10, 10]^3 by default.
std::optional<frep::Box3> knownBox(const std::string& name) {
    if (name == "plane" || name == "paraboloid") return cube(10.0);
    return std::nullopt;
}

void addSubject(std::vector<Subject>& out, const fs::path& file, const std::string& filter) {
    std::string name = file.stem().string();
    if (!filter.empty() && name.find(filter) == std::string::npos) return;
    frep::ParseResult r = frep::parseFile(file.string());
    if (!r.ok()) {
        std::fprintf(stderr, "skipping %s: it does not parse\n", file.string().c_str());
        return;
    }
    Subject s;
    s.name = name;
    s.program = std::make_shared<const frep::Program>(std::move(*r.program));
    // Our content documents its a[] in each file's header; the defaults
    // below are the garden's.
    std::vector<double> a;
    if (name == "dancer") a = {0.4};
    s.model = std::make_unique<frep::Model>(s.program, s.program->defaultBody(), a);
    s.box = knownBox(name);
    out.push_back(std::move(s));
}

// The band voxels of a sampled volume as model-space points: what a
// sampler that knew the surface in advance would still have to evaluate.
struct BandPoints {
    std::vector<float> x, y, z;
    std::size_t leaves = 0;
};

BandPoints bandPoints(const voxel::Volume& v) {
    BandPoints b;
    const openvdb::FloatGrid& grid = voxel::vdb(v);
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        const openvdb::Coord c = it.getCoord();
        b.x.push_back(static_cast<float>(v.frame.coordinate(0, c.x())));
        b.y.push_back(static_cast<float>(v.frame.coordinate(1, c.y())));
        b.z.push_back(static_cast<float>(v.frame.coordinate(2, c.z())));
    }
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf)
        if (leaf->onVoxelCount() > 0) ++b.leaves;
    return b;
}

// Evaluates the points in leaf-sized batches on all cores with the float
// batch evaluator both samplers use.
void evaluateAll(const frep::Model& model, const BandPoints& b) {
    constexpr std::size_t kBatch = 512;
    struct Worker {
        explicit Worker(const frep::Model& m) : sampler(m) {}
        frep::PointSampler<float> sampler;
        float f[kBatch];
        frep::ErrorReport errors;
    };
    tbb::enumerable_thread_specific<std::unique_ptr<Worker>> workers;
    const std::size_t n = b.x.size();
    tbb::parallel_for(std::size_t{0}, (n + kBatch - 1) / kBatch, [&](std::size_t i) {
        auto& w = workers.local();
        if (!w) w = std::make_unique<Worker>(model);
        const std::size_t lo = i * kBatch, count = std::min(kBatch, n - lo);
        w->sampler.evaluate(b.x.data() + lo, b.y.data() + lo, b.z.data() + lo, w->f, count, w->errors);
    });
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    const std::string& jsonPath = args.jsonPath;
    const std::string& filter = args.filter;
    const int repeat = args.repeat;
    std::vector<Subject> subjects;
    fs::path corpus = fs::path(HG_TEST_DATA_DIR) / "hyperfun" / "corpus";
    if (fs::exists(corpus)) {
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(corpus))
            if (e.path().extension() == ".hf") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const auto& f : files) addSubject(subjects, f, filter);
    } else {
        std::fprintf(stderr, "note: %s is absent; benchmarking our own content only\n", corpus.string().c_str());
    }
    std::vector<fs::path> ours;
    for (const auto& e : fs::directory_iterator(fs::path(HG_SOURCE_DIR) / "content" / "hyperfun"))
        if (e.path().extension() == ".hf") ours.push_back(e.path());
    std::sort(ours.begin(), ours.end());
    for (const auto& f : ours) addSubject(subjects, f, filter);

    const int resolutions[3] = {128, 256, 512};
    std::vector<Row> rows;
    for (Subject& s : subjects) {
        Row row;
        row.name = s.name;
        row.path = s.model->tape() ? std::to_string(s.model->tape()->size()) + " instrs" : "interpreter";
        voxel::VolumeRequest req;
        req.box = s.box;
        std::fprintf(stderr, "%s...\n", s.name.c_str());
        // The model box is estimated once, timed on its own: both samplers
        // then work on the same given box.
        voxel::ModelBox box;
        std::string why;
        row.boxSeconds = bestOf(1, [&] { why = voxel::resolveModelBox(*s.model, req.box, box); });
        if (!why.empty()) {
            row.note = why;
            rows.push_back(row);
            continue;
        }
        if (box.origin == voxel::BoxOrigin::Given) row.boxSeconds = 0;
        req.box = box.box;
        for (int r = 0; r < 3; ++r) {
            req.resolution = resolutions[r];
            voxel::VoxelizeResult result;
            double t = bestOf(r == 2 ? 1 : repeat, [&] { result = voxel::voxelize(*s.model, req); });
            if (!result.volume) {
                row.note = result.error;
                break;
            }
            row.culledByRes[r] = t;
            if (resolutions[r] != 256) continue;
            row.culledSeconds = t;
            row.evaluated = result.stats.evaluatedFraction();
            const voxel::Volume& v = *result.volume;
            row.denseSeconds = bestOf(repeat, [&] {
                voxel::DenseResult d = voxel::sampleDense(*s.model, v.frame, v.normalization, v.frame.indexBox);
                if (!d.error.empty()) row.note = d.error;
            });
            const double voxels = static_cast<double>(v.frame.indexBox.volume());
            BandPoints band = bandPoints(v);
            row.bandVoxels = static_cast<double>(band.x.size()) / voxels;
            row.bandLeaves = static_cast<double>(band.leaves) * 512.0 / voxels;
            row.bandOnlySeconds = bestOf(repeat, [&] { evaluateAll(*s.model, band); });
        }
        rows.push_back(row);
    }

    std::printf("Threads: %d. Culled: `voxel::voxelize` on the estimated (or given) box: normalization\n"
                "probe, interval culling, leaves, tree assembly. Dense: `voxel::sampleDense` over the same\n"
                "index box with the same evaluator. Band-only: the same evaluator on exactly the voxels\n"
                "that end up in the band (what a sampler that knew the surface beforehand would evaluate,\n"
                "with no probe, no culling and no tree): the ceiling for dense / culled. Band leaves: the\n"
                "box's share in 8^3 leaves holding band voxels, the floor for culling whole leaves.\n\n",
                tbb::info::default_concurrency());
    std::printf("| model | path | box estimate (s) | culled 256^3 (s) | dense 256^3 (s) | dense / culled | box evaluated "
                "| band leaves | band voxels | dense / band-only | 128^3 (s) | 256^3 (s) | 512^3 (s) |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const Row& r : rows) {
        if (!r.note.empty() && r.culledSeconds == 0) {
            std::printf("| %s | %s | - | - | - | - | - | - | - | - | - | - | - |  (%s)\n", r.name.c_str(), r.path.c_str(),
                        r.note.c_str());
            continue;
        }
        std::printf("| %s | %s | %.3f | %.3f | %.3f | %.1fx | %.1f%% | %.1f%% | %.1f%% | %.1fx | %.3f | %.3f | %.3f |\n",
                    r.name.c_str(), r.path.c_str(), r.boxSeconds, r.culledSeconds, r.denseSeconds,
                    r.denseSeconds / r.culledSeconds, 100.0 * r.evaluated, 100.0 * r.bandLeaves, 100.0 * r.bandVoxels,
                    r.denseSeconds / r.bandOnlySeconds, r.culledByRes[0], r.culledByRes[1], r.culledByRes[2]);
    }
    if (!jsonPath.empty()) {
        nlohmann::json j = nlohmann::json::array();
        for (const Row& r : rows)
            j.push_back({{"model", r.name}, {"path", r.path}, {"box_estimate_s", r.boxSeconds}, {"dense_256_s", r.denseSeconds},
                         {"evaluated_fraction_256", r.evaluated},
                         {"band_leaves_fraction_256", r.bandLeaves}, {"band_voxels_fraction_256", r.bandVoxels},
                         {"band_only_256_s", r.bandOnlySeconds}, {"culled_128_s", r.culledByRes[0]},
                         {"culled_256_s", r.culledByRes[1]}, {"culled_512_s", r.culledByRes[2]}, {"note", r.note}});
        std::ofstream(jsonPath) << j.dump(2) << "\n";
    }
    return 0;
}
