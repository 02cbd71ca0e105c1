#include "garden/replay/sculpt_commands.h"

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "garden/sculpt/edit_names.h"
#include "garden/sculpt/tool_settings_json.h"
#include "voxel/volume_frame.h"

namespace hg::garden {

SculptCommand readSculptCommand(const std::string& key, const nlohmann::json& v, const std::string& path) {
    if (key == "stroke") {
        ObjectReader r(v, path, {"sculpture", "tool", "radius", "softness", "strength", "falloff", "path"});
        StrokeCommand c;
        c.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        c.tool = readStrokeTool(r.required("tool"), r.pathOf("tool"));
        c.radius = readNumber(r.required("radius"), r.pathOf("radius"), 1e-6, 100.0);
        if (r.has("softness")) c.softness = readNumber(r.required("softness"), r.pathOf("softness"), 0.01, 64.0);
        // Checked against the sculpture's band when applied (checkStroke).
        if (r.has("strength")) c.strength = readNumber(r.required("strength"), r.pathOf("strength"), -64.0, 64.0);
        if (r.has("falloff")) c.falloff = readFalloff(r.required("falloff"), r.pathOf("falloff"));
        const nlohmann::json& p = r.required("path");
        if (!p.is_array() || p.empty()) throw JsonError(r.pathOf("path"), "expected a non-empty array of [x, y, z] points");
        for (std::size_t i = 0; i < p.size(); ++i) c.path.push_back(readVec3(p[i], indexPath(r.pathOf("path"), i)));
        r.finish();
        return c;
    }
    if (key == "perturb") {
        ObjectReader r(v, path, {"sculpture", "shape", "center", "radii", "strength"});
        PerturbCommand c;
        c.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        if (r.has("shape")) c.shape = readQuadricShape(r.required("shape"), r.pathOf("shape"));
        c.center = readVec3(r.required("center"), r.pathOf("center"));
        c.radii = readVec3(r.required("radii"), r.pathOf("radii"));
        for (std::size_t i = 0; i < (c.shape == QuadricShape::Ellipsoid ? 3u : 2u); ++i)
            if (!(c.radii[i] > 0.0 && c.radii[i] <= 100.0))
                throw JsonError(indexPath(r.pathOf("radii"), i), "expected a radius in (0, 100] metres");
        c.strength = readNumber(r.required("strength"), r.pathOf("strength"), -1000.0, 1000.0);
        r.finish();
        return c;
    }
    if (key == "impacts") {
        ObjectReader r(v, path, {"sculpture", "origin", "direction", "shape", "size", "volume_cm3", "spread", "spread_size",
                                 "count", "seed"});
        ImpactsCommand c;
        c.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        c.origin = readVec3(r.required("origin"), r.pathOf("origin"));
        c.direction = readVec3(r.required("direction"), r.pathOf("direction"));
        if (r.has("shape")) c.tool.shape = readImpactShape(r.required("shape"), r.pathOf("shape"));
        c.tool.size = readNumber(r.required("size"), r.pathOf("size"), 1e-6, 100.0);
        c.tool.volume = readNumber(r.required("volume_cm3"), r.pathOf("volume_cm3"), 1e-9, 1e9);
        if (r.has("spread")) c.tool.spread = readImpactSpread(r.required("spread"), r.pathOf("spread"));
        if (r.has("spread_size")) c.tool.spreadSize = readNumber(r.required("spread_size"), r.pathOf("spread_size"), 0.0, 100.0);
        if (r.has("count")) c.tool.count = readInt(r.required("count"), r.pathOf("count"), 1, 100000);
        if (r.has("seed")) c.tool.seed = static_cast<std::uint64_t>(readInt(r.required("seed"), r.pathOf("seed"), 0, 2000000000));
        r.finish();
        return c;
    }
    if (key == "edit_perturbation") {
        ObjectReader r(v, path, {"sculpture", "at", "strength", "radii"});
        EditPerturbationCommand c;
        c.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        c.at = readVec3(r.required("at"), r.pathOf("at"));
        c.strength = readNumber(r.required("strength"), r.pathOf("strength"), -1000.0, 1000.0);
        c.radii = readVec3(r.required("radii"), r.pathOf("radii"));
        r.finish();
        return c;
    }
    if (key == "reapply_impacts") {
        ObjectReader r(v, path, {"from", "to"});
        ReapplyImpactsCommand c{readString(r.required("from"), r.pathOf("from")), readString(r.required("to"), r.pathOf("to"))};
        r.finish();
        return c;
    }
    if (key == "action") return ActionCommand{readAction(v, path)};
    if (key == "sketch") {
        ObjectReader r(v, path, {"sculpture", "mode", "points", "normal", "thickness", "model"});
        SketchCommand c;
        c.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        const nlohmann::json& mode = r.required("mode");
        c.newSculpture = mode.is_string() && mode.get<std::string>() == "new";
        c.model = mode.is_string() && mode.get<std::string>() == "model";
        if (c.model) c.modelName = readString(r.required("model"), r.pathOf("model"));
        else if (r.has("model")) throw JsonError(r.pathOf("model"), "a model name goes with mode \"model\" only");
        if (!c.newSculpture && !c.model) c.mode = readSketchMode(mode, r.pathOf("mode"));
        const nlohmann::json& p = r.required("points");
        if (!p.is_array() || p.size() < 3) throw JsonError(r.pathOf("points"), "expected an array of 3 or more [x, y, z] points");
        for (std::size_t i = 0; i < p.size(); ++i) c.points.push_back(readVec3(p[i], indexPath(r.pathOf("points"), i)));
        c.normal = readVec3(r.required("normal"), r.pathOf("normal"));
        if (r.has("thickness")) c.thickness = readNumber(r.required("thickness"), r.pathOf("thickness"), 0.05, 20.0);
        r.finish();
        return c;
    }
    if (key == "deform") {
        ObjectReader r(v, path, {"sculpture", "model", "mode", "iterations"});
        DeformCommand c;
        c.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        c.model = readString(r.required("model"), r.pathOf("model"));
        c.shrink = readDeformMode(r.required("mode"), r.pathOf("mode"));
        c.iterations = readInt(r.required("iterations"), r.pathOf("iterations"), 1, 100000);
        r.finish();
        return c;
    }
    if (key == "extract") {
        ObjectReader r(v, path, {"from", "by", "name"});
        ExtractCommand c;
        c.from = readString(r.required("from"), r.pathOf("from"));
        c.by = readString(r.required("by"), r.pathOf("by"));
        if (r.has("name")) c.name = readString(r.required("name"), r.pathOf("name"));
        r.finish();
        return c;
    }
    if (key == "gesture") {
        ObjectReader r(v, path, {"points"});
        GestureCommand c;
        const nlohmann::json& p = r.required("points");
        if (!p.is_array()) throw JsonError(r.pathOf("points"), "expected an array of [x, y] points");
        for (std::size_t i = 0; i < p.size(); ++i) {
            const auto xy = readVec2(p[i], indexPath(r.pathOf("points"), i));
            c.points.push_back({xy[0], xy[1]});
        }
        r.finish();
        return c;
    }
    if (key == "add") {
        ObjectReader r(v, path, {"file", "name", "position", "yaw", "scale", "resolution", "body"});
        AddCommand c;
        c.file = readString(r.required("file"), r.pathOf("file"));
        if (r.has("name")) c.name = readString(r.required("name"), r.pathOf("name"));
        if (r.has("position")) c.position = readVec3(r.required("position"), r.pathOf("position"));
        if (r.has("yaw")) c.yaw = readNumber(r.required("yaw"), r.pathOf("yaw"), -3600.0, 3600.0);
        if (r.has("scale")) c.scale = readNumber(r.required("scale"), r.pathOf("scale"), 1e-3, 1e3);
        if (r.has("resolution"))
            c.resolution = readInt(r.required("resolution"), r.pathOf("resolution"), voxel::kMinResolution,
                                   voxel::kMaxResolution);
        if (r.has("body")) c.body = readString(r.required("body"), r.pathOf("body"));
        r.finish();
        return c;
    }
    if (key == "undo" || key == "redo") {
        const int times = readInt(v, path, 1, 1000000);
        if (key == "undo") return UndoCommand{times};
        return RedoCommand{times};
    }
    // sculpt_tool: the settings a session's view.json keeps, the kind required.
    if (v.is_object() && !v.contains("kind")) throw JsonError(path, "missing key 'kind'");
    ToolCommand c;
    c.settings = readToolSettings(v, path);
    return c;
}

}  // namespace hg::garden
