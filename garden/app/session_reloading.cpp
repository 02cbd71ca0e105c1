// GardenSession's sources edited on disk (issue 23, docs/desktop.md
// "Sources edited on disk"): a sculpture whose HyperFun file changed is read
// again and, when it parses and samples, its grid is replaced and its edits
// applied again; a broken file keeps the last good grid and says why.
// Nothing the user made (edits, undo history, placement) is lost.
//
// Three cases, each giving what a fresh open of the changed files would:
// - the grid's frame is the one it had (a "box" in the garden file, or a
//   solid that kept its extent): replaced in place, the shown meshes
//   replaced chunk by chunk like an edit's;
// - the solid grew or shrank (no "box"): the sculpture is rebuilt in its new
//   frame, its edits derived again in the new grid's units (reframe);
// - a source of the metamorphosis: the same for the source, then the
//   morph's caches are sampled again and the result blended again with the
//   budgeted blend, its own edits applied after it as on any weight change.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <system_error>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_sampling.h"
#include "garden/morph/garden_morph.h"
#include "garden/morph/morph_blend.h"
#include "garden/morph/morph_sources.h"
#include "garden/morph/morph_state.h"
#include "garden/sculpt/impacts.h"
#include "garden/sculpt/mask_margin.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/sketch_edit.h"
#include "garden/sculpt/stroke_segments.h"
#include "voxel/sampler.h"

namespace hg::garden {

namespace {

bool sameFrame(const voxel::VolumeFrame& was, const voxel::VolumeFrame& now) {
    bool same = now.voxelSize == was.voxelSize && now.band == was.band;
    for (int a = 0; a < 3; ++a)
        same = same && now.modelBox.lo[a] == was.modelBox.lo[a] && now.modelBox.hi[a] == was.modelBox.hi[a] &&
               now.indexBox.lo[a] == was.indexBox.lo[a] && now.indexBox.hi[a] == was.indexBox.hi[a];
    return same;
}

// What applying the edit's action derives from the grid's units, derived
// again in `u`: as a journal's replay on the new grid would (a stroke from
// its first point, then the rest, as applyStrokeModel segments it).
void rederive(Edit& e, const FieldUnits& u) {
    if (auto* s = std::get_if<Stroke>(&e.op)) {
        const std::vector<ModelPoint> path = s->path;
        s->segments.clear();
        s->path.assign(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(1, path.size())));
        extendStrokeSegments(*s, 0, u);
        if (path.size() > 1) {
            s->path = path;
            extendStrokeSegments(*s, 1, u);
        }
    } else if (auto* m = std::get_if<ImpactSeries>(&e.op)) {
        for (Impact& i : m->impacts) i.reach = impactReach(i, u);
    } else if (auto* k = std::get_if<SketchSolid>(&e.op)) {
        resolveSketch(*k, u);  // it resolved when made: the outline is the same
    }
    if (e.mask) e.mask->box = maskBox(e.mask->balls, maskMargin(e, u));
}

}  // namespace

std::int64_t GardenSession::sourceStamp(const std::string& path) {
    std::error_code ec;
    const auto t = std::filesystem::last_write_time(path, ec);
    if (ec) return 0;
    return static_cast<std::int64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count());
}

std::vector<GardenSession::SourceReload> GardenSession::reloadChangedSources() {
    std::vector<SourceReload> out;
    std::vector<std::size_t> reported;
    const Garden& g = *load_.garden;
    // The morphs' sources that changed and read well: replaced together, so
    // each morph's caches are sampled once however many of them changed.
    std::vector<std::size_t> morphChanged;
    std::vector<SculptureLoad> morphLoads;
    std::vector<voxel::Volume> morphGrids;
    for (std::size_t i = 0; i < fileSculptures_ && i < sculptures_.size(); ++i) {
        Sculpture& s = sculptures_[i];
        if (s.removed || s.loading) continue;
        const SculptureSpec& spec = g.sculptures[i];
        const std::int64_t stamp = sourceStamp(spec.file);
        if (stamp == 0 || stamp == s.sourceStamp) continue;
        s.sourceStamp = stamp;
        std::string problem;
        const bool morphSource = isMorphSource(g, i);
        SculptureLoad loaded = loadSculpture(spec);
        if (!loaded.ok()) {
            problem = loaded.error;
        } else {
            voxel::VoxelizeResult r = sampleSculptureSource(spec, loaded, volumeRequest(spec));
            if (!r.volume) {
                problem = spec.file + ": cannot be sampled: " + r.error;
            } else if (morphSource) {
                morphChanged.push_back(i);
                morphLoads.push_back(std::move(loaded));
                morphGrids.push_back(std::move(*r.volume));
            } else {
                problem = replaceSource(i, std::move(loaded), std::move(*r.volume));
            }
        }
        s.sourceProblem = problem;
        reported.push_back(i);
    }
    if (!morphChanged.empty()) {
        const std::string problem = replaceMorphSources(morphChanged, std::move(morphLoads), std::move(morphGrids));
        for (std::size_t i : morphChanged) sculptures_[i].sourceProblem = problem;
    }
    reloadAddedSources(reported);  // garden/app/session_added_reloading.cpp
    for (std::size_t i : reported) {
        std::string& problem = sculptures_[i].sourceProblem;
        while (!problem.empty() && problem.back() == '\n') problem.pop_back();
        out.push_back({sculptures_[i].name, problem});
    }
    return out;
}

std::string GardenSession::replaceSource(std::size_t index, SculptureLoad loaded, voxel::Volume fresh) {
    Sculpture& s = sculptures_[index];
    if (s.missing()) {
        // A sculpture that was missing comes in as if it had loaded at the start.
        s.error.clear();
        s.source.program = loaded.program;
        load_.sculptures[static_cast<std::size_t>(s.source.spec)] = std::move(loaded);
        attachGrid(index, std::make_unique<voxel::Volume>(std::move(fresh)), "");
        ++s.frameGeneration;
        return "";
    }
    if (stroking() && strokeSculpture_ == static_cast<int>(index)) endStroke();
    if (liveMove_ == static_cast<int>(index)) endLiveMove();
    const bool same = sameFrame(s.volume->frame, fresh.frame);
    // In place (the SculptureEdits holds the grid by reference).
    *s.volume = std::move(fresh);
    s.source.program = loaded.program;
    load_.sculptures[static_cast<std::size_t>(s.source.spec)] = std::move(loaded);
    if (same) {
        // The meshes already shown are replaced chunk by chunk like an edit's.
        if (s.edits) s.edits->rebase();
        showChanged(static_cast<int>(index), s.volume->frame.indexBox);
        return "";
    }
    reframeSculpture(index);
    return "";
}

void GardenSession::reframeSculpture(std::size_t index) {
    Sculpture& s = sculptures_[index];
    // The grid is in its new frame: the edits (and those a discard holds,
    // for its undo) are derived again in its units, then every cache made
    // from the grid is made anew; the view drops the old meshes (frameGeneration).
    if (s.edits) {
        const FieldUnits u = unitsOf(*s.volume);
        const auto again = [&u](Edit& e) { rederive(e, u); };
        s.edits->reframe(again);
        for (std::vector<UndoEntry>* order : {&undoOrder_, &redoOrder_})
            for (UndoEntry& entry : *order)
                if (entry.sculpture == static_cast<int>(index))
                    for (Edit& e : entry.discardedEdits) again(e);
    }
    attachMeshing(s);
    ++s.frameGeneration;
    if (selected_ == static_cast<int>(index)) navigator_.setOrbitTarget(s.worldCentre());
}

std::string GardenSession::replaceMorphSources(const std::vector<std::size_t>& changed, std::vector<SculptureLoad> loads,
                                              std::vector<voxel::Volume> grids) {
    // Every morph with a changed source gets its caches first, from the new
    // files: a failure there leaves everything as it was.
    GardenLoad trial = load_;
    ResolvedBoxes resolved = sampledModelBoxes(sculptures_);
    for (std::size_t k = 0; k < changed.size(); ++k) {
        trial.sculptures[changed[k]] = loads[k];
        resolved[changed[k]] = grids[k].frame.modelBox;
    }
    // The morph results that stand (their state made) and use a changed source, with their new caches.
    std::vector<std::pair<int, std::unique_ptr<MorphSources>>> rebuilt;
    for (int r : morphResults()) {
        const Sculpture& result = sculptures_[static_cast<std::size_t>(r)];
        const auto spec = static_cast<std::size_t>(result.source.spec);
        const MorphSpec& m = load_.garden->morphs[spec];
        const bool uses = std::any_of(changed.begin(), changed.end(), [&m](std::size_t i) { return feedsMorph(m, i); });
        if (!uses) continue;
        MorphSourcesResult built = buildGardenMorphSources(trial, spec, 0, resolved);
        if (!built.sources) {
            const std::string named = load_.garden->morphs.size() > 1 ? " '" + m.resultName + "'" : std::string();
            return "the metamorphosis" + named + " cannot be made of the changed sources: " + built.error;
        }
        // A morph that was missing comes back on reopening.
        if (result.morph) rebuilt.emplace_back(r, std::make_unique<MorphSources>(std::move(*built.sources)));
    }
    for (std::size_t k = 0; k < changed.size(); ++k)
        if (std::string why = replaceSource(changed[k], std::move(loads[k]), std::move(grids[k])); !why.empty()) return why;
    for (auto& [index, fresh] : rebuilt) {
        Sculpture& r = sculptures_[static_cast<std::size_t>(index)];
        MorphState& m = *r.morph;
        const bool same = sameFrame(m.sources->frame, fresh->frame);
        m.blender.reset();  // it reads the old caches
        *m.sources = std::move(*fresh);
        m.balance = morphBalance(load_.garden->morphs[static_cast<std::size_t>(r.source.spec)], *m.sources);
        // The weights keep their place in the triangle, balanced for the new sources.
        MorphWeights w = weightsFromBarycentric(m.weights->barycentric, m.balance);
        w.point = m.weights->point;
        w.clamped = m.weights->clamped;
        m.weights = w;
        if (!same) {
            if (stroking() && strokeSculpture_ == index) endStroke();
            if (liveMove_ == index) endLiveMove();
            *r.volume = makeMorphVolume(*m.sources);
            reframeSculpture(static_cast<std::size_t>(index));
        }
        m.blender = std::make_unique<MorphBlender>(*m.sources, r.edits ? r.edits->mutableBase() : *r.volume);
        restartMorph(index);
    }
    return "";
}

}  // namespace hg::garden
