// GardenSession's sculpting: edits applied to a sculpture's grid within the
// call (apply()'s cases, garden/app/session_actions.cpp), live strokes,
// undo and redo across sculptures, and the tool hand driving strokes and
// perturbations (docs/design.md §6: tools read hands, never devices).
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "garden/app/garden_session.h"
#include "garden/morph/morph_state.h"
#include "garden/scene/to_glm.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/edit_field.h"
#include "garden/sculpt/impacts.h"
#include "garden/sculpt/sketch_edit.h"
#include "garden/sculpt/stroke_segments.h"
#include "garden/sculpt/surface_ray.h"
#include "voxel/volume.h"

namespace hg::garden {

bool GardenSession::finite3(const std::array<double, 3>& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

std::string GardenSession::checkEditable(int sculpture) const {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return "no such sculpture";
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (s.removed) return "the sculpture '" + s.name + "' was removed";
    if (s.missing()) return "the sculpture '" + s.name + "' is missing: " + s.error;
    if (s.loading) return "the sculpture '" + s.name + "' is still loading";
    return "";
}

SculptureEdits& GardenSession::editsOf(int sculpture) {
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (s.edits) return *s.edits;
    s.edits = std::make_unique<SculptureEdits>(*s.volume);
    // Playing a journal: every grid is recomputed once at the end.
    if (restoring_) s.edits->setDeferred(true);
    if (s.morph) {
        // From now on the blend goes to the unedited grid and the edits are
        // applied after it, box by box (morph()): they persist when the
        // weights change.
        s.morph->blender.reset();  // before the new one: one writer of the grid at a time
        s.morph->blender = std::make_unique<MorphBlender>(*s.morph->sources, s.edits->mutableBase());
        restartMorph(sculpture);
    }
    return *s.edits;
}

void GardenSession::discardEdits(int sculpture) { discard(sculpture, true); }

void GardenSession::discard(int sculpture, bool undoable) {
    if (stroking()) endStroke();
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return;
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (!s.edits) return;
    UndoEntry entry(sculpture, DiscardAction{s.name, undoable});
    if (undoable) {
        takeEdits(entry);
        redoOrder_.clear();  // a new action, as any other
        undoOrder_.push_back(std::move(entry));
    } else {
        // As such a discard was made: the edits, their redo and every entry
        // of the sculpture but its moves and materials (its add too) gone.
        std::vector<voxel::IndexBox> changed;
        s.edits->takeAll(changed);
        for (const voxel::IndexBox& box : changed) showChanged(sculpture, box);
        s.edits->clearRedo();
        const auto gone = [sculpture](const UndoEntry& u) {
            return u.sculpture == sculpture && !std::holds_alternative<MoveAction>(u.action) &&
                   !std::holds_alternative<MaterialAction>(u.action);
        };
        undoOrder_.erase(std::remove_if(undoOrder_.begin(), undoOrder_.end(), gone), undoOrder_.end());
        redoOrder_.erase(std::remove_if(redoOrder_.begin(), redoOrder_.end(), gone), redoOrder_.end());
    }
    record(DiscardAction{s.name, undoable});
}

void GardenSession::takeEdits(UndoEntry& entry) {
    Sculpture& s = sculptures_[static_cast<std::size_t>(entry.sculpture)];
    std::vector<voxel::IndexBox> changed;
    entry.discardedEdits = s.edits->takeAll(changed);
    for (const voxel::IndexBox& box : changed) showChanged(entry.sculpture, box);
    // The entries of the edit list's history (replacements and earlier
    // discards too); the sculpture's moves, materials and its add stay undoable.
    std::vector<UndoEntry> kept;
    for (UndoEntry& u : undoOrder_) {
        const bool ofList = u.sculpture == entry.sculpture && !std::holds_alternative<MoveAction>(u.action) &&
                            !std::holds_alternative<AddAction>(u.action) &&
                            !std::holds_alternative<MaterialAction>(u.action);
        (ofList ? entry.discardedEntries : kept).push_back(std::move(u));
    }
    undoOrder_ = std::move(kept);
}

void GardenSession::putBackEdits(UndoEntry& entry, std::vector<UndoEntry>& undoOrder, std::size_t at) {
    Sculpture& s = sculptures_[static_cast<std::size_t>(entry.sculpture)];
    for (const voxel::IndexBox& box : s.edits->putBack(std::move(entry.discardedEdits))) showChanged(entry.sculpture, box);
    // Together where the discard stood: each sculpture's entries keep their
    // own order, which is what undo on one sculpture needs.
    undoOrder.insert(undoOrder.begin() + static_cast<std::ptrdiff_t>(at),
                     std::make_move_iterator(entry.discardedEntries.begin()),
                     std::make_move_iterator(entry.discardedEntries.end()));
    entry.discardedEdits.clear();
    entry.discardedEntries.clear();
}

void GardenSession::showChanged(int sculpture, const voxel::IndexBox& box) {
    // Playing a journal: the grids are recomputed at the end, and shown then.
    if (box.empty() || restoring_) return;
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    s.pyramid->update(box);
    if (s.errors) s.errors->update(box);
    s.queue->markChanged(box);
}

std::string GardenSession::beginStroke(int sculpture, StrokeTool tool, const std::array<double, 3>& worldPoint,
                                       double radius, double softness, double strength, Falloff falloff) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    if (!finite3(worldPoint)) return "the stroke's point is not a finite position";
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    Stroke stroke;
    stroke.tool = tool;
    stroke.radius = radius / s.scale();
    stroke.softness = softness;
    stroke.strength = strength;
    stroke.falloff = falloff;
    stroke.path.push_back(toModel(s, toGlm(worldPoint)));
    stroke.mirror = s.mirror;
    if (std::string why = startStroke(sculpture, std::move(stroke)); !why.empty()) return why;
    return "";
}

std::string GardenSession::startStroke(int sculpture, Stroke stroke) {
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    SculptureEdits& edits = editsOf(sculpture);
    if (std::string why = checkStroke(stroke, edits.units()); !why.empty()) return why;
    extendStrokeSegments(stroke, 0, edits.units());
    Edit e;
    e.op = std::move(stroke);
    e.mask = maskFor(sculpture, e);
    // At once, even when edits are spread: a live stroke's next point is
    // placed on the grid its first made (and a first point is one dot).
    showChanged(sculpture, edits.append(std::move(e)));
    strokeSculpture_ = sculpture;
    // The entry's action is the whole stroke once it ends (endStroke).
    undoOrder_.push_back(UndoEntry{sculpture, StrokeAction{}, std::nullopt, std::nullopt, std::nullopt});
    redoOrder_.clear();
    return "";
}

std::string GardenSession::applyStrokeModel(int sculpture, const Stroke& stroke) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    if (std::string why = checkStroke(stroke, editsOf(sculpture).units()); !why.empty()) return why;
    Stroke first = stroke;
    first.path.resize(1);
    first.segments.clear();
    if (std::string why = startStroke(sculpture, std::move(first)); !why.empty()) return why;
    const std::vector<ModelPoint> rest(stroke.path.begin() + 1, stroke.path.end());
    if (!rest.empty() && spreading()) editsOf(sculpture).extendLastStrokeSpread(rest);
    else if (!rest.empty()) showChanged(sculpture, editsOf(sculpture).extendLastStroke(rest));
    endStroke();
    return "";
}

std::string GardenSession::extendStroke(const std::array<double, 3>& worldPoint) {
    if (!stroking()) return "no stroke is under way";
    if (!finite3(worldPoint)) return "the stroke's point is not a finite position";
    const Sculpture& s = sculptures_[static_cast<std::size_t>(strokeSculpture_)];
    showChanged(strokeSculpture_, editsOf(strokeSculpture_).extendLastStroke(std::vector<ModelPoint>{toModel(s, toGlm(worldPoint))}));
    return "";
}

void GardenSession::endStroke() {
    if (!stroking()) return;
    const Sculpture& s = sculptures_[static_cast<std::size_t>(strokeSculpture_)];
    const Stroke& stroke = std::get<Stroke>(s.edits->list().edits().back().op);
    const StrokeAction done{s.name,   stroke.tool,     stroke.radius,  stroke.softness, stroke.path,
                            stroke.mirror, stroke.strength, stroke.falloff, stroke.fits};
    if (!undoOrder_.empty()) undoOrder_.back().action = done;  // the stroke's own entry: nothing came between
    record(done);
    strokeSculpture_ = -1;
}

std::string GardenSession::applyPerturbationModel(int sculpture, const Perturbation& p) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    SculptureEdits& edits = editsOf(sculpture);
    if (p.radii[0] < 0.5 * edits.units().voxelSize) return "the perturbation is smaller than half a voxel";
    Edit e;
    e.op = p;
    appendEdit(sculpture, std::move(e), PerturbAction{sculptures_[static_cast<std::size_t>(sculpture)].name, p});
    return "";
}

std::string GardenSession::applyImpactsModel(int sculpture, const ImpactSeries& series) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    if (series.impacts.empty()) return "the series has no impacts";
    SculptureEdits& edits = editsOf(sculpture);
    Edit e;
    e.op = series;
    auto& added = std::get<ImpactSeries>(e.op);
    for (Impact& m : added.impacts) m.reach = impactReach(m, edits.units());
    appendEdit(sculpture, std::move(e), ImpactsAction{sculptures_[static_cast<std::size_t>(sculpture)].name, series});
    return "";
}

std::string GardenSession::applySketchModel(int sculpture, const SketchAction& a) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    SculptureEdits& edits = editsOf(sculpture);
    SketchSolid solid;
    solid.mode = a.mode;
    solid.outline = a.points;
    solid.normal = a.normal;
    solid.thickness = a.thickness;
    solid.mirror = a.mirror;
    if (std::string why = resolveSketch(solid, edits.units()); !why.empty()) return why;
    Edit e;
    e.op = std::move(solid);
    appendEdit(sculpture, std::move(e), a);
    return "";
}

void GardenSession::appendEdit(int sculpture, Edit e, const Action& done) {
    e.mask = maskFor(sculpture, e);
    if (spreading())
        editsOf(sculpture).appendSpread(std::move(e));  // shown as its cells are computed (advanceEdits)
    else
        showChanged(sculpture, editsOf(sculpture).append(std::move(e)));
    undoOrder_.push_back(UndoEntry{sculpture, done, std::nullopt, std::nullopt, std::nullopt});
    redoOrder_.clear();
    record(done);
}

std::optional<std::size_t> GardenSession::pickPerturbation(int sculpture, const std::array<double, 3>& worldPoint) const {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return std::nullopt;
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (!s.edits || !finite3(worldPoint)) return std::nullopt;
    const ModelPoint m = toModel(s, toGlm(worldPoint));
    const auto& edits = s.edits->list().edits();
    for (std::size_t i = edits.size(); i-- > 0;) {
        const auto* p = std::get_if<Perturbation>(&edits[i].op);
        if (!p) continue;
        if (quadric(m[0], m[1], m[2], *p) >= 0.0 || (p->mirror && quadric(m[0], m[1], m[2], mirrored(*p)) >= 0.0))
            return i;
    }
    return std::nullopt;
}

std::string GardenSession::replacePerturbationModel(int sculpture, std::size_t edit, const Perturbation& p) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (!s.edits || edit >= s.edits->list().size()) return "no such edit";
    const auto* old = std::get_if<Perturbation>(&s.edits->list().edits()[edit].op);
    if (!old) return "edit " + std::to_string(edit) + " is not a perturbation";
    const int used = p.shape == QuadricShape::Ellipsoid ? 3 : 2;
    for (int i = 0; i < used; ++i)
        if (!(std::isfinite(p.radii[static_cast<std::size_t>(i)]) && p.radii[static_cast<std::size_t>(i)] >= 0.5 * s.edits->units().voxelSize))
            return "the perturbation's radii must be at least half a voxel";
    if (p.shape == QuadricShape::Torus && p.radii[1] >= p.radii[0]) return "a torus's tube radius must be under its ring radius";
    if (!(std::isfinite(p.strength) && std::fabs(p.strength) <= 1000.0)) return "the strength must be a number in [-1000, 1000] voxels";
    const Perturbation before = *old;
    // Made with its op (not assigned over a default Stroke: GCC 12 then
    // warns of the variant's old alternative, wrongly).
    Edit e{0, EditOp{p}, {}, s.edits->list().edits()[edit].mask};  // made inside a selection, it stays there
    Edit replaced;
    showChanged(sculpture, s.edits->replace(edit, std::move(e), replaced));
    const ReplaceAction done{s.name, edit, p};
    undoOrder_.push_back(UndoEntry{sculpture, done, std::nullopt, before, std::nullopt});
    redoOrder_.clear();
    record(done);
    return "";
}

bool GardenSession::undo() { return stepHistory(undoOrder_, redoOrder_, true); }
bool GardenSession::redo() { return stepHistory(redoOrder_, undoOrder_, false); }
bool GardenSession::undoSculpture(int sculpture) {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return false;
    return stepHistory(undoOrder_, redoOrder_, true, sculpture);
}

std::vector<HistoryItem> GardenSession::history() const {
    std::vector<HistoryItem> items;
    for (const UndoEntry& e : undoOrder_)
        items.push_back({e.sculpture, sculptures_[static_cast<std::size_t>(e.sculpture)].name, actionKind(e.action), false});
    for (auto it = redoOrder_.rbegin(); it != redoOrder_.rend(); ++it)
        items.push_back({it->sculpture, sculptures_[static_cast<std::size_t>(it->sculpture)].name, actionKind(it->action), true});
    return items;
}

bool GardenSession::stepHistory(std::vector<UndoEntry>& from, std::vector<UndoEntry>& to, bool undoing, int only) {
    if (stroking()) endStroke();
    endLiveMove();
    // Each sculpture's own edits undo and redo in their own order, so the
    // last entry of one sculpture can be taken out from among the others'.
    auto next = [&]() {
        for (std::size_t i = from.size(); i-- > 0;)
            if (only < 0 || from[i].sculpture == only) return static_cast<std::ptrdiff_t>(i);
        return static_cast<std::ptrdiff_t>(-1);
    };
    for (std::ptrdiff_t at = next(); at >= 0; at = next()) {
        UndoEntry entry = std::move(from[static_cast<std::size_t>(at)]);
        from.erase(from.begin() + at);
        Sculpture& s = sculptures_[static_cast<std::size_t>(entry.sculpture)];
        if (std::holds_alternative<DiscardAction>(entry.action)) {
            // (only undoable discards have entries)
            if (undoing) putBackEdits(entry, from, static_cast<std::size_t>(at));
            else takeEdits(entry);
        } else if (const auto* move = std::get_if<MoveAction>(&entry.action)) {
            placeSculpture(entry.sculpture, undoing ? *entry.placementBefore : move->placement);
        } else if (const auto* material = std::get_if<MaterialAction>(&entry.action)) {
            s.material = undoing ? *entry.materialBefore : material->material;
        } else if (std::holds_alternative<AddAction>(entry.action)) {
            s.removed = undoing;
            if (undoing && selected_ == entry.sculpture) select(-1);
        } else if (const auto* r = std::get_if<ReplaceAction>(&entry.action)) {
            if (!s.edits || r->edit >= s.edits->list().size()) continue;
            Edit e;
            e.op = undoing ? *entry.replacedBefore : r->perturbation;
            Edit out;
            showChanged(entry.sculpture, s.edits->replace(r->edit, std::move(e), out));
        } else {
            if (!s.edits) continue;
            const auto box = undoing ? s.edits->undo() : s.edits->redo();
            if (!box) continue;
            showChanged(entry.sculpture, *box);
        }
        to.push_back(entry);
        if (undoing) record(UndoAction{only < 0 ? std::string() : s.name});
        else record(RedoAction{});
        return true;
    }
    return false;
}

std::string GardenSession::moveSculpture(int sculpture, const Placement& placement) {
    if (stroking()) endStroke();
    endLiveMove();
    if (std::string why = checkPlacement(sculpture, placement); !why.empty()) return why;
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    const MoveAction done{s.name, placement};
    undoOrder_.push_back(UndoEntry{sculpture, done, s.placement, std::nullopt, std::nullopt});
    redoOrder_.clear();
    placeSculpture(sculpture, placement);
    record(done);
    return "";
}

std::string GardenSession::setMaterial(int sculpture, const Material& material) {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return "no such sculpture";
    if (stroking()) endStroke();
    endLiveMove();
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (s.removed) return "'" + s.name + "' is not in the garden";
    if (s.material == material) return "";
    const MaterialAction done{s.name, material};
    undoOrder_.push_back(UndoEntry{sculpture, done, std::nullopt, std::nullopt, s.material});
    redoOrder_.clear();
    s.material = material;
    record(done);
    return "";
}

void GardenSession::placeSculpture(int sculpture, const Placement& placement, bool followOrbit) {
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    s.placement = placement;
    if (followOrbit && selected_ == sculpture) select(sculpture);  // the orbit follows
}

void GardenSession::setMirror(int sculpture, std::optional<MirrorPlane> plane) {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return;
    if (plane) {
        ModelPoint& n = plane->normal;
        const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(l > 0.0) || !std::isfinite(l)) return;
        n = {n[0] / l, n[1] / l, n[2] / l};
    }
    sculptures_[static_cast<std::size_t>(sculpture)].mirror = plane;
}

std::size_t GardenSession::editCount(int sculpture) const {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return 0;
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    return s.edits ? s.edits->list().size() : 0;
}

std::optional<std::pair<int, glm::vec3>> GardenSession::toolHit(const Pose& aim) const {
    std::optional<std::pair<int, glm::vec3>> best;
    double bestT = 1e300;
    for (std::size_t i = 0; i < sculptures_.size(); ++i) {
        const Sculpture& s = sculptures_[i];
        if (!s.onShow()) continue;
        const glm::dmat4 toModelM = glm::inverse(glm::dmat4(s.modelToWorld()));
        const glm::dvec3 o = glm::dvec3(toModelM * glm::dvec4(glm::dvec3(aim.position), 1.0));
        const glm::dvec3 d = glm::dvec3(toModelM * glm::dvec4(glm::dvec3(aim.forward()), 0.0));
        // t is in world ray lengths (d is the world direction taken into the
        // model): comparable across sculptures.
        // A far grid on disk is not read back for a ray: its first coarse
        // level (in memory, and what is on show) answers.
        const poly::LodPyramid& pyramid = *s.pyramid;
        const auto t = s.volume->resident() || pyramid.levels() < 2
                           ? marchToSurface(*s.volume, {o.x, o.y, o.z}, {d.x, d.y, d.z})
                           : marchToSurface(
                                 s.volume->frame, 1,
                                 [&pyramid](int a, int b, int c) { return pyramid.value(1, a, b, c); },
                                 {o.x, o.y, o.z}, {d.x, d.y, d.z});
        if (!t || *t >= bestT) continue;
        bestT = *t;
        best = std::make_pair(static_cast<int>(i), aim.position + aim.forward() * static_cast<float>(*t));
    }
    return best;
}

void GardenSession::sculptWithHands(const Hands& hands) {
    const HandState& h = hands.tool;
    const std::uint32_t pressedNow = h.buttons & ~lastButtons_;
    lastButtons_ = h.buttons;
    if (pressedNow & kButtonUndo) undo();
    if (pressedNow & kButtonRedo) redo();
    // The gesture button takes the tool hand's ray while it is held.
    const bool gesturing = gesture_.drawing;
    gestureWithHands(h);
    deformLiveStep();
    if (gesturing || gesture_.drawing) {
        if (stroking()) endStroke();
        return;
    }
    if (tool_.kind == ToolSettings::Kind::Move) {
        moveWithHands(h);
        return;
    }
    if (tool_.kind == ToolSettings::Kind::Sketch || sketch_.drawing) {
        sketchWithHands(h);
        if (tool_.kind == ToolSettings::Kind::Sketch) return;
    }
    if (moveDrag_) {  // the tool changed during a drag
        moveDrag_.reset();
        endLiveMove();
    }
    if (tool_.kind == ToolSettings::Kind::None || !h.tracked) {
        if (stroking()) endStroke();
        return;
    }
    const bool held = h.trigger > 0.5f;
    const float rise = h.trigger - lastToolTrigger_;
    lastToolTrigger_ = h.trigger;
    if (!held) {
        if (stroking()) endStroke();
        toolArmed_ = true;
        settleFrames_ = 0;
        return;
    }
    const auto toArray = [](const glm::vec3& v) { return std::array<double, 3>{v.x, v.y, v.z}; };
    if (stroking()) {
        // Follow the hand: where the ray meets the sculpture, else as deep
        // along the ray as the stroke began.
        const auto hit = toolHit(h.aim);
        const glm::vec3 p = hit && hit->first == strokeSculpture_ ? hit->second
                                                                  : h.aim.position + h.aim.forward() * strokeDepth_;
        extendStroke(toArray(p));
        return;
    }
    if (!toolArmed_) return;  // one action per trigger pull
    // An analog trigger passes the threshold on its way in: the pressure an
    // action keeps is read once the pull has settled (it stopped deepening,
    // is all the way in, or four frames on, 44 ms at 90 Hz), so a firm pull
    // is not taken for a light one. A mouse button is all the way in at once.
    if (h.trigger < 0.98f && rise > 0.02f && settleFrames_ < 4) {
        ++settleFrames_;
        return;
    }
    settleFrames_ = 0;
    // The press picks the sculpture, and only the press (docs/desktop.md
    // "Tools"): a press that meets none does nothing until the trigger is
    // let go, rather than landing on whatever the dragged ray meets later.
    toolArmed_ = false;
    const auto hit = toolHit(h.aim);
    if (!hit) {
        toolMessage_ = std::string("the press met no sculpture: press on the sculpture to ") + toolKindName(tool_.kind);
        return;
    }
    toolMessage_.clear();
    const auto [sculpture, point] = *hit;
    if (selected_ != sculpture) select(sculpture);  // the sculpture edited is the one shown selected
    if (tool_.kind == ToolSettings::Kind::Impacts) {
        ImpactTool t;
        t.shape = tool_.impactShape;
        t.size = tool_.impactSize;
        t.volume = tool_.compactionCm3 * 1e-6;
        t.spread = tool_.spread;
        t.spreadSize = tool_.spread == ImpactSpread::Cone ? tool_.spreadSize * 3.14159265358979323846 / 180.0 : tool_.spreadSize;
        t.count = tool_.impactCount;
        t.seed = tool_.seed++;
        const glm::vec3 dir = h.aim.forward();
        applyImpacts(sculpture, toArray(h.aim.position), toArray(dir), t);
        return;
    }
    if (tool_.kind == ToolSettings::Kind::Perturb) {
        // The pressure scales the strength: what is journalled is the product.
        applyPerturbation(sculpture, tool_.shape, toArray(point), tool_.perturbRadii(),
                          tool_.perturbStrength() * static_cast<double>(h.pressure));
        return;
    }
    strokeDepth_ = glm::length(point - h.aim.position);
    // The strength the stroke is made with, pressure applied, is what the
    // journal keeps: a replay needs no pressure.
    const double strength = strokeStrength(tool_, h.pressure, editsOf(sculpture).units().band);
    beginStroke(sculpture, strokeToolOf(tool_), toArray(point), tool_.radius, tool_.softness, strength, tool_.falloff);
}

}  // namespace hg::garden
