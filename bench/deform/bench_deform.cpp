// The deformable model (issue 22): one iteration of the snake for models
// of about 1,000 and 10,000 vertices against a sculpture's grid (target: a
// 1,000-vertex model at least 10 iterations per 11.1 ms frame on 2 cores),
// on one thread and on TBB's workers (at most 2, the target's cores) from
// the same start, and the selection's balls for the deformed model.
//
// The sculpture is a ball of radius 0.6 sampled at 0.02 (70^3, band 3
// voxels); the model starts as a uniform sphere of radius 0.66, at the
// band's edge, so every iteration samples the grid twice per vertex (the
// dear path) and remeshes every 4th, as the live tool does. A row's time is
// the mean over `iterations` steps, best of --repeat runs.
//
//   ./build/release/bench/bench_deform [--json out.json] [--filter N] [--repeat N]
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "bench/bench_common.h"
#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "garden/deform/deformable_model.h"
#include "voxel/sampler.h"

namespace {

using namespace hg::garden::deform;

hg::voxel::Volume ballGrid(double radius, double half, double voxel) {
    const std::string source =
        "ball(x[3], a[1]) { ball = " + std::to_string(radius) + " - sqrt(x[1]^2 + x[2]^2 + x[3]^2); }";
    hg::frep::ParseResult parsed = hg::frep::parseProgram(source, "ball.hf");
    auto program = std::make_shared<const hg::frep::Program>(std::move(*parsed.program));
    const hg::frep::Model model(program, program->defaultBody(), {});
    hg::voxel::VolumeRequest request;
    hg::frep::Box3 box;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = -half;
        box.hi[a] = half;
    }
    request.box = box;
    request.resolution = static_cast<int>(std::lround(2.0 * half / voxel));
    hg::voxel::VoxelizeResult r = hg::voxel::voxelize(model, request);
    if (!r.volume) {
        std::fprintf(stderr, "the grid: %s\n", r.error.c_str());
        std::exit(1);
    }
    return std::move(*r.volume);
}

}  // namespace

int main(int argc, char** argv) {
    hg::bench::BenchArgs args;
    if (!hg::bench::parseBenchArgs(argc, argv, args)) return 2;
    constexpr int kThreads = 2;
    const tbb::global_control cores(tbb::global_control::max_allowed_parallelism, kThreads);
    const double voxel = 0.02;
    const hg::voxel::Volume grid = ballGrid(0.6, 0.7, voxel);
    const int iterations = 40;
    constexpr double kFrameMs = 1000.0 / 90.0;
    nlohmann::json rows = nlohmann::json::array();
    std::printf("| vertices (target) | vertices (start .. end) | edge | 1 thread (ms / iteration) | TBB, %d threads (ms / "
                "iteration) | TBB / 1 thread | iterations per 11.1 ms (TBB) | TBB, no remeshing (ms / iteration) | fit: worst (voxels) | selection balls | "
                "selectionBalls (ms) |\n",
                kThreads);
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int target : {1000, 10000}) {
        if (!args.matches(std::to_string(target))) continue;
        // A uniform triangulation of edge L on a sphere of radius r has
        // about 4 pi r^2 / (sqrt(3)/2 L^2) vertices.
        const double r = 0.66;
        const double edge = std::sqrt(4.0 * 3.141592653589793 * r * r / (std::sqrt(3.0) / 2.0 * target));
        const DeformMesh start = remeshUniform(sphereMesh(glm::dvec3(0.0), r, target > 3000 ? 5 : 3), edge, 6,
                                               [&](const glm::dvec3& p) { return r * glm::normalize(p); });
        // 0: one thread, 1: TBB, 2: TBB without the remeshing rounds (what
        // the snake step alone costs).
        double ms[3] = {0.0, 0.0, 0.0};
        DeformMesh ended;
        for (int run = 0; run < 3; ++run) {
            DeformOptions options;
            options.parallel = run >= 1;
            if (run == 2) options.remeshEvery = 0;
            DeformMesh last;
            const double seconds = hg::bench::bestOf(args.repeat, [&] {
                DeformableModel model(start, edge, options);
                for (int i = 0; i < iterations; ++i) model.deform(grid, DeformMode::Shrink, 1);
                last = model.mesh();
            });
            ms[run] = 1e3 * seconds / iterations;
            if (run == 1) ended = std::move(last);
        }
        double worst = 0.0;
        for (const glm::dvec3& p : ended.vertices) worst = std::max(worst, std::fabs(glm::length(p) - 0.6));
        std::vector<SelectionBall> balls;
        const double selectionSeconds = hg::bench::bestOf(args.repeat, [&] { balls = selectionBalls(ended, voxel); });
        std::printf("| %d | %zu .. %zu | %.4f | %.3f | %.3f | %.2f | %.1f | %.3f | %.2f | %zu | %.1f |\n", target,
                    start.vertices.size(), ended.vertices.size(), edge, ms[0], ms[1], ms[1] / ms[0],
                    kFrameMs / ms[1], ms[2], worst / voxel, balls.size(), 1e3 * selectionSeconds);
        rows.push_back({{"target_vertices", target},
                        {"start_vertices", start.vertices.size()},
                        {"end_vertices", ended.vertices.size()},
                        {"edge", edge},
                        {"single_thread_ms_per_iteration", ms[0]},
                        {"tbb_ms_per_iteration", ms[1]},
                        {"tbb_threads", kThreads},
                        {"iterations_per_frame", kFrameMs / ms[1]},
                        {"tbb_no_remeshing_ms_per_iteration", ms[2]},
                        {"worst_fit_voxels", worst / voxel},
                        {"selection_balls", balls.size()},
                        {"selection_ms", 1e3 * selectionSeconds}});
    }
    std::printf("\n%d iterations of shrink-wrap from r = 0.66 onto a ball of r = 0.6 (voxel 0.02, band 3), remeshing "
                "every 4th; target: 1,000 vertices at least 10 iterations per 11.1 ms frame\n",
                iterations);
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << rows.dump(2) << "\n";
    return 0;
}
