// GardenSession's one entry for actions (garden/action/action.h): apply()
// and playing a journal, and the edge where world-frame requests (the
// tools, the replays' commands) become actions in a sculpture's model frame
// (docs/design.md §6 and §10).
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "garden/app/garden_session.h"
#include "garden/morph/morph_state.h"
#include "garden/morph/morph_weights.h"
#include "garden/scene/to_glm.h"
#include "garden/sculpt/impacts.h"
#include "garden/sculpt/sculpture_edits.h"
#include "voxel/volume.h"

namespace hg::garden {

namespace {

using ActionOrWhy = GardenSession::ActionOrWhy;

ActionOrWhy refused(std::string why) { return {std::nullopt, std::move(why)}; }

std::string applied(GardenSession& session, const ActionOrWhy& a) { return a.action ? session.apply(*a.action) : a.why; }

}  // namespace

int GardenSession::actionSculpture(const std::string& name, std::string& why) const {
    const int i = findSculpture(name);
    if (i < 0) why = "no sculpture named '" + name + "'";
    else why = checkEditable(i);
    return i;
}

std::string GardenSession::apply(const Action& action) {
    std::string why;
    if (const auto* a = std::get_if<StrokeAction>(&action)) {
        const int i = actionSculpture(a->sculpture, why);
        if (!why.empty()) return why;
        Stroke stroke;
        stroke.tool = a->tool;
        stroke.radius = a->radius;
        stroke.softness = a->softness;
        stroke.path = a->path;
        stroke.mirror = a->mirror;
        stroke.strength = a->strength;
        stroke.falloff = a->falloff;
        stroke.fits = a->fits;
        return applyStrokeModel(i, stroke);
    }
    if (const auto* a = std::get_if<PerturbAction>(&action)) {
        const int i = actionSculpture(a->sculpture, why);
        return why.empty() ? applyPerturbationModel(i, a->perturbation) : why;
    }
    if (const auto* a = std::get_if<ImpactsAction>(&action)) {
        const int i = actionSculpture(a->sculpture, why);
        return why.empty() ? applyImpactsModel(i, a->series) : why;
    }
    if (const auto* a = std::get_if<ReplaceAction>(&action)) {
        const int i = actionSculpture(a->sculpture, why);
        return why.empty() ? replacePerturbationModel(i, a->edit, a->perturbation) : why;
    }
    if (const auto* a = std::get_if<DiscardAction>(&action)) {
        const int i = actionSculpture(a->sculpture, why);
        if (why.empty()) discard(i, a->undoable);
        return why;
    }
    if (const auto* a = std::get_if<MoveAction>(&action)) {
        // A missing sculpture still has a place in the garden.
        const int i = findSculpture(a->sculpture);
        return i < 0 ? "no sculpture named '" + a->sculpture + "'" : moveSculpture(i, a->placement);
    }
    if (const auto* a = std::get_if<MaterialAction>(&action)) {
        const int i = findSculpture(a->sculpture);
        return i < 0 ? "no sculpture named '" + a->sculpture + "'" : setMaterial(i, a->material);
    }
    if (const auto* a = std::get_if<SketchAction>(&action)) {
        const int i = actionSculpture(a->sculpture, why);
        return why.empty() ? applySketchModel(i, *a) : why;
    }
    if (const auto* a = std::get_if<AddAction>(&action)) return applyAddModel(*a);
    if (const auto* a = std::get_if<ReloadAction>(&action)) return applyReloadModel(*a);
    if (const auto* a = std::get_if<ModelAction>(&action)) return applyModelAction(*a);
    if (const auto* a = std::get_if<DeformAction>(&action)) return applyDeformAction(*a);
    if (const auto* a = std::get_if<SelectAction>(&action)) return applySelectAction(*a);
    if (const auto* u = std::get_if<UndoAction>(&action)) {
        if (u->sculpture.empty()) return undo() ? "" : "nothing to undo";
        const int i = findSculpture(u->sculpture);
        if (i < 0) return "no sculpture named '" + u->sculpture + "'";
        return undoSculpture(i) ? "" : "nothing to undo on '" + u->sculpture + "'";
    }
    if (std::holds_alternative<RedoAction>(action)) return redo() ? "" : "nothing to redo";
    const auto& m = std::get<MorphWeightsAction>(action);
    const std::vector<int> morphs = morphResults();
    const int r = m.sculpture.empty() ? (morphs.empty() ? -1 : morphs.front()) : findSculpture(m.sculpture);
    if (r < 0 || !sculptures_[static_cast<std::size_t>(r)].morphResult())
        return m.sculpture.empty() ? "the garden has no metamorphosis" : "no metamorphosis named '" + m.sculpture + "'";
    MorphState* state = morphState(r);
    if (!state) return "the metamorphosis '" + sculptures_[static_cast<std::size_t>(r)].name + "' is missing";
    state->weights = weightsFromBarycentric(m.barycentric, m.balance);
    restartMorph(r);
    MorphWeightsAction named = m;
    named.sculpture = sculptures_[static_cast<std::size_t>(r)].name;
    record(named);
    return "";
}

std::string GardenSession::restore(const std::vector<Action>& records) { return restoreRecords(records).message(); }

JournalPlayed GardenSession::restoreRecords(const std::vector<Action>& records) {
    // Actions name sculptures that must have their grids: a journal waits
    // for progressive loading to finish.
    if (!records.empty()) finishLoading();
    restoring_ = true;
    for (Sculpture& s : sculptures_)
        if (s.edits) s.edits->setDeferred(true);
    JournalPlayed result;
    for (std::size_t n = 0; n < records.size() && result.ok(); ++n) {
        const std::string why = apply(records[n]);
        if (why.empty()) {
            ++result.played;
        } else {
            result.action = actionKind(records[n]);
            result.reason = why;
        }
    }
    restoring_ = false;
    for (std::size_t i = 0; i < sculptures_.size(); ++i)
        if (sculptures_[i].edits)
            for (const voxel::IndexBox& box : sculptures_[i].edits->flush()) showChanged(static_cast<int>(i), box);
    return result;
}

// --- world-frame requests into actions ------------------------------------

ActionOrWhy GardenSession::strokeFromWorld(int sculpture, StrokeTool tool,
                                           const std::vector<std::array<double, 3>>& worldPath, double radius,
                                           double softness, double strength, Falloff falloff) const {
    if (worldPath.empty()) return refused("the stroke has no path");
    if (std::string why = checkEditable(sculpture); !why.empty()) return refused(why);
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    StrokeAction a{s.name, tool, radius / s.scale(), softness, {}, s.mirror, strength, falloff, {}};
    for (const auto& p : worldPath) {
        if (!finite3(p)) return refused("the stroke's point is not a finite position");
        a.path.push_back(toModel(s, toGlm(p)));
    }
    return {a, ""};
}

ActionOrWhy GardenSession::perturbationFromWorld(int sculpture, QuadricShape shape,
                                                 const std::array<double, 3>& worldCenter,
                                                 const std::array<double, 3>& radii, double strength) const {
    if (std::string why = checkEditable(sculpture); !why.empty()) return refused(why);
    if (!finite3(worldCenter)) return refused("the perturbation's centre is not a finite position");
    const int used = shape == QuadricShape::Ellipsoid ? 3 : 2;
    for (int i = 0; i < used; ++i)
        if (!(std::isfinite(radii[static_cast<std::size_t>(i)]) && radii[static_cast<std::size_t>(i)] > 0.0))
            return refused("the perturbation's radii must be positive numbers");
    if (shape == QuadricShape::Torus && radii[1] >= radii[0])
        return refused("a torus's tube radius must be under its ring radius");
    if (!(std::isfinite(strength) && std::fabs(strength) <= 1000.0))
        return refused("the strength must be a number in [-1000, 1000] voxels");
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    Perturbation p;
    p.shape = shape;
    p.center = toModel(s, toGlm(worldCenter));
    p.radii = {radii[0] / s.scale(), radii[1] / s.scale(), radii[2] / s.scale()};
    p.strength = strength;
    p.mirror = s.mirror;
    // The quadric's axes are the world's, turned into the model frame.
    const glm::mat3 toModelAxes = glm::mat3(glm::inverse(s.modelToWorld()));
    for (int i = 0; i < 3; ++i) {
        glm::vec3 axis(0.0f);
        axis[i] = 1.0f;
        const glm::vec3 m = glm::normalize(toModelAxes * axis);
        p.axes[static_cast<std::size_t>(i)] = {m.x, m.y, m.z};
    }
    return {PerturbAction{s.name, p}, ""};
}

ActionOrWhy GardenSession::impactsFromWorld(int sculpture, const std::array<double, 3>& worldOrigin,
                                            const std::array<double, 3>& worldDirection, ImpactTool tool) const {
    if (std::string why = checkEditable(sculpture); !why.empty()) return refused(why);
    if (!finite3(worldOrigin) || !finite3(worldDirection)) return refused("the impact ray is not finite");
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    // Into the model frame: lengths by the scale, volumes by its cube.
    tool.size /= s.scale();
    tool.volume /= s.scale() * s.scale() * s.scale();
    if (tool.spread != ImpactSpread::Cone) tool.spreadSize /= s.scale();
    const FieldUnits units = unitsOf(*s.volume);
    if (std::string why = checkImpactTool(tool, units.voxelSize); !why.empty()) return refused(why);
    const glm::dmat4 toModelM = glm::inverse(glm::dmat4(s.modelToWorld()));
    const glm::dvec3 o = glm::dvec3(toModelM * glm::dvec4(worldOrigin[0], worldOrigin[1], worldOrigin[2], 1.0));
    glm::dvec3 d = glm::dvec3(toModelM * glm::dvec4(worldDirection[0], worldDirection[1], worldDirection[2], 0.0));
    if (!(glm::length(d) > 0.0)) return refused("the impact ray has no direction");
    d = glm::normalize(d);
    ImpactSeries series;
    series.volume = tool.volume;
    const frep::Box3& box = s.volume->frame.modelBox;
    for (const ImpactRay& ray : drawImpactRays({{o.x, o.y, o.z}, {d.x, d.y, d.z}}, tool)) {
        const ImpactRay relative = raysInBox({ray}, box)[0];
        series.rayOrigins.push_back(relative.origin);
        series.rayDirections.push_back(relative.direction);
        if (auto m = castImpact(*s.volume, ray, tool, units)) series.impacts.push_back(*m);
    }
    if (series.impacts.empty()) return refused("no impact met the sculpture");
    return {ImpactsAction{s.name, series}, ""};
}

ActionOrWhy GardenSession::impactsAgain(int from, int to) const {
    if (from < 0 || from >= static_cast<int>(sculptures_.size()) || to < 0 || to >= static_cast<int>(sculptures_.size()))
        return refused("no such sculpture");
    const Sculpture& src = sculptures_[static_cast<std::size_t>(from)];
    const ImpactSeries* last = nullptr;
    if (src.edits)
        for (const Edit& e : src.edits->list().edits())
            if (const auto* m = std::get_if<ImpactSeries>(&e.op)) last = m;
    if (!last) return refused("'" + src.name + "' has no impacts to fire again");
    if (std::string why = checkEditable(to); !why.empty()) return refused(why);
    const Sculpture& dst = sculptures_[static_cast<std::size_t>(to)];
    ImpactTool tool;
    tool.shape = last->impacts[0].shape;
    // The same tool in the other sculpture's model units.
    const double k = src.scale() / dst.scale();
    tool.size = last->impacts[0].size * k;
    tool.volume = last->volume * k * k * k;
    ImpactSeries series = *last;
    series.impacts.clear();
    series.volume = tool.volume;
    std::vector<ImpactRay> relative;
    for (std::size_t i = 0; i < last->rayOrigins.size(); ++i) relative.push_back({last->rayOrigins[i], last->rayDirections[i]});
    const FieldUnits units = unitsOf(*dst.volume);
    for (const ImpactRay& ray : raysFromBox(relative, dst.volume->frame.modelBox))
        if (auto m = castImpact(*dst.volume, ray, tool, units)) series.impacts.push_back(*m);
    if (series.impacts.empty()) return refused("no impact met '" + dst.name + "'");
    return {ImpactsAction{dst.name, series}, ""};
}

ActionOrWhy GardenSession::sketchFromWorld(int sculpture, SketchMode mode,
                                           const std::vector<std::array<double, 3>>& worldPoints,
                                           const std::array<double, 3>& worldNormal, double thickness) const {
    if (std::string why = checkEditable(sculpture); !why.empty()) return refused(why);
    if (worldPoints.size() < 3) return refused("a sketch needs at least 3 points");
    if (!finite3(worldNormal)) return refused("the sketch's normal is not finite");
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    SketchAction a{s.name, mode, {}, {}, thickness, s.mirror};
    for (const auto& p : worldPoints) {
        if (!finite3(p)) return refused("a sketch's point is not a finite position");
        a.points.push_back(toModel(s, toGlm(p)));
    }
    a.normal = toModelDirection(s, worldNormal);
    return {a, ""};
}

ActionOrWhy GardenSession::perturbationChange(int sculpture, std::size_t edit, double strength,
                                              const std::array<double, 3>& radii) const {
    if (std::string why = checkEditable(sculpture); !why.empty()) return refused(why);
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    if (!s.edits || edit >= s.edits->list().size()) return refused("no such edit");
    const auto* old = std::get_if<Perturbation>(&s.edits->list().edits()[edit].op);
    if (!old) return refused("edit " + std::to_string(edit) + " is not a perturbation");
    Perturbation p = *old;
    p.strength = strength;
    p.radii = {radii[0] / s.scale(), radii[1] / s.scale(), radii[2] / s.scale()};
    return {ReplaceAction{s.name, edit, p}, ""};
}

std::string GardenSession::applyStroke(int sculpture, StrokeTool tool, const std::vector<std::array<double, 3>>& worldPath,
                                       double radius, double softness, double strength, Falloff falloff) {
    return applied(*this, strokeFromWorld(sculpture, tool, worldPath, radius, softness, strength, falloff));
}

std::string GardenSession::applySketch(int sculpture, SketchMode mode, const std::vector<std::array<double, 3>>& worldPoints,
                                       const std::array<double, 3>& worldNormal, double thickness) {
    return applied(*this, sketchFromWorld(sculpture, mode, worldPoints, worldNormal, thickness));
}

std::string GardenSession::applyPerturbation(int sculpture, QuadricShape shape, const std::array<double, 3>& worldCenter,
                                             const std::array<double, 3>& radii, double strength) {
    return applied(*this, perturbationFromWorld(sculpture, shape, worldCenter, radii, strength));
}

std::string GardenSession::applyImpacts(int sculpture, const std::array<double, 3>& worldOrigin,
                                        const std::array<double, 3>& worldDirection, ImpactTool tool) {
    settleEdits();  // the rays meet the grid as the edits so far make it
    return applied(*this, impactsFromWorld(sculpture, worldOrigin, worldDirection, tool));
}

std::string GardenSession::reapplyImpacts(int from, int to) {
    settleEdits();
    return applied(*this, impactsAgain(from, to));
}

std::string GardenSession::editPerturbation(int sculpture, std::size_t edit, double strength,
                                            const std::array<double, 3>& radii) {
    return applied(*this, perturbationChange(sculpture, edit, strength, radii));
}

}  // namespace hg::garden
