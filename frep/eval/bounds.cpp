#include "frep/eval/bounds.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_interval.h"

namespace hg::frep {

namespace {

void expand(Box3& hull, const Box3& b) {
    for (int a = 0; a < 3; ++a) {
        hull.lo[a] = std::min(hull.lo[a], b.lo[a]);
        hull.hi[a] = std::max(hull.hi[a], b.hi[a]);
    }
}

bool contains(const Box3& outer, const Box3& inner) {
    for (int a = 0; a < 3; ++a)
        if (inner.lo[a] < outer.lo[a] || inner.hi[a] > outer.hi[a]) return false;
    return true;
}

// The hull of points known to be in the solid: box centres where the
// program evaluates to f >= 0. A kept box inside this hull cannot widen the
// estimate, so it is not split further: only boxes near the solid's
// extremes are refined, instead of its whole surface.
class Witnesses {
public:
    explicit Witnesses(const Tape& tape) : points_(tape) {}

    void add(const std::vector<Box3>& boxes) {
        const std::size_t n = boxes.size();
        x_.resize(n); y_.resize(n); z_.resize(n); f_.resize(n); failed_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            x_[i] = 0.5 * (boxes[i].lo[0] + boxes[i].hi[0]);
            y_[i] = 0.5 * (boxes[i].lo[1] + boxes[i].hi[1]);
            z_[i] = 0.5 * (boxes[i].lo[2] + boxes[i].hi[2]);
        }
        ErrorReport errors;
        points_.evaluate(x_.data(), y_.data(), z_.data(), f_.data(), n, errors, failed_.data());
        for (std::size_t i = 0; i < n; ++i) {
            if (failed_[i] || !(f_[i] >= 0.0)) continue;
            Box3 p;
            p.lo[0] = p.hi[0] = x_[i]; p.lo[1] = p.hi[1] = y_[i]; p.lo[2] = p.hi[2] = z_[i];
            if (any_) expand(hull_, p);
            else hull_ = p;
            any_ = true;
        }
    }

    bool any() const { return any_; }
    const Box3& hull() const { return hull_; }
    bool covers(const Box3& b) const { return any_ && contains(hull_, b); }

private:
    BatchEvaluator<double> points_;
    std::vector<double> x_, y_, z_, f_;
    std::vector<std::uint8_t> failed_;
    Box3 hull_;
    bool any_ = false;
};

}  // namespace

BoundsEstimate estimateBounds(const Tape& tape, double s, size_t maxBoxes) {
    IntervalEvaluator ev(tape);
    Witnesses witnesses(tape);
    std::vector<Box3> boxes(1);
    for (int a = 0; a < 3; ++a) { boxes[0].lo[a] = -s; boxes[0].hi[a] = s; }
    BoundsEstimate est;
    auto keep = [&](const Box3& b) {
        Interval f = ev.evaluate(Interval(b.lo[0], b.hi[0]), Interval(b.lo[1], b.hi[1]), Interval(b.lo[2], b.hi[2]));
        return f.hi >= 0.0;
    };
    if (!keep(boxes[0])) {
        est.empty = true;
        return est;
    }
    double cell = 2 * s;
    for (int level = 1; level <= 40; ++level) {
        std::vector<Box3> next;
        next.reserve(boxes.size() * 8);
        for (const Box3& b : boxes) {
            double mid[3];
            for (int a = 0; a < 3; ++a) mid[a] = 0.5 * (b.lo[a] + b.hi[a]);
            for (int k = 0; k < 8; ++k) {
                Box3 c;
                for (int a = 0; a < 3; ++a) {
                    bool upper = (k >> a) & 1;
                    c.lo[a] = upper ? mid[a] : b.lo[a];
                    c.hi[a] = upper ? b.hi[a] : mid[a];
                }
                if (keep(c)) next.push_back(c);
            }
        }
        if (next.empty() && !witnesses.any()) {  // the interval bounds got tight enough to drop everything
            est.empty = true;
            return est;
        }
        // The hull of all kept boxes is the hull of the witnesses and of the
        // boxes they do not cover: witnesses lie in kept boxes, and covered
        // boxes lie inside the witnesses' hull.
        witnesses.add(next);
        next.erase(std::remove_if(next.begin(), next.end(), [&](const Box3& b) { return witnesses.covers(b); }),
                   next.end());
        boxes.swap(next);
        cell *= 0.5;
        est.levels = level;
        est.cellSize = cell;
        Box3 bb = witnesses.any() ? witnesses.hull() : boxes[0];
        for (const Box3& b : boxes) expand(bb, b);
        est.box = bb;
        if (boxes.empty()) break;  // every kept box lies inside the witnesses: the hull is final
        double extent = std::max({bb.hi[0] - bb.lo[0], bb.hi[1] - bb.lo[1], bb.hi[2] - bb.lo[2]});
        if (cell <= extent / kBoundsPrecision) break;
        if (boxes.size() > maxBoxes) {
            est.budgetSpent = true;
            break;
        }
    }
    for (int a = 0; a < 3; ++a)
        if (est.box.lo[a] <= -s || est.box.hi[a] >= s) est.unbounded = true;
    return est;
}

}  // namespace hg::frep
