// Sculptures brought into a running garden (docs/design.md §10, "Bringing work
// in"): a HyperFun file, or a sketch in mode `new`, becomes an AddAction
// holding the program's text; a mesh or an OpenVDB volume is copied into
// the session folder's imports/ and becomes an AddAction naming the copy
// (docs/session-format.md, "Imported files"). Applying it appends a
// sculpture (its garden entry, its load, its grid) that undo hides and redo
// shows again. Indexes of the sculptures already there never change.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_sampling.h"
#include "garden/scene/garden_making.h"
#include "garden/scene/model_file.h"
#include "garden/scene/to_glm.h"
#include "garden/sculpt/sketch_edit.h"
#include "garden/sketch/inflation_text.h"
#include "io/checked_write.h"
#include "io/read_text.h"
#include "polygonizer/export/mesh_read.h"
#include "voxel/sampler.h"

namespace hg::garden {

namespace {

using ActionOrWhy = GardenSession::ActionOrWhy;

ActionOrWhy refused(std::string why) { return {std::nullopt, std::move(why)}; }

namespace fs = std::filesystem;

// A new sketched sculpture's grid: voxels along its longest side.
constexpr int kSketchedResolution = 128;

// An imported file's name in the session folder's imports/: the
// original's, or NAME-2.EXT, ... when taken (an undone add's copy stays,
// its record may be played again).
std::string freeImportName(const fs::path& folder, const fs::path& original) {
    const std::string stem = original.stem().string(), ext = original.extension().string();
    std::string name = stem + ext;
    for (int n = 2; fs::exists(folder / name); ++n) name = stem + "-" + std::to_string(n) + ext;
    return name;
}

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
    // A mesh or a volume (.raw is refused by sizeModelFile: its file does
    // not say its layout).
    if (isMeshOrVolumeFile(path)) return importFromFile(path, name, placement, resolution, body);
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

ActionOrWhy GardenSession::importFromFile(const std::string& path, const std::string& name, const Placement& placement,
                                          int resolution, const std::string& body) const {
    // Read (and refused with the reader's message) as `garden add` reads it.
    ModelToPlace m;
    m.file = path;
    m.body = body;
    m.size = kAddedSize;
    SizedModel sized;
    VolumeDefaults volume;
    std::string error;
    if (!sizeModelFile(m, placement.position[0], placement.position[2], sized, volume, error)) {
        while (!error.empty() && error.back() == '\n') error.pop_back();
        return refused(error);
    }
    AddAction a;
    a.sculpture = uniqueName(name.empty() ? fs::path(path).stem().string() : name);
    if (!name.empty() && a.sculpture != name) return refused("a sculpture named '" + name + "' is already in the garden");
    a.origin = path;
    a.resolution = resolution;
    a.placement = placement;
    AddAction::Imported imported;
    imported.kind = poly::isMeshFileName(path) ? AddAction::Imported::Kind::Mesh : AddAction::Imported::Kind::Volume;
    imported.file = fs::absolute(path).lexically_normal().string();
    imported.iso = volume.iso;
    imported.insideAbove = volume.insideAbove;
    a.imported = imported;
    // No model box: the grid's is found from the file as a garden entry's
    // is (a mesh's bounds and margin, a volume's solid).
    if (!(placement.scale > 0.0)) {
        a.placement.scale = sized.scale;
        a.placement.position = {sized.position[0], load_.garden->ground.height + sized.position[1], sized.position[2]};
    }
    return {a, ""};
}

std::string GardenSession::importIntoSession(AddAction& a) const {
    if (!a.imported || sessionFolder_.empty()) return "";
    const fs::path folder = fs::path(sessionFolder_) / "imports";
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) return "cannot create " + folder.string() + " to copy " + a.origin + " into: " + ec.message();
    std::string bytes;
    if (std::string why = io::readText(a.imported->file, bytes); !why.empty()) return "cannot copy " + why;
    const std::string name = freeImportName(folder, a.imported->file);
    if (std::string why = io::writeFileAtomically((folder / name).string(), bytes, io::WriteSite::SessionFile);
        !why.empty())
        return "cannot copy " + a.origin + " into the session: " + why;
    a.imported->file = "imports/" + name;
    return "";
}

std::string GardenSession::importedPath(const AddAction::Imported& m) const {
    if (fs::path(m.file).is_absolute() || sessionFolder_.empty()) return m.file;
    return (fs::path(sessionFolder_) / m.file).string();
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
    SculptureSource::Kind kind = SculptureSource::Kind::HyperFun;
    if (a.imported) {
        // Read as a garden entry of the file would be; its messages name the record.
        spec.file = importedPath(*a.imported);
        const std::string at = "added sculpture '" + a.sculpture + "'";
        if (a.imported->kind == AddAction::Imported::Kind::Mesh) {
            spec.mesh = MeshSpec{at};
            kind = SculptureSource::Kind::Mesh;
        } else {
            ScanSpec scan;
            scan.format = ScanSpec::Format::Vdb;
            scan.iso = a.imported->iso;
            scan.insideAbove = a.imported->insideAbove;
            scan.at = at;
            spec.scan = scan;
            kind = SculptureSource::Kind::Scan;
        }
    }
    SculptureLoad loaded = a.imported ? loadSculpture(spec) : sculptureFromText(spec, a.source);
    if (!loaded.ok()) return loaded.error;
    voxel::VoxelizeResult r = sampleSculptureSource(spec, loaded, volumeRequest(spec));
    if (!r.volume) return "'" + a.sculpture + "' cannot be sampled: " + r.error;

    Sculpture s;
    s.name = spec.name;
    s.source.kind = kind;
    s.source.spec = static_cast<int>(load_.garden->sculptures.size());
    s.source.program = loaded.program;
    s.placement = spec.placement;
    s.material = spec.material;
    s.volume = std::make_unique<voxel::Volume>(std::move(*r.volume));
    attachMeshing(s);
    load_.garden->sculptures.push_back(std::move(spec));
    load_.sculptures.push_back(std::move(loaded));
    const int index = static_cast<int>(sculptures_.size());
    sculptures_.push_back(std::move(s));
    undoOrder_.push_back(UndoEntry{index, a, std::nullopt, std::nullopt, std::nullopt});
    redoOrder_.clear();
    if (kind == SculptureSource::Kind::HyperFun) watchAddedSource(static_cast<std::size_t>(index), a.source);
    record(a);
    return "";
}

std::string GardenSession::addSculptureFile(const std::string& path, const std::string& name,
                                            const Placement& placement, int resolution, const std::string& body) {
    ActionOrWhy a = addFromFile(path, name, placement, resolution, body);
    if (!a.action) return a.why;
    AddAction& add = std::get<AddAction>(*a.action);
    if (std::string why = importIntoSession(add); !why.empty()) return why;
    const std::string why = apply(add);
    // A copy no record names is not kept.
    if (!why.empty() && add.imported && !sessionFolder_.empty()) {
        std::error_code ec;
        fs::remove(importedPath(*add.imported), ec);
    }
    return why;
}

}  // namespace hg::garden
