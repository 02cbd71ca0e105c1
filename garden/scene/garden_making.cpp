#include "garden/scene/garden_making.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "garden/scene/garden_file.h"
#include "garden/scene/json_reader.h"
#include "garden/scene/model_file.h"
#include "voxel/model_box.h"

namespace hg::garden {

namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

bool sizeModelFile(const ModelToPlace& m, double x, double z, SizedModel& out, std::string& error) {
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

ojson entry(const ModelToPlace& m, const std::string& name, const std::string& file, const SizedModel& s) {
    ojson e;
    e["name"] = name;
    e["file"] = file;
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
    out.box = found.box;
    double longest = 0.0;
    for (int i = 0; i < 3; ++i) longest = std::max(longest, out.box.hi[i] - out.box.lo[i]);
    out.scale = std::clamp(size / longest, 1e-3, 1e3);
    out.position = {x - 0.5 * (out.box.lo[0] + out.box.hi[0]) * out.scale, -out.box.lo[1] * out.scale,
                    z - 0.5 * (out.box.lo[2] + out.box.hi[2]) * out.scale};
    return "";
}

std::string gardenOfOneModel(const ModelToPlace& model, std::string& error) {
    SizedModel s;
    if (!sizeModelFile(model, 0.0, 0.0, s, error)) return "";
    ojson g;
    g["version"] = 1;
    g["name"] = stem(model);
    g["sculptures"] = ojson::array({entry(model, stem(model), fs::absolute(model.file).lexically_normal().string(), s)});
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
    if (!sizeModelFile(model, furthest + 3.0, 0.0, s, error)) return "";
    const fs::path folder = fs::absolute(gardenPath).parent_path();
    const std::string file = fs::absolute(model.file).lexically_normal().lexically_relative(folder).generic_string();
    g["sculptures"].push_back(entry(model, name, file, s));
    const std::string text = g.dump(2) + "\n";
    if (!readsBack(text, gardenPath, error)) return "";
    return text;
}

}  // namespace hg::garden
