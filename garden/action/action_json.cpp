#include "garden/action/action.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "garden/scene/materials.h"
#include "garden/sculpt/edit_names.h"
#include "voxel/volume_frame.h"

namespace hg::garden {

namespace {

nlohmann::json point(const ModelPoint& p) { return nlohmann::json::array({p[0], p[1], p[2]}); }
nlohmann::json corner(const double (&p)[3]) { return nlohmann::json::array({p[0], p[1], p[2]}); }


// A finite number: journals hold only what the session accepted.
double finite(const nlohmann::json& v, const std::string& path) {
    const double d = readNumber(v, path);
    if (!std::isfinite(d)) throw JsonError(path, "expected a finite number");
    return d;
}

}  // namespace

bool readDeformMode(const nlohmann::json& v, const std::string& path) {
    const std::string m = readString(v, path);
    if (m == "shrink") return true;
    if (m == "grow") return false;
    throw JsonError(path, "expected \"shrink\" or \"grow\", not '" + m + "'");
}

namespace {

ModelPoint readPoint(const nlohmann::json& v, const std::string& path) {
    const auto p = readVec3(v, path);
    for (std::size_t i = 0; i < 3; ++i)
        if (!std::isfinite(p[i])) throw JsonError(indexPath(path, i), "expected a finite number");
    return p;
}

nlohmann::json mirrorJson(const MirrorPlane& m) { return {{"point", point(m.point)}, {"normal", point(m.normal)}}; }

MirrorPlane readMirror(const nlohmann::json& v, const std::string& path) {
    ObjectReader r(v, path, {"point", "normal"});
    MirrorPlane m;
    m.point = readPoint(r.required("point"), r.pathOf("point"));
    m.normal = readPoint(r.required("normal"), r.pathOf("normal"));
    const double n = std::sqrt(m.normal[0] * m.normal[0] + m.normal[1] * m.normal[1] + m.normal[2] * m.normal[2]);
    if (std::fabs(n - 1.0) > 1e-6) throw JsonError(r.pathOf("normal"), "expected a unit vector");
    r.finish();
    return m;
}

// A smooth stroke's fits: null for a segment left as it was, else its
// quadric's centre, scale and ten coefficients.
nlohmann::json fitsJson(const std::vector<std::optional<SegmentFit>>& fits) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& fit : fits) {
        if (!fit) {
            list.push_back(nullptr);
            continue;
        }
        list.push_back({{"centre", point(fit->centre)}, {"scale", fit->scale}, {"c", fit->c}});
    }
    return list;
}

std::vector<std::optional<SegmentFit>> readFits(const nlohmann::json& v, const std::string& path) {
    if (!v.is_array()) throw JsonError(path, "expected an array of fits (null or {\"centre\", \"scale\", \"c\"})");
    std::vector<std::optional<SegmentFit>> fits;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const std::string at = indexPath(path, i);
        if (v[i].is_null()) {
            fits.emplace_back();
            continue;
        }
        ObjectReader r(v[i], at, {"centre", "scale", "c"});
        SegmentFit fit;
        fit.centre = readPoint(r.required("centre"), r.pathOf("centre"));
        fit.scale = readPositive(r.required("scale"), r.pathOf("scale"));
        const nlohmann::json& c = r.required("c");
        if (!c.is_array() || c.size() != fit.c.size()) throw JsonError(r.pathOf("c"), "expected 10 coefficients");
        for (std::size_t k = 0; k < c.size(); ++k) fit.c[k] = finite(c[k], indexPath(r.pathOf("c"), k));
        r.finish();
        fits.push_back(fit);
    }
    return fits;
}

void writePerturbation(const Perturbation& q, nlohmann::json& j) {
    j["shape"] = quadricShapeName(q.shape);
    j["center"] = point(q.center);
    j["axes"] = nlohmann::json::array({point(q.axes[0]), point(q.axes[1]), point(q.axes[2])});
    j["radii"] = point(q.radii);
    j["strength"] = q.strength;
    if (q.mirror) j["mirror"] = mirrorJson(*q.mirror);
}

void writePlacement(const Placement& p, nlohmann::json& j) {
    j["position"] = point(p.position);
    j["yaw"] = p.yawDegrees;
    j["scale"] = p.scale;
}

Placement readPlacement(ObjectReader& r) {
    Placement p;
    p.position = readPoint(r.required("position"), r.pathOf("position"));
    p.yawDegrees = finite(r.required("yaw"), r.pathOf("yaw"));
    p.scale = readPositive(r.required("scale"), r.pathOf("scale"));
    return p;
}

// An added mesh's or volume's file (docs/session-format.md, "Imported
// files"): {"mesh": {"file"}} or {"volume": {"file", "iso", "inside"}}.
void writeImported(const AddAction::Imported& m, nlohmann::json& j) {
    if (m.kind == AddAction::Imported::Kind::Mesh)
        j["mesh"] = {{"file", m.file}};
    else
        j["volume"] = {{"file", m.file}, {"iso", m.iso}, {"inside", m.insideAbove ? "above" : "below"}};
}

AddAction::Imported readImported(ObjectReader& r) {
    using Kind = AddAction::Imported::Kind;
    if (static_cast<int>(r.has("source")) + static_cast<int>(r.has("mesh")) + static_cast<int>(r.has("volume")) > 1)
        throw JsonError(r.path(), "an add holds one of \"source\", \"mesh\" or \"volume\", not two");
    AddAction::Imported m;
    m.kind = r.has("mesh") ? Kind::Mesh : Kind::Volume;
    const char* key = m.kind == Kind::Mesh ? "mesh" : "volume";
    const nlohmann::json& v = r.required(key);
    const std::string at = r.pathOf(key);
    if (m.kind == Kind::Mesh) {
        ObjectReader o(v, at, {"file"});
        m.file = readString(o.required("file"), o.pathOf("file"));
        o.finish();
    } else {
        ObjectReader o(v, at, {"file", "iso", "inside"});
        m.file = readString(o.required("file"), o.pathOf("file"));
        m.iso = finite(o.required("iso"), o.pathOf("iso"));
        const std::string inside = readString(o.required("inside"), o.pathOf("inside"));
        if (inside != "above" && inside != "below")
            throw JsonError(o.pathOf("inside"), "expected \"above\" or \"below\", found '" + inside + "'");
        m.insideAbove = inside == "above";
        o.finish();
    }
    if (m.file.empty()) throw JsonError(childPath(at, "file"), "expected the imported file's name");
    return m;
}

}  // namespace

std::string actionKind(const Action& r) {
    static const char* const names[] = {"stroke", "perturb", "undo",    "redo",    "discard",
                                        "morph",  "move",    "impacts", "replace", "sketch", "add", "material",
                                        "model",  "deform",  "select",  "reload"};
    return names[r.index()];
}

std::string actionJson(const Action& record) {
    nlohmann::json j;
    j["action"] = actionKind(record);
    if (const auto* s = std::get_if<StrokeAction>(&record)) {
        j["sculpture"] = s->sculpture;
        j["tool"] = strokeToolName(s->tool);
        j["radius"] = s->radius;
        if (s->tool == StrokeTool::Melt) j["softness"] = s->softness;
        if (s->tool == StrokeTool::Smooth || s->tool == StrokeTool::Inflate) {
            j["strength"] = s->strength;
            j["falloff"] = falloffName(s->falloff);
        }
        nlohmann::json path = nlohmann::json::array();
        for (const ModelPoint& p : s->path) path.push_back(point(p));
        j["path"] = std::move(path);
        if (s->mirror) j["mirror"] = mirrorJson(*s->mirror);
        if (s->tool == StrokeTool::Smooth) j["fits"] = fitsJson(s->fits);
    } else if (const auto* p = std::get_if<PerturbAction>(&record)) {
        j["sculpture"] = p->sculpture;
        writePerturbation(p->perturbation, j);
    } else if (const auto* rp = std::get_if<ReplaceAction>(&record)) {
        j["sculpture"] = rp->sculpture;
        j["edit"] = rp->edit;
        writePerturbation(rp->perturbation, j);
    } else if (const auto* u = std::get_if<UndoAction>(&record)) {
        if (!u->sculpture.empty()) j["sculpture"] = u->sculpture;
    } else if (const auto* d = std::get_if<DiscardAction>(&record)) {
        j["sculpture"] = d->sculpture;
        if (d->undoable) j["undoable"] = true;
    } else if (const auto* m = std::get_if<MorphWeightsAction>(&record)) {
        if (!m->sculpture.empty()) j["sculpture"] = m->sculpture;
        j["barycentric"] = point(m->barycentric);
        j["balance"] = point(m->balance);
    } else if (const auto* im = std::get_if<ImpactsAction>(&record)) {
        j["sculpture"] = im->sculpture;
        nlohmann::json list = nlohmann::json::array();
        for (const Impact& hit : im->series.impacts)
            list.push_back({{"shape", impactShapeName(hit.shape)}, {"tip", point(hit.tip)}, {"direction", point(hit.direction)},
                            {"across", point(hit.across)}, {"size", hit.size}, {"depth", hit.depth}});
        j["impacts"] = std::move(list);
        nlohmann::json rays = nlohmann::json::array();
        for (std::size_t i = 0; i < im->series.rayOrigins.size(); ++i)
            rays.push_back({point(im->series.rayOrigins[i]), point(im->series.rayDirections[i])});
        j["rays"] = std::move(rays);
        j["volume"] = im->series.volume;
    } else if (const auto* k = std::get_if<SketchAction>(&record)) {
        j["sculpture"] = k->sculpture;
        j["mode"] = sketchModeName(k->mode);
        nlohmann::json points = nlohmann::json::array();
        for (const ModelPoint& q : k->points) points.push_back(point(q));
        j["points"] = std::move(points);
        j["normal"] = point(k->normal);
        j["thickness"] = k->thickness;
        if (k->mirror) j["mirror"] = mirrorJson(*k->mirror);
    } else if (const auto* md = std::get_if<ModelAction>(&record)) {
        j["name"] = md->name;
        j["sculpture"] = md->sculpture;
        nlohmann::json points = nlohmann::json::array();
        for (const ModelPoint& q : md->points) points.push_back(point(q));
        j["points"] = std::move(points);
        j["normal"] = point(md->normal);
        j["thickness"] = md->thickness;
    } else if (const auto* df = std::get_if<DeformAction>(&record)) {
        j["model"] = df->model;
        j["mode"] = df->shrink ? "shrink" : "grow";
        j["iterations"] = df->iterations;
    } else if (const auto* se = std::get_if<SelectAction>(&record)) {
        j["sculpture"] = se->sculpture;
        j["model"] = se->model;
    } else if (const auto* mv = std::get_if<MoveAction>(&record)) {
        j["sculpture"] = mv->sculpture;
        writePlacement(mv->placement, j);
    } else if (const auto* ma = std::get_if<MaterialAction>(&record)) {
        j["sculpture"] = ma->sculpture;
        if (!ma->material.name.empty()) j["name"] = ma->material.name;
        j["material"] = materialObjectJson(ma->material);
    } else if (const auto* ad = std::get_if<AddAction>(&record)) {
        j["sculpture"] = ad->sculpture;
        if (ad->imported) writeImported(*ad->imported, j);
        else j["source"] = ad->source;
        j["origin"] = ad->origin;
        if (!ad->body.empty()) j["body"] = ad->body;
        if (ad->box) j["box"] = {corner(ad->box->lo), corner(ad->box->hi)};
        j["resolution"] = ad->resolution;
        writePlacement(ad->placement, j);
    } else if (const auto* rl = std::get_if<ReloadAction>(&record)) {
        j["sculpture"] = rl->sculpture;
        j["source"] = rl->source;
    }
    return j.dump();
}

Action parseAction(const std::string& text, const std::string& path) { return readAction(parseStrictJson(text), path); }

Action readAction(const nlohmann::json& v, const std::string& path) {
    if (!v.is_object() || !v.contains("action")) throw JsonError(path, "expected an object with an \"action\"");
    const std::string action = readString(v.at("action"), childPath(path, "action"));
    if (action == "stroke") {
        ObjectReader r(v, path,
                       {"action", "sculpture", "tool", "radius", "softness", "path", "mirror", "strength", "falloff", "fits"});
        StrokeAction s;
        s.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        s.tool = readStrokeTool(r.required("tool"), r.pathOf("tool"));
        s.radius = readPositive(r.required("radius"), r.pathOf("radius"));
        if (r.has("softness")) s.softness = readPositive(r.required("softness"), r.pathOf("softness"));
        const nlohmann::json& p = r.required("path");
        if (!p.is_array() || p.empty()) throw JsonError(r.pathOf("path"), "expected a non-empty array of points");
        for (std::size_t i = 0; i < p.size(); ++i) s.path.push_back(readPoint(p[i], indexPath(r.pathOf("path"), i)));
        if (r.has("mirror")) s.mirror = readMirror(r.required("mirror"), r.pathOf("mirror"));
        if (r.has("strength")) s.strength = finite(r.required("strength"), r.pathOf("strength"));
        if (r.has("falloff")) s.falloff = readFalloff(r.required("falloff"), r.pathOf("falloff"));
        if (r.has("fits")) s.fits = readFits(r.required("fits"), r.pathOf("fits"));
        r.finish();
        return s;
    }
    if (action == "perturb" || action == "replace") {
        ObjectReader r(v, path, action == "perturb"
                                    ? std::initializer_list<const char*>{"action", "sculpture", "shape", "center", "axes",
                                                                         "radii", "strength", "mirror"}
                                    : std::initializer_list<const char*>{"action", "sculpture", "edit", "shape", "center",
                                                                         "axes", "radii", "strength", "mirror"});
        PerturbAction p;
        p.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        p.perturbation.shape = readQuadricShape(r.required("shape"), r.pathOf("shape"));
        p.perturbation.center = readPoint(r.required("center"), r.pathOf("center"));
        const nlohmann::json& axes = r.required("axes");
        if (!axes.is_array() || axes.size() != 3) throw JsonError(r.pathOf("axes"), "expected three axes");
        for (std::size_t i = 0; i < 3; ++i) p.perturbation.axes[i] = readPoint(axes[i], indexPath(r.pathOf("axes"), i));
        p.perturbation.radii = readPoint(r.required("radii"), r.pathOf("radii"));
        for (std::size_t i = 0; i < (p.perturbation.shape == QuadricShape::Ellipsoid ? 3u : 2u); ++i)
            if (!(p.perturbation.radii[i] > 0.0)) throw JsonError(indexPath(r.pathOf("radii"), i), "expected a positive radius");
        p.perturbation.strength = finite(r.required("strength"), r.pathOf("strength"));
        if (r.has("mirror")) p.perturbation.mirror = readMirror(r.required("mirror"), r.pathOf("mirror"));
        if (action == "replace") {
            ReplaceAction rp{p.sculpture, static_cast<std::size_t>(readInt(r.required("edit"), r.pathOf("edit"), 0, 100000000)),
                             p.perturbation};
            r.finish();
            return rp;
        }
        r.finish();
        return p;
    }
    if (action == "undo") {
        ObjectReader r(v, path, {"action", "sculpture"});
        UndoAction u;
        if (r.has("sculpture")) u.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        r.finish();
        return u;
    }
    if (action == "redo") {
        ObjectReader r(v, path, {"action"});
        r.finish();
        return RedoAction{};
    }
    if (action == "discard") {
        ObjectReader r(v, path, {"action", "sculpture", "undoable"});
        DiscardAction d{readString(r.required("sculpture"), r.pathOf("sculpture")), false};
        if (const auto* u = r.optional("undoable")) d.undoable = readBool(*u, r.pathOf("undoable"));
        r.finish();
        return d;
    }
    if (action == "morph") {
        ObjectReader r(v, path, {"action", "sculpture", "barycentric", "balance"});
        MorphWeightsAction m{readPoint(r.required("barycentric"), r.pathOf("barycentric")),
                             readPoint(r.required("balance"), r.pathOf("balance")), ""};
        if (const auto* x = r.optional("sculpture")) m.sculpture = readString(*x, r.pathOf("sculpture"));
        r.finish();
        return m;
    }
    if (action == "impacts") {
        ObjectReader r(v, path, {"action", "sculpture", "impacts", "rays", "volume"});
        ImpactsAction rec;
        rec.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        const nlohmann::json& list = r.required("impacts");
        if (!list.is_array()) throw JsonError(r.pathOf("impacts"), "expected an array of impacts");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string ip = indexPath(r.pathOf("impacts"), i);
            ObjectReader ir(list[i], ip, {"shape", "tip", "direction", "across", "size", "depth"});
            Impact m;
            m.shape = readImpactShape(ir.required("shape"), ir.pathOf("shape"));
            m.tip = readPoint(ir.required("tip"), ir.pathOf("tip"));
            m.direction = readPoint(ir.required("direction"), ir.pathOf("direction"));
            m.across = readPoint(ir.required("across"), ir.pathOf("across"));
            m.size = readPositive(ir.required("size"), ir.pathOf("size"));
            m.depth = finite(ir.required("depth"), ir.pathOf("depth"));
            ir.finish();
            rec.series.impacts.push_back(m);
        }
        const nlohmann::json& rays = r.required("rays");
        if (!rays.is_array()) throw JsonError(r.pathOf("rays"), "expected an array of [origin, direction] pairs");
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const std::string rp = indexPath(r.pathOf("rays"), i);
            if (!rays[i].is_array() || rays[i].size() != 2) throw JsonError(rp, "expected [origin, direction]");
            rec.series.rayOrigins.push_back(readPoint(rays[i][0], indexPath(rp, 0)));
            rec.series.rayDirections.push_back(readPoint(rays[i][1], indexPath(rp, 1)));
        }
        rec.series.volume = readPositive(r.required("volume"), r.pathOf("volume"));
        r.finish();
        return rec;
    }
    if (action == "move") {
        ObjectReader r(v, path, {"action", "sculpture", "position", "yaw", "scale"});
        MoveAction m;
        m.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        m.placement = readPlacement(r);
        r.finish();
        return m;
    }
    if (action == "add") {
        ObjectReader r(v, path, {"action", "sculpture", "source", "mesh", "volume", "origin", "body", "box",
                                 "resolution", "position", "yaw", "scale"});
        AddAction a;
        a.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        // A program's text, or an imported mesh or volume (journals before
        // imports hold only "source").
        if (r.has("mesh") || r.has("volume")) a.imported = readImported(r);
        else a.source = readString(r.required("source"), r.pathOf("source"));
        a.origin = readString(r.required("origin"), r.pathOf("origin"));
        if (r.has("body")) a.body = readString(r.required("body"), r.pathOf("body"));
        if (r.has("box")) {
            const nlohmann::json& b = r.required("box");
            if (!b.is_array() || b.size() != 2) throw JsonError(r.pathOf("box"), "expected [lo, hi]");
            const ModelPoint lo = readPoint(b[0], indexPath(r.pathOf("box"), 0));
            const ModelPoint hi = readPoint(b[1], indexPath(r.pathOf("box"), 1));
            frep::Box3 box;
            for (std::size_t i = 0; i < 3; ++i) {
                if (!(lo[i] < hi[i])) throw JsonError(r.pathOf("box"), "expected lo < hi on every axis");
                box.lo[i] = lo[i];
                box.hi[i] = hi[i];
            }
            a.box = box;
        }
        a.resolution = readInt(r.required("resolution"), r.pathOf("resolution"), voxel::kMinResolution,
                               voxel::kMaxResolution);
        a.placement = readPlacement(r);
        r.finish();
        return a;
    }
    if (action == "material") {
        ObjectReader r(v, path, {"action", "sculpture", "name", "material"});
        MaterialAction m;
        m.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        const std::string name = r.has("name") ? readString(r.required("name"), r.pathOf("name")) : std::string();
        m.material = readMaterialObject(r.required("material"), r.pathOf("material"), name);
        r.finish();
        return m;
    }
    if (action == "sketch") {
        ObjectReader r(v, path, {"action", "sculpture", "mode", "points", "normal", "thickness", "mirror"});
        SketchAction k;
        k.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        k.mode = readSketchMode(r.required("mode"), r.pathOf("mode"));
        const nlohmann::json& points = r.required("points");
        if (!points.is_array() || points.size() < 3) throw JsonError(r.pathOf("points"), "expected an array of 3 or more points");
        for (std::size_t i = 0; i < points.size(); ++i) k.points.push_back(readPoint(points[i], indexPath(r.pathOf("points"), i)));
        k.normal = readPoint(r.required("normal"), r.pathOf("normal"));
        if (r.has("thickness")) k.thickness = readPositive(r.required("thickness"), r.pathOf("thickness"));
        if (r.has("mirror")) k.mirror = readMirror(r.required("mirror"), r.pathOf("mirror"));
        r.finish();
        return k;
    }
    if (action == "model") {
        ObjectReader r(v, path, {"action", "name", "sculpture", "points", "normal", "thickness"});
        ModelAction m;
        m.name = readString(r.required("name"), r.pathOf("name"));
        m.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        const nlohmann::json& points = r.required("points");
        if (!points.is_array() || points.size() < 3) throw JsonError(r.pathOf("points"), "expected an array of 3 or more points");
        for (std::size_t i = 0; i < points.size(); ++i) m.points.push_back(readPoint(points[i], indexPath(r.pathOf("points"), i)));
        m.normal = readPoint(r.required("normal"), r.pathOf("normal"));
        if (r.has("thickness")) m.thickness = readPositive(r.required("thickness"), r.pathOf("thickness"));
        r.finish();
        return m;
    }
    if (action == "deform") {
        ObjectReader r(v, path, {"action", "model", "mode", "iterations"});
        DeformAction d;
        d.model = readString(r.required("model"), r.pathOf("model"));
        d.shrink = readDeformMode(r.required("mode"), r.pathOf("mode"));
        d.iterations = readInt(r.required("iterations"), r.pathOf("iterations"), 1, 100000);
        r.finish();
        return d;
    }
    if (action == "select") {
        ObjectReader r(v, path, {"action", "sculpture", "model"});
        SelectAction s;
        s.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        s.model = readString(r.required("model"), r.pathOf("model"));
        r.finish();
        return s;
    }
    if (action == "reload") {
        ObjectReader r(v, path, {"action", "sculpture", "source"});
        ReloadAction a;
        a.sculpture = readString(r.required("sculpture"), r.pathOf("sculpture"));
        a.source = readString(r.required("source"), r.pathOf("source"));
        r.finish();
        return a;
    }
    throw JsonError(childPath(path, "action"), "unknown action '" + action +
                                                   "' (expected stroke, perturb, replace, impacts, undo, redo, discard, "
                                                   "morph, move, sketch, add, material, model, deform, select or reload)");
}

}  // namespace hg::garden
