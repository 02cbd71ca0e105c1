// The edits of one sculpture and the grid they make (docs/design.md §4): the
// unedited grid (its source sampled, or the morph's blend) kept as the
// base, the edit list, the redo stack, and the shown grid updated box by
// box: a new edit, a live stroke's new segments, an undo or a redo each
// recompute only the box their pieces reach, from the base and the edits
// that reach that box, so the shown grid always equals the base with every
// edit applied (rebuild()), bit for bit.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "garden/sculpt/edit_list.h"
#include "voxel/edit_region.h"
#include "voxel/index_box.h"
#include "voxel/leaf_snapshot.h"
#include "voxel/volume.h"

namespace hg::garden {

// Index cells of the edit list, in voxels: about a chunk.
constexpr int kEditIndexCellVoxels = 32;

// The units an edit of a grid is measured in: its voxel and its band.
FieldUnits unitsOf(const voxel::Volume& v);

class SculptureEdits {
public:
    // `shown` is the sculpture's grid, unedited so far; it must outlive this.
    explicit SculptureEdits(voxel::Volume& shown);
    ~SculptureEdits();

    const EditList& list() const { return list_; }
    const FieldUnits& units() const { return list_.units(); }
    const voxel::Volume& base() const { return *base_; }
    // The base is written by someone else (the morph's blend): call after a
    // box of it changed, to bring the shown grid up to date there.
    voxel::Volume& mutableBase() { return *base_; }
    std::size_t redoCount() const { return redo_.size(); }
    void clearRedo() { redo_.clear(); }

    // Appends an edit whose pieces are computed (stroke segments) and
    // updates the grid; returns the box of voxels recomputed.
    voxel::IndexBox append(Edit edit);
    // Adds points to the path of the last edit, a stroke (a live stroke
    // following the hand): segments them and updates the grid where the new
    // segments reach.
    voxel::IndexBox extendLastStroke(const std::vector<ModelPoint>& points);
    // Undo and redo of the last edit; none when there is nothing to undo
    // or redo. A new edit clears the redo stack.
    std::optional<voxel::IndexBox> undo();
    std::optional<voxel::IndexBox> redo();
    // Puts `edit` in place of edit `index` and recomputes where either
    // reaches; `replaced` receives the edit it replaced (to put back).
    voxel::IndexBox replace(std::size_t index, Edit edit, Edit& replaced);
    // Every edit taken out (the grid back to its base), in list order, the
    // redo stack left as it is: a discard, which undo brings back with
    // putBack. Returns the boxes recomputed (none while deferred: flush).
    std::vector<Edit> takeAll(std::vector<voxel::IndexBox>& changed);
    // The shown grid was replaced by a new unedited one of the same frame
    // (its source file read again): it becomes the base, and every edit is
    // applied again on it, each voxel once. The boxes recomputed (none while
    // deferred: flush).
    std::vector<voxel::IndexBox> rebase();
    // The shown grid was replaced by a new unedited one of another frame
    // (its source file read again, the solid grown or shrunk): it becomes
    // the base, the units are its own, and every edit (those in the redo
    // stack too) is derived again in them by `rederive` (what a journal's
    // replay derives: a stroke's segments, reaches, a mask's margin), its
    // id kept, and applied again, each voxel once. Undo copies are dropped.
    // The boxes recomputed (none while deferred: flush).
    std::vector<voxel::IndexBox> reframe(const std::function<void(Edit&)>& rederive);
    // Edits taken out appended again, their ids kept and the redo stack
    // left as it is; each voxel they reach is recomputed once.
    std::vector<voxel::IndexBox> putBack(std::vector<Edit> edits);

    // The shown grid's `box` recomputed from the base and the edits that
    // reach it.
    voxel::EditRegionStats update(const voxel::IndexBox& box);
    // The base changed in `box` (the morph's blend): the shown grid there is
    // recomputed, and the copies undo would restore are dropped.
    voxel::EditRegionStats baseChanged(const voxel::IndexBox& box);
    // The last edit's pieces from `firstPiece` on applied to the shown grid
    // as it stands: the field is bounded, so what the grid stores is the
    // field before them exactly, and the float operations are those a
    // whole rebuild runs, in the same order. An edit made on top of a
    // thousand others costs what it would on a fresh sculpture.
    voxel::EditRegionStats applyOnTop(const voxel::IndexBox& box, std::size_t firstPiece);
    // The base with every edit applied, from scratch (what the shown grid
    // must equal).
    std::unique_ptr<voxel::Volume> rebuild() const;

    // Voxels of the frame that a model box covers (grown by one voxel).
    voxel::IndexBox voxelsOf(const frep::Box3& box) const;
    std::uint64_t nextId() const { return nextId_; }

    // Deferred: edits, undo and redo change the list only and remember the
    // boxes they reach; flush() then recomputes those boxes once, cell by
    // cell (reopening a session: thousands of actions, each voxel computed
    // once, equal to having applied them one by one).
    void setDeferred(bool deferred) { deferred_ = deferred; }
    std::vector<voxel::IndexBox> flush();

    // Spread over frames: appendSpread() puts a new edit in the list at
    // once and leaves its grid update waiting, in cells of 16^3 voxels
    // that advance() computes within a time (a frame's share). Every other
    // change first settles what waits (computes it all), so the grid is
    // always the list applied in order, some cells of the last edit late,
    // and once nothing waits it equals rebuild() bit for bit.
    voxel::IndexBox appendSpread(Edit edit);
    // extendLastStroke the same way: the list (and a smooth stroke's fits,
    // on the grid settled first) at once, the grid update waiting.
    voxel::IndexBox extendLastStrokeSpread(const std::vector<ModelPoint>& points);
    // The waiting cells computed, oldest first, for at least one cell and
    // then while `milliseconds` last (none when it is 0); returns the boxes
    // that changed, with those a settle computed since the last call (for
    // the caller to show).
    std::vector<voxel::IndexBox> advance(double milliseconds);
    // The shown grid as it will be once nothing waits (a copy; the grid
    // itself is left as it is): what an export of the grid reads.
    voxel::Volume settledGrid() const;
    // Cells still waiting, or computed by a settle and not yet returned by advance().
    bool late() const { return spreadNext_ < spread_.size() || !settled_.empty(); }

    // Statistics of the last update.
    const voxel::EditRegionStats& lastStats() const { return lastStats_; }

private:
    voxel::Volume& shown_;
    std::unique_ptr<voxel::Volume> base_;
    EditList list_;
    std::vector<Edit> redo_;
    std::uint64_t nextId_ = 1;
    voxel::EditRegionStats lastStats_;
    bool deferred_ = false;
    std::vector<voxel::IndexBox> pending_;
    // For each edit of the list, the shown grid's leaves as they were before
    // it, where it wrote (none: dropped, or never taken): undo of the last
    // edit puts them back. Kept within kUndoCopyBytes, oldest dropped first.
    std::vector<std::unique_ptr<voxel::LeafSnapshot>> before_;
    void capture(const voxel::IndexBox& box);
    // Appends an edit (new, or redone), copies the leaves it will write and
    // applies it on top of the grid; returns its box.
    voxel::IndexBox applyAppended(Edit edit);
    // A smooth stroke's segments without a fit fitted to the shown grid
    // (brought up to date first where deferred).
    void fitNewSegments(Stroke& stroke);
    void dropCopies();
    // The spread cells, in order; spreadNext_ is the first not computed.
    struct SpreadCell {
        voxel::IndexBox box;
        std::uint32_t firstPiece = 0;  // on top: the last edit's pieces from this one on
        bool fromBase = false;         // else from the base with every edit reaching it
    };
    std::vector<SpreadCell> spread_;
    std::size_t spreadNext_ = 0;
    std::vector<voxel::IndexBox> settled_;  // computed by settle(), not yet returned
    bool queueing_ = false;  // within appendSpread and extendLastStrokeSpread: updates wait
    void queue(const voxel::IndexBox& clip, std::uint32_t firstPiece, bool fromBase);
    void computeSpreadCell(const SpreadCell& cell, voxel::Volume& grid) const;
    // Every waiting cell computed: what each change but appendSpread and
    // advance does first.
    void settle();
};

// Memory the leaf copies for undo may take per sculpture.
constexpr std::size_t kUndoCopyBytes = std::size_t{256} << 20;

}  // namespace hg::garden
