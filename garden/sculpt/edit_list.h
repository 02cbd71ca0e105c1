// A sculpture's edits in order, with a spatial index over their pieces (a
// stroke's segments, a perturbation's quadric): a box update asks which
// pieces reach the box and evaluates only those, so a sculpture with
// thousands of edits updates a small box as fast as one with ten (docs/design.md
// §4). The list's field is exactly the base field with every edit applied
// in order; pieces outside a box leave it unchanged there (edit_field.h).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "frep/compiler/tape.h"
#include "garden/sculpt/edit.h"

namespace hg::garden {

// The pieces of one edit that reach a box.
struct EditPick {
    std::uint32_t edit = 0;
    std::vector<std::uint32_t> pieces;  // ascending
};

class EditList {
public:
    // `cellSize`: the index's cell edge, model units (a few dozen voxels).
    EditList(FieldUnits units, double cellSize);

    const FieldUnits& units() const { return units_; }
    const std::vector<Edit>& edits() const { return edits_; }
    std::size_t size() const { return edits_.size(); }
    bool empty() const { return edits_.empty(); }

    // Appends an edit (its pieces and reach computed already).
    void append(Edit edit);
    // The last edit's stroke, to grow its path and segments before
    // extendLast (a live stroke); throws when the last edit is no stroke.
    Stroke& lastStroke() { return std::get<Stroke>(edits_.back().op); }
    // A live stroke grew: indexes the last edit's segments from `firstPiece`
    // on and widens its reach. Returns the box the new pieces reach.
    frep::Box3 extendLast(std::size_t firstPiece);
    // Removes the last edit (undo) and returns it.
    Edit removeLast();
    // Puts `edit` in place of edit `index` (a perturbation's factor or
    // extent changed: replaced, not stacked) and returns the one it replaced.
    Edit replace(std::size_t index, Edit edit);

    // The pieces that reach `box`, by edit in list order.
    std::vector<EditPick> reaching(const frep::Box3& box) const;
    // Every piece of every edit.
    std::vector<EditPick> all() const;

    std::size_t indexedPieces() const { return pieceCount_; }

private:
    struct Piece {
        std::uint32_t edit, piece;
        frep::Box3 box;
    };
    using CellKey = std::uint64_t;
    void index(std::uint32_t edit, std::uint32_t piece, const frep::Box3& box);
    void unindex(std::uint32_t edit);
    void cellRange(const frep::Box3& box, std::int64_t lo[3], std::int64_t hi[3]) const;
    static CellKey key(std::int64_t i, std::int64_t j, std::int64_t k);

    FieldUnits units_;
    double cellSize_;
    std::vector<Edit> edits_;
    std::unordered_map<CellKey, std::vector<Piece>> cells_;
    std::size_t pieceCount_ = 0;
};

// The pieces of an edit and where each reaches.
std::size_t pieceCount(const Edit& e);
frep::Box3 pieceReach(const Edit& e, std::size_t piece);
// The reach of a perturbation's quadric.
frep::Box3 perturbationReach(const Perturbation& p);

// The grid update's tape: the base field (input W, voxels) at (x, y, z)
// with the picked pieces of the list's edits applied in order.
frep::Tape editTape(const EditList& list, const std::vector<EditPick>& picks);

// The same expression in double with every edit (the reference).
double editedValue(const EditList& list, double base, double x, double y, double z);

}  // namespace hg::garden
