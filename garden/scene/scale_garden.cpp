#include "garden/scene/scale_garden.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"

namespace hg::garden {

int scaleGardenColumns(int count) {
    int c = 1;
    while (c * c < count) ++c;
    return c;
}

std::string scaleGardenText(const std::string& templateText, const ScaleGardenSpec& spec) {
    const nlohmann::json t = nlohmann::json::parse(templateText);
    const auto& source = t.at("sculptures");
    if (!source.is_array() || source.empty()) throw JsonError("$.sculptures", "the template garden has no sculptures");
    const int columns = scaleGardenColumns(spec.count);
    const int rows = (spec.count + columns - 1) / columns;
    nlohmann::json g = nlohmann::json::object();
    g["version"] = t.value("version", 1);
    g["name"] = "scale garden: " + std::to_string(spec.count) + " copies of " + t.value("name", std::string("a garden"));
    if (t.contains("materials")) g["materials"] = t["materials"];
    if (t.contains("lights")) g["lights"] = t["lights"];
    nlohmann::json ground = t.value("ground", nlohmann::json::object());
    const double side = spec.spacing * (columns + 2);
    ground["size"] = {side, spec.spacing * (rows + 4)};
    g["ground"] = ground;
    g["sculptures"] = nlohmann::json::array();
    // Columns along x centred on 0, rows from z = 0 away from the visitor (-z).
    for (int n = 0; n < spec.count; ++n) {
        nlohmann::json s = source[static_cast<std::size_t>(n) % source.size()];
        const int column = n % columns, row = n / columns;
        s["name"] = "copy " + std::to_string(n) + ": " + s.value("name", std::string());
        s["placement"]["position"] = {(column - 0.5 * (columns - 1)) * spec.spacing, 0.0, -row * spec.spacing};
        if (spec.resolution > 0) s["resolution"] = spec.resolution;
        g["sculptures"].push_back(s);
    }
    g["start"] = {{"position", {0.0, 1.7, 2.0 * spec.spacing}}, {"look_at", {0.0, 1.1, -0.5 * rows * spec.spacing}}};
    return g.dump(1);
}

GardenLoad loadScaleGarden(const std::string& templatePath, const ScaleGardenSpec& spec) {
    std::ifstream in(templatePath, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    std::string generated;
    try {
        if (!in) throw JsonError("", "cannot read the template garden file");
        generated = scaleGardenText(text.str(), spec);
    } catch (const std::exception& e) {  // JsonError or nlohmann's parse error
        GardenLoad refused;
        refused.errorReason = e.what();
        refused.error = templatePath + ": " + e.what();
        return refused;
    }
    return loadGardenText(generated, templatePath);
}

}  // namespace hg::garden
