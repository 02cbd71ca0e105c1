// An axis-aligned box in a model's coordinates: a plain value, so that
// headers that only pass boxes around (volumes, gardens, edits, the
// polygonizer) need not see the tape or the AST.
#pragma once

namespace hg::frep {

struct Box3 {
    double lo[3] = {0, 0, 0};
    double hi[3] = {0, 0, 0};
};

}  // namespace hg::frep
