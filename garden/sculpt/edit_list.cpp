#include "garden/sculpt/edit_list.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "frep/compiler/tape_builder.h"
#include "garden/sculpt/edit_field.h"

namespace hg::garden {

namespace {

bool overlaps(const frep::Box3& a, const frep::Box3& b) {
    for (int i = 0; i < 3; ++i)
        if (a.hi[i] < b.lo[i] || b.hi[i] < a.lo[i]) return false;
    return true;
}

frep::Box3 hull(const frep::Box3& a, const frep::Box3& b) {
    frep::Box3 r;
    for (int i = 0; i < 3; ++i) {
        r.lo[i] = std::min(a.lo[i], b.lo[i]);
        r.hi[i] = std::max(a.hi[i], b.hi[i]);
    }
    return r;
}

}  // namespace

std::size_t pieceCount(const Edit& e) {
    if (const auto* s = std::get_if<Stroke>(&e.op)) return s->segments.size();
    if (const auto* m = std::get_if<ImpactSeries>(&e.op)) return m->impacts.size();
       if (const auto* k = std::get_if<SketchSolid>(&e.op)) return k->reach.size();
    return std::get<Perturbation>(e.op).mirror ? 2 : 1;
}

ModelPoint reflect(const MirrorPlane& m, const ModelPoint& p) {
    const double d = (p[0] - m.point[0]) * m.normal[0] + (p[1] - m.point[1]) * m.normal[1] + (p[2] - m.point[2]) * m.normal[2];
    return {p[0] - 2.0 * d * m.normal[0], p[1] - 2.0 * d * m.normal[1], p[2] - 2.0 * d * m.normal[2]};
}

ModelPoint reflectDirection(const MirrorPlane& m, const ModelPoint& v) {
    const double d = v[0] * m.normal[0] + v[1] * m.normal[1] + v[2] * m.normal[2];
    return {v[0] - 2.0 * d * m.normal[0], v[1] - 2.0 * d * m.normal[1], v[2] - 2.0 * d * m.normal[2]};
}

Perturbation mirrored(const Perturbation& p) {
    Perturbation m = p;
    m.mirror.reset();
    m.center = reflect(*p.mirror, p.center);
    for (auto& a : m.axes) a = reflectDirection(*p.mirror, a);
    return m;
}

frep::Box3 perturbationReach(const Perturbation& p) {
    frep::Box3 b;
    for (int j = 0; j < 3; ++j) {
        double half = 0.0;
        if (p.shape == QuadricShape::Ellipsoid) {
            // The ellipsoid's exact extent along axis j.
            for (int i = 0; i < 3; ++i) half += p.radii[i] * p.radii[i] * p.axes[i][j] * p.axes[i][j];
            half = std::sqrt(half);
        } else {
            half = p.radii[0] + p.radii[1];
        }
        b.lo[j] = p.center[j] - half * 1.001;
        b.hi[j] = p.center[j] + half * 1.001;
    }
    return b;
}

namespace {

frep::Box3 unmaskedReach(const Edit& e, std::size_t piece) {
    if (const auto* s = std::get_if<Stroke>(&e.op)) return s->segments[piece].reach;
    if (const auto* m = std::get_if<ImpactSeries>(&e.op)) return m->impacts[piece].reach;
    if (const auto* k = std::get_if<SketchSolid>(&e.op)) return k->reach[piece];
    const auto& p = std::get<Perturbation>(e.op);
    return perturbationReach(piece == 0 ? p : mirrored(p));
}

}  // namespace

frep::Box3 pieceReach(const Edit& e, std::size_t piece) {
    frep::Box3 b = unmaskedReach(e, piece);
    if (!e.mask) return b;
    // Beyond the mask's box the masked edit returns the field before it.
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = std::max(b.lo[a], e.mask->box.lo[a]);
        b.hi[a] = std::max(b.lo[a], std::min(b.hi[a], e.mask->box.hi[a]));
    }
    return b;
}

EditList::EditList(FieldUnits units, double cellSize) : units_(units), cellSize_(cellSize) {
    if (!(cellSize > 0.0)) throw std::invalid_argument("EditList: the cell size must be positive");
}

EditList::CellKey EditList::key(std::int64_t i, std::int64_t j, std::int64_t k) {
    // 21 bits a coordinate, offset to be non-negative: cells of a few dozen
    // voxels never number a million along an axis.
    const auto f = [](std::int64_t v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffffu; };
    return f(i) | (f(j) << 21) | (f(k) << 42);
}

void EditList::cellRange(const frep::Box3& box, std::int64_t lo[3], std::int64_t hi[3]) const {
    for (int a = 0; a < 3; ++a) {
        lo[a] = static_cast<std::int64_t>(std::floor(box.lo[a] / cellSize_));
        hi[a] = static_cast<std::int64_t>(std::floor(box.hi[a] / cellSize_));
    }
}

void EditList::index(std::uint32_t edit, std::uint32_t piece, const frep::Box3& box) {
    std::int64_t lo[3], hi[3];
    cellRange(box, lo, hi);
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
        for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
            for (std::int64_t i = lo[0]; i <= hi[0]; ++i) cells_[key(i, j, k)].push_back({edit, piece, box});
    ++pieceCount_;
}

void EditList::append(Edit edit) {
    const auto e = static_cast<std::uint32_t>(edits_.size());
    edits_.push_back(std::move(edit));
    Edit& added = edits_.back();
    const std::size_t n = garden::pieceCount(added);
    for (std::size_t p = 0; p < n; ++p) {
        const frep::Box3 box = pieceReach(added, p);
        index(e, static_cast<std::uint32_t>(p), box);
        added.reach = p == 0 ? box : hull(added.reach, box);
    }
}

frep::Box3 EditList::extendLast(std::size_t firstPiece) {
    Edit& last = edits_.back();
    const auto e = static_cast<std::uint32_t>(edits_.size() - 1);
    frep::Box3 grown;
    const std::size_t n = garden::pieceCount(last);
    for (std::size_t p = firstPiece; p < n; ++p) {
        const frep::Box3 box = pieceReach(last, p);
        index(e, static_cast<std::uint32_t>(p), box);
        grown = p == firstPiece ? box : hull(grown, box);
        last.reach = hull(last.reach, box);
    }
    return grown;
}

Edit EditList::removeLast() {
    unindex(static_cast<std::uint32_t>(edits_.size() - 1));
    Edit out = std::move(edits_.back());
    edits_.pop_back();
    return out;
}

void EditList::unindex(std::uint32_t e) {
    const Edit& edit = edits_[e];
    for (std::size_t p = 0; p < garden::pieceCount(edit); ++p) {
        std::int64_t lo[3], hi[3];
        cellRange(pieceReach(edit, p), lo, hi);
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
            for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
                for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
                    auto it = cells_.find(key(i, j, k));
                    if (it == cells_.end()) continue;
                    auto& v = it->second;
                    v.erase(std::remove_if(v.begin(), v.end(), [e](const Piece& q) { return q.edit == e; }), v.end());
                    if (v.empty()) cells_.erase(it);
                }
        --pieceCount_;
    }
}

Edit EditList::replace(std::size_t at, Edit edit) {
    const auto e = static_cast<std::uint32_t>(at);
    unindex(e);
    Edit old = std::move(edits_[at]);
    edits_[at] = std::move(edit);
    Edit& added = edits_[at];
    for (std::size_t p = 0; p < garden::pieceCount(added); ++p) {
        const frep::Box3 box = pieceReach(added, p);
        index(e, static_cast<std::uint32_t>(p), box);
        added.reach = p == 0 ? box : hull(added.reach, box);
    }
    return old;
}

std::vector<EditPick> EditList::reaching(const frep::Box3& box) const {
    std::map<std::uint32_t, std::vector<std::uint32_t>> byEdit;
    std::int64_t lo[3], hi[3];
    cellRange(box, lo, hi);
    for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
        for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
            for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
                auto it = cells_.find(key(i, j, k));
                if (it == cells_.end()) continue;
                for (const Piece& p : it->second)
                    if (overlaps(p.box, box)) byEdit[p.edit].push_back(p.piece);
            }
    std::vector<EditPick> out;
    out.reserve(byEdit.size());
    for (auto& [edit, pieces] : byEdit) {
        std::sort(pieces.begin(), pieces.end());
        pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
        out.push_back({edit, std::move(pieces)});
    }
    return out;
}

std::vector<EditPick> EditList::all() const {
    std::vector<EditPick> out;
    for (std::size_t e = 0; e < edits_.size(); ++e) {
        EditPick pick{static_cast<std::uint32_t>(e), {}};
        for (std::size_t p = 0; p < garden::pieceCount(edits_[e]); ++p) pick.pieces.push_back(static_cast<std::uint32_t>(p));
        out.push_back(std::move(pick));
    }
    return out;
}

frep::Tape editTape(const EditList& list, const std::vector<EditPick>& picks) {
    frep::TapeBuilder b;
    const frep::Sym x(&b, b.x()), y(&b, b.y()), z(&b, b.z());
    frep::Sym f(&b, b.w());
    for (const EditPick& pick : picks) f = applyEdit(f, x, y, z, list.edits()[pick.edit], pick.pieces, list.units());
    return b.finish(f.on(b));
}

double editedValue(const EditList& list, double base, double x, double y, double z) {
    double f = base;
    for (const EditPick& pick : list.all()) f = applyEdit(f, x, y, z, list.edits()[pick.edit], pick.pieces, list.units());
    return f;
}

frep::Box3 maskBox(const std::vector<MaskBall>& balls, double margin) {
    frep::Box3 box;
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            const double lo = balls[i].centre[a] - balls[i].radius - margin;
            const double hi = balls[i].centre[a] + balls[i].radius + margin;
            box.lo[a] = i == 0 ? lo : std::min(box.lo[a], lo);
            box.hi[a] = i == 0 ? hi : std::max(box.hi[a], hi);
        }
    return box;
}

std::string describe(const Edit& e) {
    if (const auto* m = std::get_if<ImpactSeries>(&e.op))
        return std::to_string(m->impacts.size()) + " impacts" +
               (m->impacts.empty() ? std::string() : std::string(" (") + impactShapeName(m->impacts[0].shape) + ")");
    if (const auto* k = std::get_if<SketchSolid>(&e.op))
        return std::string("sketch (") + sketchModeName(k->mode) + "), " + std::to_string(k->outline.size()) +
               " outline points, " + std::to_string(k->reach.size()) + " pieces";
    if (const auto* s = std::get_if<Stroke>(&e.op))
        return std::string(strokeToolName(s->tool)) + " stroke, radius " + std::to_string(s->radius) + ", " +
               std::to_string(s->path.size()) + " path points, " + std::to_string(s->segments.size()) + " segments";
    const auto& p = std::get<Perturbation>(e.op);
    return std::string(p.shape == QuadricShape::Ellipsoid ? "ellipsoid" : "torus") + " perturbation, strength " +
           std::to_string(p.strength);
}

}  // namespace hg::garden
