// Deformable models and selections (seed 003's snakes, issue 22;
// docs/sketching.md "Selections"): an outline sketched around part of a
// sculpture is inflated and meshed (a ModelAction), its snake shrinks onto
// the sculpture's surface or grows (DeformActions, a number of iterations
// each, live while the user circles), and what it encloses, fitted with
// balls, becomes the sculpture's selection: edits made while it is set act
// only inside it, and extractPart makes it a sculpture of its own.
// Selections are state, like the tool in hand: undo takes back the edits
// made with them, not the selection.
#include <algorithm>
#include <cmath>

#include "garden/app/garden_session.h"
#include "garden/deform/deformable_model.h"
#include "garden/deform/selection.h"
#include "garden/deform/sketch_mesh.h"
#include "garden/scene/to_glm.h"
#include "garden/sculpt/mask_margin.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/sketch_edit.h"
#include "voxel/volume.h"

namespace hg::garden {

namespace {

using ActionOrWhy = GardenSession::ActionOrWhy;

ActionOrWhy refused(std::string why) { return {std::nullopt, std::move(why)}; }

// The model's triangles, in voxels: small enough to follow a sculpture's
// form, large enough that a few frames' iterations cross a selection.
constexpr double kModelEdgeVoxels = 2.5;
// Between the stroke that sketched it and its first deformation, a model
// this many triangles across its outline's extent at most.
constexpr double kModelMaxEdgesAcross = 48.0;
// The selection's balls grown by this many voxels of the sculpture.
constexpr double kSelectionMarginVoxels = 2.0;
// The selection's balls are fitted at this many of the sculpture's voxels.
constexpr double kSelectionFitVoxels = 2.0;

}  // namespace

GardenSession::ModelEntry::ModelEntry() = default;
GardenSession::ModelEntry::~ModelEntry() = default;
GardenSession::ModelEntry::ModelEntry(ModelEntry&&) noexcept = default;
GardenSession::ModelEntry& GardenSession::ModelEntry::operator=(ModelEntry&&) noexcept = default;

ActionOrWhy GardenSession::modelFromWorld(int sculpture, const std::string& name,
                                          const std::vector<std::array<double, 3>>& worldPoints,
                                          const std::array<double, 3>& worldNormal, double thickness) const {
    if (std::string why = checkEditable(sculpture); !why.empty()) return refused(why);
    if (worldPoints.size() < 3) return refused("a model's outline needs at least 3 points");
    if (!finite3(worldNormal)) return refused("the model's normal is not finite");
    const Sculpture& s = sculptures_[static_cast<std::size_t>(sculpture)];
    ModelAction a;
    const std::string wanted = name.empty() ? "model" : name;
    a.name = wanted;
    for (int n = 2; std::any_of(models_.begin(), models_.end(), [&](const ModelEntry& m) { return m.name == a.name; });
         ++n)
        a.name = wanted + "-" + std::to_string(n);
    if (!name.empty() && a.name != name) return refused("a model named '" + name + "' is already made");
    a.sculpture = s.name;
    a.thickness = thickness;
    for (const auto& p : worldPoints) {
        if (!finite3(p)) return refused("a model's point is not a finite position");
        a.points.push_back(toModel(s, toGlm(p)));
    }
    a.normal = toModelDirection(s, worldNormal);
    return {a, ""};
}

std::string GardenSession::applyModelAction(const ModelAction& a) {
    std::string why;
    const int i = actionSculpture(a.sculpture, why);
    if (!why.empty()) return why;
    if (a.name.empty()) return "a model needs a name";
    for (const ModelEntry& m : models_)
        if (m.name == a.name) return "a model named '" + a.name + "' is already made";
    commitLiveDeform();
    const Sculpture& s = sculptures_[static_cast<std::size_t>(i)];
    const FieldUnits units = unitsOf(*s.volume);
    // The outline resolved as a sketch's is (resampled, inflated), then meshed.
    SketchSolid solid;
    solid.mode = SketchMode::Add;
    solid.outline = a.points;
    solid.normal = a.normal;
    solid.thickness = a.thickness;
    if (std::string w = resolveSketch(solid, units); !w.empty()) return w;
    double extent = 0.0;
    for (int k = 0; k < 3; ++k)
        extent = std::max(extent, solid.solid.paddedHi(0.0)[k] - solid.solid.paddedLo(0.0)[k]);
    const double edge = std::max(kModelEdgeVoxels * units.voxelSize, extent / kModelMaxEdgesAcross);
    ModelEntry entry;
    entry.name = a.name;
    entry.sculpture = a.sculpture;
    entry.model = std::make_unique<deform::DeformableModel>(deform::meshOfInflatedSketch(solid.solid, edge), edge);
    if (entry.model->mesh().triangles.empty()) return "the model's outline made no solid";
    models_.push_back(std::move(entry));
    activeModel_ = a.name;
    record(a);
    return "";
}

GardenSession::ModelEntry* GardenSession::findModel(const std::string& name) {
    for (ModelEntry& m : models_)
        if (m.name == name) return &m;
    return nullptr;
}

const GardenSession::ModelEntry* GardenSession::findModel(const std::string& name) const {
    for (const ModelEntry& m : models_)
        if (m.name == name) return &m;
    return nullptr;
}

int GardenSession::modelSculpture(const ModelEntry& m, std::string& why) const {
    const int i = actionSculpture(m.sculpture, why);
    if (why.empty() && !sculptures_[static_cast<std::size_t>(i)].hasGrid())
        why = "sculpture '" + m.sculpture + "' has no grid yet";
    return i;
}

bool GardenSession::deformModelLive(const std::string& model, bool shrink, int iterations) {
    ModelEntry* m = findModel(model);
    if (!m || iterations <= 0) return false;
    std::string why;
    const int i = modelSculpture(*m, why);
    if (!why.empty()) return false;
    if (!liveDeform_.model.empty() && (liveDeform_.model != model || liveDeform_.shrink != shrink)) commitLiveDeform();
    m->model->deform(*sculptures_[static_cast<std::size_t>(i)].volume,
                     shrink ? deform::DeformMode::Shrink : deform::DeformMode::Grow, iterations);
    liveDeform_.model = model;
    liveDeform_.shrink = shrink;
    liveDeform_.iterations += iterations;
    return true;
}

void GardenSession::commitLiveDeform() {
    if (liveDeform_.iterations <= 0) {
        liveDeform_ = LiveDeform{};
        return;
    }
    const DeformAction done{liveDeform_.model, liveDeform_.shrink, liveDeform_.iterations};
    liveDeform_ = LiveDeform{};
    const ModelEntry* m = findModel(done.model);
    if (!m) return;
    selectModel(*m);
    record(done);
    gestureMessage_ = std::string(done.shrink ? "shrink" : "grow") + ": " + std::to_string(done.iterations) +
                      " iterations on '" + done.model + "'; its selection is on '" + m->sculpture + "'";
}

std::string GardenSession::deformModel(const std::string& model, bool shrink, int iterations) {
    return apply(DeformAction{model, shrink, iterations});
}

std::string GardenSession::applyDeformAction(const DeformAction& a) {
    commitLiveDeform();
    ModelEntry* m = findModel(a.model);
    if (!m) return "no model named '" + a.model + "'";
    if (a.iterations <= 0) return "a deformation needs at least one iteration";
    std::string why;
    const int i = modelSculpture(*m, why);
    if (!why.empty()) return why;
    Sculpture& s = sculptures_[static_cast<std::size_t>(i)];
    // A journal being played defers grid updates; the snake must see the
    // grid as it stood when the action was made.
    if (s.edits && restoring_)
        for (const voxel::IndexBox& box : s.edits->flush()) showChanged(i, box);
    m->model->deform(*s.volume, a.shrink ? deform::DeformMode::Shrink : deform::DeformMode::Grow, a.iterations);
    selectModel(*m);
    record(a);
    return "";
}

std::optional<SelectionMask> GardenSession::modelMask(const std::string& model, std::string& why) const {
    const ModelEntry* m = findModel(model);
    if (!m) {
        why = "no model named '" + model + "'";
        return std::nullopt;
    }
    const int i = modelSculpture(*m, why);
    if (!why.empty()) return std::nullopt;
    const double voxel = sculptures_[static_cast<std::size_t>(i)].volume->frame.voxelSize;
    SelectionMask mask;
    // Grown a little: a shrunk model lies on the sculpture's surface, and
    // the balls' bumpy hull just inside it would cut the surface it wraps;
    // grown, the sculpture's own surface bounds the selection there and
    // the balls only where the model cuts through the material.
    // Fitted on a grid of twice the sculpture's voxel: most of the fit's
    // time is the mesh's level set, and eight times fewer voxels keep the
    // hitch when a circling gesture ends to a few tens of milliseconds;
    // the growth below covers the coarser fit.
    for (const deform::SelectionBall& b : deform::selectionBalls(m->model->mesh(), kSelectionFitVoxels * voxel))
        mask.balls.push_back(MaskBall{{b.centre.x, b.centre.y, b.centre.z}, b.radius + kSelectionMarginVoxels * voxel});
    if (mask.balls.empty()) {
        why = "model '" + model + "' encloses nothing";
        return std::nullopt;
    }
    // The balls' hull; maskFor grows it by each edit's reach beyond them.
    mask.box = maskBox(mask.balls, 0.0);
    return mask;
}

void GardenSession::selectModel(const ModelEntry& m) {
    std::string why;
    auto mask = modelMask(m.name, why);
    const int i = findSculpture(m.sculpture);
    if (i < 0) return;
    Sculpture& s = sculptures_[static_cast<std::size_t>(i)];
    s.selection = std::move(mask);
    s.selectionModel = s.selection ? m.name : std::string();
}

std::string GardenSession::selectWithModel(const std::string& sculpture, const std::string& model) {
    return apply(SelectAction{sculpture, model});
}

std::string GardenSession::applySelectAction(const SelectAction& a) {
    const int i = findSculpture(a.sculpture);
    if (i < 0) return "no sculpture named '" + a.sculpture + "'";
    commitLiveDeform();
    Sculpture& s = sculptures_[static_cast<std::size_t>(i)];
    if (a.model.empty()) {
        s.selection.reset();
        s.selectionModel.clear();
    } else {
        const ModelEntry* m = findModel(a.model);
        if (!m) return "no model named '" + a.model + "'";
        if (m->sculpture != a.sculpture)
            return "model '" + a.model + "' surrounds '" + m->sculpture + "', not '" + a.sculpture + "'";
        selectModel(*m);
        if (!s.selection) return "model '" + a.model + "' encloses nothing";
    }
    record(a);
    return "";
}

const std::optional<SelectionMask>& GardenSession::selectionOf(int sculpture) const {
    return sculptures_.at(static_cast<std::size_t>(sculpture)).selection;
}

std::optional<SelectionMask> GardenSession::maskFor(int sculpture, const Edit& e) const {
    std::optional<SelectionMask> mask = selectionOf(sculpture);
    if (!mask) return mask;
    mask->box = maskBox(mask->balls, maskMargin(e, unitsOf(*sculptures_[static_cast<std::size_t>(sculpture)].volume)));
    return mask;
}

std::vector<GardenSession::ModelView> GardenSession::models() const {
    std::vector<ModelView> out;
    for (const ModelEntry& m : models_) {
        ModelView v;
        v.name = m.name;
        v.sculpture = findSculpture(m.sculpture);
        v.vertices = &m.model->mesh().vertices;
        v.triangles = &m.model->mesh().triangles;
        v.iterations = m.model->iterationsRun();
        v.settled = m.model->settled();
        out.push_back(v);
    }
    return out;
}

ActionOrWhy GardenSession::partFromText(int from, const std::string& name, std::string text, const SelectionMask& mask,
                                        const std::string& origin) const {
    if (std::string why = checkEditable(from); !why.empty()) return refused(why);
    const Sculpture& s = sculptures_[static_cast<std::size_t>(from)];
    const voxel::VolumeFrame& frame = s.volume->frame;
    AddAction a;
    a.sculpture = uniqueName(name.empty() ? s.name + "-part" : name);
    if (!name.empty() && a.sculpture != name) return refused("a sculpture named '" + name + "' is already in the garden");
    a.source = std::move(text);
    a.origin = origin;
    // The mask's box within the sculpture's, sampled at its voxel size.
    frep::Box3 box;
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::max(frame.modelBox.lo[k], mask.box.lo[k]);
        box.hi[k] = std::min(frame.modelBox.hi[k], mask.box.hi[k]);
        if (!(box.hi[k] > box.lo[k])) return refused("the selection lies outside '" + s.name + "'");
        longest = std::max(longest, box.hi[k] - box.lo[k]);
    }
    a.box = box;
    a.resolution = std::clamp(static_cast<int>(std::ceil(longest / frame.voxelSize)), voxel::kMinResolution,
                              voxel::kMaxResolution);
    // Beside its sculpture, to its right as the garden is laid out (+x).
    a.placement = s.placement;
    double width = 0.0;
    for (int k = 0; k < 3; ++k) width = std::max(width, frame.modelBox.hi[k] - frame.modelBox.lo[k]);
    a.placement.position[0] += width * s.scale() + 0.3;
    return {a, ""};
}

}  // namespace hg::garden
