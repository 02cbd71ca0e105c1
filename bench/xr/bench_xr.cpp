// XR frame benchmark (issue 13): the default garden in the mock headset at
// 90 Hz (xrWaitFrame paces the frames, two 512 x 512 views drawn each
// frame), played from a script: a carving stroke with the right hand, a
// walk, a morph to a new blend. CPU time per stage per frame against the
// runtime's predicted display period (11.1 ms). Needs an X display
// (xvfb-run -a) and the mock runtime, which it selects itself.
//
// With --scale N (issue 25): the scale garden of bench_garden (N copies of
// the default garden's sculptures on a grid 3 m apart, at --scale-resolution)
// instead, left to load for --settle-frames and then walked down an aisle
// with the thumbstick for --walk-frames; mean / p95 / p99 / max per stage,
// the GPU's milliseconds and the frames over the display's period. --view
// WxH sets each eye's size (HG_MOCK_XR_VIEW_SIZE: 2064x2208 is the issue's
// headset), --quality the picture's preset.
//
//   xvfb-run -a ./build/release/bench/bench_xr [--json out.json]
//   xvfb-run -a ./build/release/bench/bench_xr --scale 200 --view 2064x2208 [--quality high]
//       [--scale-resolution 64] [--settle-frames 600] [--walk-frames 600] [--json out.json]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"
#include "../bench_json.h"

#include "garden/app/frame_stats.h"
#include "garden/app/garden_session.h"
#include "garden/render/render_quality.h"
#include "garden/scene/scale_garden.h"
#include "xr/xr_garden.h"

namespace {

using namespace hg;

struct Phase {
    const char* name;
    int first, last;  // focused frames, inclusive
};

// The viewer starts at (0, 1.7, 13) facing the ring gate 1.5 m ahead.
constexpr const char* kScript = R"({"garden": "%GARDEN%", "steps": [
  {"frames": 2, "commands": [{"sculpt_tool": {"kind": "carve", "radius": 0.06}}]},
  {"frames": 30, "tool": {"aim": {"position": [0.15, 1.4, -0.4], "direction": [-0.05, -0.05, -1]}, "trigger": 1}},
  {"frames": 30, "tool": {"aim": {"position": [0.05, 1.4, -0.4], "direction": [-0.02, -0.08, -1]}, "trigger": 1}},
  {"frames": 30, "tool": {"aim": {"position": [-0.05, 1.4, -0.4], "direction": [0.02, -0.11, -1]}, "trigger": 1}},
  {"frames": 8},
  {"frames": 180, "navigation": {"aim": {"position": [-0.2, 1.0, -0.3]}, "thumbstick": [0, 1]}},
  {"frames": 1, "commands": [{"morph": [0.5, -1.0]}]},
  {"frames": 179}
]})";

const Phase kPhases[] = {{"carving", 2, 91}, {"navigation", 100, 279}, {"morph", 280, 459}};

// Writes `text` to `path`; false, and a message naming the file, when it cannot.
bool writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (out) return true;
    std::fprintf(stderr, "bench_xr: cannot write %s\n", path.c_str());
    return false;
}

struct ScaleOptions {
    int count = 0;  // 0: the default garden's carve, walk and morph
    int resolution = 64;
    int settleFrames = 600, walkFrames = 600;
    std::string view;     // WxH per eye ("": the mock runtime's 512 x 512)
    std::string quality;  // low, medium, high ("": the renderer's)
};

// Our flags first; what is left goes to parseBenchArgs.
bool parseOptions(int argc, char** argv, bench::BenchArgs& args, ScaleOptions& o) {
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--scale" && hasValue) o.count = std::max(0, std::atoi(argv[++i]));
        else if (a == "--scale-resolution" && hasValue) o.resolution = std::max(16, std::atoi(argv[++i]));
        else if (a == "--settle-frames" && hasValue) o.settleFrames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--walk-frames" && hasValue) o.walkFrames = std::max(10, std::atoi(argv[++i]));
        else if (a == "--view" && hasValue) {
            int w = 0, h = 0;
            o.view = argv[++i];
            if (std::sscanf(o.view.c_str(), "%dx%d", &w, &h) != 2 || w <= 0 || h <= 0) {
                std::fprintf(stderr, "--view: expected WxH\n");
                return false;
            }
        } else if (a == "--quality" && hasValue) {
            o.quality = argv[++i];
            if (!garden::parseQualityPreset(o.quality)) {
                std::fprintf(stderr, "--quality: low, medium or high\n");
                return false;
            }
        } else rest.push_back(argv[i]);
    }
    if (!bench::parseBenchArgs(static_cast<int>(rest.size()), rest.data(), args)) {
        std::fprintf(stderr, "       [--scale N] [--scale-resolution R] [--settle-frames N] [--walk-frames N]\n"
                             "       [--view WxH] [--quality low|medium|high]\n");
        return false;
    }
    return true;
}

// The scale garden written beside the script, its sculpture files made
// absolute (they were the template's, relative to content/gardens), the
// visitor at the start of an aisle between two columns.
std::string writeScaleGarden(const std::filesystem::path& dir, const ScaleOptions& o) {
    const std::filesystem::path templatePath = std::filesystem::path(HG_SOURCE_DIR) / "content/gardens/default.json";
    std::ifstream in(templatePath);
    std::stringstream text;
    text << in.rdbuf();
    garden::ScaleGardenSpec spec;
    spec.count = o.count;
    spec.resolution = o.resolution;
    nlohmann::json g = nlohmann::json::parse(garden::scaleGardenText(text.str(), spec));
    for (auto& sculpture : g["sculptures"])
        if (sculpture.contains("file"))
            sculpture["file"] = (templatePath.parent_path() / sculpture["file"].get<std::string>()).lexically_normal().string();
    const double x = garden::scaleGardenColumns(o.count) % 2 ? 0.5 * spec.spacing : 0.0;
    g["start"]["position"][0] = x;
    g["start"]["look_at"][0] = x;
    const std::filesystem::path out = dir / ("scale" + std::to_string(o.count) + ".json");
    return writeText(out.string(), g.dump(1)) ? out.string() : std::string();
}

// The frames of `stats` from `first` to `last` (inclusive): a row of mean /
// p95 / p99 / max per stage, total and GPU, and the frames over budget.
nlohmann::json spreadRow(const char* phase, const std::vector<garden::FrameStats>& stats, int first, int last) {
    std::vector<double> total, gpu;
    std::array<std::vector<double>, garden::kStageCount> stage;
    int over = 0;
    for (int f = first; f <= last; ++f) {
        const garden::FrameStats& s = stats[static_cast<std::size_t>(f)];
        total.push_back(s.totalMs);
        if (s.gpuMs >= 0.0) gpu.push_back(s.gpuMs);
        over += s.totalMs > s.budgetMs || s.gpuMs > s.budgetMs;
        for (std::size_t k = 0; k < stage.size(); ++k) stage[k].push_back(s.stageMs[k]);
    }
    std::printf("| %s | %d | %.1f |", phase, last - first + 1, stats[static_cast<std::size_t>(first)].budgetMs);
    nlohmann::json row = {{"phase", phase}, {"frames", last - first + 1}, {"over_budget", over},
                          {"budget_ms", stats[static_cast<std::size_t>(first)].budgetMs}};
    for (std::size_t k = 0; k < stage.size(); ++k) {
        const bench::Spread v = bench::spread(stage[k]);
        std::printf(" %s |", bench::spreadCell(v).c_str());
        row["stages_ms"][garden::stageName(static_cast<garden::Stage>(k))] = bench::spreadJson(v);
    }
    std::printf(" %s | %s | %d |\n", bench::spreadCell(bench::spread(total)).c_str(),
                gpu.empty() ? "-" : bench::spreadCell(bench::spread(gpu)).c_str(), over);
    row["total_ms"] = bench::spreadJson(bench::spread(total));
    row["gpu_ms"] = bench::spreadJson(bench::spread(gpu));
    return row;
}

int runScale(const ScaleOptions& o, const bench::BenchArgs& args, const std::filesystem::path& dir) {
    const std::string gardenPath = writeScaleGarden(dir, o);
    if (gardenPath.empty()) return 1;
    const nlohmann::json script = {
        {"garden", gardenPath},
        {"steps",
         {{{"frames", o.settleFrames}},
          {{"frames", o.walkFrames},
           {"navigation", {{"aim", {{"position", {-0.2, 1.0, -0.3}}}}, {"thumbstick", {0, 1}}}}}}}};
    const std::string scriptPath = (dir / "bench_xr_scale.json").string();
    if (!writeText(scriptPath, script.dump(1))) return 1;
    ::setenv("HG_MOCK_XR_SCRIPT", scriptPath.c_str(), 1);
    if (!o.view.empty()) ::setenv("HG_MOCK_XR_VIEW_SIZE", o.view.c_str(), 1);

    std::vector<garden::FrameStats> frames;
    xr::XrOptions x;
    x.script = scriptPath;
    x.frames = o.settleFrames + o.walkFrames;
    if (!o.quality.empty()) x.quality = garden::qualityOf(*garden::parseQualityPreset(o.quality));
    x.onFrame = [&](const garden::FrameStats& s, int) { frames.push_back(s); };
    std::size_t loading = 0;
    const int status = xr::runXrGarden(x, [&](garden::GardenSession& s, const xr::XrRunInfo&) {
        for (const garden::Sculpture& st : s.sculptures()) loading += st.onShow() ? 0 : 1;
    });
    if (status != 0) return status;
    const int settled = std::min(o.settleFrames, static_cast<int>(frames.size()));
    std::printf("XR frames on the mock runtime at 90 Hz: %d copies of the default garden's sculptures at %d^3, "
                "3 m apart; each eye %s, quality %s. %d frames to load, then %d walking down an aisle "
                "(%zu sculptures not on show at the end). ms per frame: mean / p95 / p99 / max.\n\n",
                o.count, o.resolution, o.view.empty() ? "512x512" : o.view.c_str(),
                o.quality.empty() ? "as set" : o.quality.c_str(), settled,
                static_cast<int>(frames.size()) - settled, loading);
    std::printf("| phase | frames | budget ms |");
    for (int s = 0; s < garden::kStageCount; ++s) std::printf(" %s |", garden::stageName(static_cast<garden::Stage>(s)));
    std::printf(" total | GPU ms | over budget (CPU or GPU) |\n|---|---:|---:|");
    for (int s = 0; s < garden::kStageCount + 2; ++s) std::printf("---|");
    std::printf("---:|\n");
    nlohmann::json rows = nlohmann::json::array();
    if (settled > 0) rows.push_back(spreadRow("loading", frames, 0, settled - 1));
    if (static_cast<int>(frames.size()) > settled)
        rows.push_back(spreadRow("walk", frames, settled, static_cast<int>(frames.size()) - 1));
    if (!args.jsonPath.empty())
        return writeText(args.jsonPath, nlohmann::json{{"sculptures", o.count}, {"resolution", o.resolution},
                                                       {"view", o.view}, {"quality", o.quality}, {"rows", rows}}
                                                .dump(2) + "\n")
                   ? 0
                   : 1;
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    ScaleOptions scale;
    if (!parseOptions(argc, argv, args, scale)) return 2;
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        std::fprintf(stderr, "bench_xr: no X display: run under xvfb-run -a\n");
        return 1;
    }
    ::setenv("XR_RUNTIME_JSON", HG_MOCK_XR_MANIFEST, 1);
    ::unsetenv("HG_MOCK_XR_NO_THROTTLE");
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hg_bench_xr";
    std::filesystem::create_directories(dir);
    if (scale.count > 0) return runScale(scale, args, dir);
    if (!scale.view.empty()) ::setenv("HG_MOCK_XR_VIEW_SIZE", scale.view.c_str(), 1);
    std::string script = kScript;
    script.replace(script.find("%GARDEN%"), 8, std::string(HG_SOURCE_DIR) + "/content/gardens/default.json");
    const std::string scriptPath = (dir / "bench_xr.json").string();
    if (!writeText(scriptPath, script)) return 1;
    ::setenv("HG_MOCK_XR_SCRIPT", scriptPath.c_str(), 1);

    std::vector<garden::FrameStats> frames;
    xr::XrOptions o;
    o.script = scriptPath;
    o.onFrame = [&](const garden::FrameStats& s, int) { frames.push_back(s); };
    std::size_t edits = 0;
    const int status = xr::runXrGarden(o, [&](garden::GardenSession& s, const xr::XrRunInfo&) {
        for (std::size_t i = 0; i < s.sculptures().size(); ++i) edits += s.editCount(static_cast<int>(i));
    });
    if (status != 0) return status;

    std::printf("XR frames on the mock runtime at 90 Hz, default garden, two %s views (%zu edits made)\n\n",
                scale.view.empty() ? "512x512" : scale.view.c_str(), edits);
    std::printf("| phase | frames | budget ms | total ms mean | max |");
    for (int s = 0; s < garden::kStageCount; ++s) std::printf(" %s |", garden::stageName(static_cast<garden::Stage>(s)));
    std::printf(" over budget |\n|---|---|---|---|---|");
    for (int s = 0; s <= garden::kStageCount; ++s) std::printf("---|");
    std::printf("\n");
    nlohmann::json rows = nlohmann::json::array();
    for (const Phase& p : kPhases) {
        const int last = std::min(p.last, static_cast<int>(frames.size()) - 1);
        if (last < p.first) continue;
        double total = 0.0, worst = 0.0, budget = frames[static_cast<std::size_t>(p.first)].budgetMs;
        std::array<double, garden::kStageCount> stage{};
        int over = 0;
        for (int f = p.first; f <= last; ++f) {
            const garden::FrameStats& s = frames[static_cast<std::size_t>(f)];
            total += s.totalMs;
            worst = std::max(worst, s.totalMs);
            over += s.totalMs > s.budgetMs;
            for (int k = 0; k < garden::kStageCount; ++k) stage[static_cast<std::size_t>(k)] += s.stageMs[static_cast<std::size_t>(k)];
        }
        const double n = last - p.first + 1;
        std::printf("| %s | %d | %.1f | %.2f | %.2f |", p.name, static_cast<int>(n), budget, total / n, worst);
        nlohmann::json row = {{"phase", p.name}, {"frames", n}, {"budget_ms", budget}, {"mean_ms", total / n}, {"max_ms", worst},
                              {"over_budget", over}};
        for (int k = 0; k < garden::kStageCount; ++k) {
            std::printf(" %.2f |", stage[static_cast<std::size_t>(k)] / n);
            row["stages_ms"][garden::stageName(static_cast<garden::Stage>(k))] = stage[static_cast<std::size_t>(k)] / n;
        }
        std::printf(" %d |\n", over);
        rows.push_back(row);
    }
    if (!args.jsonPath.empty() && !writeText(args.jsonPath, rows.dump(2) + "\n")) return 1;
    return 0;
}
