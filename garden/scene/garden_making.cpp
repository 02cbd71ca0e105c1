#include "garden/scene/garden_making.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include <nlohmann/json.hpp>

#include "garden/scene/garden_file.h"
#include "garden/scene/json_reader.h"
#include "garden/scene/model_file.h"
#include "polygonizer/export/mesh_read.h"
#include "voxel/mesh_volume.h"
#include "voxel/model_box.h"
#include "voxel/scalar_volume.h"

namespace hg::garden {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

std::string lowerExtension(const std::string& file) {
    std::string ext = fs::path(file).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// The solid's box of a .vdb volume: its level set made coarsely (32 voxels
// along the longest side), which also checks that it has an inside.
bool volumeBox(const ModelToPlace& m, frep::Box3& box, VolumeDefaults& d, std::string& error) {
    voxel::ScalarVolume volume;
    if (std::string why = voxel::readScalarVdb(m.file, "", volume); !why.empty()) {
        error = why;
        return false;
    }
    if (!volume.levelSet) {
        d.iso = 0.5 * (volume.minValue + volume.maxValue);
        d.insideAbove = true;
    }
    voxel::IsoSurfaceRequest request;
    request.iso = d.iso;
    request.insideAbove = d.insideAbove;
    request.resolution = 32;
    const voxel::VoxelizeResult r = voxel::levelSetFromScalar(volume, request);
    if (!r.volume) {
        error = m.file + ": " + r.error;
        return false;
    }
    box = r.modelBox.box;
    return true;
}

}  // namespace

bool isMeshOrVolumeFile(const std::string& file) {
    const std::string ext = lowerExtension(file);
    return poly::isMeshFileName(file) || ext == ".vdb" || ext == ".raw";
}

bool sizeModelFile(const ModelToPlace& m, double x, double z, SizedModel& out, VolumeDefaults& volume,
                   std::string& error) {
    const std::string ext = lowerExtension(m.file);
    const bool mesh = poly::isMeshFileName(m.file);
    if (isMeshOrVolumeFile(m.file) && !m.body.empty()) {
        error = m.file + ": a body (--body) applies to a HyperFun file, not to a " + (mesh ? "mesh" : "volume") + "\n";
        return false;
    }
    if (ext == ".raw") {
        error = m.file + ": a raw volume needs its dimensions, sample type and iso-value, which its file does not "
                         "say: write its \"volume\" entry by hand (docs/garden-format.md), or convert it to .vdb\n";
        return false;
    }
    frep::Box3 box;
    if (mesh) {
        const poly::MeshReadResult read = poly::readMeshFile(m.file);
        if (!read.error.empty()) {
            error = read.error + "\n";
            return false;
        }
        box = voxel::meshBounds(read.mesh.positions);
    } else if (ext == ".vdb") {
        if (!volumeBox(m, box, volume, error)) return false;
    } else {
        const ModelFile mf = loadModelFile(m.file, m.body, {});
        if (!mf.ok()) {
            error = mf.error;
            return false;
        }
        if (std::string why = sizeModel(*mf.model, m.size, x, z, out); !why.empty()) {
            error = m.file + ": " + why;
            return false;
        }
        return true;
    }
    sizeBox(box, m.size, x, z, out);
    return true;
}

namespace {

ojson entry(const ModelToPlace& m, const std::string& name, const std::string& file, const SizedModel& s,
            const VolumeDefaults& volume) {
    ojson e;
    e["name"] = name;
    const std::string ext = lowerExtension(m.file);
    if (poly::isMeshFileName(m.file)) {
        e["mesh"] = {{"file", file}};
    } else if (ext == ".vdb") {
        e["volume"] = {{"file", file}, {"iso", volume.iso}, {"inside", volume.insideAbove ? "above" : "below"}};
    } else {
        e["file"] = file;
    }
    if (!m.body.empty()) e["body"] = m.body;
    e["resolution"] = m.resolution;
    e["placement"] = {{"position", {s.position[0], s.position[1], s.position[2]}}, {"scale", s.scale}};
    return e;
}

std::string stem(const ModelToPlace& m) { return m.name.empty() ? fs::path(m.file).stem().string() : m.name; }

// Read back as a garden: what will be written is what opens.
bool readsBack(const std::string& text, const std::string& path, std::string& error) {
    try {
        std::string folder = fs::path(path).parent_path().string();
        parseGarden(text, path, folder.empty() ? "." : folder);
        return true;
    } catch (const JsonError& e) {
        error = path + ": " + e.what();
        return false;
    }
}

}  // namespace

std::string sizeModel(const frep::Model& model, double size, double x, double z, SizedModel& out) {
    voxel::ModelBox found;
    if (std::string why = voxel::resolveModelBox(model, std::nullopt, found); !why.empty()) return why;
    sizeBox(found.box, size, x, z, out);
    return "";
}

void sizeBox(const frep::Box3& box, double size, double x, double z, SizedModel& out) {
    out.box = box;
    double longest = 0.0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, out.box.hi[i] - out.box.lo[i]);
    out.scale = std::clamp(size / longest, 1e-3, 1e3);
    out.position = {x - 0.5 * (out.box.lo[0] + out.box.hi[0]) * out.scale, -out.box.lo[1] * out.scale,
                    z - 0.5 * (out.box.lo[2] + out.box.hi[2]) * out.scale};
}

std::string gardenOfOneModel(const ModelToPlace& model, std::string& error) {
    SizedModel s;
    VolumeDefaults volume;
    if (!sizeModelFile(model, 0.0, 0.0, s, volume, error)) return "";
    ojson g;
    g["version"] = 1;
    g["name"] = stem(model);
    g["sculptures"] = ojson::array({entry(model, stem(model), fs::absolute(model.file).lexically_normal().string(), s, volume)});
    // Far enough back to see all of it with a 60-degree view, and a little above.
    const double h = model.size;
    g["start"] = {{"position", {0.0, 0.6 * h + 0.8, 1.4 * h + 1.0}}, {"look_at", {0.0, 0.5 * h, 0.0}}};
    const std::string text = g.dump(2) + "\n";
    if (!readsBack(text, fs::absolute(model.file).string(), error)) return "";
    return text;
}

std::string gardenWithModel(const std::string& gardenText, const std::string& gardenPath, const ModelToPlace& model,
                            std::string& error) {
    ojson g;
    try {
        g = ojson::parse(gardenText);
    } catch (const ojson::parse_error& e) {
        error = gardenPath + ": not JSON: " + e.what();
        return "";
    }
    if (!readsBack(gardenText, gardenPath, error)) return "";
    const std::string name = stem(model);
    double furthest = -3.0;
    if (g.contains("sculptures"))
        for (const auto& e : g["sculptures"]) {
            if (e.value("name", "") == name) {
                error = gardenPath + ": the garden already has a sculpture named '" + name + "' (give another with --name)";
                return "";
            }
            if (e.contains("placement") && e["placement"].contains("position"))
                furthest = std::max(furthest, e["placement"]["position"][0].get<double>());
        }
    SizedModel s;
    VolumeDefaults volume;
    if (!sizeModelFile(model, furthest + 3.0, 0.0, s, volume, error)) return "";
    const fs::path folder = fs::absolute(gardenPath).parent_path();
    const std::string file = fs::absolute(model.file).lexically_normal().lexically_relative(folder).generic_string();
    g["sculptures"].push_back(entry(model, name, file, s, volume));
    const std::string text = g.dump(2) + "\n";
    if (!readsBack(text, gardenPath, error)) return "";
    return text;
}

}  // namespace hg::garden
