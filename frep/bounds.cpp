#include "frep/bounds.h"

#include <algorithm>
#include <vector>

#include "frep/eval_interval.h"

namespace hg::frep {

BoundsEstimate estimateBounds(const Tape& tape, double s, size_t maxBoxes) {
    IntervalEvaluator ev(tape);
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
        if (next.empty()) {  // the interval bounds got tight enough to drop everything
            est.empty = true;
            return est;
        }
        boxes.swap(next);
        cell *= 0.5;
        est.levels = level;
        est.cellSize = cell;
        Box3 bb = boxes[0];
        for (const Box3& b : boxes)
            for (int a = 0; a < 3; ++a) { bb.lo[a] = std::min(bb.lo[a], b.lo[a]); bb.hi[a] = std::max(bb.hi[a], b.hi[a]); }
        est.box = bb;
        double extent = std::max({bb.hi[0] - bb.lo[0], bb.hi[1] - bb.lo[1], bb.hi[2] - bb.lo[2]});
        if (cell <= extent / 128.0) break;
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
