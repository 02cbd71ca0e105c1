// Morph blend benchmark: the default garden's three key sculptures as morph
// sources at 128^3 and 256^3 (longest side of the shared box), blended from
// scratch and by budgeted partial updates of a million samples per step
// (docs/design.md §9: at least 1,000,000 samples per frame inside the budget). The
// peer, measured in the same run, is a plain single-threaded loop over three
// float arrays computing the same clamped weighted sum into a fourth (the
// streaming bound, no grid). A second table drains the same change off the
// frame thread (MorphBlender::stepInBackground, a jobs::JobThread computing
// the batches) and compares the frame thread's time per million samples
// with the in-frame steps' of the first table. Prints Markdown tables;
// --json FILE writes the rows too.
//
//   ./build/release/bench/bench_morph [--json out.json] [--filter NAME] [--repeat N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "../bench_common.h"

#include "garden/morph/garden_morph.h"
#include "garden/morph/morph_blend.h"
#include "jobs/job_thread.h"

namespace {

using namespace hg;
using bench::bestOf;

// The peer: the blend with nothing but three arrays in and one out.
void plainBlend(const garden::MorphSources& s, const float w[3], float band, std::vector<float>& out) {
    const float* a = s.fields[0].data();
    const float* b = s.fields[1].data();
    const float* c = s.fields[2].data();
    const std::size_t n = s.fields[0].size();
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = std::min(std::max(w[0] * a[i] + w[1] * b[i] + w[2] * c[i], -band), band);
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    garden::GardenLoad load = garden::loadGarden(std::string(HG_SOURCE_DIR) + "/content/gardens/default.json");
    if (!load.ok() || load.garden->morphs.empty() || !load.morphErrors[0].empty()) {
        std::fprintf(stderr, "default garden: %s%s\n", load.error.c_str(),
                     load.ok() && !load.morphErrors.empty() ? load.morphErrors[0].c_str() : " (no morph)");
        return 1;
    }
    nlohmann::json rows = nlohmann::json::array();
    std::vector<std::string> offThreadRows;
    std::printf("| sources | res | voxels | sampling (s) | from scratch (ms) | coarse pass (ms) | fine step of 1M (ms) | "
                "fine steps | partial (M samples/s) | peer, 1 thread (M samples/s) | partial / peer |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int res : {128, 256}) {
        const std::string name = "keys@" + std::to_string(res);
        if (!args.matches(name)) continue;
        load.garden->morphs[0].resolution = res;
        garden::MorphSourcesResult built = garden::buildGardenMorphSources(load, 0);
        if (!built.sources) {
            std::fprintf(stderr, "%s: %s\n", name.c_str(), built.error.c_str());
            continue;
        }
        const garden::MorphSources& s = *built.sources;
        garden::MorphTriangle t = garden::morphTriangle(*load.garden, 0);
        garden::MorphWeights w1 = garden::morphWeights(t, t.centroid(), garden::morphBalance(load.garden->morphs[0], s));
        garden::MorphWeights w2 = garden::morphWeights(t, t.corners[0], w1.balance);
        const std::uint64_t voxels = s.frame.indexBox.volume();

        double scratch = bestOf(args.repeat, [&] { garden::blendMorph(s, w1); });

        // Partial: from the blend at the centroid to corner 0. First the
        // coarse pass in one step, then steps of a million samples; the
        // fine steps' mean time over the whole drain.
        double coarseSeconds = 1e30, stepSeconds = 1e30;
        std::uint64_t coarseSamples = 0, fineSamples = 0;
        std::size_t steps = 0;
        for (int r = 0; r < args.repeat; ++r) {
            voxel::Volume result = garden::blendMorph(s, w1);
            garden::MorphBlender blender(s, result);
            blender.restart(w2, {0.0, 1.0, 5.0});
            garden::BlendBudget budget;
            budget.maxSamples = 0;
            for (const auto& item : blender.workList())
                budget.maxSamples += item.pass == garden::BlendPass::Coarse ? item.samples : 0;
            auto t0 = std::chrono::steady_clock::now();
            blender.step(budget);
            double coarse = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            coarseSeconds = std::min(coarseSeconds, coarse);
            coarseSamples = budget.maxSamples;
            budget.maxSamples = 1000000;
            std::size_t n = 0;
            t0 = std::chrono::steady_clock::now();
            while (!blender.done()) {
                blender.step(budget);
                ++n;
            }
            double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            if (sec / static_cast<double>(n) < stepSeconds) {
                stepSeconds = sec / static_cast<double>(n);
                steps = n;
                fineSamples = blender.totalSamples() - coarseSamples;
            }
        }
        const double partialRate = static_cast<double>(fineSamples) / (stepSeconds * static_cast<double>(steps));

        // Off the frame thread: the same change drained by frames paced at
        // 90 Hz (as a display paces them), each writing what the thread has
        // finished and handing it the next batch; the frame thread's time
        // is the steps' time.
        double frameSeconds = 1e30, wallSeconds = 1e30;
        std::size_t frames = 0;
        for (int r = 0; r < args.repeat; ++r) {
            voxel::Volume result = garden::blendMorph(s, w1);
            garden::MorphBlender blender(s, result);
            jobs::JobThread thread;
            blender.restart(w2, {0.0, 1.0, 5.0});
            garden::BlendBudget budget;
            budget.maxSamples = 0;
            double inSteps = 0.0;
            std::size_t n = 0;
            const auto start = std::chrono::steady_clock::now();
            while (!blender.done()) {
                const auto t0 = std::chrono::steady_clock::now();
                blender.stepInBackground(budget, thread);
                inSteps += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                ++n;
                std::this_thread::sleep_until(start + std::chrono::microseconds(11111 * n));
            }
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (inSteps < frameSeconds) frameSeconds = inSteps, wallSeconds = wall, frames = n;
        }
        const double total = static_cast<double>(fineSamples + coarseSamples);
        const double inFramePerM = (coarseSeconds + stepSeconds * static_cast<double>(steps)) / total * 1e9;
        const double offThreadPerM = frameSeconds / total * 1e9;
        char line[256];
        std::snprintf(line, sizeof line, "| dryad/orant/knot | %d | %.2f | %.2f | %.1f | %zu | %.2f |", res, inFramePerM,
                      offThreadPerM, inFramePerM / offThreadPerM, frames, wallSeconds);
        offThreadRows.push_back(line);

        std::vector<float> out;
        const float wf[3] = {static_cast<float>(w1.w[0]), static_cast<float>(w1.w[1]), static_cast<float>(w1.w[2])};
        double peer = bestOf(args.repeat, [&] { plainBlend(s, wf, s.frame.band, out); });
        const double peerRate = static_cast<double>(s.fields[0].size()) / peer;

        std::printf("| %s | %d | %llu | %.2f | %.1f | %.2f | %.2f | %zu | %.0f | %.0f | %.2f |\n", "dryad/orant/knot",
                    res, static_cast<unsigned long long>(voxels), built.seconds, scratch * 1e3, coarseSeconds * 1e3,
                    stepSeconds * 1e3, steps,
                    partialRate * 1e-6, peerRate * 1e-6, partialRate / peerRate);
        std::fflush(stdout);
        rows.push_back({{"name", name}, {"resolution", res}, {"voxels", voxels}, {"sampling_s", built.seconds},
                        {"scratch_ms", scratch * 1e3}, {"coarse_ms", coarseSeconds * 1e3},
                        {"step_ms", stepSeconds * 1e3}, {"steps", steps},
                        {"partial_samples_per_s", partialRate}, {"peer_samples_per_s", peerRate},
                        {"in_frame_ms_per_million", inFramePerM}, {"off_thread_frame_ms_per_million", offThreadPerM},
                        {"off_thread_frames", frames}, {"off_thread_wall_s", wallSeconds}});
    }
    if (!offThreadRows.empty()) {
        std::printf("\nThe same change off the frame thread: frames paced at 90 Hz, each writing the batches a job\n"
                    "thread has blended; the frame thread's ms per million samples, against the in-frame steps above.\n\n");
        std::printf("| sources | res | in the frame (ms per 1M) | off the frame thread (ms per 1M) | frame thread spared (x) | "
                    "frames | drained in (s) |\n");
        std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
        for (const std::string& l : offThreadRows) std::printf("%s\n", l.c_str());
    }
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << rows.dump(2) << "\n";
    return 0;
}
