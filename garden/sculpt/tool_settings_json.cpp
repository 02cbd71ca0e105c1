#include "garden/sculpt/tool_settings_json.h"

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "garden/sculpt/edit_names.h"

namespace hg::garden {

namespace {

using K = ToolSettings::Kind;
using Use = ToolSettings::SketchUse;

const char* sketchUseName(Use u) {
    switch (u) {
        case Use::Auto: return "auto";
        case Use::New: return "new";
        case Use::Join: return "join";
        case Use::Cut: return "cut";
        case Use::Model: return "model";
    }
    return "auto";
}

}  // namespace

nlohmann::json toolSettingsJson(const ToolSettings& t) {
    nlohmann::json j;
    j["kind"] = toolKindName(t.kind);
    j["radius"] = t.radius;
    j["softness"] = t.softness;
    j["shape"] = quadricShapeName(t.shape);
    j["radii"] = {t.radii[0], t.radii[1], t.radii[2]};
    j["strength"] = t.strength;
    j["perturb_scale"] = t.perturbScale;
    j["reverse"] = t.reverse;
    j["impact_shape"] = impactShapeName(t.impactShape);
    j["impact_size"] = t.impactSize;
    j["compaction_cm3"] = t.compactionCm3;
    j["spread"] = impactSpreadName(t.spread);
    j["spread_size"] = t.spreadSize;
    j["impact_count"] = t.impactCount;
    j["sketch"] = sketchUseName(t.sketchUse);
    j["smooth_strength"] = t.smoothStrength;
    j["inflate_strength"] = t.inflateStrength;
    j["falloff"] = falloffName(t.falloff);
    return j;
}

ToolSettings readToolSettings(const nlohmann::json& v, const std::string& path, ToolSettings t) {
    ObjectReader r(v, path,
                   {"kind", "radius", "softness", "shape", "radii", "strength", "perturb_scale", "reverse", "impact_shape",
                    "impact_size", "compaction_cm3", "spread", "spread_size", "impact_count", "sketch", "smooth_strength",
                    "inflate_strength", "falloff"});
    if (const auto* k = r.optional("kind")) {
        const std::string name = readString(*k, r.pathOf("kind"));
        bool found = false;
        for (K kind : {K::None, K::Carve, K::Add, K::Melt, K::Perturb, K::Impacts, K::Move, K::Sketch, K::Smooth, K::Inflate})
            if (name == toolKindName(kind)) {
                if (kind != t.kind) selectTool(t, kind);
                found = true;
            }
        if (!found) throw JsonError(r.pathOf("kind"), "expected none, carve, add, melt, perturb, impacts, move, sketch, smooth or inflate");
    }
    if (r.has("radius")) t.radius = readNumber(r.required("radius"), r.pathOf("radius"), 1e-6, 100.0);
    if (r.has("softness")) t.softness = readNumber(r.required("softness"), r.pathOf("softness"), 0.01, 64.0);
    if (r.has("shape")) t.shape = readQuadricShape(r.required("shape"), r.pathOf("shape"));
    if (r.has("radii")) t.radii = readVec3(r.required("radii"), r.pathOf("radii"));
    if (r.has("strength")) t.strength = readNumber(r.required("strength"), r.pathOf("strength"), -1000.0, 1000.0);
    if (r.has("perturb_scale"))
        t.perturbScale = readNumber(r.required("perturb_scale"), r.pathOf("perturb_scale"), 1e-6, 1e6);
    if (r.has("reverse")) t.reverse = readBool(r.required("reverse"), r.pathOf("reverse"));
    if (r.has("impact_shape")) t.impactShape = readImpactShape(r.required("impact_shape"), r.pathOf("impact_shape"));
    if (r.has("impact_size")) t.impactSize = readNumber(r.required("impact_size"), r.pathOf("impact_size"), 1e-6, 100.0);
    if (r.has("compaction_cm3"))
        t.compactionCm3 = readNumber(r.required("compaction_cm3"), r.pathOf("compaction_cm3"), 1e-6, 1e6);
    if (r.has("spread")) t.spread = readImpactSpread(r.required("spread"), r.pathOf("spread"));
    if (r.has("spread_size")) t.spreadSize = readNumber(r.required("spread_size"), r.pathOf("spread_size"), 0.0, 1e3);
    if (r.has("impact_count")) t.impactCount = readInt(r.required("impact_count"), r.pathOf("impact_count"), 1, 10000);
    if (const auto* s = r.optional("sketch")) {
        const std::string name = readString(*s, r.pathOf("sketch"));
        bool found = false;
        for (Use u : {Use::Auto, Use::New, Use::Join, Use::Cut, Use::Model})
            if (name == sketchUseName(u)) {
                t.sketchUse = u;
                found = true;
            }
        if (!found) throw JsonError(r.pathOf("sketch"), "expected auto, new, join, cut or model");
    }
    if (r.has("smooth_strength"))
        t.smoothStrength = readNumber(r.required("smooth_strength"), r.pathOf("smooth_strength"), 0.0, 1.0);
    if (r.has("inflate_strength"))
        t.inflateStrength = readNumber(r.required("inflate_strength"), r.pathOf("inflate_strength"), 0.0, 64.0);
    if (r.has("falloff")) t.falloff = readFalloff(r.required("falloff"), r.pathOf("falloff"));
    r.finish();
    clampToolSettings(t);
    return t;
}

}  // namespace hg::garden
