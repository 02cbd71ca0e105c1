// Sculptures brought into a running garden (docs/design.md §10, "Bringing work
// in"): a HyperFun file, or a sketch in mode `new`, becomes an AddAction
// holding the program's text; applying it appends a sculpture (its garden
// entry, its load, its grid) that undo hides and redo shows again. Indexes
// of the sculptures already there never change.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "garden/app/garden_session.h"
#include "garden/scene/garden_making.h"
#include "garden/scene/model_file.h"
#include "garden/scene/to_glm.h"
#include "garden/sculpt/sketch_edit.h"
#include "garden/sketch/inflation_text.h"
#include "io/read_text.h"
#include "voxel/sampler.h"

namespace hg::garden {

namespace {

using ActionOrWhy = GardenSession::ActionOrWhy;

ActionOrWhy refused(std::string why) { return {std::nullopt, std::move(why)}; }

// A new sketched sculpture's grid: voxels along its longest side.
constexpr int kSketchedResolution = 128;

}  // namespace

std::string GardenSession::uniqueName(const std::string& wanted) const {
    std::string base = wanted.empty() ? "sculpture" : wanted;
    if (findSculpture(base) < 0) return base;
    for (int n = 2;; ++n) {
        const std::string name = base + "-" + std::to_string(n);
        if (findSculpture(name) < 0) return name;
    }
}

std::array<double, 3> GardenSession::placeInView(double distance) const {
    const glm::vec3 eye = navigator_.eye();
    glm::vec3 ahead = navigator_.forward();
    ahead.y = 0.0f;
    if (glm::length(ahead) < 1e-4f) ahead = glm::vec3(0.0f, 0.0f, -1.0f);
    const glm::vec3 p = eye + glm::normalize(ahead) * static_cast<float>(distance);
    return {p.x, load_.garden->ground.height, p.z};
}

ActionOrWhy GardenSession::addFromFile(const std::string& path, const std::string& name, const Placement& placement,
                                       int resolution, const std::string& body) const {
    std::string text;
    if (std::string why = io::readText(path, text); !why.empty()) return refused("cannot open " + why);
    AddAction a;
    a.sculpture = uniqueName(name.empty() ? std::filesystem::path(path).stem().string() : name);
    if (!name.empty() && a.sculpture != name) return refused("a sculpture named '" + name + "' is already in the garden");
    a.source = std::move(text);
    a.origin = path;
    a.body = body;
    a.resolution = resolution;
    a.placement = placement;
    // Refused here, with the parser's messages, rather than as a journalled
    // action that cannot be played.
    const ModelFile mf = modelFromText(a.source, a.origin, a.body, {});
    if (!mf.ok()) return refused(mf.error);
    if (!(placement.scale > 0.0)) {
        // Sized to the garden, standing on the ground where it was put.
        SizedModel sized;
        if (std::string why = sizeModel(*mf.model, kAddedSize, placement.position[0], placement.position[2], sized);
            !why.empty())
            return refused(path + ": " + why);
        a.placement.scale = sized.scale;
        a.placement.position = {sized.position[0], load_.garden->ground.height + sized.position[1], sized.position[2]};
        a.box = sized.box;
    }
    return {a, ""};
}

ActionOrWhy GardenSession::sketchNewFromWorld(const std::string& name,
                                              const std::vector<std::array<double, 3>>& worldPoints,
                                              const std::array<double, 3>& worldNormal, double thickness) const {
    if (worldPoints.size() < 3) return refused("a sketch needs at least 3 points");
    if (!finite3(worldNormal)) return refused("the sketch's normal is not finite");
    // The model frame is the world's, moved to the outline's centroid (one
    // metre per unit, not turned), so the new sculpture stands where it
    // was drawn.
    std::array<double, 3> centroid{0.0, 0.0, 0.0};
    for (const auto& p : worldPoints) {
        if (!finite3(p)) return refused("a sketch's point is not a finite position");
        for (std::size_t i = 0; i < 3; ++i) centroid[i] += p[i] / static_cast<double>(worldPoints.size());
    }
    SketchSolid solid;
    solid.mode = SketchMode::Add;
    solid.normal = worldNormal;
    solid.thickness = thickness;
    double extent = 0.0;
    for (const auto& p : worldPoints) {
        solid.outline.push_back({p[0] - centroid[0], p[1] - centroid[1], p[2] - centroid[2]});
        for (std::size_t i = 0; i < 3; ++i) extent = std::max(extent, 2.0 * std::fabs(p[i] - centroid[i]));
    }
    FieldUnits units;
    units.voxelSize = std::max(extent, 1e-3) / kSketchedResolution;
    if (std::string why = resolveSketch(solid, units); !why.empty()) return refused(why);
    // The model box: the solid's bounds and the band around them.
    frep::Box3 box;
    const double margin = 2.0 * units.band * units.voxelSize;
    const sketch::Vec3 lo = solid.solid.paddedLo(margin), hi = solid.solid.paddedHi(margin);
    for (int i = 0; i < 3; ++i) {
        box.lo[i] = lo[i];
        box.hi[i] = hi[i];
    }
    AddAction a;
    a.sculpture = uniqueName(name.empty() ? "sketch" : name);
    if (!name.empty() && a.sculpture != name) return refused("a sculpture named '" + name + "' is already in the garden");
    a.source = sketch::inflatedHyperFun(solid.solid);
    a.origin = "sketch";
    a.box = box;
    a.resolution = kSketchedResolution;
    a.placement.position = centroid;
    return {a, ""};
}

std::string GardenSession::applyAddModel(const AddAction& a) {
    if (stroking()) endStroke();
    endLiveMove();
    if (a.sculpture.empty()) return "a sculpture needs a name";
    if (findSculpture(a.sculpture) >= 0) return "a sculpture named '" + a.sculpture + "' is already in the garden";
    if (std::string why = checkPlacementValues(a.placement); !why.empty()) return why;
    SculptureSpec spec;
    spec.name = a.sculpture;
    spec.fileAsWritten = a.origin;
    spec.body = a.body;
    spec.box = a.box;
    spec.resolution = settings_.sculptureResolution > 0 ? settings_.sculptureResolution : a.resolution;
    spec.placement = a.placement;
    SculptureLoad loaded = sculptureFromText(spec, a.source);
    if (!loaded.ok()) return loaded.error;
    voxel::VolumeRequest request;
    request.box = spec.box;
    request.resolution = spec.resolution;
    request.band = spec.band;
    voxel::VoxelizeResult r = voxel::voxelize(*loaded.model, request);
    if (!r.volume) return "'" + a.sculpture + "' cannot be sampled: " + r.error;

    Sculpture s;
    s.name = spec.name;
    s.source.kind = SculptureSource::Kind::HyperFun;
    s.source.spec = static_cast<int>(load_.garden->sculptures.size());
    s.source.program = loaded.program;
    s.placement = spec.placement;
    s.material = spec.material;
    s.modelToWorld = placementMatrix(spec.placement);
    s.scale = spec.placement.scale;
    s.volume = std::make_unique<voxel::Volume>(std::move(*r.volume));
    attachMeshing(s);
    load_.garden->sculptures.push_back(std::move(spec));
    load_.sculptures.push_back(std::move(loaded));
    const int index = static_cast<int>(sculptures_.size());
    sculptures_.push_back(std::move(s));
    undoOrder_.push_back(UndoEntry{index, a, std::nullopt, std::nullopt, std::nullopt});
    redoOrder_.clear();
    record(a);
    return "";
}

std::string GardenSession::addSculptureFile(const std::string& path, const std::string& name,
                                            const Placement& placement, int resolution, const std::string& body) {
    const ActionOrWhy a = addFromFile(path, name, placement, resolution, body);
    return a.action ? apply(*a.action) : a.why;
}

}  // namespace hg::garden
