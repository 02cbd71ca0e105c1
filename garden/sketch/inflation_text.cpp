#include "garden/sketch/inflation_text.h"

#include <memory>

#include "frep/language/parser.h"
#include "garden/sketch/inflation_field.h"

namespace hg::garden::sketch {

namespace {

// A constant as an operand (inflation_field.h's hfDecimal, the spelling
// whose lexed value the C++ field uses), negative ones in parentheses so
// that `u - (-0.5)` never turns into a `--` comment.
std::string num(double v) {
    std::string s = hfDecimal(v);
    return s[0] == '-' ? "(" + s + ")" : s;
}

}  // namespace

std::string inflatedHyperFun(const InflatedSolid& s, const std::string& name) {
    const SketchPlane& p = s.plane;
    int spokes = 0;
    for (const ConePiece& c : s.pieces) spokes += c.spoke;
    std::string out;
    out += "-- A sketched solid (garden/sketch/inflation.h): the union of " + std::to_string(s.pieces.size()) +
           " pieces\n";
    out += "-- along the chordal axis of a sketched outline (" + std::to_string(spokes) + " of them spokes to its corners).\n";
    out += "-- A piece is a segment of the sketch plane with radii growing linearly from its start\n";
    out += "-- to its end; its value is that radius minus the distance to the segment, the normal\n";
    out += "-- coordinate divided by the thickness factor " + hfDecimal(s.thickness) + ".\n";
    out += name + "(x[3], a[1])\n{\n";
    out += "   px = x[1] - " + num(p.origin.x) + ";\n";
    out += "   py = x[2] - " + num(p.origin.y) + ";\n";
    out += "   pz = x[3] - " + num(p.origin.z) + ";\n";
    out += "   -- plane coordinates u, v and the scaled normal coordinate w\n";
    out += "   u = px * " + num(p.u.x) + " + py * " + num(p.u.y) + " + pz * " + num(p.u.z) + ";\n";
    out += "   v = px * " + num(p.v.x) + " + py * " + num(p.v.y) + " + pz * " + num(p.v.z) + ";\n";
    out += "   w = (px * " + num(p.normal.x) + " + py * " + num(p.normal.y) + " + pz * " + num(p.normal.z) + ") * " +
           num(normalScale(s)) + ";\n";
    out += "   ww = w * w;\n";
    bool first = true;
    for (const ConePiece& c : s.pieces) {
        const PieceConstants k = pieceConstants(c);
        std::string value;
        if (k.point) {
            out += "   ex = u - " + num(k.ax) + ";\n";
            out += "   ey = v - " + num(k.ay) + ";\n";
            value = num(k.ra) + " - sqrt(ex * ex + ey * ey + ww)";
        } else {
            out += "   t = ((u - " + num(k.ax) + ") * " + num(k.dx) + " + (v - " + num(k.ay) + ") * " + num(k.dy) +
                   ") * " + num(k.invLength2) + ";\n";
            out += "   t = max(min(t, 1), 0);\n";
            out += "   ex = u - " + num(k.ax) + " - t * " + num(k.dx) + ";\n";
            out += "   ey = v - " + num(k.ay) + " - t * " + num(k.dy) + ";\n";
            value = num(k.ra) + " + t * " + num(k.dr) + " - sqrt(ex * ex + ey * ey + ww)";
        }
        out += first ? "   f = " + value + ";\n" : "   f = max(f, " + value + ");\n";
        first = false;
    }
    out += "   " + name + " = f;\n}\n";
    return out;
}

std::optional<frep::Model> compileHyperFun(const std::string& text, std::string& error) {
    frep::ParseResult parsed = frep::parseProgram(text, "sketch.hf");
    if (!parsed.ok()) {
        error.clear();
        for (const auto& d : parsed.errors) error += frep::formatDiagnostic(d);
        if (error.empty()) error = "the sketch's HyperFun text did not parse\n";
        return std::nullopt;
    }
    auto program = std::make_shared<const frep::Program>(std::move(*parsed.program));
    return frep::Model(program, program->defaultBody());
}

}  // namespace hg::garden::sketch
