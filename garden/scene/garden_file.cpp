#include "garden/scene/garden_file.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "garden/scene/materials.h"
#include "garden/scene/model_file.h"
#include "polygonizer/export/mesh_read.h"
#include "voxel/scalar_volume.h"
#include "voxel/volume_frame.h"

namespace hg::garden {

namespace {

using json = nlohmann::json;

constexpr int kVersion = 1;
// A morph triangle smaller than this (square metres) has no usable inside.
constexpr double kMinTriangleArea = 1e-4;

struct Reader {
    std::string file;    // the garden file, for the messages a scan gives when it is read
    std::string folder;
    std::map<std::string, Material> materials;

    // A name: an entry of $.materials, else a built-in (garden/scene/materials.h).
    Material material(const json& v, const std::string& path) const {
        if (v.is_string()) {
            std::string name = v.get<std::string>();
            auto it = materials.find(name);
            if (it != materials.end()) return it->second;
            if (auto builtin = builtinMaterial(name)) return *builtin;
            std::vector<std::string> names = materialKindNames();
            for (const auto& m : materials) names.push_back(m.first);
            std::string hint = nearMiss(name, names);
            throw JsonError(path, "no material named '" + name + "' in $.materials or built in" +
                                      (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)"));
        }
        if (!v.is_object()) throw JsonError(path, "expected a material name or a material object");
        return readMaterialObject(v, path, "");
    }

    static frep::Box3 box(const json& v, const std::string& path) {
        ObjectReader o(v, path, {"min", "max"});
        o.finish();
        Vec3 lo = readVec3(o.required("min"), o.pathOf("min"));
        Vec3 hi = readVec3(o.required("max"), o.pathOf("max"));
        frep::Box3 b;
        static const char* axes[] = {"x", "y", "z"};
        for (int a = 0; a < 3; ++a) {
            if (!(lo[static_cast<std::size_t>(a)] < hi[static_cast<std::size_t>(a)]))
                throw JsonError(path, std::string("min must be below max on every axis (") + axes[a] + ": " +
                                          formatNumber(lo[static_cast<std::size_t>(a)]) + " >= " +
                                          formatNumber(hi[static_cast<std::size_t>(a)]) + ")");
            b.lo[a] = lo[static_cast<std::size_t>(a)];
            b.hi[a] = hi[static_cast<std::size_t>(a)];
        }
        return b;
    }

    static Placement placement(const json& v, const std::string& path, Placement p) {
        ObjectReader o(v, path, {"position", "yaw", "scale"});
        o.finish();
        if (auto* x = o.optional("position")) p.position = readVec3(*x, o.pathOf("position"));
        if (auto* x = o.optional("yaw")) p.yawDegrees = readNumber(*x, o.pathOf("yaw"), -360, 360);
        if (auto* x = o.optional("scale")) p.scale = readPositive(*x, o.pathOf("scale"));
        return p;
    }

    static int resolution(const json& v, const std::string& path) {
        return readInt(v, path, voxel::kMinResolution, voxel::kMaxResolution);
    }
    static float band(const json& v, const std::string& path) {
        return static_cast<float>(readNumber(v, path, voxel::kMinBand, voxel::kMaxBand));
    }

    std::string resolve(const std::string& written) const {
        std::filesystem::path p(written);
        if (p.is_absolute()) return p.lexically_normal().string();
        return (std::filesystem::path(folder) / p).lexically_normal().string();
    }

    SculptureSpec sculpture(const json& v, const std::string& path, const Material& fallback) const {
        ObjectReader o(v, path, {"name", "file", "volume", "mesh", "body", "a", "box", "resolution", "band", "placement", "material"});
        o.finish();
        SculptureSpec s;
        s.name = readString(o.required("name"), o.pathOf("name"));
        const int sources = int(o.has("file")) + int(o.has("volume")) + int(o.has("mesh"));
        if (sources > 1)
            throw JsonError(path, "give one of 'file' (a HyperFun program), 'volume' (a scanned volume) or 'mesh' "
                                  "(an STL, OBJ or PLY mesh), not several");
        if (sources == 0)
            throw JsonError(path, "missing key 'file' (a HyperFun program), 'volume' (a scanned volume) or 'mesh' "
                                  "(an STL, OBJ or PLY mesh)");
        const char* grid = o.has("volume") ? "volume" : o.has("mesh") ? "mesh" : nullptr;
        if (grid)
            for (const char* key : {"body", "a"})
                if (o.has(key))
                    throw JsonError(o.pathOf(key), std::string("'") + key + "' applies to a HyperFun file, not to a " + grid);
        if (auto* x = o.optional("volume")) {
            s.scan = scan(*x, o.pathOf("volume"), s);
        } else if (auto* m = o.optional("mesh")) {
            s.mesh = mesh(*m, o.pathOf("mesh"), s);
        } else {
            s.fileAsWritten = readString(o.required("file"), o.pathOf("file"));
            s.file = resolve(s.fileAsWritten);
        }
        if (auto* x = o.optional("body")) s.body = readString(*x, o.pathOf("body"));
        if (auto* x = o.optional("a")) s.a = readNumbers(*x, o.pathOf("a"));
        if (auto* x = o.optional("box")) s.box = box(*x, o.pathOf("box"));
        if (auto* x = o.optional("resolution")) s.resolution = resolution(*x, o.pathOf("resolution"));
        if (auto* x = o.optional("band")) s.band = band(*x, o.pathOf("band"));
        if (auto* x = o.optional("placement")) s.placement = placement(*x, o.pathOf("placement"), Placement{});
        s.material = fallback;
        if (auto* x = o.optional("material")) s.material = material(*x, o.pathOf("material"));
        return s;
    }

    // A scanned volume's entry (docs/garden-format.md, "volume"); its file
    // is read with the sculptures (loadSculpture), so a missing or wrong
    // file marks the sculpture missing instead of refusing the garden.
    ScanSpec scan(const json& v, const std::string& path, SculptureSpec& s) const {
        ObjectReader o(v, path, {"file", "grid", "dims", "type", "spacing", "iso", "inside"});
        o.finish();
        ScanSpec scan;
        scan.at = file + ": " + path;
        s.fileAsWritten = readString(o.required("file"), o.pathOf("file"));
        s.file = resolve(s.fileAsWritten);
        std::string ext = std::filesystem::path(s.fileAsWritten).extension().string();
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (ext == ".vdb") scan.format = ScanSpec::Format::Vdb;
        else if (ext != ".raw")
            throw JsonError(o.pathOf("file"), "expected a raw volume (.raw) or an OpenVDB file (.vdb), found '" +
                                                  s.fileAsWritten + "'");
        const bool raw = scan.format == ScanSpec::Format::Raw;
        for (const char* key : {"dims", "type", "spacing"})
            if (!raw && o.has(key))
                throw JsonError(o.pathOf(key), std::string("'") + key + "' applies to a raw volume; a .vdb grid has its own");
        if (raw && o.has("grid")) throw JsonError(o.pathOf("grid"), "'grid' applies to a .vdb file");
        if (auto* x = o.optional("grid")) scan.grid = readString(*x, o.pathOf("grid"));
        if (raw) {
            const json& dims = o.required("dims");
            const std::string at = o.pathOf("dims");
            if (!dims.is_array() || dims.size() != 3) throw JsonError(at, "expected an array of 3 integers [nx, ny, nz]");
            for (std::size_t a = 0; a < 3; ++a)
                scan.dims[a] = readInt(dims[a], indexPath(at, a), voxel::kMinRawDim, voxel::kMaxRawDim);
        }
        if (auto* x = o.optional("type")) {
            const std::string type = readString(*x, o.pathOf("type"));
            if (type != "u8" && type != "u16")
                throw JsonError(o.pathOf("type"), "expected \"u8\" or \"u16\" (16 bits little-endian), found '" + type + "'");
            scan.sixteenBit = type == "u16";
        }
        if (auto* x = o.optional("spacing")) {
            if (x->is_number()) {
                const double d = readPositive(*x, o.pathOf("spacing"));
                scan.spacing = {d, d, d};
            } else {
                scan.spacing = readVec3(*x, o.pathOf("spacing"));
                for (std::size_t a = 0; a < 3; ++a)
                    if (!(scan.spacing[a] > 0.0))
                        throw JsonError(indexPath(o.pathOf("spacing"), a), "expected a positive number");
            }
        }
        scan.iso = readNumber(o.required("iso"), o.pathOf("iso"));
        if (auto* x = o.optional("inside")) {
            const std::string inside = readString(*x, o.pathOf("inside"));
            if (inside != "above" && inside != "below")
                throw JsonError(o.pathOf("inside"), "expected \"above\" (the solid is where samples exceed iso) or "
                                                    "\"below\", found '" + inside + "'");
            scan.insideAbove = inside == "above";
        }
        return scan;
    }

    // A mesh's entry (docs/garden-format.md, "mesh"); like a scan's, its
    // file is read with the sculptures.
    MeshSpec mesh(const json& v, const std::string& path, SculptureSpec& s) const {
        ObjectReader o(v, path, {"file"});
        o.finish();
        MeshSpec m;
        m.at = file + ": " + path;
        s.fileAsWritten = readString(o.required("file"), o.pathOf("file"));
        s.file = resolve(s.fileAsWritten);
        if (!poly::isMeshFileName(s.fileAsWritten))
            throw JsonError(o.pathOf("file"), "expected a mesh file (.stl, .obj or .ply), found '" + s.fileAsWritten + "'");
        return m;
    }

    PathSpec path(const json& v, const std::string& at, const Material& fallback) const {
        ObjectReader o(v, at, {"name", "points", "width", "closed", "material"});
        o.finish();
        PathSpec p;
        if (auto* x = o.optional("name")) p.name = readString(*x, o.pathOf("name"));
        const json& points = o.required("points");
        std::string pointsPath = o.pathOf("points");
        if (!points.is_array() || points.size() < 2)
            throw JsonError(pointsPath, "expected an array of at least 2 points [x, z]");
        for (std::size_t i = 0; i < points.size(); ++i) p.points.push_back(readVec2(points[i], indexPath(pointsPath, i)));
        if (auto* x = o.optional("width")) p.width = readPositive(*x, o.pathOf("width"));
        if (auto* x = o.optional("closed")) p.closed = readBool(*x, o.pathOf("closed"));
        p.material = fallback;
        if (auto* x = o.optional("material")) p.material = material(*x, o.pathOf("material"));
        return p;
    }

    static Light light(const json& v, const std::string& path) {
        if (!v.is_object()) throw JsonError(path, "expected an object");
        Light l;
        auto typeIt = v.find("type");
        if (typeIt == v.end()) throw JsonError(path, "missing key 'type'");
        std::string type = readString(*typeIt, childPath(path, "type"));
        if (type == "ambient") {
            ObjectReader o(v, path, {"type", "color", "intensity"});
            o.finish();
            l.kind = Light::Kind::Ambient;
            l.intensity = 0.25;
        } else if (type == "directional") {
            ObjectReader o(v, path, {"type", "color", "intensity", "direction"});
            o.finish();
            l.kind = Light::Kind::Directional;
            if (auto* x = o.optional("direction")) {
                Vec3 d = readVec3(*x, o.pathOf("direction"));
                double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (!(n > 1e-9)) throw JsonError(o.pathOf("direction"), "expected a non-zero direction");
                l.direction = {d[0] / n, d[1] / n, d[2] / n};
            }
        } else if (type == "point") {
            ObjectReader o(v, path, {"type", "color", "intensity", "position", "range"});
            o.finish();
            l.kind = Light::Kind::Point;
            if (auto* x = o.optional("position")) l.position = readVec3(*x, o.pathOf("position"));
            if (auto* x = o.optional("range")) l.range = readPositive(*x, o.pathOf("range"));
        } else {
            throw JsonError(childPath(path, "type"),
                            "unknown light type '" + type + "'; expected one of: ambient directional point");
        }
        if (auto it = v.find("color"); it != v.end()) l.color = readColor(*it, childPath(path, "color"));
        if (auto it = v.find("intensity"); it != v.end()) l.intensity = readNumber(*it, childPath(path, "intensity"), 0, 1e6);
        return l;
    }

    static StartPose start(const json& v, const std::string& path) {
        ObjectReader o(v, path, {"position", "look_at"});
        o.finish();
        StartPose s;
        if (auto* x = o.optional("position")) s.position = readVec3(*x, o.pathOf("position"));
        if (auto* x = o.optional("look_at")) s.lookAt = readVec3(*x, o.pathOf("look_at"));
        double d = 0.0;
        for (std::size_t a = 0; a < 3; ++a) d += (s.lookAt[a] - s.position[a]) * (s.lookAt[a] - s.position[a]);
        if (!(d > 1e-12)) throw JsonError(o.pathOf("look_at"), "must differ from the position");
        return s;
    }

    static Ground ground(const json& v, const std::string& path, const Reader& r, const Material& fallback) {
        ObjectReader o(v, path, {"height", "size", "material"});
        o.finish();
        Ground g;
        g.material = fallback;
        if (auto* x = o.optional("height")) g.height = readNumber(*x, o.pathOf("height"));
        if (auto* x = o.optional("size")) {
            g.size = readVec2(*x, o.pathOf("size"));
            if (!(g.size[0] > 0 && g.size[1] > 0)) throw JsonError(o.pathOf("size"), "expected two positive numbers");
        }
        if (auto* x = o.optional("material")) g.material = r.material(*x, o.pathOf("material"));
        return g;
    }

    // What already has `name` ("a sculpture", "the result of $.morphs[0]"), or "".
    static std::string nameTaken(const Garden& g, const std::string& name) {
        if (g.findSculpture(name) >= 0) return "a sculpture";
        const int m = g.findMorph(name);
        if (m >= 0) return "the result of morph " + std::to_string(m);
        return "";
    }

    MorphSpec morph(const json& v, const std::string& path, const Garden& g, const Material& fallback) const {
        ObjectReader o(v, path, {"sources", "balance", "selector", "result"});
        o.finish();
        MorphSpec m;
        const json& sources = o.required("sources");
        std::string sourcesPath = o.pathOf("sources");
        if (!sources.is_array() || sources.size() != 3)
            throw JsonError(sourcesPath, "expected an array of 3 sculpture names (the triangle's corners)");
        std::vector<std::string> names;
        for (const auto& s : g.sculptures) names.push_back(s.name);
        for (std::size_t i = 0; i < 3; ++i) {
            std::string at = indexPath(sourcesPath, i);
            m.sources[i] = readString(sources[i], at);
            int index = g.findSculpture(m.sources[i]);
            if (index < 0) {
                std::string hint = nearMiss(m.sources[i], names);
                throw JsonError(at, "no sculpture named '" + m.sources[i] + "'" +
                                        (hint.empty() ? std::string() : " (did you mean '" + hint + "'?)"));
            }
            for (std::size_t j = 0; j < i; ++j)
                if (m.sources[j] == m.sources[i])
                    throw JsonError(at, "'" + m.sources[i] + "' is already source " + std::to_string(j));
            m.sourceIndex[i] = static_cast<std::size_t>(index);
        }
        std::array<Vec2, 3> c;
        for (std::size_t i = 0; i < 3; ++i) {
            const Vec3& p = g.sculptures[m.sourceIndex[i]].placement.position;
            c[i] = {p[0], p[2]};
        }
        double area = 0.5 * std::fabs((c[1][0] - c[0][0]) * (c[2][1] - c[0][1]) - (c[2][0] - c[0][0]) * (c[1][1] - c[0][1]));
        if (area < kMinTriangleArea)
            throw JsonError(sourcesPath, "the three sources stand on one line: the morph triangle (their positions "
                                         "on the ground) has no area");
        Vec2 centroid = {(c[0][0] + c[1][0] + c[2][0]) / 3.0, (c[0][1] + c[1][1] + c[2][1]) / 3.0};
        m.selector = centroid;
        if (auto* x = o.optional("selector")) m.selector = readVec2(*x, o.pathOf("selector"));
        if (auto* x = o.optional("balance")) {
            std::string at = o.pathOf("balance");
            if (x->is_string()) {
                if (x->get<std::string>() != "computed")
                    throw JsonError(at, "expected \"computed\" or an array of 3 positive numbers");
            } else {
                if (!x->is_array() || x->size() != 3)
                    throw JsonError(at, "expected \"computed\" or an array of 3 positive numbers");
                std::array<double, 3> b{};
                for (std::size_t i = 0; i < 3; ++i) b[i] = readPositive((*x)[i], indexPath(at, i));
                m.balance = b;
            }
        }
        m.resultPlacement.position = {centroid[0], g.ground.height, centroid[1]};
        m.material = fallback;
        bool named = false;
        std::string namePath;
        if (auto* x = o.optional("result")) {
            ObjectReader r(*x, o.pathOf("result"), {"name", "placement", "box", "resolution", "band", "material"});
            r.finish();
            namePath = r.pathOf("name");
            if (auto* y = r.optional("name")) m.resultName = readString(*y, namePath), named = true;
            if (auto* y = r.optional("placement")) m.resultPlacement = placement(*y, r.pathOf("placement"), m.resultPlacement);
            if (auto* y = r.optional("box")) m.box = box(*y, r.pathOf("box"));
            if (auto* y = r.optional("resolution")) m.resolution = resolution(*y, r.pathOf("resolution"));
            if (auto* y = r.optional("band")) m.band = band(*y, r.pathOf("band"));
            if (auto* y = r.optional("material")) m.material = material(*y, r.pathOf("material"));
        }
        if (std::string taken = nameTaken(g, m.resultName); !taken.empty()) {
            if (named) throw JsonError(namePath, "'" + m.resultName + "' is already the name of " + taken);
            throw JsonError(path, "the result's default name '" + m.resultName + "' is already the name of " + taken +
                                      "; give " + childPath(childPath(path, "result"), "name"));
        }
        return m;
    }
};

std::vector<Light> defaultLights() {
    Light ambient;
    ambient.kind = Light::Kind::Ambient;
    ambient.intensity = 0.25;
    Light sun;
    sun.kind = Light::Kind::Directional;
    double n = std::sqrt(0.3 * 0.3 + 1.0 + 0.5 * 0.5);
    sun.direction = {-0.3 / n, -1.0 / n, -0.5 / n};
    return {ambient, sun};
}

}  // namespace

int Garden::findSculpture(const std::string& sculptureName) const {
    for (std::size_t i = 0; i < sculptures.size(); ++i)
        if (sculptures[i].name == sculptureName) return static_cast<int>(i);
    return -1;
}

int Garden::findMorph(const std::string& resultName) const {
    for (std::size_t i = 0; i < morphs.size(); ++i)
        if (morphs[i].resultName == resultName) return static_cast<int>(i);
    return -1;
}

std::size_t GardenLoad::missingCount() const {
    std::size_t n = 0;
    for (const auto& s : sculptures) n += s.ok() ? 0 : 1;
    return n;
}

Garden parseGarden(const std::string& text, const std::string& file, const std::string& folder) {
    json doc = parseStrictJson(text);
    ObjectReader top(doc, "$",
                     {"version", "name", "ground", "materials", "sculptures", "paths", "morph", "morphs", "lights", "start"});
    top.finish();
    Garden g;
    g.file = file;
    g.folder = folder;
    const json& version = top.required("version");
    g.version = readInt(version, top.pathOf("version"), 1, 1 << 20);
    if (g.version != kVersion)
        throw JsonError(top.pathOf("version"), "unsupported version " + std::to_string(g.version) +
                                                   " (this program reads version " + std::to_string(kVersion) + ")");
    if (auto* x = top.optional("name")) g.name = readString(*x, top.pathOf("name"), true);

    Reader r;
    r.file = file;
    r.folder = folder;
    if (auto* x = top.optional("materials")) {
        std::string at = top.pathOf("materials");
        if (!x->is_object()) throw JsonError(at, "expected an object of named materials");
        for (auto it = x->begin(); it != x->end(); ++it) {
            Material m = readMaterialObject(it.value(), childPath(at, it.key()), it.key());
            r.materials[it.key()] = m;
            g.materials.push_back(m);
        }
    }
    const Material stone{};  // the default: grey, half rough
    Material lawn;
    lawn.color = {0.18f, 0.32f, 0.12f};
    lawn.roughness = 0.9f;
    g.ground.material = lawn;
    if (auto* x = top.optional("ground")) g.ground = Reader::ground(*x, top.pathOf("ground"), r, lawn);

    if (auto* x = top.optional("sculptures")) {
        std::string at = top.pathOf("sculptures");
        if (!x->is_array()) throw JsonError(at, "expected an array of sculptures");
        for (std::size_t i = 0; i < x->size(); ++i) {
            std::string here = indexPath(at, i);
            SculptureSpec s = r.sculpture((*x)[i], here, stone);
            int before = g.findSculpture(s.name);
            if (before >= 0)
                throw JsonError(childPath(here, "name"), "'" + s.name + "' is already the name of " +
                                                             indexPath(at, static_cast<std::size_t>(before)));
            g.sculptures.push_back(std::move(s));
        }
    }
    if (auto* x = top.optional("paths")) {
        std::string at = top.pathOf("paths");
        if (!x->is_array()) throw JsonError(at, "expected an array of paths");
        Material gravel;
        gravel.color = {0.55f, 0.52f, 0.47f};
        gravel.roughness = 1.0f;
        for (std::size_t i = 0; i < x->size(); ++i) g.paths.push_back(r.path((*x)[i], indexPath(at, i), gravel));
    }
    // One morph ($.morph) or several ($.morphs), each with its own triangle and result.
    if (auto* x = top.optional("morph")) {
        if (top.optional("morphs")) throw JsonError(top.pathOf("morphs"), "give $.morph or $.morphs, not both");
        g.morphs.push_back(r.morph(*x, top.pathOf("morph"), g, stone));
    }
    if (auto* x = top.optional("morphs")) {
        std::string at = top.pathOf("morphs");
        if (!x->is_array()) throw JsonError(at, "expected an array of morphs");
        for (std::size_t i = 0; i < x->size(); ++i) g.morphs.push_back(r.morph((*x)[i], indexPath(at, i), g, stone));
    }
    if (auto* x = top.optional("lights")) {
        std::string at = top.pathOf("lights");
        if (!x->is_array()) throw JsonError(at, "expected an array of lights");
        for (std::size_t i = 0; i < x->size(); ++i) g.lights.push_back(Reader::light((*x)[i], indexPath(at, i)));
    } else {
        g.lights = defaultLights();
    }
    if (auto* x = top.optional("start")) g.start = Reader::start(*x, top.pathOf("start"));
    return g;
}

namespace {

SculptureLoad sculptureFrom(ModelFile mf, const SculptureSpec& spec) {
    SculptureLoad s;
    s.program = std::move(mf.program);
    s.error = std::move(mf.error);
    if (!mf.model) return s;
    int aSize = mf.model->body().aSize();
    if (spec.a.size() > static_cast<std::size_t>(aSize)) {
        s.error = (spec.file.empty() ? spec.fileAsWritten : spec.file) + ": error: " + std::to_string(spec.a.size()) + " values given for a[], but body '" +
                  mf.model->body().spelling + "' declares a[" + std::to_string(aSize) + "]\n";
        return s;
    }
    s.model = std::move(mf.model);
    return s;
}

// A scanned volume read and its iso-value checked against the samples (the
// level set itself is built when the sculpture is sampled).
SculptureLoad loadScan(const SculptureSpec& spec) {
    const ScanSpec& scan = *spec.scan;
    SculptureLoad s;
    auto volume = std::make_shared<voxel::ScalarVolume>();
    std::string why;
    if (scan.format == ScanSpec::Format::Vdb) {
        why = voxel::readScalarVdb(spec.file, scan.grid, *volume);
    } else {
        voxel::RawVolumeLayout layout;
        layout.dims = scan.dims;
        layout.type = scan.sixteenBit ? voxel::SampleType::U16 : voxel::SampleType::U8;
        layout.spacing = scan.spacing;
        why = voxel::readRawVolume(spec.file, layout, *volume);
    }
    if (why.empty() && !(scan.iso > volume->minValue && scan.iso < volume->maxValue))
        why = "iso " + formatNumber(scan.iso) + " is outside the data's range (" + formatNumber(volume->minValue) +
              " to " + formatNumber(volume->maxValue) + "): it must lie strictly between the lowest and the highest sample";
    if (!why.empty()) {
        s.error = scan.at + ": " + why + "\n";
        return s;
    }
    s.scan = std::move(volume);
    return s;
}

}  // namespace

// A mesh read (the level set is built when the sculpture is sampled).
SculptureLoad loadMesh(const SculptureSpec& spec) {
    SculptureLoad s;
    poly::MeshReadResult read = poly::readMeshFile(spec.file);
    if (!read.error.empty()) {
        s.error = spec.mesh->at + ": " + read.error + "\n";
        return s;
    }
    s.mesh = std::make_shared<const poly::Mesh>(std::move(read.mesh));
    return s;
}

SculptureLoad loadSculpture(const SculptureSpec& spec) {
    if (spec.scan) return loadScan(spec);
    if (spec.mesh) return loadMesh(spec);
    return sculptureFrom(loadModelFile(spec.file, spec.body, spec.a), spec);
}

SculptureLoad sculptureFromText(const SculptureSpec& spec, const std::string& text) {
    return sculptureFrom(modelFromText(text, spec.fileAsWritten, spec.body, spec.a), spec);
}

GardenLoad loadGarden(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        GardenLoad load;
        load.errorReason = std::string("cannot open the garden file: ") + std::strerror(errno);
        load.error = path + ": " + load.errorReason;
        return load;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return loadGardenText(text.str(), path);
}

GardenLoad loadGardenText(const std::string& text, const std::string& path) {
    GardenLoad load;
    std::string folder = std::filesystem::path(path).parent_path().string();
    if (folder.empty()) folder = ".";
    try {
        load.garden = parseGarden(text, path, folder);
    } catch (const JsonError& e) {
        load.errorPath = e.path();
        load.errorReason = e.reason();
        load.error = path + ": " + e.what();
        return load;
    }
    // Sculptures with the same file, body and a[] share one parse (a
    // generated garden of a thousand copies reads each file once).
    std::map<std::string, std::size_t> first;
    for (const auto& spec : load.garden->sculptures) {
        std::ostringstream key;
        key.precision(17);
        key << spec.file << '\n' << spec.body;
        for (double a : spec.a) key << ' ' << a;
        if (spec.mesh) key << "\nmesh";
        if (const auto& c = spec.scan)
            key << '\n' << c->grid << ' ' << c->dims[0] << ' ' << c->dims[1] << ' ' << c->dims[2] << ' ' << c->sixteenBit
                << ' ' << c->spacing[0] << ' ' << c->spacing[1] << ' ' << c->spacing[2] << ' ' << c->iso << ' '
                << c->insideAbove;
        const auto [it, fresh] = first.emplace(key.str(), load.sculptures.size());
        load.sculptures.push_back(fresh ? loadSculpture(spec) : load.sculptures[it->second]);
    }
    // Each morph's result shows its reason as the sculpture's error (named by its result).
    for (const MorphSpec& m : load.garden->morphs) {
        std::string& why = load.morphErrors.emplace_back();
        for (std::size_t i = 0; i < 3 && why.empty(); ++i) {
            const SculptureLoad& source = load.sculptures[m.sourceIndex[i]];
            const std::string named = "morph source '" + m.sources[i] + "'";
            if (!source.ok())
                why = named + " is missing, so there is no metamorphosis";
            else if (source.scan)
                why = named + " is a scanned volume; the metamorphosis blends HyperFun sculptures, so there is none";
            else if (source.mesh)
                why = named + " is a mesh; the metamorphosis blends HyperFun sculptures, so there is none";
        }
    }
    return load;
}

}  // namespace hg::garden
