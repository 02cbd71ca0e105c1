// The inflated solid's field at a world point, written once over the value
// type V with the operations `ops` supplies (max, min, sqrt), so that the
// same steps run on double (the tests' and the fitting's reference), and
// can run on the edit list's symbolic type when the sketch becomes an edit.
// inflation_text.cpp writes exactly these operations, in this order, as
// HyperFun; on double with HyperFun's min and max (DoubleOps) the parsed
// text gives the same values.
#pragma once

#include "frep/language/hf_math.h"
#include "garden/sketch/inflation.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace hg::garden::sketch {

// HyperFun's built-ins on double (frep/language/hf_math.h: max(p, q) is p > q ? p : q).
struct DoubleOps {
    double max(double p, double q) const { return frep::hf::maximum(p, q); }
    double min(double p, double q) const { return frep::hf::minimum(p, q); }
    double sqrt(double p) const { return std::sqrt(p); }
};

// Constants are written as plain decimals with 12 digits after the point
// (a picometre: far below any sculpture's detail) and the field uses the
// value HyperFun's lexer reads from that text, so the C++ field and the
// parsed text agree bit for bit. frep::writeNumber would keep every bit of
// the original double, but searching for its spelling costs about 18 us a
// number, most of a frame for a few hundred pieces.
inline std::string hfDecimal(double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.12f", std::fabs(v));
    std::string s = b;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    if (s != "0" && v < 0.0) s = "-" + s;
    return s;
}

// The value frep's lexer gives a plain decimal (frep/language/lexer.cpp): the
// integer digits accumulated as value * 10 + d, then each fraction digit
// added as d / 10^k.
inline double hfLexedValue(const std::string& s) {
    size_t i = s[0] == '-' ? 1 : 0;
    double value = 0.0;
    for (; i < s.size() && s[i] != '.'; ++i) value = value * 10.0 + (s[i] - '0');
    double scale = 10.0;
    for (++i; i < s.size(); ++i) {
        value = value + (s[i] - '0') / scale;
        scale = scale * 10.0;
    }
    return s[0] == '-' ? -value : value;
}

inline double hfConstant(double v) { return hfLexedValue(hfDecimal(v)); }

// The per-piece constants, computed once in double; the field uses each
// through hfConstant, the text writes it with hfDecimal.
struct PieceConstants {
    double ax, ay, dx, dy, invLength2, ra, dr;
    bool point;
};

inline PieceConstants pieceConstants(const ConePiece& c) {
    PieceConstants k{};
    k.ax = c.a.x;
    k.ay = c.a.y;
    k.dx = c.b.x - c.a.x;
    k.dy = c.b.y - c.a.y;
    const double l2 = k.dx * k.dx + k.dy * k.dy;
    k.point = !(l2 > 0.0);
    k.invLength2 = k.point ? 0.0 : 1.0 / l2;
    k.ra = c.ra;
    k.dr = c.rb - c.ra;
    return k;
}

// The factor on the normal coordinate: 1 / thickness.
inline double normalScale(const InflatedSolid& s) { return 1.0 / s.thickness; }

// One piece at plane coordinates (u, v) and squared scaled normal
// coordinate ww.
template <class V, class Ops>
V pieceField(const V& u, const V& v, const V& ww, const PieceConstants& k, const Ops& ops) {
    if (k.point) {
        const V ex = u - V(hfConstant(k.ax));
        const V ey = v - V(hfConstant(k.ay));
        return V(hfConstant(k.ra)) - ops.sqrt(ex * ex + ey * ey + ww);
    }
    const V ax(hfConstant(k.ax)), ay(hfConstant(k.ay)), dx(hfConstant(k.dx)), dy(hfConstant(k.dy));
    V t = ((u - ax) * dx + (v - ay) * dy) * V(hfConstant(k.invLength2));
    t = ops.max(ops.min(t, V(1.0)), V(0.0));
    const V ex = u - ax - t * dx;
    const V ey = v - ay - t * dy;
    return V(hfConstant(k.ra)) + t * V(hfConstant(k.dr)) - ops.sqrt(ex * ex + ey * ey + ww);
}

// The solid's field at the world point (x, y, z): >= 0 inside, about minus
// the distance outside (for thickness 1).
template <class V, class Ops>
V inflatedField(const V& x, const V& y, const V& z, const InflatedSolid& s, const Ops& ops) {
    const SketchPlane& p = s.plane;
    const auto c = [](double value) { return V(hfConstant(value)); };
    const V px = x - c(p.origin.x);
    const V py = y - c(p.origin.y);
    const V pz = z - c(p.origin.z);
    const V u = px * c(p.u.x) + py * c(p.u.y) + pz * c(p.u.z);
    const V v = px * c(p.v.x) + py * c(p.v.y) + pz * c(p.v.z);
    const V w = (px * c(p.normal.x) + py * c(p.normal.y) + pz * c(p.normal.z)) * c(normalScale(s));
    const V ww = w * w;
    V f = pieceField(u, v, ww, pieceConstants(s.pieces.front()), ops);
    for (size_t i = 1; i < s.pieces.size(); ++i) f = ops.max(f, pieceField(u, v, ww, pieceConstants(s.pieces[i]), ops));
    return f;
}

inline double inflatedValue(const InflatedSolid& s, const Vec3& p) {
    return inflatedField<double>(p.x, p.y, p.z, s, DoubleOps{});
}

}  // namespace hg::garden::sketch
