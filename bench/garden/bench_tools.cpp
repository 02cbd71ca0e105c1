// Sculpting benchmark. Seed 004's carving table form: a key sculpture at
// 256^3, a live stroke extended one step at a time, for tool radii of 8, 16
// and 32 voxels: the box each step recomputes, the time to apply it and to
// remesh the chunks it touched (level 0, 32^3 chunks), with no earlier edits
// and with 1,000 earlier strokes spread over the sculpture; undo of one
// stroke with 1,000 edits. The peer, measured in the same run: the same box
// resampled from the sculpture's HyperFun source alone (voxel::resampleRegion,
// interval-culled), what a box update costs without the unedited grid.
// Seed 002's impact table form: 10, 100 and 1,000 impacts in one pull, cast,
// applied and remeshed. A whole carving frame in the running garden.
// Reopening a session of 10,000 journalled actions. Exporting a sculpture
// of 1,000 edits as HyperFun, and meshed to binary STL (`export-stl`,
// issue 20) beside the same sculpture unedited and beside the edited one
// evaluated with the full tape (specialization off): the tape each leaf
// ran, mean and longest, against the full tape's length.
// Prints a Markdown table; --json FILE writes the rows too.
//
//   ./build/release/bench/bench_tools [--json out.json] [--filter NAME] [--repeat N]
//   (HG_BENCH_EXPORT_RES=256,512 sets the export-stl rows' resolutions)
#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "../bench_common.h"

#include "frep/language/parser.h"
#include "garden/app/garden_session.h"
#include "frep/eval/model.h"
#include "frep/eval/tape_specializer.h"
#include "garden/export/export_file.h"
#include "garden/export/hyperfun_export.h"
#include "garden/sculpt/impacts.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/stroke_segments.h"
#include "garden/scene/garden_file.h"
#include "polygonizer/realtime/chunk_layout.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "polygonizer/realtime/remesh_queue.h"
#include "voxel/sampler.h"

namespace {

using namespace hg;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct Meshing {
    explicit Meshing(const voxel::Volume& v)
        : pyramid(v, 1), layout(v.frame, 32), queue(pyramid, layout, std::vector<int>(layout.count(), 0)) {
        queue.process(poly::RemeshBudget{});
    }
    // Remeshes what `box` touched; returns the chunks meshed.
    std::size_t remesh(const voxel::IndexBox& box) {
        pyramid.update(box);
        queue.markChanged(box);
        return queue.process(poly::RemeshBudget{}).meshed;
    }
    poly::LodPyramid pyramid;
    poly::ChunkLayout layout;
    poly::RemeshQueue queue;
};

// A carving stroke across the front of the sculpture, step by step.
struct StepResult {
    double applyMs = 0, remeshMs = 0, peerMs = 0;
    std::size_t chunks = 0, pieces = 0;
    std::uint64_t voxels = 0;
};

StepResult strokeSteps(garden::SculptureEdits& edits, Meshing& meshing, const frep::Model& model, voxel::Volume& shown,
                       double radiusVoxels, int steps) {
    const voxel::VolumeFrame& f = shown.frame;
    const double v = f.voxelSize;
    const double cx = 0.5 * (f.modelBox.lo[0] + f.modelBox.hi[0]), cy = 0.5 * (f.modelBox.lo[1] + f.modelBox.hi[1]);
    const double z = 0.5 * (f.modelBox.lo[2] + f.modelBox.hi[2]);
    garden::Stroke s;
    s.tool = garden::StrokeTool::Carve;
    s.radius = radiusVoxels * v;
    s.path = {{cx, cy, z}};
    garden::extendStrokeSegments(s, 0, edits.units());
    garden::Edit e;
    e.op = s;
    meshing.remesh(edits.append(std::move(e)));
    StepResult r;
    voxel::Volume peer = shown.clone();
    for (int i = 1; i <= steps; ++i) {
        // One step of half the radius: what a hand moves in a frame.
        const garden::ModelPoint p{cx + 0.5 * radiusVoxels * v * i, cy, z};
        auto t0 = Clock::now();
        const voxel::IndexBox box = edits.extendLastStroke({p});
        r.applyMs += msSince(t0);
        r.voxels += box.volume();
        t0 = Clock::now();
        r.chunks += meshing.remesh(box);
        r.remeshMs += msSince(t0);
        t0 = Clock::now();
        voxel::resampleRegion(peer, model, box);
        r.peerMs += msSince(t0);
    }
    r.applyMs /= steps; r.remeshMs /= steps; r.peerMs /= steps;
    r.voxels /= static_cast<std::uint64_t>(steps);
    r.chunks /= static_cast<std::size_t>(steps);
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    bench::BenchArgs args;
    if (!bench::parseBenchArgs(argc, argv, args)) return 2;
    const std::string file = std::string(HG_SOURCE_DIR) + "/content/hyperfun/key_dryad.hf";
    garden::SculptureLoad load = garden::loadSculpture([&] {
        garden::SculptureSpec spec;
        spec.file = file;
        return spec;
    }());
    if (!load.ok()) {
        std::fprintf(stderr, "%s", load.error.c_str());
        return 1;
    }
    voxel::VolumeRequest req;
    req.resolution = 256;
    voxel::VoxelizeResult vr = voxel::voxelize(*load.model, req);
    if (!vr.volume) {
        std::fprintf(stderr, "%s\n", vr.error.c_str());
        return 1;
    }
    const int steps = 8 * args.repeat;
    nlohmann::json rows = nlohmann::json::array();
    std::printf("| sculpture | earlier edits | radius (voxels) | box voxels | pieces indexed | apply (ms) | remesh (ms) | "
                "chunks | apply + remesh (ms) | peer: source resample (ms) | peer / apply | undo (ms) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int earlier : {0, 1000}) {
        for (double radius : {8.0, 16.0, 32.0}) {
            const std::string name = "dryad@256/" + std::to_string(earlier) + "/r" + std::to_string(static_cast<int>(radius));
            if (!args.matches(name)) continue;
            voxel::Volume shown = vr.volume->clone();
            garden::SculptureEdits edits(shown);
            // Earlier strokes: short carves and adds spread over the model box.
            std::mt19937 rng(42);
            const voxel::VolumeFrame& f = shown.frame;
            std::uniform_real_distribution<double> ux(f.modelBox.lo[0], f.modelBox.hi[0]), uy(f.modelBox.lo[1], f.modelBox.hi[1]),
                uz(f.modelBox.lo[2], f.modelBox.hi[2]);
            for (int i = 0; i < earlier; ++i) {
                garden::Stroke s;
                s.tool = i % 2 ? garden::StrokeTool::Carve : garden::StrokeTool::Add;
                s.radius = 4.0 * f.voxelSize;
                const garden::ModelPoint a{ux(rng), uy(rng), uz(rng)};
                s.path = {a, {a[0] + 8 * f.voxelSize, a[1], a[2]}};
                garden::extendStrokeSegments(s, 0, edits.units());
                garden::Edit e;
                e.op = s;
                edits.append(std::move(e));
            }
            Meshing meshing(shown);
            const StepResult r = strokeSteps(edits, meshing, *load.model, shown, radius, steps);
            const auto t0 = Clock::now();
            const auto undone = edits.undo();
            const double undoMs = msSince(t0);
            if (!undone) return 1;
            const std::size_t pieces = edits.list().indexedPieces();
            std::printf("| key_dryad 256^3 | %d | %.0f | %llu | %zu | %.2f | %.2f | %zu | %.2f | %.2f | %.1fx | %.2f |\n", earlier,
                        radius, static_cast<unsigned long long>(r.voxels), pieces, r.applyMs, r.remeshMs, r.chunks,
                        r.applyMs + r.remeshMs, r.peerMs, r.peerMs / r.applyMs, undoMs);
            rows.push_back({{"name", name}, {"earlier_edits", earlier}, {"radius_voxels", radius},
                            {"box_voxels", r.voxels}, {"apply_ms", r.applyMs}, {"remesh_ms", r.remeshMs},
                            {"chunks", r.chunks}, {"peer_resample_ms", r.peerMs}, {"undo_ms", undoMs}});
        }
    }
    // Seed 002's table form: impacts fired at the dryad's front in one pull,
    // applied and remeshed.
    std::printf("\n| sculpture | impacts | tool | cast (ms) | apply (ms) | remesh (ms) | total (ms) | per impact (ms) | seed 002 per impact (ms) |\n");
    std::printf("|---|---:|---|---:|---:|---:|---:|---:|---:|\n");
    for (int count : {10, 100, 1000}) {
        const std::string name = "impacts/" + std::to_string(count);
        if (!args.matches(name)) continue;
        voxel::Volume shown = vr.volume->clone();
        garden::SculptureEdits edits(shown);
        Meshing meshing(shown);
        const voxel::VolumeFrame& f = shown.frame;
        garden::ImpactTool tool;
        tool.shape = garden::ImpactShape::Sphere;
        tool.size = 4.0 * f.voxelSize;
        tool.volume = 20.0 * f.voxelSize * f.voxelSize * f.voxelSize;
        tool.count = count;
        tool.spreadSize = 0.25 * (f.modelBox.hi[0] - f.modelBox.lo[0]);
        const garden::ImpactRay aim{{0.5 * (f.modelBox.lo[0] + f.modelBox.hi[0]), 0.5 * (f.modelBox.lo[1] + f.modelBox.hi[1]),
                                     f.modelBox.hi[2] + 0.1},
                                    {0.0, 0.0, -1.0}};
        auto t0 = Clock::now();
        garden::ImpactSeries series;
        for (const garden::ImpactRay& ray : garden::drawImpactRays(aim, tool))
            if (auto m = garden::castImpact(shown, ray, tool, edits.units())) series.impacts.push_back(*m);
        const double castMs = msSince(t0);
        garden::Edit e;
        e.op = series;
        t0 = Clock::now();
        const voxel::IndexBox box = edits.append(std::move(e));
        const double applyMs = msSince(t0);
        t0 = Clock::now();
        meshing.remesh(box);
        const double remeshMs = msSince(t0);
        const double total = castMs + applyMs + remeshMs;
        const std::size_t hits = series.impacts.size();
        std::printf("| key_dryad 256^3 | %zu of %d | sphere, 4 voxels | %.1f | %.1f | %.1f | %.1f | %.3f | 25-32 |\n", hits, count,
                    castMs, applyMs, remeshMs, total, total / static_cast<double>(std::max<std::size_t>(hits, 1)));
        rows.push_back({{"name", name}, {"impacts", hits}, {"cast_ms", castMs}, {"apply_ms", applyMs},
                        {"remesh_ms", remeshMs}, {"total_ms", total}});
    }
    // A whole carving frame: the default garden (the dryad at 192^3), the
    // tool hand carving across the dryad at a radius of 16 voxels, one step
    // of half the radius a frame, every stage within the scheduler's
    // 11.1 ms budget (remeshing on its time allowance).
    if (args.matches("frame")) {
        garden::SessionSettings settings;
        garden::GardenSession session(garden::loadGarden(std::string(HG_SOURCE_DIR) + "/content/gardens/default.json"),
                                      settings);
        for (int f = 0; f < 400 && !session.idle(); ++f) {
            session.frame(garden::FrameInput(garden::Hands{}, 1.0 / 90.0));
        }
        const int d = session.findSculpture("dryad");
        const garden::Sculpture& dryad = session.sculptures()[static_cast<std::size_t>(d)];
        const double voxelMetres = dryad.volume->frame.voxelSize * dryad.scale();
        session.tool().kind = garden::ToolSettings::Kind::Carve;
        session.tool().radius = 16.0 * voxelMetres;
        const glm::vec3 c = dryad.worldCentre();
        garden::Hands hands;
        hands.tool.tracked = true;
        hands.tool.trigger = 1.0f;
        hands.tool.aim.orientation = glm::quatLookAt(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
        std::vector<garden::FrameStats> frames;
        for (int f = 0; f < 60; ++f) {
            hands.tool.aim.position = c + glm::vec3(-0.3f + 0.5f * static_cast<float>(16.0 * voxelMetres) * static_cast<float>(f),
                                                    0.2f, 3.0f);
            frames.push_back(session.frame(garden::FrameInput(hands, 1.0 / 90.0)));
        }
        double total = 0, worst = 0, input = 0, remesh = 0;
        int over = 0;
        for (const auto& fs : frames) {
            total += fs.totalMs;
            worst = std::max(worst, fs.totalMs);
            input += fs.stageMs[static_cast<int>(garden::Stage::Input)];
            remesh += fs.stageMs[static_cast<int>(garden::Stage::Remesh)];
            over += fs.totalMs > 11.1;
        }
        const double n = static_cast<double>(frames.size());
        std::printf("\n| garden | tool | frames | stroke (input stage) mean (ms) | remesh mean (ms) | frame mean (ms) | frame max (ms) | "
                    "frames over 11.1 ms | edits |\n");
        std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
        std::printf("| default, dryad 192^3 | carve, 16 voxels | %zu | %.2f | %.2f | %.2f | %.2f | %d | %zu |\n", frames.size(),
                    input / n, remesh / n, total / n, worst, over, session.editCount(d));
        rows.push_back({{"name", "frame/carve16"}, {"frame_mean_ms", total / n}, {"frame_max_ms", worst},
                        {"stroke_mean_ms", input / n}, {"over_budget", over}});
    }
    // Reopening a session: 10,000 journalled actions (strokes, perturbations,
    // impacts, a tenth of them undone) played into the default garden, the
    // grids recomputed once at the end. Peer: opening the garden itself.
    if (args.matches("reopen")) {
        std::printf("\n| garden | journalled actions | open the garden (s) | play the journal (s) | total (s) | play / open |\n");
        std::printf("|---|---:|---:|---:|---:|---:|\n");
        const std::string gardenPath = std::string(HG_SOURCE_DIR) + "/content/gardens/default.json";
        std::vector<garden::Action> records;
        {
            garden::GardenSession probe(garden::loadGarden(gardenPath));
            std::mt19937 rng(9);
            std::vector<int> editable;
            for (std::size_t i = 0; i < probe.sculptures().size(); ++i)
                if (!probe.sculptures()[i].missing() && !probe.sculptures()[i].morphResult()) editable.push_back(static_cast<int>(i));
            std::size_t made = 0;
            while (records.size() < 10000) {
                const auto& sc = probe.sculptures()[static_cast<std::size_t>(editable[rng() % editable.size()])];
                const frep::Box3& b = sc.volume->frame.modelBox;
                const double v = sc.volume->frame.voxelSize;
                std::uniform_real_distribution<double> ux(b.lo[0], b.hi[0]), uy(b.lo[1], b.hi[1]), uz(b.lo[2], b.hi[2]);
                const garden::ModelPoint a{ux(rng), uy(rng), uz(rng)};
                if (made > 0 && rng() % 10 == 0) {
                    records.push_back(garden::UndoAction{});
                    --made;
                } else if (rng() % 4 == 0) {
                    garden::Perturbation p;
                    p.center = a;
                    p.radii = {6 * v, 5 * v, 6 * v};
                    p.strength = 2.0;
                    records.push_back(garden::PerturbAction{sc.name, p});
                    ++made;
                } else {
                    records.push_back(garden::StrokeAction{sc.name, rng() % 2 ? garden::StrokeTool::Carve : garden::StrokeTool::Add,
                                                           4 * v, 2.0, {a, {a[0] + 10 * v, a[1] + 4 * v, a[2]}}, std::nullopt, 1.0,
                                                           garden::Falloff::Smooth, {}});
                    ++made;
                }
            }
        }
        auto t0 = Clock::now();
        garden::GardenSession session(garden::loadGarden(gardenPath));
        const double openS = msSince(t0) / 1000.0;
        t0 = Clock::now();
        const std::string why = session.restore(records);
        const double playS = msSince(t0) / 1000.0;
        if (!why.empty()) std::fprintf(stderr, "reopen: %s\n", why.c_str());
        std::printf("| default | %zu | %.2f | %.2f | %.2f | %.2f |\n", records.size(), openS, playS, openS + playS, playS / openS);
        rows.push_back({{"name", "reopen/10000"}, {"open_s", openS}, {"play_s", playS}});
    }
    // Exporting a sculpture of 1,000 edits as HyperFun (docs/export.md):
    // the text made, written atomically, and read back by our parser.
    // The dryad of the default garden with 1,000 edits in a fixed seeded
    // script, where a sculptor puts them: on its surface (voxels within one
    // voxel of it); strokes carving and adding, one perturbation in four.
    const std::string gardenPath = std::string(HG_SOURCE_DIR) + "/content/gardens/default.json";
    const auto editDryad = [&](garden::GardenSession& session) {
        const int d = session.findSculpture("dryad");
        const garden::Sculpture& dryad = session.sculptures()[static_cast<std::size_t>(d)];
        const voxel::VolumeFrame& f = dryad.volume->frame;
        const double v = f.voxelSize;
        std::vector<garden::ModelPoint> surface;
        for (int k = f.indexBox.lo[2]; k <= f.indexBox.hi[2]; ++k)
            for (int j = f.indexBox.lo[1]; j <= f.indexBox.hi[1]; ++j)
                for (int i = f.indexBox.lo[0]; i <= f.indexBox.hi[0]; ++i)
                    if (std::fabs(dryad.volume->value(i, j, k)) < 1.0f) {
                        const auto p = f.position(i, j, k);
                        surface.push_back({p[0], p[1], p[2]});
                    }
        std::mt19937 rng(17);
        std::uniform_int_distribution<std::size_t> pick(0, surface.size() - 1);
        std::vector<garden::Action> records;
        for (int i = 0; i < 1000; ++i) {
            const garden::ModelPoint a = surface[pick(rng)];
            if (i % 4 == 3) {
                garden::Perturbation p;
                p.center = a;
                p.radii = {6 * v, 5 * v, 6 * v};
                p.strength = 2.0;
                records.push_back(garden::PerturbAction{dryad.name, p});
            } else {
                records.push_back(garden::StrokeAction{dryad.name, i % 2 ? garden::StrokeTool::Carve : garden::StrokeTool::Add,
                                                       4 * v, 2.0, {a, {a[0] + 10 * v, a[1] + 4 * v, a[2]}}, std::nullopt, 1.0,
                                                           garden::Falloff::Smooth, {}});
            }
        }
        if (const std::string why = session.restore(records); !why.empty()) std::fprintf(stderr, "edits: %s\n", why.c_str());
        return d;
    };
    if (args.matches("export-stl")) {
        // The point tape: each leaf's tape specialized further to single
        // voxels of it (voxel/box_walker.h), the floor any box could reach.
        std::printf("\n| sculpture | res | unedited (s) | edited (s) | edited / unedited | edited, full tape (s) | speed-up | full tape | leaf tape mean | leaf tape max | point tape mean |\n");
        std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        garden::SessionSettings settings;
        settings.maxLevel = 0;
        garden::GardenSession plain(garden::loadGarden(gardenPath), settings);
        garden::GardenSession edited(garden::loadGarden(gardenPath), settings);
        const int d = editDryad(edited);
        std::vector<int> resolutions = {256};
        if (const char* r = std::getenv("HG_BENCH_EXPORT_RES")) {
            resolutions.clear();
            for (std::stringstream in(r); in.good();) {
                int v = 0;
                in >> v;
                in.ignore(1);
                if (v >= 0) resolutions.push_back(v);  // 0: the grid's, the Export panel's default
            }
        }
        const std::string out = (std::filesystem::temp_directory_path() / "bench_tools_export.stl").string();
        const auto exportSeconds = [&](const garden::GardenSession& s, int res, bool specialize) {
            frep::setSpecialization(specialize);
            garden::ExportFileOptions fo;
            fo.resolution = res;
            garden::ExportFileReport report;
            const double seconds = bench::bestOf(args.repeat, [&] {
                const std::string why = garden::exportSculptureFile(s, d, out, fo, report);
                if (!why.empty()) std::fprintf(stderr, "export-stl: %s\n", why.c_str());
            });
            frep::setSpecialization(true);
            return seconds;
        };
        // The tape per leaf, from the exported file voxelized as the export samples it.
        const garden::HyperFunExport e = garden::exportHyperFun(edited, d);
        frep::ParseResult parsed = frep::parseProgram(e.text, "export.hf");
        if (!parsed.ok()) {
            std::fprintf(stderr, "export-stl: the exported text does not parse\n");
            return 1;
        }
        const frep::Model model(std::make_shared<const frep::Program>(std::move(*parsed.program)), parsed.program->defaultBody());
        for (int res : resolutions) {
            const double plainS = exportSeconds(plain, res, true);
            const double editedS = exportSeconds(edited, res, true);
            // The full tape at every point takes minutes past 512^3: left out there.
            const double fullS = res <= 512 ? exportSeconds(edited, res, false) : 0.0;
            const int gridRes = edited.sculptures()[static_cast<std::size_t>(d)].volume->frame.resolution;
            voxel::VolumeRequest tapeReq;
            tapeReq.resolution = res > 0 ? res : gridRes;
            tapeReq.box = edited.sculptures()[static_cast<std::size_t>(d)].volume->frame.modelBox;
            ::setenv("HG_PROBE_POINT_TAPES", "1", 1);
            const voxel::VoxelizeResult tapeRun = voxel::voxelize(model, tapeReq);
            ::unsetenv("HG_PROBE_POINT_TAPES");
            const std::size_t full = model.tape() ? model.tape()->size() : 0;
            const std::string resName = res > 0 ? std::to_string(res) : std::to_string(gridRes) + " (the grid's)";
            char fullText[64] = "-";
            if (fullS > 0.0) std::snprintf(fullText, sizeof fullText, "%.2f | %.1fx", fullS, fullS / editedS);
            else std::snprintf(fullText, sizeof fullText, "- | -");
            std::printf("| key_dryad, 1,000 edits | %s | %.2f | %.2f | %.2fx | %s | %zu | %.0f | %llu | %.0f |\n", resName.c_str(),
                        plainS, editedS, editedS / plainS, fullText, full, tapeRun.stats.leafTapeMean,
                        static_cast<unsigned long long>(tapeRun.stats.leafTapeMax), tapeRun.stats.pointTapeMean);
            rows.push_back({{"name", "export-stl/" + std::to_string(res)}, {"unedited_s", plainS}, {"edited_s", editedS},
                            {"edited_full_tape_s", fullS}, {"full_tape", full}, {"leaf_tape_mean", tapeRun.stats.leafTapeMean},
                            {"leaf_tape_max", tapeRun.stats.leafTapeMax}, {"point_tape_mean", tapeRun.stats.pointTapeMean}});
        }
        std::filesystem::remove(out);
    }
    if (args.matches("export")) {
        std::printf("\n| sculpture | edits | pieces | statements | bytes | export (ms) | write (ms) | parse back (ms) |\n");
        std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
        garden::SessionSettings settings;
        settings.maxLevel = 0;
        garden::GardenSession session(garden::loadGarden(gardenPath), settings);
        const int d = editDryad(session);
        garden::HyperFunExport e;
        const double exportS = bench::bestOf(args.repeat, [&] { e = garden::exportHyperFun(session, d); });
        if (!e.error.empty()) std::fprintf(stderr, "export: %s\n", e.error.c_str());
        const std::string out = (std::filesystem::temp_directory_path() / "bench_tools_export.hf").string();
        const double writeS = bench::bestOf(args.repeat, [&] { garden::writeHyperFunExport(e, out); });
        if (!std::getenv("HG_BENCH_KEEP")) std::filesystem::remove(out);
        bool parsed = false;
        const double parseS = bench::bestOf(args.repeat, [&] { parsed = frep::parseProgram(e.text, "export.hf").ok(); });
        if (!parsed) std::fprintf(stderr, "export: the exported text does not parse\n");
        std::printf("| key_dryad 192^3 | %zu | %zu | %zu | %zu | %.1f | %.1f | %.1f |\n", e.edits, e.pieces, e.statements,
                    e.text.size(), exportS * 1e3, writeS * 1e3, parseS * 1e3);
        rows.push_back({{"name", "export/hf/1000"}, {"edits", e.edits}, {"pieces", e.pieces}, {"statements", e.statements},
                        {"bytes", e.text.size()}, {"export_ms", exportS * 1e3}, {"write_ms", writeS * 1e3},
                        {"parse_ms", parseS * 1e3}});
    }
    if (!args.jsonPath.empty()) std::ofstream(args.jsonPath) << rows.dump(2) << "\n";
    return 0;
}
