// GardenSession's sculpting: edits applied to a sculpture's grid within the
// call, undo and redo across sculptures, and the tool hand driving strokes
// and perturbations (docs/design.md §6: tools read hands, never devices).
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "garden/app/garden_session.h"
#include "garden/morph/morph_blend.h"
#include "garden/scene/to_glm.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/edit_field.h"
#include "garden/sculpt/impacts.h"
#include "garden/sculpt/stroke_segments.h"
#include "garden/sculpt/surface_ray.h"
#include "voxel/volume.h"

namespace hg::garden {

namespace {

bool finite3(const std::array<double, 3>& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

}  // namespace

std::string GardenSession::checkEditable(int sculpture) const {
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return "no such sculpture";
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (s.missing()) return "the sculpture '" + s.name + "' is missing: " + s.error;
    return "";
}

SculptureEdits& GardenSession::editsOf(int sculpture) {
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (s.edits) return *s.edits;
    s.edits = std::make_unique<SculptureEdits>(*s.volume);
    if (s.morphResult() && blender_) {
        // From now on the blend goes to the unedited grid and the edits are
        // applied after it, box by box (morph()): they persist when the
        // weights change.
        blender_ = std::make_unique<MorphBlender>(*sources_, s.edits->mutableBase());
        restartMorph();
    }
    return *s.edits;
}

void GardenSession::discardEdits(int sculpture) {
    if (stroking()) endStroke();
    if (sculpture < 0 || sculpture >= static_cast<int>(sculptures_.size())) return;
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (!s.edits) return;
    while (const auto box = s.edits->undo()) showChanged(sculpture, *box);
    s.edits->clearRedo();
    const auto isEdit = [sculpture](const UndoEntry& u) { return u.sculpture == sculpture && !u.move; };
    // (replacements go too: the edits they replaced are gone)
    undoOrder_.erase(std::remove_if(undoOrder_.begin(), undoOrder_.end(), isEdit), undoOrder_.end());
    redoOrder_.erase(std::remove_if(redoOrder_.begin(), redoOrder_.end(), isEdit), redoOrder_.end());
    record(DiscardAction{s.name});
}

std::string GardenSession::restore(const std::vector<Action>& records) { return restoreRecords(records).message(); }

JournalPlayed GardenSession::restoreRecords(const std::vector<Action>& records) {
    restoring_ = true;
    for (Sculpture& s : sculptures_)
        if (s.edits) s.edits->setDeferred(true);
    JournalPlayed result;
    for (std::size_t n = 0; n < records.size() && result.ok(); ++n) {
        const Action& r = records[n];
        std::string why;
        const auto sculptureOf = [&](const std::string& name) {
            const int i = findSculpture(name);
            if (i < 0) why = "no sculpture named '" + name + "'";
            else if (sculptures_[static_cast<std::size_t>(i)].missing()) why = "the sculpture '" + name + "' is missing";
            else if (!sculptures_[static_cast<std::size_t>(i)].edits) editsOf(i).setDeferred(true);
            return i;
        };
        if (const auto* st = std::get_if<StrokeAction>(&r)) {
            const int i = sculptureOf(st->sculpture);
            if (why.empty()) {
                Stroke stroke;
                stroke.tool = st->tool;
                stroke.radius = st->radius;
                stroke.softness = st->softness;
                stroke.path = st->path;
                why = applyStrokeModel(i, stroke);
            }
        } else if (const auto* p = std::get_if<PerturbAction>(&r)) {
            const int i = sculptureOf(p->sculpture);
            if (why.empty()) why = applyPerturbationModel(i, p->perturbation);
        } else if (std::holds_alternative<UndoAction>(r)) {
            if (!undo()) why = "nothing to undo";
        } else if (std::holds_alternative<RedoAction>(r)) {
            if (!redo()) why = "nothing to redo";
        } else if (const auto* d = std::get_if<DiscardAction>(&r)) {
            const int i = sculptureOf(d->sculpture);
            if (why.empty()) discardEdits(i);
        } else if (const auto* rp = std::get_if<ReplaceAction>(&r)) {
            const int i = sculptureOf(rp->sculpture);
            if (why.empty()) why = replacePerturbationModel(i, rp->edit, rp->perturbation);
        } else if (const auto* im = std::get_if<ImpactsAction>(&r)) {
            const int i = sculptureOf(im->sculpture);
            if (why.empty()) why = applyImpactsModel(i, im->series);
        } else if (const auto* mv = std::get_if<MoveAction>(&r)) {
            const int i = findSculpture(mv->sculpture);
            if (i < 0) why = "no sculpture named '" + mv->sculpture + "'";
            else why = moveSculpture(i, mv->placement);
        } else if (const auto* m = std::get_if<MorphWeightsAction>(&r)) {
            if (!blender_) why = "the garden has no metamorphosis";
            else {
                weights_ = weightsFromBarycentric(m->barycentric, m->balance);
                restartMorph();
            }
        }
        if (why.empty()) {
            ++result.played;
        } else {
            result.action = actionKind(r);
            result.reason = why;
        }
    }
    restoring_ = false;
    for (std::size_t i = 0; i < sculptures_.size(); ++i)
        if (sculptures_[i].edits)
            for (const voxel::IndexBox& box : sculptures_[i].edits->flush()) showChanged(static_cast<int>(i), box);
    return result;
}

void GardenSession::showChanged(int sculpture, const voxel::IndexBox& box) {
    // Playing a journal: the grids are recomputed at the end, and shown then.
    if (box.empty() || restoring_) return;
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    s.pyramid->update(box);
    s.queue->markChanged(box);
}

std::string GardenSession::applyStroke(int sculpture, StrokeTool tool, const std::vector<std::array<double, 3>>& worldPath,
                                       double radius, double softness) {
    if (worldPath.empty()) return "the stroke has no path";
    std::string why = beginStroke(sculpture, tool, worldPath[0], radius, softness);
    if (!why.empty()) return why;
    for (std::size_t i = 1; i < worldPath.size(); ++i) {
        why = extendStroke(worldPath[i]);
        if (!why.empty()) {
            endStroke();
            return why;
        }
    }
    endStroke();
    return "";
}

std::string GardenSession::beginStroke(int sculpture, StrokeTool tool, const std::array<double, 3>& worldPoint,
                                       double radius, double softness) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    if (!finite3(worldPoint)) return "the stroke's point is not a finite position";
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    Stroke stroke;
    stroke.tool = tool;
    stroke.radius = radius / s.scale;
    stroke.softness = softness;
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
    showChanged(sculpture, edits.append(std::move(e)));
    strokeSculpture_ = sculpture;
    undoOrder_.push_back(UndoEntry::edit(sculpture));
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
    if (!rest.empty()) showChanged(sculpture, editsOf(sculpture).extendLastStroke(rest));
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
    record(StrokeAction{s.name, stroke.tool, stroke.radius, stroke.softness, stroke.path, stroke.mirror});
    strokeSculpture_ = -1;
}

std::string GardenSession::applyPerturbation(int sculpture, QuadricShape shape, const std::array<double, 3>& worldCenter,
                                             const std::array<double, 3>& radii, double strength) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    if (!finite3(worldCenter)) return "the perturbation's centre is not a finite position";
    const int used = shape == QuadricShape::Ellipsoid ? 3 : 2;
    for (int i = 0; i < used; ++i)
        if (!(std::isfinite(radii[static_cast<std::size_t>(i)]) && radii[static_cast<std::size_t>(i)] > 0.0))
            return "the perturbation's radii must be positive numbers";
    if (shape == QuadricShape::Torus && radii[1] >= radii[0]) return "a torus's tube radius must be under its ring radius";
    if (!(std::isfinite(strength) && std::fabs(strength) <= 1000.0)) return "the strength must be a number in [-1000, 1000] voxels";
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    Perturbation p;
    p.shape = shape;
    p.center = toModel(s, toGlm(worldCenter));
    p.radii = {radii[0] / s.scale, radii[1] / s.scale, radii[2] / s.scale};
    p.strength = strength;
    p.mirror = s.mirror;
    // The quadric's axes are the world's, turned into the model frame.
    const glm::mat3 toModelAxes = glm::mat3(glm::inverse(s.modelToWorld));
    for (int i = 0; i < 3; ++i) {
        glm::vec3 axis(0.0f);
        axis[i] = 1.0f;
        const glm::vec3 m = glm::normalize(toModelAxes * axis);
        p.axes[static_cast<std::size_t>(i)] = {m.x, m.y, m.z};
    }
    return applyPerturbationModel(sculpture, p);
}

std::string GardenSession::applyPerturbationModel(int sculpture, const Perturbation& p) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    SculptureEdits& edits = editsOf(sculpture);
    if (p.radii[0] < 0.5 * edits.units().voxelSize) return "the perturbation is smaller than half a voxel";
    Edit e;
    e.op = p;
    showChanged(sculpture, edits.append(std::move(e)));
    undoOrder_.push_back(UndoEntry::edit(sculpture));
    redoOrder_.clear();
    record(PerturbAction{sculptures_[static_cast<std::size_t>(sculpture)].name, p});
    return "";
}

std::string GardenSession::applyImpacts(int sculpture, const std::array<double, 3>& worldOrigin,
                                        const std::array<double, 3>& worldDirection, ImpactTool tool) {
    if (stroking()) endStroke();
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    if (!finite3(worldOrigin) || !finite3(worldDirection)) return "the impact ray is not finite";
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    // Into the model frame: lengths by the scale, volumes by its cube.
    tool.size /= s.scale;
    tool.volume /= s.scale * s.scale * s.scale;
    if (tool.spread != ImpactSpread::Cone) tool.spreadSize /= s.scale;
    SculptureEdits& edits = editsOf(sculpture);
    if (std::string why = checkImpactTool(tool, edits.units().voxelSize); !why.empty()) return why;
    const glm::dmat4 toModelM = glm::inverse(glm::dmat4(s.modelToWorld));
    const glm::dvec3 o = glm::dvec3(toModelM * glm::dvec4(worldOrigin[0], worldOrigin[1], worldOrigin[2], 1.0));
    glm::dvec3 d = glm::dvec3(toModelM * glm::dvec4(worldDirection[0], worldDirection[1], worldDirection[2], 0.0));
    if (!(glm::length(d) > 0.0)) return "the impact ray has no direction";
    d = glm::normalize(d);
    ImpactSeries series;
    series.volume = tool.volume;
    const frep::Box3& box = s.volume->frame.modelBox;
    for (const ImpactRay& ray : drawImpactRays({{o.x, o.y, o.z}, {d.x, d.y, d.z}}, tool)) {
        const ImpactRay relative = raysInBox({ray}, box)[0];
        series.rayOrigins.push_back(relative.origin);
        series.rayDirections.push_back(relative.direction);
        if (auto m = castImpact(*s.volume, ray, tool, edits.units())) series.impacts.push_back(*m);
    }
    if (series.impacts.empty()) return "no impact met the sculpture";
    return applyImpactsModel(sculpture, series);
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
    showChanged(sculpture, edits.append(std::move(e)));
    undoOrder_.push_back(UndoEntry::edit(sculpture));
    redoOrder_.clear();
    record(ImpactsAction{sculptures_[static_cast<std::size_t>(sculpture)].name, series});
    return "";
}

std::string GardenSession::reapplyImpacts(int from, int to) {
    if (from < 0 || from >= static_cast<int>(sculptures_.size()) || to < 0 || to >= static_cast<int>(sculptures_.size()))
        return "no such sculpture";
    const Sculpture& src = sculptures_[static_cast<std::size_t>(from)];
    const ImpactSeries* last = nullptr;
    if (src.edits)
        for (const Edit& e : src.edits->list().edits())
            if (const auto* m = std::get_if<ImpactSeries>(&e.op)) last = m;
    if (!last) return "'" + src.name + "' has no impacts to fire again";
    if (std::string why = checkEditable(to); !why.empty()) return why;
    const Sculpture& dst = sculptures_[static_cast<std::size_t>(to)];
    SculptureEdits& edits = editsOf(to);
    ImpactTool tool;
    tool.shape = last->impacts[0].shape;
    // The same tool in the other sculpture's model units.
    const double k = src.scale / dst.scale;
    tool.size = last->impacts[0].size * k;
    tool.volume = last->volume * k * k * k;
    ImpactSeries series = *last;
    series.impacts.clear();
    series.volume = tool.volume;
    std::vector<ImpactRay> relative;
    for (std::size_t i = 0; i < last->rayOrigins.size(); ++i) relative.push_back({last->rayOrigins[i], last->rayDirections[i]});
    for (const ImpactRay& ray : raysFromBox(relative, dst.volume->frame.modelBox))
        if (auto m = castImpact(*dst.volume, ray, tool, edits.units())) series.impacts.push_back(*m);
    if (series.impacts.empty()) return "no impact met '" + dst.name + "'";
    return applyImpactsModel(to, series);
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

std::string GardenSession::editPerturbation(int sculpture, std::size_t edit, double strength,
                                            const std::array<double, 3>& radii) {
    if (std::string why = checkEditable(sculpture); !why.empty()) return why;
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (!s.edits || edit >= s.edits->list().size()) return "no such edit";
    const auto* old = std::get_if<Perturbation>(&s.edits->list().edits()[edit].op);
    if (!old) return "edit " + std::to_string(edit) + " is not a perturbation";
    Perturbation p = *old;
    p.strength = strength;
    p.radii = {radii[0] / s.scale, radii[1] / s.scale, radii[2] / s.scale};
    return replacePerturbationModel(sculpture, edit, p);
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
    Edit e;
    e.op = p;
    Edit replaced;
    showChanged(sculpture, s.edits->replace(edit, std::move(e), replaced));
    UndoEntry entry;
    entry.sculpture = sculpture;
    entry.replaced = edit;
    entry.replacement = std::make_pair(before, p);
    undoOrder_.push_back(entry);
    redoOrder_.clear();
    record(ReplaceAction{s.name, edit, p});
    return "";
}

bool GardenSession::undo() { return stepHistory(undoOrder_, redoOrder_, true); }
bool GardenSession::redo() { return stepHistory(redoOrder_, undoOrder_, false); }

bool GardenSession::stepHistory(std::vector<UndoEntry>& from, std::vector<UndoEntry>& to, bool undoing) {
    if (stroking()) endStroke();
    endLiveMove();
    while (!from.empty()) {
        UndoEntry entry = from.back();
        from.pop_back();
        Sculpture& s = sculptures_[static_cast<std::size_t>(entry.sculpture)];
        if (entry.move) {
            // A move holds the placements before and after it.
            placeSculpture(entry.sculpture, undoing ? entry.move->first : entry.move->second);
        } else if (entry.replaced) {
            if (!s.edits || *entry.replaced >= s.edits->list().size()) continue;
            Edit e;
            e.op = undoing ? entry.replacement->first : entry.replacement->second;
            Edit out;
            showChanged(entry.sculpture, s.edits->replace(*entry.replaced, std::move(e), out));
        } else {
            if (!s.edits) continue;
            const auto box = undoing ? s.edits->undo() : s.edits->redo();
            if (!box) continue;
            showChanged(entry.sculpture, *box);
        }
        to.push_back(entry);
        if (undoing) record(UndoAction{});
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
    UndoEntry entry = UndoEntry::edit(sculpture);
    entry.move = std::make_pair(s.placement, placement);
    undoOrder_.push_back(entry);
    redoOrder_.clear();
    placeSculpture(sculpture, placement);
    record(MoveAction{s.name, placement});
    return "";
}

void GardenSession::placeSculpture(int sculpture, const Placement& placement, bool followOrbit) {
    Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    s.placement = placement;
    s.modelToWorld = placementMatrix(placement);
    s.scale = placement.scale;
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
        if (s.missing()) continue;
        const glm::dmat4 toModelM = glm::inverse(glm::dmat4(s.modelToWorld));
        const glm::dvec3 o = glm::dvec3(toModelM * glm::dvec4(glm::dvec3(aim.position), 1.0));
        const glm::dvec3 d = glm::dvec3(toModelM * glm::dvec4(glm::dvec3(aim.forward()), 0.0));
        // t is in world ray lengths (d is the world direction taken into the
        // model): comparable across sculptures.
        const auto t = marchToSurface(*s.volume, {o.x, o.y, o.z}, {d.x, d.y, d.z});
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
    if (tool_.kind == ToolSettings::Kind::Move) {
        moveWithHands(h);
        return;
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
    if (!held) {
        if (stroking()) endStroke();
        toolArmed_ = true;
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
    const auto hit = toolHit(h.aim);
    if (!hit) return;
    toolArmed_ = false;
    const auto [sculpture, point] = *hit;
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
        applyPerturbation(sculpture, tool_.shape, toArray(point), tool_.perturbRadii(), tool_.perturbStrength());
        return;
    }
    StrokeTool t = tool_.kind == ToolSettings::Kind::Add ? StrokeTool::Add
                   : tool_.kind == ToolSettings::Kind::Melt ? StrokeTool::Melt : StrokeTool::Carve;
    if (tool_.reverse && t != StrokeTool::Melt) t = t == StrokeTool::Carve ? StrokeTool::Add : StrokeTool::Carve;
    strokeDepth_ = glm::length(point - h.aim.position);
    beginStroke(sculpture, t, toArray(point), tool_.radius, tool_.softness);
}

}  // namespace hg::garden
