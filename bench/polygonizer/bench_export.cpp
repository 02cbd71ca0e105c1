// Mesh export benchmark (issue 12): poly::exportMesh to binary STL (tiled
// sampling and meshing, welding, validation, writing) at 256^3, 512^3 and
// 1024^3, beside the untiled path on the same frame (voxelize the whole
// narrow band, then meshVolume) and OpenVDB's tools::volumeToMesh on that
// same whole grid (isovalue 0, adaptivity 0), where the grid fits in
// memory. Each row runs in a child process of its own so that its peak
// resident memory (VmHWM) is its own. Prints a Markdown table; --json FILE
// writes the rows too.
//
// With --simplify ERROR (model units) only the export runs, simplified,
// and a table of triangles before and after is printed instead.
//
// With --stages only the export runs, and a table says where its time
// goes (the plan: normalization and coarse sampling; sampling the tiles;
// meshing, welding, validating and writing), what CPU time it took (all
// threads: less disturbed than the clock by other work on the cores) and
// which tape each evaluated leaf ran (mean, longest) beside the full tape
// (docs/hyperfun.md, "Evaluation specialized to a region"). --hf FILE adds
// a HyperFun file of one's own (an exported edited sculpture, say) to the
// models; --box gives those files' model box (an export's header states it).
//
//   ./build/release/bench/bench_export [--json out.json] [--filter NAME] [--repeat N] [--res 256,512,1024]
//                                      [--memory-limit MiB] [--simplify ERROR] [--stages] [--hf FILE]... [--box x0,y0,z0,x1,y1,z1]
#include <openvdb/tools/VolumeToMesh.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../bench_common.h"

#include "frep/language/parser.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/export/mesh_export.h"
#include "voxel/model_box.h"
#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace {

using namespace hg;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Source {
    std::string name;
    std::string text;  // program text, or "" with a file
    fs::path file;
    std::optional<frep::Box3> box;  // none: resolveModelBox's
};

std::uint64_t peakResidentBytes() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        std::uint64_t kb = 0;
        if (key == "VmHWM:" && status >> kb) return kb * 1024;
    }
    return 0;
}

// User and system time of every thread of this process: what a run cost
// when other work shares the cores and the clock on the wall says little.
double cpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::optional<frep::Model> load(const Source& s) {
    frep::ParseResult r = s.text.empty() ? frep::parseFile(s.file.string()) : frep::parseProgram(s.text, s.name + ".hf");
    if (!r.ok()) return std::nullopt;
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    return frep::Model(program, program->defaultBody(), {});
}

// One measurement, in the child: a JSON object.
double gSimplifyError = 0.0;

nlohmann::json measure(const Source& s, int res, const std::string& path, std::uint64_t limitMiB, int repeat) {
    nlohmann::json row = {{"model", s.name}, {"res", res}, {"path", path}};
    std::optional<frep::Model> model = load(s);
    voxel::ModelBox box;
    if (!model || !voxel::resolveModelBox(*model, s.box, box).empty()) {
        row["error"] = "cannot load or bound the model";
        return row;
    }
    const fs::path out = fs::temp_directory_path() / ("hg_bench_export_" + std::to_string(getpid()) + ".stl");
    if (path == "export") {
        poly::MeshExportOptions o;
        o.resolution = res;
        o.memoryLimitMiB = limitMiB;
        o.simplifyError = gSimplifyError;
        poly::MeshExportReport report;
        std::string why;
        const double cpu0 = cpuSeconds();
        const double t = bench::bestOf(repeat, [&] { why = poly::exportMesh(*model, box.box, o, out.string(), report); });
        row["cpu_seconds"] = (cpuSeconds() - cpu0) / repeat;
        if (!why.empty()) row["error"] = why;
        row["seconds"] = t;
        row["mesh_seconds"] = report.meshSeconds;
        row["plan_seconds"] = report.planSeconds;
        row["sample_seconds"] = report.sampleSeconds;
        row["leaf_tape_mean"] = report.leafTapeMean;
        row["leaf_tape_max"] = report.leafTapeMax;
        row["full_tape"] = model->tape() ? model->tape()->size() : 0;
        row["triangles"] = report.triangles;
        row["triangles_before_simplify"] = report.trianglesBeforeSimplify;
        row["simplify_note"] = report.simplifyNote;
        row["tiles"] = report.tiles;
        row["tile_size"] = report.tileSize;
        row["estimated_bytes"] = report.estimatedBytes;
        row["file_bytes"] = fs::exists(out) ? fs::file_size(out) : 0;
        fs::remove(out);
    } else {
        voxel::VolumeRequest req;
        req.box = box.box;
        req.resolution = res;
        voxel::SampleOptions so;
        so.memoryLimit = limitMiB << 20;
        double sample = 1e30, mesh = 1e30;
        std::size_t triangles = 0;
        for (int i = 0; i < repeat; ++i) {
            auto t0 = Clock::now();
            voxel::VoxelizeResult v = voxel::voxelize(*model, req, so);
            if (!v.volume) {
                row["error"] = v.error;
                return row;
            }
            sample = std::min(sample, seconds(t0));
            t0 = Clock::now();
            if (path == "untiled") {
                triangles = poly::meshVolume(*v.volume).triangleCount();
            } else {
                std::vector<openvdb::Vec3s> points;
                std::vector<openvdb::Vec3I> tris;
                std::vector<openvdb::Vec4I> quads;
                openvdb::tools::volumeToMesh(voxel::vdb(*v.volume), points, tris, quads, 0.0, 0.0, false);
                triangles = tris.size() + 2 * quads.size();
            }
            mesh = std::min(mesh, seconds(t0));
            row["grid_bytes"] = v.volume->memoryBytes();
        }
        row["seconds"] = sample + mesh;
        row["sample_seconds"] = sample;
        row["mesh_seconds"] = mesh;
        row["triangles"] = triangles;
    }
    row["peak_bytes"] = peakResidentBytes();
    return row;
}

// Runs measure() in a child (a fresh process: no TBB threads are started
// before the fork) and reads its row back through a pipe.
nlohmann::json inChild(const Source& s, int res, const std::string& path, std::uint64_t limitMiB, int repeat) {
    int fds[2];
    if (pipe(fds) != 0) return {{"error", "pipe"}};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        const std::string text = measure(s, res, path, limitMiB, repeat).dump();
        const ssize_t w = write(fds[1], text.data(), text.size());
        _exit(w == static_cast<ssize_t>(text.size()) ? 0 : 1);
    }
    close(fds[1]);
    std::string text;
    char buf[4096];
    ssize_t n;
    while ((n = read(fds[0], buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(n));
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (text.empty()) return {{"model", s.name}, {"res", res}, {"path", path}, {"error", "the child died (out of memory?)"}};
    return nlohmann::json::parse(text);
}

std::string mib(const nlohmann::json& row, const char* key) {
    if (!row.contains(key)) return "-";
    char b[32];
    std::snprintf(b, sizeof b, "%.0f", row[key].get<double>() / (1024.0 * 1024.0));
    return b;
}

std::string secs(const nlohmann::json& row) {
    if (row.contains("error")) return "does not fit";
    char b[32];
    std::snprintf(b, sizeof b, "%.2f", row["seconds"].get<double>());
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    // Our own options first, the shared ones after.
    std::vector<int> resolutions = {256, 512, 1024};
    std::uint64_t limitMiB = 0;
    bool stages = false;
    std::optional<frep::Box3> fileBox;
    std::vector<fs::path> files;
    std::vector<char*> rest = {argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--res") == 0 && i + 1 < argc) {
            resolutions.clear();
            std::stringstream list(argv[++i]);
            for (std::string r; std::getline(list, r, ',');) resolutions.push_back(std::atoi(r.c_str()));
        } else if (std::strcmp(argv[i], "--simplify") == 0 && i + 1 < argc) {
            gSimplifyError = std::atof(argv[++i]);
        } else if (std::strcmp(argv[i], "--stages") == 0) {
            stages = true;
        } else if (std::strcmp(argv[i], "--box") == 0 && i + 1 < argc) {
            frep::Box3 b;
            if (std::sscanf(argv[++i], "%lf,%lf,%lf,%lf,%lf,%lf", &b.lo[0], &b.lo[1], &b.lo[2], &b.hi[0], &b.hi[1],
                            &b.hi[2]) != 6) {
                std::fprintf(stderr, "--box takes x0,y0,z0,x1,y1,z1\n");
                return 2;
            }
            fileBox = b;
        } else if (std::strcmp(argv[i], "--hf") == 0 && i + 1 < argc) {
            files.emplace_back(argv[++i]);
        } else if (std::strcmp(argv[i], "--memory-limit") == 0 && i + 1 < argc) {
            limitMiB = std::strtoull(argv[++i], nullptr, 10);
        } else {
            rest.push_back(argv[i]);
        }
    }
    bench::BenchArgs args;
    args.repeat = 1;
    if (!bench::parseBenchArgs(static_cast<int>(rest.size()), rest.data(), args)) return 2;

    std::vector<Source> sources = {
        {"sphere", "q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }", {}, std::nullopt},
    };
    for (const char* n : {"key_dryad", "path_boulder"})
        sources.push_back({n, "", fs::path(HG_SOURCE_DIR) / "content" / "hyperfun" / (std::string(n) + ".hf"), std::nullopt});
    for (const fs::path& f : files) sources.push_back({f.stem().string(), "", f, fileBox});

    nlohmann::json rows = nlohmann::json::array();
    // Every model the filter takes, at every resolution asked for, then the rows written.
    const auto eachRun = [&](const auto& run) {
        for (const Source& s : sources) {
            if (!args.matches(s.name)) continue;
            for (int res : resolutions) run(s, res);
        }
        if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << nlohmann::json{{"mesh_export", rows}}.dump(2) << "\n";
    };
    if (gSimplifyError > 0.0) {
        std::printf("| model | res | triangles | simplified (error %g) | export STL (s) | peak (MiB) | note |\n",
                    gSimplifyError);
        std::printf("|---|---:|---:|---:|---:|---:|---|\n");
        eachRun([&](const Source& s, int res) {
            const nlohmann::json ours = inChild(s, res, "export", limitMiB, args.repeat);
            std::printf("| %s | %d^3 | %zu | %zu | %s | %s | %s |\n", s.name.c_str(), res,
                        ours.value("triangles_before_simplify", std::size_t{0}), ours.value("triangles", std::size_t{0}),
                        secs(ours).c_str(), mib(ours, "peak_bytes").c_str(), ours.value("simplify_note", "").c_str());
            std::fflush(stdout);
            if (ours.contains("error")) std::fprintf(stderr, "%s\n", ours["error"].get<std::string>().c_str());
            rows.push_back({{"export", ours}});
        });
        return 0;
    }
    if (stages) {
        std::printf("| model | res | export STL (s) | CPU (s) | plan (s) | sampling tiles (s) | meshing, welding, writing (s) "
                    "| full tape | leaf tape mean | leaf tape max |\n");
        std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        eachRun([&](const Source& s, int res) {
            const nlohmann::json r = inChild(s, res, "export", limitMiB, args.repeat);
            if (r.contains("error")) {
                std::fprintf(stderr, "%s %d: %s\n", s.name.c_str(), res, r["error"].get<std::string>().c_str());
                return;
            }
            const double total = r["seconds"].get<double>(), plan = r["plan_seconds"].get<double>(),
                         sample = r["sample_seconds"].get<double>();
            std::printf("| %s | %d^3 | %.2f | %.2f | %.2f | %.2f | %.2f | %zu | %.0f | %zu |\n", s.name.c_str(), res, total,
                        r.value("cpu_seconds", 0.0), plan, sample, total - plan - sample, r.value("full_tape", std::size_t{0}),
                        r.value("leaf_tape_mean", 0.0), r.value("leaf_tape_max", std::size_t{0}));
            std::fflush(stdout);
            rows.push_back({{"export", r}});
        });
        return 0;
    }
    std::printf("| model | res | triangles | export STL (s) | of which tiled meshing (s) | peak (MiB) | tiles "
                "| untiled: voxelize + meshVolume (s) | peak (MiB) | voxelize + volumeToMesh (s) "
                "| volumeToMesh alone (s) | peak (MiB) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    eachRun([&](const Source& s, int res) {
        const nlohmann::json ours = inChild(s, res, "export", limitMiB, args.repeat);
        const nlohmann::json untiled = inChild(s, res, "untiled", limitMiB, args.repeat);
        const nlohmann::json vdb = inChild(s, res, "openvdb", limitMiB, args.repeat);
        char tiles[32];
        std::snprintf(tiles, sizeof tiles, "%d x %d^3", ours.value("tiles", 0), ours.value("tile_size", 0));
        char tiled[32] = "-";
        if (ours.contains("mesh_seconds")) std::snprintf(tiled, sizeof tiled, "%.2f", ours["mesh_seconds"].get<double>());
        char mesh[32] = "-";
        if (vdb.contains("mesh_seconds")) std::snprintf(mesh, sizeof mesh, "%.2f", vdb["mesh_seconds"].get<double>());
        std::printf("| %s | %d^3 | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", s.name.c_str(), res,
                    ours.value("triangles", std::size_t{0}), secs(ours).c_str(), tiled, mib(ours, "peak_bytes").c_str(), tiles,
                    secs(untiled).c_str(), mib(untiled, "peak_bytes").c_str(), secs(vdb).c_str(), mesh,
                    mib(vdb, "peak_bytes").c_str());
        std::fflush(stdout);
        for (const auto& r : {ours, untiled, vdb})
            if (r.contains("error")) std::fprintf(stderr, "%s %d %s: %s\n", s.name.c_str(), res,
                                                  r.value("path", "").c_str(), r["error"].get<std::string>().c_str());
        rows.push_back({{"export", ours}, {"untiled", untiled}, {"openvdb", vdb}});
    });
    return 0;
}
