// The running garden, replay-driven (issue 5; docs/design.md §9): GardenSession
// frames played by runReplay, headless (input, level selection, morph,
// remesh) or with --offscreen (the upload and render stages too, through
// OffscreenGarden: a hidden GL 3.3 window; needs xvfb-run -a here).
//
//  1. Morph (seed 004's Table 1): the default garden with every sculpture
//     and the morph at 128^3 and 256^3, the viewer on the path 6.5 m in
//     front of the morph result. From a settled garden with the selector at
//     the triangle's centroid, the selector moves halfway to the dryad; the
//     frames then blend N samples each (N from 1,600 to 1,000,000) and
//     remesh with the scheduler's time (or --remesh-chunks) until the morph
//     and every remesh queue have drained. Per row: frames, mean CPU ms per
//     stage, the frame rate, and the time from the selection until the
//     result is shown whole: back to back (frames as fast as they run) and
//     at 90 Hz (each frame rounded up to whole 11.1 ms display periods).
//  2. Navigation: content/replays/garden_walk.json (the approach path, then
//     one lap of the circuit facing the centre) at 256^3, LOD on and off,
//     for the three key sculptures and the morph result (four sculptures)
//     and for the whole default garden (ten); the garden is settled first,
//     then the walk is timed. Mean, 95th percentile and max CPU ms per frame
//     per stage, chunks remeshed, triangles shown (and drawn, offscreen).
//  3. Scale (issue 25): generated gardens of N copies of the default
//     garden's sculptures on a grid 3 m apart (garden/scene/scale_garden.h),
//     N = 48, 200, 1,000 at --scale-resolution (64^3 by default: these
//     machines have 2 cores), headless, the sculptures sampled in the
//     background nearest first (--scale-load progressive, the default) or
//     all before the first frame (start). Time to the first frame and to a
//     settled garden at the start pose (frames at most 90 a second, the
//     scheduler's time per frame), then a scripted walk (--scale-frames frames down the
//     middle aisle at 1.5 m/s, looking left and right): mean, p95, p99 and
//     max CPU ms per stage and in all, chunks the LOD stage tested,
//     triangles shown, the most new mesh bytes a frame showed (what a
//     renderer uploads; --upload-bytes sets the session's per-frame
//     budget), peak resident memory of the row. --level-error walks a
//     garden for each value of SessionSettings::levelErrorPixels (0: levels
//     by voxel size alone, the peer of levels by measured error).
//
//  4. Stages (issue 21): content/replays/sculpting_session.json (carving)
//     and walk_and_morph.json in timing mode (the morph and the remesh on
//     the scheduler's time), headless, frames paced at 90 Hz, remeshing
//     within the frame and off the frame thread in turn: p99 and max CPU ms
//     per stage, and the frames whose stages before the render went over
//     the budget.
//
// Prints Markdown tables; --json FILE writes the rows too.
//
//   ./build/release/bench/bench_garden [--json FILE] [--filter NAME] [--repeat N]
//       [--offscreen] [--viewport WxH] [--max-frames N] [--remesh-chunks N]
//       [--walk-speed S] [--samples N,N,...] [--resolutions R,R]
//       [--scale N,N,...] [--scale-resolution R] [--scale-frames N]
//       [--scale-load start|progressive] [--upload-bytes N] [--memory-budget MIB]
//       [--draw multi|per-chunk|both] [--quality low|medium|high] [--impostor-distance M,M,...]
//       [--hidden on|off|both] [--level-error P,P,...]
//
// Row names for --filter: morph/128/1600 ... morph/256/1000000,
// nav/keys/lod, nav/keys/nolod, nav/all/lod, nav/all/nolod, scale/48,
// scale/200, scale/1000, cards/48, cards/200, cards/1000 (with --offscreen),
// stages/carve/in-frame, stages/carve/off-thread,
// stages/morph/in-frame, stages/morph/off-thread.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"
#include "../bench_json.h"

#include "garden/app/garden_session.h"
#include "garden/app/memory_report.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/scene/json_reader.h"
#include "garden/scene/scale_garden.h"

#ifdef HG_BENCH_OFFSCREEN
#include "garden/desktop/offscreen_garden.h"
#include "garden/render/gl_context.h"
#endif

namespace {

using namespace hg;
using namespace hg::garden;
using bench::Spread;
using bench::spread;
using bench::spreadCell;
using bench::spreadJson;
using Clock = std::chrono::steady_clock;

constexpr std::uint64_t kUnlimited = std::uint64_t{1} << 40;

struct Options {
    bench::BenchArgs bench;
    bool offscreen = false;
    int width = 1280, height = 720;
    int maxFrames = 30000;
    std::size_t remeshChunks = 0;  // 0: the scheduler's time
    double walkSpeed = 1.0;
    std::vector<std::uint64_t> samples{1600, 6400, 25600, 64000, 250000, 1000000};
    std::vector<int> resolutions{128, 256};
    std::vector<int> scaleCounts{48, 200, 1000};
    int scaleResolution = 64;
    int scaleFrames = 1000;
    bool scaleProgressive = true;
    std::size_t uploadBytes = 0;  // SessionSettings::uploadBytesPerFrame (0: no limit)
    std::size_t memoryBudgetMiB = 1024;  // SessionSettings::memoryBudgetBytes (0: none)
    // Offscreen scale rows: each walk drawn with multi-draw, one call per
    // chunk, or both in turn over the same garden (the peer in the same run).
    std::vector<std::string> drawModes{"multi", "per-chunk"};
    std::vector<double> impostorDistances{30.0};  // offscreen scale rows: one walk each (0: no impostors)
    std::vector<bool> hiddenCulling{true};  // offscreen scale rows: hidden sculptures left out (occlusion queries)
    // Scale rows: SessionSettings::levelErrorPixels, a garden each (0: levels by voxel size alone).
    std::vector<double> levelErrors{SessionSettings{}.levelErrorPixels};
    std::string quality = "high";
    // Offscreen: GardenView::setArenaCompactBytes (0: the arena never
    // compacted; none: the view's default).
    std::optional<std::size_t> arenaCompactBytes;
};

template <class T>
std::vector<T> parseList(const std::string& text) {
    std::vector<T> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
        if (!item.empty()) {
            if constexpr (std::is_floating_point_v<T>) out.push_back(static_cast<T>(std::strtod(item.c_str(), nullptr)));
            else out.push_back(static_cast<T>(std::strtoull(item.c_str(), nullptr, 10)));
        }
    return out;
}

// Our flags first; what is left goes to parseBenchArgs.
bool parseOptions(int argc, char** argv, Options& o) {
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--offscreen") o.offscreen = true;
        else if (a == "--viewport" && hasValue) {
            if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2 || o.width <= 0 || o.height <= 0) {
                std::fprintf(stderr, "--viewport: expected WxH\n");
                return false;
            }
        } else if (a == "--max-frames" && hasValue) o.maxFrames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--remesh-chunks" && hasValue) o.remeshChunks = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--walk-speed" && hasValue) o.walkSpeed = std::clamp(std::atof(argv[++i]), 0.1, 20.0);
        else if (a == "--samples" && hasValue) o.samples = parseList<std::uint64_t>(argv[++i]);
        else if (a == "--resolutions" && hasValue) o.resolutions = parseList<int>(argv[++i]);
        else if (a == "--scale" && hasValue) o.scaleCounts = parseList<int>(argv[++i]);
        else if (a == "--scale-resolution" && hasValue) o.scaleResolution = std::max(16, std::atoi(argv[++i]));
        else if (a == "--scale-frames" && hasValue) o.scaleFrames = std::max(10, std::atoi(argv[++i]));
        else if (a == "--upload-bytes" && hasValue) o.uploadBytes = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--arena-compact-bytes" && hasValue) o.arenaCompactBytes = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--memory-budget" && hasValue) o.memoryBudgetMiB = std::strtoull(argv[++i], nullptr, 10);
        else if (a == "--impostor-distance" && hasValue) o.impostorDistances = parseList<double>(argv[++i]);
        else if (a == "--level-error" && hasValue) o.levelErrors = parseList<double>(argv[++i]);
        else if (a == "--hidden" && hasValue) {
            const std::string how = argv[++i];
            if (how != "on" && how != "off" && how != "both") {
                std::fprintf(stderr, "--hidden: on, off or both\n");
                return false;
            }
            o.hiddenCulling = how == "both" ? std::vector<bool>{true, false} : std::vector<bool>{how == "on"};
        } else if (a == "--draw" && hasValue) {
            const std::string how = argv[++i];
            if (how != "multi" && how != "per-chunk" && how != "both") {
                std::fprintf(stderr, "--draw: multi, per-chunk or both\n");
                return false;
            }
            o.drawModes = how == "both" ? std::vector<std::string>{"multi", "per-chunk"} : std::vector<std::string>{how};
        } else if (a == "--quality" && hasValue) {
            o.quality = argv[++i];
            if (o.quality != "low" && o.quality != "medium" && o.quality != "high") {
                std::fprintf(stderr, "--quality: low, medium or high\n");
                return false;
            }
        }
        else if (a == "--scale-load" && hasValue) {
            const std::string how = argv[++i];
            if (how != "start" && how != "progressive") {
                std::fprintf(stderr, "--scale-load: start or progressive\n");
                return false;
            }
            o.scaleProgressive = how == "progressive";
        }
        else rest.push_back(argv[i]);
    }
    if (!bench::parseBenchArgs(static_cast<int>(rest.size()), rest.data(), o.bench)) {
        std::fprintf(stderr,
                     "       [--offscreen] [--viewport WxH] [--max-frames N] [--remesh-chunks N] [--walk-speed S]\n"
                     "       [--samples N,N,...] [--resolutions R,R] [--scale N,N,...] [--scale-resolution R]\n"
                     "       [--scale-frames N] [--scale-load start|progressive] [--upload-bytes N]\n"
                     "       [--draw multi|per-chunk|both] [--quality low|medium|high] [--memory-budget MIB]\n"
                     "       [--impostor-distance M,M,...] [--hidden on|off|both] [--level-error P,P,...]\n"
                     "       [--arena-compact-bytes N]\n");
        return false;
    }
    return true;
}

// At the start of the upload stage: counts the triangles on show (outside
// any stage; its own time is taken off the frame's total afterwards), then
// uploads and draws when there is a GL renderer behind it.
class Recorder : public FrameRenderer {
public:
    explicit Recorder(FrameRenderer* inner) : inner_(inner) {}
    ViewUpload upload(GardenSession& session, double allowanceMs) override {
        session.scheduler().endStage();
        const auto t0 = Clock::now();
        shown.push_back(session.trianglesShown());
        countMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
        session.scheduler().beginStage(Stage::Upload);
        return inner_ ? inner_->upload(session, allowanceMs) : ViewUpload{};
    }
    ViewDraw render(GardenSession& session) override { return inner_ ? inner_->render(session) : ViewDraw{}; }
    std::string screenshot(const std::string& path) override {
        return inner_ ? inner_->screenshot(path) : "no renderer";
    }
    void clear() {
        shown.clear();
        countMs.clear();
    }
    std::vector<std::size_t> shown;
    std::vector<double> countMs;

private:
    FrameRenderer* inner_;
};

// A session of the default garden with its renderer (offscreen, when asked).
struct Scene {
    std::unique_ptr<GardenSession> session;
#ifdef HG_BENCH_OFFSCREEN
    std::unique_ptr<OffscreenGarden> offscreen;
#endif
    std::unique_ptr<Recorder> recorder;
    double buildSeconds = 0.0;
    int sculptures = 0;
};

std::string defaultGarden() { return std::string(HG_SOURCE_DIR) + "/content/gardens/default.json"; }

// keysOnly: the three key sculptures (the morph's sources) and the result.
std::unique_ptr<Scene> makeScene(const Options& o, int resolution, bool lod, bool keysOnly, std::string& error) {
    GardenLoad load = loadGarden(defaultGarden());
    if (!load.ok() || load.garden->morphs.empty() || !load.morphErrors[0].empty()) {
        error = "default garden: " + load.error + (load.ok() && !load.morphErrors.empty() ? load.morphErrors[0] : " (no morph)");
        return nullptr;
    }
    if (keysOnly) {  // the sources are sculptures 0-2 (the morph refers to them by index)
        for (std::size_t i = 0; i < 3; ++i)
            if (load.garden->morphs[0].sourceIndex[i] != i) {
                error = "the default garden's morph sources are not its first three sculptures";
                return nullptr;
            }
        load.garden->sculptures.resize(3);
        load.sculptures.resize(3);
    }
    SessionSettings settings;
    settings.lod = lod;
    settings.sculptureResolution = resolution;
    settings.morphResolution = resolution;
    settings.viewportHeight = o.height;
    auto scene = std::make_unique<Scene>();
    const auto t0 = Clock::now();
    scene->session = std::make_unique<GardenSession>(std::move(load), settings);
    scene->buildSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    for (const Sculpture& s : scene->session->sculptures()) {
        if (s.missing()) {
            error = "sculpture '" + s.name + "' is missing: " + s.error;
            return nullptr;
        }
        ++scene->sculptures;
    }
    FrameRenderer* inner = nullptr;
#ifdef HG_BENCH_OFFSCREEN
    if (o.offscreen) {
        scene->offscreen = OffscreenGarden::create(o.width, o.height, error);
        if (!scene->offscreen) return nullptr;
        inner = scene->offscreen.get();
    }
#endif
    scene->recorder = std::make_unique<Recorder>(inner);
    return scene;
}

ReplayCommand poseCommand(double x, double y, double z, double yawDeg, double pitchDeg) {
    ReplayCommand c;
    c.kind = ReplayCommand::Kind::Pose;
    c.vec = {x, y, z};
    c.pair = {yawDeg, pitchDeg};
    return c;
}

ReplayCommand morphCommand(double x, double z) {
    ReplayCommand c;
    c.kind = ReplayCommand::Kind::Morph;
    c.pair = {x, z};
    return c;
}

ReplayScript baseScript(const Options& o) {
    ReplayScript s;
    s.file = "bench_garden";
    s.garden = defaultGarden();
    s.timestep = 1.0 / 90.0;
    s.budgetMs = 11.1;
    s.viewport = {o.width, o.height};
    return s;
}

// Plays `script` with unlimited work per frame until it ends (settling).
std::string settle(Scene& scene, const ReplayScript& script) {
    SessionSettings& st = scene.session->settings();
    const std::uint64_t samples = st.morphSamplesPerFrame;
    const std::size_t chunks = st.remeshChunksPerFrame;
    st.morphSamplesPerFrame = kUnlimited;
    st.remeshChunksPerFrame = std::numeric_limits<std::size_t>::max() / 2;
    ReplayResult r = runReplay(script, *scene.session, scene.recorder.get(), ReplayOptions{});
    st.morphSamplesPerFrame = samples;
    st.remeshChunksPerFrame = chunks;
    scene.recorder->clear();
    return r.error;
}

// What a timed run measured, per frame with the recorder's time taken off.
struct Run {
    std::string error;
    std::vector<FrameStats> frames;
    std::vector<std::size_t> shown;
    double wallSeconds = 0.0;
};

Run timedRun(Scene& scene, const ReplayScript& script) {
    Run run;
    scene.recorder->clear();
    const auto t0 = Clock::now();
    ReplayResult r = runReplay(script, *scene.session, scene.recorder.get(), ReplayOptions{});
    run.wallSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    run.error = r.error;
    run.frames = std::move(r.stats);
    run.shown = scene.recorder->shown;
    for (std::size_t i = 0; i < run.frames.size() && i < scene.recorder->countMs.size(); ++i) {
        run.frames[i].totalMs -= scene.recorder->countMs[i];
        run.wallSeconds -= scene.recorder->countMs[i] * 1e-3;
    }
    return run;
}

struct Summary {
    std::array<double, kStageCount> meanStage{}, maxStage{};
    double meanTotal = 0.0, p95Total = 0.0, maxTotal = 0.0;
    double at90HzSeconds = 0.0;  // every frame rounded up to whole display periods
    double samplesPerFrame = 0.0, chunksPerFrame = 0.0, pendingMean = 0.0;
    std::size_t chunksMeshed = 0, chunksShown = 0, overBudget = 0;
    double meanShown = 0.0, meanDrawn = 0.0;
    std::size_t maxShown = 0, maxDrawn = 0;
};

Summary summarize(const Run& run, double budgetMs) {
    Summary s;
    const std::size_t n = run.frames.size();
    if (n == 0) return s;
    std::vector<double> totals;
    for (std::size_t i = 0; i < n; ++i) {
        const FrameStats& f = run.frames[i];
        for (std::size_t k = 0; k < kStageCount; ++k) {
            s.meanStage[k] += f.stageMs[k];
            s.maxStage[k] = std::max(s.maxStage[k], f.stageMs[k]);
        }
        totals.push_back(f.totalMs);
        s.meanTotal += f.totalMs;
        s.maxTotal = std::max(s.maxTotal, f.totalMs);
        s.at90HzSeconds += std::max(1.0, std::ceil(f.totalMs / budgetMs - 1e-9)) * budgetMs * 1e-3;
        s.samplesPerFrame += static_cast<double>(f.morphSamples);
        s.chunksMeshed += f.chunksMeshed;
        s.chunksShown += f.chunksShown;
        s.pendingMean += static_cast<double>(f.remeshPending);
        s.overBudget += f.totalMs > budgetMs ? 1 : 0;
        s.meanDrawn += static_cast<double>(f.trianglesDrawn);
        s.maxDrawn = std::max(s.maxDrawn, f.trianglesDrawn);
        if (i < run.shown.size()) {
            s.meanShown += static_cast<double>(run.shown[i]);
            s.maxShown = std::max(s.maxShown, run.shown[i]);
        }
    }
    const double dn = static_cast<double>(n);
    for (auto& v : s.meanStage) v /= dn;
    s.meanTotal /= dn;
    s.samplesPerFrame /= dn;
    s.chunksPerFrame = static_cast<double>(s.chunksMeshed) / dn;
    s.pendingMean /= dn;
    s.meanShown /= dn;
    s.meanDrawn /= dn;
    std::sort(totals.begin(), totals.end());
    s.p95Total = totals[std::min(n - 1, static_cast<std::size_t>(std::ceil(0.95 * dn)) - 1)];
    return s;
}

double stage(const std::array<double, kStageCount>& a, Stage s) { return a[static_cast<std::size_t>(s)]; }

nlohmann::json stagesJson(const std::array<double, kStageCount>& a) {
    nlohmann::json j = nlohmann::json::object();
    for (int k = 0; k < kStageCount; ++k) j[stageName(static_cast<Stage>(k))] = a[static_cast<std::size_t>(k)];
    return j;
}

// Seed 004, Table 1: frame rate and the metamorphosis' share of the frame.
struct SeedRow {
    std::uint64_t samples;
    double fps, morphPercent;
};
constexpr SeedRow kSeed004[] = {{64000, 1.37, 92.9}, {32000, 2.56, 86.5}, {16000, 4.56, 75.3}, {8000, 7.41, 61.5},
                                {6400, 8.45, 55.8},  {3200, 11.65, 39.6}, {1600, 14.04, 26.7}};

std::string seedColumn(std::uint64_t samples) {
    for (const SeedRow& r : kSeed004)
        if (r.samples == samples) {
            char b[64];
            std::snprintf(b, sizeof b, "%.2f fps (%.0f%%)", r.fps, r.morphPercent);
            return b;
        }
    return "-";
}

// --- 1. the morph ------------------------------------------------------------

void morphTable(const Options& o, nlohmann::json& json) {
    bool anyRow = false;
    for (int res : o.resolutions)
        for (std::uint64_t n : o.samples) anyRow = anyRow || o.bench.matches("morph/" + std::to_string(res) + "/" + std::to_string(n));
    if (!anyRow) return;
    const bool gl = o.offscreen;
    std::printf("Morph: the default garden (every sculpture and the result at RES^3), viewer 6.5 m in front of the\n"
                "result; selector from the centroid to halfway to the dryad; remesh: %s. Mean CPU ms per frame.\n\n",
                o.remeshChunks ? (std::to_string(o.remeshChunks) + " chunks per frame").c_str() : "the scheduler's time");
    std::printf("| res | samples/frame | frames | input | lod | morph | remesh |%s total | max | fps | morph %% | "
                "frames over 11.1 ms | chunks meshed | shown, back to back (s) | shown at 90 Hz (s) | seed 004: fps (morph %%) |\n",
                gl ? " upload | render |" : "");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|%s---:|---:|---:|---:|---:|---:|---:|---:|---|\n", gl ? "---:|---:|" : "");
    std::vector<std::string> notes;
    for (int res : o.resolutions) {
        bool any = false;
        for (std::uint64_t n : o.samples) any = any || o.bench.matches("morph/" + std::to_string(res) + "/" + std::to_string(n));
        if (!any) continue;
        std::string error;
        std::unique_ptr<Scene> scene = makeScene(o, res, true, false, error);
        if (!scene) {
            std::fprintf(stderr, "morph %d: %s\n", res, error.c_str());
            continue;
        }
        std::fprintf(stderr, "morph %d: %d sculptures sampled in %.1f s\n", res, scene->sculptures, scene->buildSeconds);
        std::size_t resultChunks = 0;
        std::uint64_t resultVoxels = 0;
        for (const Sculpture& st : scene->session->sculptures())
            if (st.morphResult()) {
                resultChunks = st.layout->count();
                resultVoxels = st.volume->frame.indexBox.volume();
            }
        std::uint64_t reblendSamples = 0;
        // Where the viewer stands: on the path, 6.5 m in front of the result, looking at its middle.
        ReplayScript place = baseScript(o);
        place.steps.resize(1);
        place.steps[0].commands = {poseCommand(0.0, 1.7, 6.5, 0.0, -6.0)};
        for (std::uint64_t n : o.samples) {
            const std::string name = "morph/" + std::to_string(res) + "/" + std::to_string(n);
            if (!o.bench.matches(name)) continue;
            scene->session->settings().morphSamplesPerFrame = n;
            scene->session->settings().remeshChunksPerFrame = o.remeshChunks;
            // From the settled blend at the centroid to a point halfway to
            // the dryad; best of --repeat by the time on screen at 90 Hz.
            ReplayScript from = baseScript(o), to = baseScript(o);
            from.steps.resize(2);
            from.steps[0].commands = place.steps[0].commands;
            from.steps[0].commands.push_back(morphCommand(0.0, 0.0));
            from.steps[1].untilIdle = true;
            from.steps[1].frames = 100000;
            to.steps.resize(2);
            to.steps[0].commands = {morphCommand(0.0, -2.0)};
            to.steps[1].untilIdle = true;
            to.steps[1].frames = std::max(1, o.maxFrames - 1);
            Run best;
            Summary bestSummary;
            std::vector<double> all;
            for (int r = 0; r < o.bench.repeat; ++r) {
                error = settle(*scene, from);
                if (!error.empty()) break;
                Run run = timedRun(*scene, to);
                if (!run.error.empty() && run.frames.empty()) {
                    error = run.error;
                    break;
                }
                Summary s = summarize(run, to.budgetMs);
                all.push_back(s.at90HzSeconds);
                if (best.frames.empty() || s.at90HzSeconds < bestSummary.at90HzSeconds) {
                    best = std::move(run);
                    bestSummary = s;
                }
            }
            if (best.frames.empty()) {
                std::fprintf(stderr, "%s: %s\n", name.c_str(), error.c_str());
                continue;
            }
            const Summary& s = bestSummary;
            const bool done = best.error.empty();
            reblendSamples = best.frames.front().morphSamples + best.frames.front().morphPending;
            const double fps = 1000.0 / s.meanTotal;
            const double morphPct = 100.0 * stage(s.meanStage, Stage::Morph) / s.meanTotal;
            char glCols[64] = "";
            if (gl)
                std::snprintf(glCols, sizeof glCols, " %.2f | %.2f |", stage(s.meanStage, Stage::Upload),
                              stage(s.meanStage, Stage::Render));
            std::printf("| %d | %llu | %zu%s | %.2f | %.2f | %.2f | %.2f |%s %.2f | %.1f | %.1f | %.0f%% | %zu | %zu | %.2f | %.2f | %s |\n",
                        res, static_cast<unsigned long long>(n), best.frames.size(), done ? "" : " (cap)",
                        stage(s.meanStage, Stage::Input), stage(s.meanStage, Stage::Lod), stage(s.meanStage, Stage::Morph),
                        stage(s.meanStage, Stage::Remesh), glCols, s.meanTotal, s.maxTotal, fps, morphPct, s.overBudget,
                        s.chunksMeshed, best.wallSeconds, s.at90HzSeconds, seedColumn(n).c_str());
            std::fflush(stdout);
            json["morph"].push_back({{"name", name}, {"resolution", res}, {"samples_per_frame", n},
                                     {"sculptures", scene->sculptures}, {"frames", best.frames.size()},
                                     {"drained", done}, {"error", best.error},
                                     {"mean_stage_ms", stagesJson(s.meanStage)}, {"max_stage_ms", stagesJson(s.maxStage)},
                                     {"mean_total_ms", s.meanTotal}, {"p95_total_ms", s.p95Total},
                                     {"max_total_ms", s.maxTotal}, {"fps", fps}, {"morph_percent", morphPct},
                                     {"frames_over_budget", s.overBudget}, {"chunks_meshed", s.chunksMeshed},
                                     {"chunks_shown", s.chunksShown},
                                     {"mean_samples_per_frame", s.samplesPerFrame},
                                     {"shown_back_to_back_s", best.wallSeconds}, {"shown_at_90hz_s", s.at90HzSeconds},
                                     {"shown_at_90hz_s_all_runs", all},
                                     {"last_frame_uploads_pending", best.frames.back().uploadsPending},
                                     {"offscreen", gl}});
        }
        char b[200];
        std::snprintf(b, sizeof b, "%d^3: %d sculptures; the result: %llu voxels in %zu chunks of 32^3, %llu samples per re-blend",
                      res, scene->sculptures, static_cast<unsigned long long>(resultVoxels), resultChunks,
                      static_cast<unsigned long long>(reblendSamples));
        notes.push_back(b);
    }
    std::printf("\n");
    for (const std::string& n : notes) std::printf("%s\n", n.c_str());
    std::printf("\n");
}

// --- 2. navigation -------------------------------------------------------------

void navigationTable(const Options& o, nlohmann::json& json) {
    bool anyRow = false;
    for (const char* n : {"nav/keys/lod", "nav/keys/nolod", "nav/all/lod", "nav/all/nolod"}) anyRow = anyRow || o.bench.matches(n);
    if (!anyRow) return;
    ReplayScript walk;
    const std::string path = std::string(HG_SOURCE_DIR) + "/content/replays/garden_walk.json";
    try {
        walk = loadReplayScript(path);
    } catch (const JsonError& e) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
        return;
    }
    // Settling: every step up to the last until_idle one; then the walk, at
    // --walk-speed times the stroll (the same path in fewer frames).
    std::size_t split = 0;
    for (std::size_t i = 0; i < walk.steps.size(); ++i)
        if (walk.steps[i].untilIdle) split = i + 1;
    ReplayScript settleScript = walk, walkScript = walk;
    settleScript.steps.resize(split);
    walkScript.steps.erase(walkScript.steps.begin(), walkScript.steps.begin() + static_cast<std::ptrdiff_t>(split));
    for (ReplayStep& st : walkScript.steps) {
        st.frames = std::max(1, static_cast<int>(std::lround(st.frames / o.walkSpeed)));
        st.hands.speedScale *= static_cast<float>(o.walkSpeed);
        st.hands.look *= static_cast<float>(o.walkSpeed);
    }
    walkScript.viewport = {o.width, o.height};
    const bool gl = o.offscreen;
    std::printf("Navigation: content/replays/garden_walk.json (approach, one lap of the circuit facing the centre), "
                "walk speed x%.2f, %d frames, 256^3, remesh: %s. CPU ms per frame: mean (max).\n\n",
                o.walkSpeed, walkScript.totalFrames(),
                o.remeshChunks ? (std::to_string(o.remeshChunks) + " chunks per frame").c_str() : "the scheduler's time");
    std::printf("| scene | sculptures | LOD | input | lod | morph | remesh |%s total | total p95 | frames over 11.1 ms | "
                "chunks meshed/frame | new meshes shown | chunks waiting (mean) | triangles shown (mean) | triangles shown (max) |%s\n",
                gl ? " upload | render |" : "", gl ? " triangles drawn (mean) |" : "");
    std::printf("|---|---:|---|---:|---:|---:|---:|%s---:|---:|---:|---:|---:|---:|---:|---:|%s\n", gl ? "---:|---:|" : "",
                gl ? "---:|" : "");
    std::vector<std::string> ratios;
    for (const bool keysOnly : {true, false}) {
        double shownOn = 0.0, shownOff = 0.0, drawnOn = 0.0, drawnOff = 0.0;
        const std::string sceneName = keysOnly ? "keys" : "all";
        for (const bool lod : {true, false}) {
            const std::string name = "nav/" + sceneName + "/" + (lod ? "lod" : "nolod");
            if (!o.bench.matches(name)) continue;
            Run best;
            Summary bestSummary;
            int sculptures = 0;
            std::vector<double> allMeans;
            std::string error;
            for (int r = 0; r < o.bench.repeat; ++r) {
                // A fresh session each time: the walk starts from the same settled state.
                std::unique_ptr<Scene> scene = makeScene(o, 256, lod, keysOnly, error);
                if (!scene) break;
                sculptures = scene->sculptures;
                scene->session->settings().morphSamplesPerFrame = 0;
                scene->session->settings().remeshChunksPerFrame = o.remeshChunks;
                error = settle(*scene, settleScript);
                if (!error.empty()) break;
                Run run = timedRun(*scene, walkScript);
                if (!run.error.empty()) {
                    error = run.error;
                    break;
                }
                Summary s = summarize(run, walkScript.budgetMs);
                allMeans.push_back(s.meanTotal);
                if (best.frames.empty() || s.meanTotal < bestSummary.meanTotal) {
                    best = std::move(run);
                    bestSummary = s;
                }
            }
            if (best.frames.empty()) {
                std::fprintf(stderr, "%s: %s\n", name.c_str(), error.c_str());
                continue;
            }
            const Summary& s = bestSummary;
            auto cell = [&](Stage st) {
                char b[48];
                std::snprintf(b, sizeof b, "%.2f (%.1f)", stage(s.meanStage, st), stage(s.maxStage, st));
                return std::string(b);
            };
            std::string glCols, drawn;
            if (gl) {
                glCols = " " + cell(Stage::Upload) + " | " + cell(Stage::Render) + " |";
                drawn = " " + std::to_string(static_cast<long long>(std::llround(s.meanDrawn))) + " |";
            }
            std::printf("| %s | %d | %s | %s | %s | %s | %s |%s %.2f (%.1f) | %.2f | %zu of %zu | %.1f | %zu | %.1f | %.0f | %zu |%s\n",
                        keysOnly ? "three keys + morph result" : "default garden", sculptures, lod ? "on" : "off",
                        cell(Stage::Input).c_str(), cell(Stage::Lod).c_str(), cell(Stage::Morph).c_str(),
                        cell(Stage::Remesh).c_str(), glCols.c_str(), s.meanTotal, s.maxTotal, s.p95Total,
                        s.overBudget, best.frames.size(), s.chunksPerFrame, s.chunksShown, s.pendingMean, s.meanShown, s.maxShown,
                        drawn.c_str());
            std::fflush(stdout);
            (lod ? shownOn : shownOff) = s.meanShown;
            (lod ? drawnOn : drawnOff) = s.meanDrawn;
            json["navigation"].push_back({{"name", name}, {"sculptures", sculptures}, {"resolution", 256},
                                          {"lod", lod}, {"frames", best.frames.size()}, {"walk_speed", o.walkSpeed},
                                          {"mean_stage_ms", stagesJson(s.meanStage)},
                                          {"max_stage_ms", stagesJson(s.maxStage)}, {"mean_total_ms", s.meanTotal},
                                          {"p95_total_ms", s.p95Total}, {"max_total_ms", s.maxTotal},
                                          {"mean_total_ms_all_runs", allMeans}, {"frames_over_budget", s.overBudget},
                                          {"chunks_meshed_per_frame", s.chunksPerFrame},
                                          {"chunks_shown", s.chunksShown},
                                          {"chunks_waiting_mean", s.pendingMean},
                                          {"triangles_shown_mean", s.meanShown}, {"triangles_shown_max", s.maxShown},
                                          {"triangles_drawn_mean", s.meanDrawn}, {"triangles_drawn_max", s.maxDrawn},
                                          {"offscreen", gl}});
        }
        if (shownOn > 0.0 && shownOff > 0.0) {
            char b[160];
            std::snprintf(b, sizeof b, "%s: triangles shown LOD off / on %.2fx", sceneName.c_str(), shownOff / shownOn);
            std::string line = b;
            if (drawnOn > 0.0) {
                std::snprintf(b, sizeof b, ", triangles drawn LOD off / on %.2fx", drawnOff / drawnOn);
                line += b;
            }
            ratios.push_back(line);
            json["navigation_ratio"].push_back({{"scene", sceneName}, {"triangles_shown_off_over_on", shownOff / shownOn},
                                                {"triangles_drawn_off_over_on", drawnOn > 0.0 ? drawnOff / drawnOn : 0.0}});
        }
    }
    std::printf("\n");
    for (const std::string& line : ratios) std::printf("%s\n", line.c_str());
    std::printf("\n");
}


// --- 3. scale --------------------------------------------------------------------

// The process' peak resident set (VmHWM), and its reset (Linux: writing 5
// to clear_refs), so that each row reports its own peak.
std::uint64_t peakResidentBytes() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::strtoull(line.c_str() + 6, nullptr, 10) * 1024;
    return 0;
}
void resetPeakResident() { std::ofstream("/proc/self/clear_refs") << "5"; }



// The walk: down the aisle between the middle columns, from the start
// (two rows before the grid) at 1.5 m/s, turning the head 35 degrees left
// and right every 8 s, one pose per frame.
ReplayScript scaleWalk(const Options& o, int count, double spacing) {
    ReplayScript s = baseScript(o);
    const double x = scaleGardenColumns(count) % 2 ? 0.5 * spacing : 0.0;
    for (int f = 0; f < o.scaleFrames; ++f) {
        const double t = f * s.timestep;
        ReplayStep step;
        step.commands = {poseCommand(x, 1.7, 2.0 * spacing - 1.5 * t, 35.0 * std::sin(2.0 * M_PI * t / 8.0), -8.0)};
        s.steps.push_back(step);
    }
    return s;
}

// Frames from the start pose until the session is idle (nothing left to
// sample, mesh or upload), at most 90 a second: the garden settling as a
// display would pace it. The number of frames, or 0 when it did not settle
// within --max-frames. With `frameMs`, each frame's time (what a visitor
// feels while the garden loads).
std::size_t settle(const Options& o, Scene& scene, const ReplayScript& walk, std::vector<double>* frameMs = nullptr) {
    ReplayScript start = baseScript(o);
    start.steps.assign(walk.steps.begin(), walk.steps.begin() + 1);
    ReplayResult r = runReplay(start, *scene.session, scene.recorder.get(), ReplayOptions{});
    if (!r.ok()) return 0;
    std::size_t frames = 1;
    for (; !scene.session->idle() && frames < static_cast<std::size_t>(o.maxFrames); ++frames) {
        const auto f0 = Clock::now();
        scene.session->frame(FrameInput{}, *scene.recorder);
        if (frameMs) frameMs->push_back(std::chrono::duration<double, std::milli>(Clock::now() - f0).count());
        std::this_thread::sleep_until(f0 + std::chrono::microseconds(11111));
    }
    scene.recorder->clear();
    return scene.session->idle() ? frames : 0;
}


// The scale garden of `n` copies for row `name`; none (and a message) when it cannot be read.
std::optional<GardenLoad> scaleLoad(const Options& o, const std::string& name, int n, double spacing) {
    ScaleGardenSpec spec;
    spec.count = n;
    spec.spacing = spacing;
    spec.resolution = o.scaleResolution;
    GardenLoad load = loadScaleGarden(defaultGarden(), spec);
    if (load.ok()) return load;
    std::fprintf(stderr, "%s: %s\n", name.c_str(), load.error.c_str());
    return std::nullopt;
}

void scaleTable(const Options& o, nlohmann::json& json) {
    bool anyRow = false;
    for (int n : o.scaleCounts) anyRow = anyRow || o.bench.matches("scale/" + std::to_string(n));
    if (!anyRow) return;
    constexpr double kSpacing = 3.0;
    const bool gl = o.offscreen;
    std::printf("Scale: N copies of the default garden's sculptures on a grid %.0f m apart at %d^3, %s, sampled %s; "
                "the walk: %d frames down the middle aisle at 1.5 m/s. CPU ms per frame: mean / p95 / p99 / max.\n\n",
                kSpacing, o.scaleResolution,
                gl ? ("drawn offscreen at " + std::to_string(o.width) + " x " + std::to_string(o.height) + ", quality " +
                      o.quality)
                           .c_str()
                   : "headless",
                o.scaleProgressive ? "in the background, nearest first" : "before the first frame", o.scaleFrames);
    // Printed before the first row, after the GL line that names the card.
    bool headed = false;
    auto head = [&] {
        if (headed) return;
        headed = true;
        std::printf("| sculptures | level error (px) | chunks | first frame (s) | loading at first frame | settled (s) | frame while settling | %sinput | lod | remesh | %stotal | "
                    "frames over 11.1 ms | chunks tested by LOD (mean) | triangles shown (mean) | %snew mesh KiB per frame (max) | "
                    "peak memory (MiB) | held after the walk: grids / levels / meshes / morph sources (MiB), grids on disk |%s\n",
                    gl ? "draw | " : "", gl ? "upload | render | GPU ms | " : "",
                    gl ? "chunks drawn (mean) | impostors drawn (mean) | sculptures hidden (mean) | triangles drawn (mean) | "
                         "draw calls (mean) | "
                       : "",
                    gl ? " GPU arena after the walk: held / used (MiB), pages (made), moved (MiB) |" : "");
        std::printf("|---:|---:|---:|---:|---:|---:|---|%s---|---|---|%s---|---:|---:|---:|%s---:|---:|---|%s\n", gl ? "---|" : "",
                    gl ? "---|---|---|" : "", gl ? "---:|---:|---:|---:|---:|" : "", gl ? "---|" : "");
    };
    for (int n : o.scaleCounts)
    for (double levelError : o.levelErrors) {
        const std::string name = "scale/" + std::to_string(n);
        if (!o.bench.matches(name)) continue;
        resetPeakResident();
        const auto t0 = Clock::now();
        std::optional<GardenLoad> loaded = scaleLoad(o, name, n, kSpacing);
        if (!loaded) continue;
        GardenLoad& load = *loaded;
        SessionSettings settings;
        settings.viewportHeight = o.height;
        settings.remeshChunksPerFrame = o.remeshChunks;
        settings.progressiveLoading = o.scaleProgressive;
        settings.uploadBytesPerFrame = o.uploadBytes;
        settings.memoryBudgetBytes = o.memoryBudgetMiB << 20;
        settings.levelErrorPixels = levelError;
        Scene scene;
        FrameRenderer* inner = nullptr;
#ifdef HG_BENCH_OFFSCREEN
        if (gl) {
            std::string error;
            scene.offscreen = OffscreenGarden::create(o.width, o.height, error);
            if (!scene.offscreen) {
                std::fprintf(stderr, "%s: %s\n", name.c_str(), error.c_str());
                return;
            }
            scene.offscreen->setQuality(qualityOf(*parseQualityPreset(o.quality)));
            if (o.arenaCompactBytes) scene.offscreen->setArenaCompactBytes(*o.arenaCompactBytes);
            static bool named = false;  // the card, once: GPU figures mean nothing without it
            if (!named) std::printf("GL: %s\n\n", GlWindow::glVersionString().c_str());
            std::fflush(stdout);
            named = true;
            inner = scene.offscreen.get();
        }
#endif
        scene.session = std::make_unique<GardenSession>(std::move(load), settings);
        scene.recorder = std::make_unique<Recorder>(inner);
        const ReplayScript walk = scaleWalk(o, n, kSpacing);
        // The first frame, then frames at 90 Hz at most (a display's pace:
        // sampling goes on in the background meanwhile) until settled.
        ReplayScript first = baseScript(o);
        first.steps.assign(walk.steps.begin(), walk.steps.begin() + 1);
        ReplayResult r = runReplay(first, *scene.session, scene.recorder.get(), ReplayOptions{});
        const double firstFrame = std::chrono::duration<double>(Clock::now() - t0).count();
        const std::size_t loadingAtFirst = r.stats.empty() ? 0 : r.stats.back().sculpturesLoading;
        std::vector<double> settlingMs;
        const std::size_t settleFrames = r.ok() ? settle(o, scene, walk, &settlingMs) : 0;
        const double settled = std::chrono::duration<double>(Clock::now() - t0).count();
        if (settleFrames == 0) {
            std::fprintf(stderr, "%s: %s\n", name.c_str(), r.ok() ? "not settled within --max-frames" : r.error.c_str());
            continue;
        }
        // Offscreen: each draw mode with each impostor distance, walked in turn.
        struct Mode {
            std::string draw;
            double cards = 0.0;
            bool hidden = false;  // hidden sculptures left out
        };
        std::vector<Mode> modes;
        for (const std::string& d : gl ? o.drawModes : std::vector<std::string>{""})
            for (double cards : gl ? o.impostorDistances : std::vector<double>{0.0})
                for (bool hidden : gl ? o.hiddenCulling : std::vector<bool>{false}) modes.push_back({d, cards, hidden});
        for (std::size_t m = 0; m < modes.size(); ++m) {
#ifdef HG_BENCH_OFFSCREEN
            if (gl && !scene.offscreen->setMultiDraw(modes[m].draw == "multi")) {
                std::fprintf(stderr, "%s: this GL has no multi-draw (GL 4.3)\n", name.c_str());
                continue;
            }
            if (gl) scene.offscreen->setImpostorDistance(static_cast<float>(modes[m].cards));
            if (gl) scene.offscreen->setOcclusionCulling(modes[m].hidden);
#endif
            // Back at the start and settled again: each mode walks the same garden from the same state.
            if (m > 0 && settle(o, scene, walk) == 0) {
                std::fprintf(stderr, "%s: not settled again within --max-frames\n", name.c_str());
                continue;
            }
            Run run = timedRun(scene, walk);
            if (!run.error.empty()) {
                std::fprintf(stderr, "%s: %s\n", name.c_str(), run.error.c_str());
                continue;
            }
            std::array<std::vector<double>, kStageCount> perStage;
            std::vector<double> totals, visited, shown, gpu, calls, drawn, triangles, cards, hidden;
            std::size_t over = 0, bytesMax = 0;
            for (std::size_t i = 0; i < run.frames.size(); ++i) {
                const FrameStats& f = run.frames[i];
                for (std::size_t k = 0; k < kStageCount; ++k) perStage[k].push_back(f.stageMs[k]);
                totals.push_back(f.totalMs);
                visited.push_back(static_cast<double>(f.lodChunksVisited));
                shown.push_back(i < run.shown.size() ? static_cast<double>(run.shown[i]) : 0.0);
                if (f.gpuMs >= 0.0) gpu.push_back(f.gpuMs);
                calls.push_back(static_cast<double>(f.drawCalls));
                drawn.push_back(static_cast<double>(f.chunksDrawn));
                triangles.push_back(static_cast<double>(f.trianglesDrawn));
                cards.push_back(static_cast<double>(f.impostorsDrawn));
                hidden.push_back(static_cast<double>(f.sculpturesHidden));
                over += f.totalMs > 11.1 ? 1 : 0;
                bytesMax = std::max(bytesMax, f.meshBytesShown);
            }
            auto stage = [&](Stage st) { return spread(perStage[static_cast<std::size_t>(st)]); };
            std::size_t chunks = 0;
            for (const Sculpture& st : scene.session->sculptures())
                if (st.layout) chunks += st.layout->count();
            const double peakMiB = static_cast<double>(peakResidentBytes()) / (1024.0 * 1024.0);
            const MemoryReport held = memoryReport(*scene.session);
            auto mib = [](std::size_t b) { return static_cast<double>(b) / (1024.0 * 1024.0); };
            char heldCell[128];
            std::snprintf(heldCell, sizeof heldCell, "%.0f / %.0f / %.0f / %.0f, %zu", mib(held.grids), mib(held.levels),
                          mib(held.meshes), mib(held.morphSources), held.pagedOut);
            std::string drawColumns, glColumns, countColumns, arenaColumn;
            nlohmann::json arenaJson;
#ifdef HG_BENCH_OFFSCREEN
            if (gl) {
                const OffscreenGarden::ArenaUse a = scene.offscreen->arenaUse();
                char b[128];
                std::snprintf(b, sizeof b, " %.0f / %.0f, %zu (%zu), %.0f |", mib(a.capacityBytes), mib(a.usedBytes), a.pages,
                              a.pagesMade, mib(a.bytesMoved));
                arenaColumn = b;
                arenaJson = {{"capacity_bytes", a.capacityBytes}, {"used_bytes", a.usedBytes}, {"pages", a.pages},
                             {"pages_made", a.pagesMade}, {"bytes_moved", a.bytesMoved},
                             {"compact_bytes_per_frame", a.compactBytesPerFrame}};
            }
#endif
            if (gl) {
                char mode[64];
                const char* culling = modes[m].hidden ? "hidden left out" : "all drawn";
                if (modes[m].cards > 0.0)
                    std::snprintf(mode, sizeof mode, "%s, cards beyond %.0f m, %s", modes[m].draw.c_str(), modes[m].cards,
                                  culling);
                else
                    std::snprintf(mode, sizeof mode, "%s, no cards, %s", modes[m].draw.c_str(), culling);
                drawColumns = std::string(mode) + " | ";
                glColumns = spreadCell(stage(Stage::Upload)) + " | " + spreadCell(stage(Stage::Render)) + " | " +
                            (gpu.empty() ? std::string("-") : spreadCell(spread(gpu))) + " | ";
                char b[128];
                std::snprintf(b, sizeof b, "%.0f | %.0f | %.1f | %.0f | %.1f | ", spread(drawn).mean, spread(cards).mean,
                              spread(hidden).mean, spread(triangles).mean, spread(calls).mean);
                countColumns = b;
            }
            head();
            char errorCell[32];
            std::snprintf(errorCell, sizeof errorCell, "%.2f", levelError);
            const std::string levelErrorCell = levelError > 0.0 ? errorCell : "none (voxel size)";
            std::printf("| %d | %s | %zu | %.2f | %zu | %.1f (%zu frames) | %s | %s%s | %s | %s | %s%s | %zu of %zu | %.0f | %.0f | %s%.0f | %.0f | %s |%s\n",
                        n, levelErrorCell.c_str(), chunks, firstFrame, loadingAtFirst, settled, settleFrames,
                        spreadCell(spread(settlingMs)).c_str(), drawColumns.c_str(),
                        spreadCell(stage(Stage::Input)).c_str(), spreadCell(stage(Stage::Lod)).c_str(),
                        spreadCell(stage(Stage::Remesh)).c_str(), glColumns.c_str(), spreadCell(spread(totals)).c_str(),
                        over, run.frames.size(), spread(visited).mean, spread(shown).mean, countColumns.c_str(),
                        static_cast<double>(bytesMax) / 1024.0, peakMiB, heldCell, arenaColumn.c_str());
            std::fflush(stdout);
            nlohmann::json stages = nlohmann::json::object();
            for (int k = 0; k < kStageCount; ++k)
                stages[stageName(static_cast<Stage>(k))] = spreadJson(spread(perStage[static_cast<std::size_t>(k)]));
            json["scale"].push_back({{"name", name}, {"sculptures", n}, {"resolution", o.scaleResolution},
                                     {"chunks", chunks}, {"first_frame_s", firstFrame}, {"settled_s", settled},
                                     {"level_error_pixels", levelError},
                                     {"progressive", o.scaleProgressive}, {"loading_at_first_frame", loadingAtFirst},
                                     {"upload_bytes_per_frame", o.uploadBytes}, {"mesh_bytes_shown_max", bytesMax},
                                     {"settle_frames", settleFrames}, {"walk_frames", run.frames.size()},
                                     {"settling_frame_ms", spreadJson(spread(settlingMs))},
                                     {"offscreen", gl}, {"draw", modes[m].draw}, {"quality", gl ? o.quality : ""},
                                     {"impostor_distance", modes[m].cards},
                                     {"impostors_drawn", spreadJson(spread(cards))},
                                     {"hidden_left_out", modes[m].hidden},
                                     {"sculptures_hidden", spreadJson(spread(hidden))},
                                     {"viewport", {o.width, o.height}},
                                     {"stage_ms", stages}, {"total_ms", spreadJson(spread(totals))},
                                     {"gpu_ms", spreadJson(spread(gpu))}, {"draw_calls", spreadJson(spread(calls))},
                                     {"chunks_drawn", spreadJson(spread(drawn))},
                                     {"triangles_drawn", spreadJson(spread(triangles))},
                                     {"frames_over_budget", over}, {"lod_chunks_visited", spreadJson(spread(visited))},
                                     {"triangles_shown", spreadJson(spread(shown))}, {"peak_resident_bytes", peakResidentBytes()},
                                     {"held_bytes", {{"grids", held.grids}, {"levels", held.levels}, {"meshes", held.meshes},
                                                     {"edit_bases", held.editBases}, {"morph_sources", held.morphSources}}},
                                     {"gpu_arena", arenaJson}});
        }
    }
    std::printf("\n");
}

// The render stage alone with and without impostors (issue 25): the scale
// garden settled headless from the visitor's start, then drawn offscreen
// from there, each impostor distance in turn after the cards are baked;
// the render's wall time per frame includes glFinish (on llvmpipe, the
// rasterizing itself).
void cardsTable(const Options& o, nlohmann::json& json) {
#ifdef HG_BENCH_OFFSCREEN
    if (!o.offscreen) return;
    bool anyRow = false;
    for (int n : o.scaleCounts) anyRow = anyRow || o.bench.matches("cards/" + std::to_string(n));
    if (!anyRow) return;
    constexpr int kFrames = 30;
    std::printf("Impostors: the scale garden (3 m apart, %d^3) from the visitor's start, drawn offscreen at %d x %d, "
                "quality %s, %d frames each: render ms per frame (draw calls, then glFinish) mean / p95 / p99 / max.\n\n",
                o.scaleResolution, o.width, o.height, o.quality.c_str(), kFrames);
    bool headed = false;
    for (int n : o.scaleCounts) {
        const std::string name = "cards/" + std::to_string(n);
        if (!o.bench.matches(name)) continue;
        std::optional<GardenLoad> load = scaleLoad(o, name, n, 3.0);
        if (!load) continue;
        SessionSettings settings;
        settings.viewportHeight = o.height;
        settings.remeshChunksPerFrame = 4096;
        GardenSession session(std::move(*load), settings);
        session.finishLoading();
        for (int f = 0; f < o.maxFrames && !session.idle(); ++f) session.frame(FrameInput{});
        std::string error;
        std::unique_ptr<OffscreenGarden> offscreen = OffscreenGarden::create(o.width, o.height, error);
        if (!offscreen) {
            std::fprintf(stderr, "%s: %s\n", name.c_str(), error.c_str());
            return;
        }
        offscreen->setQuality(qualityOf(*parseQualityPreset(o.quality)));
        if (!headed) {
            std::printf("GL: %s\n\n", GlWindow::glVersionString().c_str());
            std::printf("| sculptures | impostors beyond | render ms | chunks drawn | impostors drawn | impostors baked | "
                        "triangles drawn | draw calls | bake ms (first frames) |\n|---:|---|---|---:|---:|---:|---:|---:|---:|\n");
            headed = true;
        }
        for (double distance : o.impostorDistances) {
            offscreen->setImpostorDistance(static_cast<float>(distance));
            // Uploads, then the frames that ask for cards and bake them.
            const auto bakeStart = Clock::now();
            for (int f = 0; f < 4; ++f) {
                offscreen->upload(session, 1e9);
                offscreen->render(session);
            }
            for (int f = 0; f < 200; ++f) {  // two bakes a frame: until every card is baked
                offscreen->upload(session, 1e9);
                const ViewDraw d = offscreen->render(session);
                (void)d;
                if (f > 0 && offscreen->impostorsWanted() == 0) break;
            }
            const double bakeMs = std::chrono::duration<double, std::milli>(Clock::now() - bakeStart).count();
            std::vector<double> ms;
            ViewDraw last;
            for (int f = 0; f < kFrames; ++f) {
                const auto t = Clock::now();
                last = offscreen->render(session);
                ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t).count());
            }
            char cards[48];
            if (distance > 0.0) std::snprintf(cards, sizeof cards, "%.0f m", distance);
            else std::snprintf(cards, sizeof cards, "none");
            const std::size_t baked = offscreen->impostorsBaked();
            std::printf("| %d | %s | %s | %zu | %zu | %zu | %zu | %zu | %.0f |\n", n, cards, spreadCell(spread(ms)).c_str(),
                        last.chunksDrawn, last.impostorsDrawn, baked, last.trianglesDrawn, last.drawCalls, bakeMs);
            std::fflush(stdout);
            json["cards"].push_back({{"name", name}, {"sculptures", n}, {"resolution", o.scaleResolution},
                                     {"impostor_distance", distance}, {"render_ms", spreadJson(spread(ms))},
                                     {"chunks_drawn", last.chunksDrawn}, {"impostors_drawn", last.impostorsDrawn},
                                     {"impostors_baked", baked}, {"triangles_drawn", last.trianglesDrawn},
                                     {"draw_calls", last.drawCalls}, {"bake_ms", bakeMs},
                                     {"viewport", {o.width, o.height}}, {"quality", o.quality}});
        }
    }
    std::printf("\n");
#else
    (void)o;
    (void)json;
#endif
}

}  // namespace

// --- 4. the frame thread's stages (issue 21) ------------------------------------

// The render stage of a display: each frame's render returns at the next
// 11.1 ms mark after the last (vsync), so the frames come at 90 a second
// and the worker meshes while the frame waits there, as it would in a
// window or a headset. Headless otherwise.
class PacedSink : public FrameRenderer {
public:
    ViewUpload upload(GardenSession&, double) override { return {}; }
    ViewDraw render(GardenSession&) override {
        next_ = std::max(next_ + std::chrono::microseconds(11111), Clock::now());
        std::this_thread::sleep_until(next_);
        return {};
    }
    std::string screenshot(const std::string&) override { return ""; }  // nothing drawn, nothing to take

private:
    Clock::time_point next_ = Clock::now();
};

// The carving and morph replays in timing mode (the scheduler's time for
// the morph and the remesh), with remeshing within the frame and off the
// frame thread (with the edits' grid updates spread over frames, as the
// window and the headset run), one after the other on the same machine: per stage p99 and
// max, and the frames whose stages before the render (input, levels,
// morph, remesh) went over the 11.1 ms budget.
void stagesTable(const Options& o, nlohmann::json& json) {
    struct Replay {
        const char* name;
        const char* file;
    };
    const Replay replays[] = {{"carve", "sculpting_session.json"}, {"morph", "walk_and_morph.json"}};
    const char* modes[] = {"in-frame", "off-thread"};
    bool anyRow = false;
    for (const Replay& r : replays)
        for (const char* m : modes) anyRow = anyRow || o.bench.matches(std::string("stages/") + r.name + "/" + m);
    if (!anyRow) return;
    std::printf("Stages before the render: content/replays' carving and morph replays, headless, the morph and the\n"
                "remesh on the scheduler's time, frames paced at 90 Hz. in-frame: meshing and blending in the\n"
                "frame, edits whole; off-thread: meshing and blending off the frame thread (the frame writes the\n"
                "blend's batches) and edits spread over frames (the window's and the headset's settings).\n"
                "CPU ms per frame: p99 / max.\n\n");
    std::printf("| replay | work | frames | input | lod | morph | remesh | before render | frames over 11.1 ms | "
                "chunks meshed | played in (s) |\n");
    std::printf("|---|---|---:|---|---|---|---|---|---:|---:|---:|\n");
    for (const Replay& rp : replays)
        for (const char* mode : modes) {
            const std::string row = std::string("stages/") + rp.name + "/" + mode;
            if (!o.bench.matches(row)) continue;
            const std::string path = std::string(HG_SOURCE_DIR) + "/content/replays/" + rp.file;
            ReplayScript script;
            try {
                script = loadReplayScript(path);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "%s: %s\n", row.c_str(), e.what());
                continue;
            }
            GardenLoad load = loadGarden(script.garden);
            if (!load.ok()) {
                std::fprintf(stderr, "%s: %s\n", row.c_str(), load.error.c_str());
                continue;
            }
            SessionSettings settings;
            settings.remeshChunksPerFrame = 0;
            settings.morphSamplesPerFrame = 0;
            settings.workOffFrameThread = std::string(mode) == "off-thread";
            settings.spreadEdits = settings.workOffFrameThread;
            settings.viewportHeight = script.viewport[1];
            GardenSession session(std::move(load), settings);
            PacedSink sink;
            const auto t0 = Clock::now();
            ReplayResult r = runReplay(script, session, &sink, ReplayOptions{});
            const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
            if (!r.ok()) {
                std::fprintf(stderr, "%s: %s\n", row.c_str(), r.error.c_str());
                continue;
            }
            std::array<std::vector<double>, kStageCount> per;
            std::vector<double> before;
            std::size_t over = 0, meshed = 0;
            for (const FrameStats& f : r.stats) {
                for (std::size_t k = 0; k < kStageCount; ++k) per[k].push_back(f.stageMs[k]);
                const double b = stage(f.stageMs, Stage::Input) + stage(f.stageMs, Stage::Lod) +
                                 stage(f.stageMs, Stage::Morph) + stage(f.stageMs, Stage::Remesh) +
                                 stage(f.stageMs, Stage::Upload);
                before.push_back(b);
                over += b > 11.1 ? 1 : 0;
                if (b > 11.1 && std::getenv("HG_BENCH_VERBOSE"))
                    std::fprintf(stderr, "%s frame %llu: input %.2f lod %.2f morph %.2f remesh %.2f upload %.2f\n",
                                 row.c_str(), static_cast<unsigned long long>(f.frame), stage(f.stageMs, Stage::Input),
                                 stage(f.stageMs, Stage::Lod), stage(f.stageMs, Stage::Morph),
                                 stage(f.stageMs, Stage::Remesh), stage(f.stageMs, Stage::Upload));
                meshed += f.chunksMeshed;
            }
            auto cell = [](const std::vector<double>& v) {
                const Spread s = spread(v);
                char b[48];
                std::snprintf(b, sizeof b, "%.2f / %.2f", s.p99, s.max);
                return std::string(b);
            };
            auto at = [&per](Stage s) -> const std::vector<double>& { return per[static_cast<std::size_t>(s)]; };
            std::printf("| %s | %s | %zu | %s | %s | %s | %s | %s | %zu | %zu | %.1f |\n", rp.name, mode, r.stats.size(),
                        cell(at(Stage::Input)).c_str(), cell(at(Stage::Lod)).c_str(), cell(at(Stage::Morph)).c_str(),
                        cell(at(Stage::Remesh)).c_str(), cell(before).c_str(), over, meshed, seconds);
            std::fflush(stdout);
            nlohmann::json j = {{"name", row}, {"frames", r.stats.size()}, {"over_budget", over},
                                {"chunks_meshed", meshed}, {"seconds", seconds},
                                {"before_render", spreadJson(spread(before))}};
            for (int k = 0; k < kStageCount; ++k)
                j["stages"][stageName(static_cast<Stage>(k))] = spreadJson(spread(per[static_cast<std::size_t>(k)]));
            json["stages"].push_back(j);
        }
    std::printf("\n");
}

int main(int argc, char** argv) {
    Options o;
    if (!parseOptions(argc, argv, o)) return 2;
#ifndef HG_BENCH_OFFSCREEN
    if (o.offscreen) {
        std::fprintf(stderr, "--offscreen: this build has no renderer (configure with HG_BUILD_APP=ON)\n");
        return 2;
    }
#endif
    nlohmann::json json = {{"morph", nlohmann::json::array()}, {"navigation", nlohmann::json::array()},
                           {"navigation_ratio", nlohmann::json::array()}, {"scale", nlohmann::json::array()},
                           {"stages", nlohmann::json::array()}, {"cards", nlohmann::json::array()}};
    json["options"] = {{"offscreen", o.offscreen}, {"viewport", {o.width, o.height}}, {"max_frames", o.maxFrames},
                       {"remesh_chunks", o.remeshChunks}, {"walk_speed", o.walkSpeed}, {"repeat", o.bench.repeat},
                       {"scale_resolution", o.scaleResolution}, {"scale_frames", o.scaleFrames},
                       {"upload_bytes", o.uploadBytes}};
    morphTable(o, json);
    navigationTable(o, json);
    scaleTable(o, json);
    cardsTable(o, json);
    stagesTable(o, json);
    if (!o.bench.jsonPath.empty()) std::ofstream(o.bench.jsonPath) << json.dump(2) << "\n";
    return 0;
}
