// XR frame benchmark (issue 13): the default garden in the mock headset at
// 90 Hz (xrWaitFrame paces the frames, two 512 x 512 views drawn each
// frame), played from a script: a carving stroke with the right hand, a
// walk, a morph to a new blend. CPU time per stage per frame against the
// runtime's predicted display period (11.1 ms). Needs an X display
// (xvfb-run -a) and the mock runtime, which it selects itself.
//
//   xvfb-run -a ./build/release/bench/bench_xr [--json out.json]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"

#include "garden/app/frame_stats.h"
#include "garden/app/garden_session.h"
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

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        std::fprintf(stderr, "bench_xr: no X display: run under xvfb-run -a\n");
        return 1;
    }
    ::setenv("XR_RUNTIME_JSON", HG_MOCK_XR_MANIFEST, 1);
    ::unsetenv("HG_MOCK_XR_NO_THROTTLE");
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hg_bench_xr";
    std::filesystem::create_directories(dir);
    std::string script = kScript;
    script.replace(script.find("%GARDEN%"), 8, std::string(HG_SOURCE_DIR) + "/content/gardens/default.json");
    const std::string scriptPath = (dir / "bench_xr.json").string();
    std::ofstream(scriptPath) << script;
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

    std::printf("XR frames on the mock runtime at 90 Hz, default garden, two 512 x 512 views (%zu edits made)\n\n", edits);
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
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << rows.dump(2) << "\n";
    return 0;
}
