#include "garden/replay/replay_runner.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "garden/scene/to_glm.h"

namespace hg::garden {

namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

std::string screenshotPath(const ReplayOptions& o, const std::string& name) {
    const std::filesystem::path p(name);
    return p.is_absolute() ? name : (std::filesystem::path(o.screenshotDir) / p).string();
}

// "" or why the command cannot run.
std::string apply(const ReplayCommand& c, GardenSession& s, FrameRenderer* renderer, const ReplayOptions& o,
                  ReplayResult& result, std::vector<std::string>& shotsThisFrame) {
    if (c.kind == ReplayCommand::Kind::Screenshot) {
        if (!renderer) {
            result.notes.push_back("frame " + std::to_string(result.frames) + ": screenshot '" + c.text +
                                   "' skipped (headless)");
            return "";
        }
        shotsThisFrame.push_back(screenshotPath(o, c.text));
        return "";
    }
    if (c.kind == ReplayCommand::Kind::Sculpt)
        if (const auto* x = std::get_if<ExtractCommand>(&c.sculpt)) {
            if (!o.extractor) return "extract: this program cannot extract from a replay";
            if (std::string why = o.extractor(s, x->from, x->by, x->name); !why.empty()) return "extract: " + why;
            return "";
        }
    if (c.kind == ReplayCommand::Kind::Export) {
        const int i = c.text.empty() ? s.selected() : s.findSculpture(c.text);
        if (i < 0)
            return c.text.empty() ? "export: no sculpture named and none selected" : "export: no sculpture named '" + c.text + "'";
        if (!o.exporter) return "export: this program cannot export from a replay";
        std::string summary;
        if (std::string why = o.exporter(s, i, c.file, static_cast<int>(c.number), summary); !why.empty())
            return "export: " + why;
        result.notes.push_back("frame " + std::to_string(result.frames) + ": " + summary);
        result.exports.push_back(c.file);
        return "";
    }
    return runReplayCommand(c, s);
}

}  // namespace

std::string runReplayCommand(const ReplayCommand& c, GardenSession& s) {
    switch (c.kind) {
        case ReplayCommand::Kind::Morph:
            if (!s.hasMorph()) return "the garden has no metamorphosis to select";
            s.setMorphPoint(c.pair[0], c.pair[1]);
            return "";
        case ReplayCommand::Kind::MorphWeights:
            if (!s.hasMorph()) return "the garden has no metamorphosis to weigh";
            s.setMorphWeights(c.vec);
            return "";
        case ReplayCommand::Kind::Screenshot: return "";  // the caller's (apply above)
        case ReplayCommand::Kind::Detail:
            if (c.number <= 0.0) s.setDetail(std::nullopt);
            else s.setDetail(poly::Sphere{c.vec, c.number});
            return "";
        case ReplayCommand::Kind::Pose:
            s.navigator().setPose(toGlm(c.vec), static_cast<float>(c.pair[0] * kDegrees),
                                  static_cast<float>(c.pair[1] * kDegrees));
            return "";
        case ReplayCommand::Kind::Select: {
            if (c.text.empty()) {
                s.select(-1);
                return "";
            }
            const int i = s.findSculpture(c.text);
            if (i < 0) return "no sculpture named '" + c.text + "'";
            s.select(i);
            return "";
        }
        case ReplayCommand::Kind::Orbit:
            if (c.flag && s.selected() < 0) return "orbit needs a selected sculpture";
            s.navigator().setMode(c.flag ? NavigationMode::Orbit : NavigationMode::Walk);
            return "";
        case ReplayCommand::Kind::Budget:
            s.scheduler().setBudgetMs(c.number);
            return "";
        case ReplayCommand::Kind::Sculpt:
            return runSculptCommand(c.sculpt, s);
        case ReplayCommand::Kind::Export:  // the caller's (apply above)
            return "export: only `hypergarden replay` exports from a script";
    }
    return "";
}

std::string runSculptCommand(const SculptCommand& command, GardenSession& session) {
    if (const auto* a = std::get_if<ActionCommand>(&command)) return session.apply(a->action);
    if (const auto* c = std::get_if<SketchCommand>(&command)) {
        const int s = session.findSculpture(c->sculpture);
        if (c->model) {
            if (s < 0) return "no sculpture named '" + c->sculpture + "'";
            const auto a = session.modelFromWorld(s, c->modelName, c->points, c->normal, c->thickness);
            return a.action ? session.apply(*a.action) : a.why;
        }
        if (c->newSculpture) {
            const auto a = session.sketchNewFromWorld(c->sculpture, c->points, c->normal, c->thickness);
            return a.action ? session.apply(*a.action) : a.why;
        }
        if (s < 0) return "no sculpture named '" + c->sculpture + "'";
        return session.applySketch(s, c->mode, c->points, c->normal, c->thickness);
    }
    if (const auto* c = std::get_if<DeformCommand>(&command)) {
        if (session.findSculpture(c->sculpture) < 0) return "no sculpture named '" + c->sculpture + "'";
        const auto models = session.models();
        const auto m = std::find_if(models.begin(), models.end(), [&](const auto& v) { return v.name == c->model; });
        if (m != models.end() && m->sculpture != session.findSculpture(c->sculpture))
            return "model '" + c->model + "' does not surround '" + c->sculpture + "'";
        return session.deformModel(c->model, c->shrink, c->iterations);
    }
    if (std::holds_alternative<ExtractCommand>(command))
        return "extract: this program cannot extract from a replay";  // the caller's (runReplay's options)
    if (const auto* c = std::get_if<GestureCommand>(&command)) return session.applyGesture(c->points);
    if (const auto* c = std::get_if<AddCommand>(&command)) {
        Placement p;
        p.position = c->position ? *c->position : session.placeInView(3.0);
        p.yawDegrees = c->yaw;
        p.scale = c->scale;
        return session.addSculptureFile(c->file, c->name, p, c->resolution, c->body);
    }
    const auto find = [&](const std::string& name, int& index) -> std::string {
        index = session.findSculpture(name);
        return index < 0 ? "no sculpture named '" + name + "'" : "";
    };
    int i = -1;
    if (const auto* c = std::get_if<StrokeCommand>(&command)) {
        if (std::string why = find(c->sculpture, i); !why.empty()) return why;
        return session.applyStroke(i, c->tool, c->path, c->radius, c->softness, c->strength, c->falloff);
    }
    if (const auto* c = std::get_if<PerturbCommand>(&command)) {
        if (std::string why = find(c->sculpture, i); !why.empty()) return why;
        return session.applyPerturbation(i, c->shape, c->center, c->radii, c->strength);
    }
    if (const auto* c = std::get_if<ImpactsCommand>(&command)) {
        if (std::string why = find(c->sculpture, i); !why.empty()) return why;
        ImpactTool tool = c->tool;
        tool.volume *= 1e-6;  // cm^3 to m^3
        if (tool.spread == ImpactSpread::Cone) tool.spreadSize *= 3.14159265358979323846 / 180.0;
        return session.applyImpacts(i, c->origin, c->direction, tool);
    }
    if (const auto* c = std::get_if<EditPerturbationCommand>(&command)) {
        if (std::string why = find(c->sculpture, i); !why.empty()) return why;
        const auto edit = session.pickPerturbation(i, c->at);
        if (!edit) return "no perturbation of '" + c->sculpture + "' under that point";
        return session.editPerturbation(i, *edit, c->strength, c->radii);
    }
    if (const auto* c = std::get_if<ReapplyImpactsCommand>(&command)) {
        int j = -1;
        if (std::string why = find(c->from, i); !why.empty()) return why;
        if (std::string why = find(c->to, j); !why.empty()) return why;
        return session.reapplyImpacts(i, j);
    }
    if (const auto* c = std::get_if<UndoCommand>(&command)) {
        for (int n = 0; n < c->times; ++n)
            if (!session.undo()) return "nothing to undo";
        return "";
    }
    if (const auto* c = std::get_if<RedoCommand>(&command)) {
        for (int n = 0; n < c->times; ++n)
            if (!session.redo()) return "nothing to redo";
        return "";
    }
    session.tool() = std::get<ToolCommand>(command).settings;
    return "";
}

ReplayResult runReplay(const ReplayScript& script, GardenSession& session, FrameRenderer* renderer,
                       const ReplayOptions& options) {
    ReplayResult result;
    session.scheduler().setBudgetMs(script.budgetMs);
    for (std::size_t stepIndex = 0; stepIndex < script.steps.size(); ++stepIndex) {
        const ReplayStep& step = script.steps[stepIndex];
        bool settled = false;
        for (int f = 0; f < step.frames; ++f) {
            std::vector<std::string> shots;
            FrameInput in;
            in.hands = stepHands(step, f);
            in.dt = script.timestep;
            if (f == 0)
                in.commands = [&](GardenSession& s, Hands&) {
                    for (std::size_t c = 0; c < step.commands.size(); ++c) {
                        const std::string why = apply(step.commands[c], s, renderer, options, result, shots);
                        if (!why.empty()) {
                            result.error = script.file + ": $.steps[" + std::to_string(stepIndex) + "].commands[" +
                                           std::to_string(c) + "]: " + why;
                            return false;
                        }
                    }
                    return true;
                };
            NullViewSink headless;
            const FrameStats& stats = session.frame(in, renderer ? static_cast<ViewSink&>(*renderer) : headless);
            if (!result.error.empty()) return result;
            result.stats.push_back(stats);
            ++result.frames;
            if (renderer && options.screenshotEvery > 0 && result.frames % options.screenshotEvery == 0) {
                char name[64];
                std::snprintf(name, sizeof name, "frame_%06d.png", result.frames);
                shots.push_back(screenshotPath(options, name));
            }
            for (const std::string& path : shots) {
                const std::string why = renderer->screenshot(path);
                if (!why.empty()) {
                    result.error = why;
                    return result;
                }
                result.screenshots.push_back(path);
            }
            if (step.untilIdle && session.idle()) {
                settled = true;
                break;
            }
        }
        if (step.untilIdle && !settled) {
            result.error = script.file + ": $.steps[" + std::to_string(stepIndex) + "]: still busy after " +
                           std::to_string(step.frames) + " frames (morph samples left " +
                           std::to_string(session.morphRemaining()) + ", chunks waiting " +
                           std::to_string(session.remeshPending()) + ")";
            return result;
        }
    }
    return result;
}

std::string statsJson(const ReplayScript& script, const ReplayResult& result) {
    nlohmann::json frames = nlohmann::json::array();
    std::array<double, kStageCount> sum{}, worst{};
    double totalSum = 0.0, totalWorst = 0.0;
    for (const FrameStats& f : result.stats) {
        nlohmann::json stages = nlohmann::json::object();
        for (int s = 0; s < kStageCount; ++s) {
            const double t = f.stageMs[static_cast<std::size_t>(s)];
            stages[stageName(static_cast<Stage>(s))] = t;
            sum[static_cast<std::size_t>(s)] += t;
            worst[static_cast<std::size_t>(s)] = std::max(worst[static_cast<std::size_t>(s)], t);
        }
        totalSum += f.totalMs;
        totalWorst = std::max(totalWorst, f.totalMs);
        frames.push_back({{"frame", f.frame}, {"total_ms", f.totalMs}, {"budget_ms", f.budgetMs}, {"stages_ms", stages},
                          {"morph_samples", f.morphSamples}, {"morph_pending", f.morphPending},
                          {"chunks_meshed", f.chunksMeshed}, {"chunks_shown", f.chunksShown},
                          {"remesh_pending", f.remeshPending}, {"lod_chunks_visited", f.lodChunksVisited},
                          {"sculptures_loading", f.sculpturesLoading},
                          {"mesh_bytes_shown", f.meshBytesShown}, {"upload_bytes", f.uploadBytes},
                          {"uploads_pending", f.uploadsPending}, {"triangles_shown", f.trianglesShown},
                          {"triangles_drawn", f.trianglesDrawn},
                          {"chunks_drawn", f.chunksDrawn}, {"draw_calls", f.drawCalls},
                          {"impostors_drawn", f.impostorsDrawn}, {"sculptures_hidden", f.sculpturesHidden},
                          {"shadow_maps_drawn", f.shadowMapsDrawn}, {"shadow_maps_kept", f.shadowMapsKept},
                          {"pictures_kept", f.picturesKept}, {"pictures_sharpened", f.picturesSharpened},
                          {"gpu_ms", f.gpuMs},
                          {"gpu_pass_ms", {{"shadow", f.gpuPassMs.shadow}, {"scene", f.gpuPassMs.scene},
                                           {"occlusion", f.gpuPassMs.occlusion}, {"post", f.gpuPassMs.post}}}});
    }
    const double n = std::max<double>(1.0, static_cast<double>(result.stats.size()));
    // The GPU's time over the frames that have a measurement (none headless,
    // and the first few of a renderer's: timer results come views later).
    double gpuSum = 0.0, gpuWorst = 0.0;
    std::size_t gpuFrames = 0;
    for (const FrameStats& f : result.stats)
        if (f.gpuMs >= 0.0) {
            gpuSum += f.gpuMs;
            gpuWorst = std::max(gpuWorst, f.gpuMs);
            ++gpuFrames;
        }
    nlohmann::json mean = nlohmann::json::object(), maxima = nlohmann::json::object();
    for (int s = 0; s < kStageCount; ++s) {
        mean[stageName(static_cast<Stage>(s))] = sum[static_cast<std::size_t>(s)] / n;
        maxima[stageName(static_cast<Stage>(s))] = worst[static_cast<std::size_t>(s)];
    }
    nlohmann::json doc = {{"script", script.file},
                          {"frames", frames},
                          {"summary", {{"frames", result.stats.size()}, {"mean_total_ms", totalSum / n},
                                       {"max_total_ms", totalWorst}, {"mean_stage_ms", mean}, {"max_stage_ms", maxima},
                                       {"gpu_frames", gpuFrames},
                                       {"mean_gpu_ms", gpuFrames ? nlohmann::json(gpuSum / static_cast<double>(gpuFrames))
                                                                 : nlohmann::json()},
                                       {"max_gpu_ms", gpuFrames ? nlohmann::json(gpuWorst) : nlohmann::json()}}},
                          {"screenshots", result.screenshots},
                          {"exports", result.exports},
                          {"notes", result.notes},
                          {"error", result.error}};
    return doc.dump(1) + "\n";
}

}  // namespace hg::garden
