// hf_text.h first: the edit templates must see its overloads (see there).
#include "garden/export/hf_text.h"

#include "garden/export/hyperfun_export.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "frep/language/parser.h"
#include "frep/language/writer.h"
#include "garden/app/garden_session.h"
#include "garden/export/export_field.h"
#include "garden/morph/morph_sources.h"
#include "garden/sculpt/edit_field.h"
#include "garden/sculpt/sculpture_edits.h"
#include "io/checked_write.h"

namespace hg::garden {

namespace {

using hfexport::HfStatements;
using hfexport::HfText;

// Syntax nodes of a typical statement of my_model (`t3 = min(t2, 3);`:
// the statement, the call, two operands), as our parser counts them.
constexpr std::size_t kNodesPerStatement = 4;

// Numbers in comments: short, for people (the code itself is exact).
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string vec(const std::array<double, 3>& v) { return "(" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + ")"; }

std::string list(const std::vector<double>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(v[i]);
    return s + "]";
}

std::string mirrorText(const std::optional<MirrorPlane>& m) {
    return m ? ", mirrored across the plane through " + vec(m->point) + " with normal " + vec(m->normal) : "";
}

// What an edit is, for the comment above its statements.
std::string describeEdit(const Edit& e) {
    std::string s = "edit " + std::to_string(e.id) + " (creation order): ";
    if (const auto* st = std::get_if<Stroke>(&e.op)) {
        s += std::string(strokeToolName(st->tool)) + " stroke, radius " + num(st->radius) + " model units";
        if (st->tool == StrokeTool::Melt) s += ", softness " + num(st->softness) + " voxels";
        const bool capsule = st->tool == StrokeTool::Smooth || st->tool == StrokeTool::Inflate;
        if (capsule)
            s += std::string(", strength ") + num(st->strength) + (st->tool == StrokeTool::Inflate ? " voxels" : "") +
                 ", " + falloffName(st->falloff) + " falloff";
        s += ", " + std::to_string(st->path.size()) + " path points, " + std::to_string(st->segments.size()) +
             (capsule ? st->tool == StrokeTool::Smooth ? " capsule segments, each blending towards its fitted quadric"
                                                       : " capsule segments"
                      : " convolution segments (hfConvLine)") +
             mirrorText(st->mirror);
    } else if (const auto* k = std::get_if<SketchSolid>(&e.op)) {
        s += std::string("sketch ") + (k->mode == SketchMode::Add ? "joined" : "cut") + ": an outline of " +
             std::to_string(k->outline.size()) + " points inflated to " + std::to_string(k->solid.pieces.size()) +
             " cone pieces along its chordal axis, thickness " + num(k->thickness) + mirrorText(k->mirror);
    } else if (const auto* m = std::get_if<ImpactSeries>(&e.op)) {
        s += std::to_string(m->impacts.size()) + " impacts";
        if (!m->impacts.empty())
            s += " of a " + std::string(impactShapeName(m->impacts[0].shape)) + " tool, size " +
                 num(m->impacts[0].size) + " model units";
    } else {
        const auto& p = std::get<Perturbation>(e.op);
        s += std::string(p.shape == QuadricShape::Ellipsoid ? "ellipsoid" : "torus") + " perturbation at " +
             vec(p.center) + ", radii " + vec(p.radii) + ", strength " + num(p.strength) + " voxels" +
             mirrorText(p.mirror);
    }
    return s;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return s;
}

// Bodies 0 .. model.bodyIndex() of the model's program (a body calls only
// bodies above it), each renamed prefix + its name; the model's own body is
// named `own` instead when that is given. Sets `callee` to the model's body's
// new name.
std::string renamedBodies(const frep::Model& model, const std::string& prefix, const std::string& own,
                          const std::string& label, std::string& callee) {
    // A mutable copy: the program written and read back (the writer's text
    // parses to the same program).
    frep::ParseResult r = frep::parseProgram(frep::writeProgram(model.program()), model.program().file);
    if (!r.ok()) throw std::runtime_error("the source " + label + " cannot be written back as HyperFun");
    frep::Program& p = *r.program;
    const int last = model.bodyIndex();
    std::set<std::string> names;
    for (int i = 0; i <= last; ++i) {
        frep::Body& b = p.bodies[static_cast<std::size_t>(i)];
        b.spelling = i == last && !own.empty() ? own : prefix + b.spelling;
        b.name = lower(b.spelling);
        names.insert(b.name);
    }
    callee = p.bodies[static_cast<std::size_t>(last)].spelling;
    std::string out;
    for (int i = 0; i <= last; ++i) {
        const frep::Body& b = p.bodies[static_cast<std::size_t>(i)];
        for (const auto& v : b.variables)
            if (names.count(v.name))
                throw std::runtime_error("the source " + label + ": variable '" + v.spelling + "' of body '" +
                                         b.spelling + "' has the name a body is renamed to");
        for (const auto& v : b.arrays)
            if (names.count(v.name))
                throw std::runtime_error("the source " + label + ": array '" + v.spelling + "' of body '" +
                                         b.spelling + "' has the name a body is renamed to");
        out += "-- from " + label + (i == last ? "" : " (called by the body below)") + "\n";
        out += frep::writeBody(b, p);
        out += "\n";
    }
    return out;
}

// A body being written: its statements, and the arrays it declares.
struct BodyWriter {
    HfStatements st;
    std::vector<std::string> arrays;  // "name[size]"

    bool declaresS = false;  // the body resets its own s[1] between calls
    int calls = 0;

    // A call of a source body with the garden's a[] (array `aName`) and
    // s[] at 0, as a Model evaluates it: a body that declares s[] gets a
    // fresh array `sName`, as the conformance suite's sarray.hf passes it;
    // one that does not gets the caller's s[1] (it can change it only
    // through bodies it calls), set back to 0 before every call but the
    // body's first.
    HfText callSource(const frep::Model& m, const std::string& callee, const std::string& aName,
                      const std::string& sName) {
        const frep::Body& b = m.body();
        if (b.xSize() != 3) throw std::runtime_error("the source body '" + b.spelling + "' does not declare x[3]");
        std::vector<double> a(static_cast<std::size_t>(b.aSize()), 0.0);
        for (std::size_t i = 0; i < a.size() && i < m.parameters().size(); ++i) a[i] = m.parameters()[i];
        arrays.push_back(aName + "[" + std::to_string(a.size()) + "]");
        hfexport::fillArray(st, aName, a);
        std::string args = "x, " + aName;
        if (b.declaresS) {
            arrays.push_back(sName + "[" + std::to_string(b.sSize()) + "]");
            hfexport::fillArray(st, sName, std::vector<double>(static_cast<std::size_t>(b.sSize()), 0.0));
            args += ", " + sName;
        } else if (calls > 0) {
            declaresS = true;
            st.statement("s = [0]");
        }
        ++calls;
        return HfText::assign(st, callee + "(" + args + ")");
    }

    std::string finish(const std::string& name, const HfText& result) const {
        std::string out = name + (declaresS ? "(x[3], a[1], s[1])\n{\n" : "(x[3], a[1])\n{\n");
        std::vector<std::string> all = arrays;
        if (st.usesSegmentArrays()) {
            all.push_back(std::string(hfexport::kSegmentBegin) + "[3]");
            all.push_back(std::string(hfexport::kSegmentEnd) + "[3]");
            all.push_back(std::string(hfexport::kSegmentWidth) + "[1]");
        }
        if (!all.empty()) {
            out += "   array ";
            for (std::size_t i = 0; i < all.size(); ++i) out += (i ? ", " : "") + all[i];
            out += ";\n";
        }
        out += st.text();
        out += "   " + name + " = " + result.operand() + ";\n}\n";
        return out;
    }
};

// `index` into the garden's sculptures (Sculpture::source.spec).
const frep::Model& modelOf(const GardenSession& session, std::size_t index) {
    const SculptureLoad& l = session.load().sculptures.at(index);
    if (!l.model)
        throw std::runtime_error("sculpture '" + session.garden().sculptures.at(index).name + "' has no program");
    return *l.model;
}

std::string sourceLabel(const SculptureSpec& spec, const frep::Model& m) {
    return "'" + spec.fileAsWritten + "', body '" + m.body().spelling + "' with a = " + list(m.parameters()) +
           " (sculpture '" + spec.name + "')";
}

// Morph result `result`'s blend as a body named `name`, after its sources'
// bodies; `statements` receives the blend body's count.
std::string morphBodies(const GardenSession& session, int result, const std::string& name, std::size_t& statements) {
    const MorphSpec& spec = *session.morphSpec(result);
    const MorphSources* sources = session.morphSources(result);
    const auto& weights = session.morphWeights(result);
    if (!sources || !weights) throw std::runtime_error("the morph has no sources or weights");
    std::string out;
    BodyWriter w;
    std::array<HfText, 3> f;
    for (std::size_t i = 0; i < 3; ++i) {
        const frep::Model& m = modelOf(session, spec.sourceIndex[i]);
        const std::string n = std::to_string(i + 1);
        std::string callee;
        out += renamedBodies(m, "m" + n + "_", "", sourceLabel(session.garden().sculptures[spec.sourceIndex[i]], m),
                             callee);
        f[i] = w.callSource(m, callee, "ma" + n, "ms" + n);
    }
    MorphBlendConstants c;
    c.normalization = sources->normalization;
    c.w = weights->w;
    c.band = sources->frame.band;
    w.st.comment("the blend: clamp(w1 F1 + w2 F2 + w3 F3, -band, band), F_i = f_i * normalization_i, all at x");
    w.st.comment("barycentric " + vec(weights->barycentric) + ", balancing factors " + vec(weights->balance) +
                 ", weights w " + vec(c.w));
    w.st.comment("normalizations " + vec(c.normalization) + " voxels per unit of f, band " + num(c.band) + " voxels");
    const HfText blend = morphBlendField(f[0], f[1], f[2], c);
    out += "-- the metamorphosis of '" + spec.sources[0] + "', '" + spec.sources[1] + "' and '" + spec.sources[2] +
           "'\n";
    out += w.finish(name, blend);
    out += "\n";
    statements = w.st.statementCount();
    return out;
}

HyperFunExport exportOrThrow(const GardenSession& session, int index, const SelectionMask* part) {
    HyperFunExport r;
    if (index < 0 || index >= static_cast<int>(session.sculptures().size()))
        throw std::runtime_error("no sculpture with index " + std::to_string(index));
    const Sculpture& s = session.sculptures()[static_cast<std::size_t>(index)];
    if (s.removed) throw std::runtime_error("sculpture '" + s.name + "' was removed");
    if (s.missing()) throw std::runtime_error("sculpture '" + s.name + "' is missing: " + s.error);
    if (!s.volume) throw std::runtime_error("sculpture '" + s.name + "' has no grid");
    if (s.gridOnly()) throw std::runtime_error(scanRefusal(session, s));
    // A part is written as an edited sculpture is, in voxels, then cut to the mask.
    const bool edited = (s.edits && !s.edits->list().empty()) || part;
    const FieldUnits units = s.edits ? s.edits->units() : unitsOf(*s.volume);
    const voxel::VolumeFrame& frame = s.volume->frame;

    std::ostringstream head;
    head << "-- Hypergarden export of sculpture '" << s.name << "' of garden '" << session.garden().name << "'\n"
         << "-- my_model is the sculpture in its model frame. Its placement in the garden:\n"
         << "--   position " << vec(s.placement.position) << " m, turned " << num(s.placement.yawDegrees)
         << " degrees about +y, " << num(s.placement.scale) << " m per model unit.\n"
         << "-- Model box " << vec({frame.modelBox.lo[0], frame.modelBox.lo[1], frame.modelBox.lo[2]}) << " to "
         << vec({frame.modelBox.hi[0], frame.modelBox.hi[1], frame.modelBox.hi[2]}) << ",\n"
         << "--   grid of " << frame.resolution << " voxels along its longest side (voxel size "
         << num(frame.voxelSize) << ").\n";
    if (s.mirror)
        head << "-- Mirror plane for new edits: through " << vec(s.mirror->point) << ", normal "
             << vec(s.mirror->normal) << ".\n";
    if (!edited)
        head << "-- Unedited: my_model " << (s.morphResult() ? "is the morph's blend" : "evaluates as the source body")
             << ".\n";
    else
        head << "-- Edited: my_model is the grid's field in voxels, clamped to +-" << num(units.band)
             << ",\n--   after " << (s.edits ? s.edits->list().size() : 0) << " edits, in order.\n";
    if (part)
        head << "-- A part: the sculpture inside a selection of " << part->balls.size()
             << " balls (min with the balls' field in voxels).\n";
    std::string out = head.str() + "\n";

    std::string base;  // the body the edits start from
    BodyWriter w;
    HfText f;
    if (s.morphResult()) {
        out += morphBodies(session, index, edited ? "hg_morph" : "my_model", r.statements);
        if (!edited) {
            r.text = out;
            return r;
        }
        w.st.comment("the morph's blend (clamped to +-band)");
        f = HfText::assign(w.st, "hg_morph(x, a)");
    } else {
        const frep::Model& m = modelOf(session, static_cast<std::size_t>(s.source.spec));
        const SculptureSpec& spec = session.garden().sculptures.at(static_cast<std::size_t>(s.source.spec));
        // Unedited and without a[]: the source body itself is my_model.
        const bool itself = !edited && m.parameters().empty();
        std::string callee;
        out += renamedBodies(m, "src_", itself ? "my_model" : "", sourceLabel(spec, m), callee);
        if (itself) {
            r.text = out;
            return r;
        }
        w.st.comment("the source with the garden's a[]");
        f = w.callSource(m, callee, "sa", "ss");
        if (!edited) {
            r.text = out + w.finish("my_model", f);
            r.statements = w.st.statementCount();
            return r;
        }
        const double normalization = s.edits ? s.edits->base().normalization : s.volume->normalization;
        w.st.comment("the grid's field: clamp(f * " + num(normalization) + ", -band, band), in voxels");
        f = normalizedSourceField(f, normalization, units.band);
    }
    const HfText x = HfText::named(w.st, "x[1]"), y = HfText::named(w.st, "x[2]"), z = HfText::named(w.st, "x[3]");
    if (s.edits) {
        const EditList& edits = s.edits->list();
        for (const EditPick& pick : edits.all()) {
            const Edit& e = edits.edits()[pick.edit];
            w.st.comment(describeEdit(e));
            f = applyEdit(f, x, y, z, e, pick.pieces, edits.units());
            ++r.edits;
            r.pieces += pick.pieces.size();
        }
    }
    if (part) {
        w.st.comment("inside the selection");
        f = insideMask(f, x, y, z, *part, units);
    }
    out += "-- the edited sculpture\n";
    out += w.finish("my_model", f);
    r.statements = w.st.statementCount();
    r.text = std::move(out);
    if (r.statements * kNodesPerStatement > frep::ParseLimits::kMaxNodes)
        r.warning = std::to_string(r.statements) + " statements: more than our parser reads in one program (" +
                    std::to_string(frep::ParseLimits::kMaxNodes) + " syntax nodes, about " +
                    std::to_string(frep::ParseLimits::kMaxNodes / kNodesPerStatement) + " statements)";
    return r;
}

}  // namespace

HyperFunExport exportHyperFunPart(const GardenSession& session, int sculpture, const SelectionMask& mask) {
    try {
        return exportOrThrow(session, sculpture, &mask);
    } catch (const std::exception& e) {
        HyperFunExport r;
        r.error = e.what();
        return r;
    }
}

std::string scanRefusal(const GardenSession& session, const Sculpture& s) {
    const SculptureSpec& spec = session.garden().sculptures.at(static_cast<std::size_t>(s.source.spec));
    const char* what = s.meshed() ? "a mesh" : "a scanned volume";
    const char* thing = s.meshed() ? "a mesh" : "a volume";
    return "sculpture '" + s.name + "' is made from " + what + " (" + spec.fileAsWritten +
           "), and HyperFun has no way to read " + thing + ", so it cannot be written as exact HyperFun; export it as a "
           "mesh or a level set instead (.stl, .obj, .glb or .vdb), made from its grid";
}

HyperFunExport exportHyperFun(const GardenSession& session, int sculpture) {
    try {
        return exportOrThrow(session, sculpture, nullptr);
    } catch (const std::exception& e) {
        HyperFunExport r;
        r.error = e.what();
        return r;
    }
}

std::string writeHyperFunExport(const HyperFunExport& r, const std::string& path) {
    if (!r.error.empty()) return r.error;
    return io::writeFileAtomically(path, r.text, io::WriteSite::Export);
}

std::string exportSculptureHyperFun(const GardenSession& session, int sculpture, const std::string& path) {
    return writeHyperFunExport(exportHyperFun(session, sculpture), path);
}

}  // namespace hg::garden
