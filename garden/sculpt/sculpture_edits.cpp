#include "garden/sculpt/sculpture_edits.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "garden/sculpt/smooth_fit.h"
#include "garden/sculpt/stroke_segments.h"

namespace hg::garden {

FieldUnits unitsOf(const voxel::Volume& v) { return {v.frame.voxelSize, static_cast<double>(v.frame.band)}; }

SculptureEdits::SculptureEdits(voxel::Volume& shown)
    : shown_(shown),
      base_(std::make_unique<voxel::Volume>(shown.clone())),
      list_(unitsOf(shown), kEditIndexCellVoxels * shown.frame.voxelSize) {}

SculptureEdits::~SculptureEdits() = default;

voxel::IndexBox SculptureEdits::voxelsOf(const frep::Box3& box) const {
    const voxel::VolumeFrame& f = shown_.frame;
    voxel::IndexBox r;
    for (int a = 0; a < 3; ++a) {
        const double lo = std::floor((box.lo[a] - f.modelBox.lo[a]) / f.voxelSize) - 1.0;
        const double hi = std::ceil((box.hi[a] - f.modelBox.lo[a]) / f.voxelSize) + 1.0;
        r.lo[a] = static_cast<int>(std::clamp(lo, -1e9, 1e9));
        r.hi[a] = static_cast<int>(std::clamp(hi, -1e9, 1e9));
    }
    return voxel::intersect(r, f.indexBox);
}

namespace {

constexpr int kFlushCellVoxels = 16;

// The model box of `cell`'s voxels, one voxel wider than their positions:
// picking a piece too many changes no value, one too few would.
frep::Box3 modelBoxOf(const voxel::VolumeFrame& f, const voxel::IndexBox& cell) {
    frep::Box3 model;
    for (int a = 0; a < 3; ++a) {
        model.lo[a] = f.coordinate(a, cell.lo[a] - 1);
        model.hi[a] = f.coordinate(a, cell.hi[a] + 1);
    }
    return model;
}

// The index cells (kEditIndexCellVoxels a side, aligned) that cover `box`,
// each clipped to it: a big box (a long stroke, a pull of a thousand
// impacts) is evaluated cell by cell with the pieces that reach each cell.
std::vector<voxel::IndexBox> cellsOf(const voxel::IndexBox& box, int size = kEditIndexCellVoxels) {
    std::vector<voxel::IndexBox> out;
    const int n = size - 1;
    for (const auto& o : voxel::alignedBoxes(box, size))
        out.push_back(voxel::intersect(voxel::IndexBox::fromCorners(o[0], o[1], o[2], o[0] + n, o[1] + n, o[2] + n), box));
    return out;
}

void add(voxel::EditRegionStats& total, const voxel::EditRegionStats& s) {
    total.voxels += s.voxels;
    total.seconds += s.seconds;
    total.errors.merge(s.errors);
}

// The pieces of the list's last edit, from `firstPiece` on, that reach
// `cell`: what goes on top of the grid there (none: the cell stands).
EditPick lastEditPieces(const EditList& list, const voxel::VolumeFrame& frame, const voxel::IndexBox& cell,
                        std::size_t firstPiece) {
    const auto last = static_cast<std::uint32_t>(list.size() - 1);
    EditPick pick{last, {}};
    for (const EditPick& p : list.reaching(modelBoxOf(frame, cell)))
        if (p.edit == last)
            for (std::uint32_t piece : p.pieces)
                if (piece >= firstPiece) pick.pieces.push_back(piece);
    return pick;
}

}  // namespace

voxel::EditRegionStats SculptureEdits::update(const voxel::IndexBox& box) {
    settle();
    const voxel::IndexBox clip = voxel::intersect(box, shown_.frame.indexBox);
    if (clip.empty()) return {};
    if (deferred_) {
        pending_.push_back(clip);
        return {};
    }
    if (queueing_) {
        queue(clip, 0, true);
        return {};
    }
    voxel::EditRegionStats total;
    for (const voxel::IndexBox& cell : cellsOf(clip)) {
        const frep::Tape tape = editTape(list_, list_.reaching(modelBoxOf(shown_.frame, cell)));
        add(total, voxel::applyEditTape(*base_, shown_, cell, tape));
    }
    lastStats_ = total;
    return lastStats_;
}

voxel::EditRegionStats SculptureEdits::applyOnTop(const voxel::IndexBox& box, std::size_t firstPiece) {
    settle();
    if (deferred_) return update(box);
    const voxel::IndexBox clip = voxel::intersect(box, shown_.frame.indexBox);
    if (clip.empty()) return {};
    if (queueing_) {
        queue(clip, static_cast<std::uint32_t>(firstPiece), false);
        return {};
    }
    voxel::EditRegionStats total;
    for (const voxel::IndexBox& cell : cellsOf(clip)) {
        const EditPick pick = lastEditPieces(list_, shown_.frame, cell, firstPiece);
        if (pick.pieces.empty()) continue;  // nothing new reaches the cell: it stands
        add(total, voxel::applyEditTape(shown_, shown_, cell, editTape(list_, {pick})));
    }
    lastStats_ = total;
    return lastStats_;
}

void SculptureEdits::capture(const voxel::IndexBox& box) {
    if (deferred_ || before_.empty() || !before_.back()) return;
    before_.back()->capture(shown_, box);
    // Over the budget: the oldest copies go (their undo recomputes instead).
    std::size_t total = 0;
    for (const auto& b : before_) total += b ? b->bytes() : 0;
    for (auto& b : before_) {
        if (total <= kUndoCopyBytes || &b == &before_.back()) break;
        if (!b) continue;
        total -= b->bytes();
        b.reset();
    }
}

void SculptureEdits::dropCopies() {
    for (auto& b : before_) b.reset();
}

voxel::EditRegionStats SculptureEdits::baseChanged(const voxel::IndexBox& box) {
    settle();
    dropCopies();
    return update(box);
}

void SculptureEdits::fitNewSegments(Stroke& stroke) {
    if (stroke.tool != StrokeTool::Smooth || stroke.fits.size() >= stroke.segments.size()) return;
    // Fits that came with the stroke (a journal) are kept: a replay never
    // fits again, so it equals the session it replays. A record without
    // them (a hand-written action) is fitted to the grid as the edits
    // before it leave it: while deferred (a journal played in one go) the
    // pending boxes are brought up to date first, and stay pending so the
    // caller's flush still reports them.
    if (deferred_ && !pending_.empty()) {
        std::vector<voxel::IndexBox> keep = pending_;
        flush();
        pending_ = std::move(keep);
        deferred_ = true;
    }
    for (std::size_t i = stroke.fits.size(); i < stroke.segments.size(); ++i)
        stroke.fits.push_back(fitSegment(shown_, stroke.segments[i], stroke.radius));
}

voxel::IndexBox SculptureEdits::append(Edit edit) {
    settle();
    if (auto* stroke = std::get_if<Stroke>(&edit.op)) fitNewSegments(*stroke);
    edit.id = nextId_++;
    redo_.clear();
    return applyAppended(std::move(edit));
}

voxel::IndexBox SculptureEdits::applyAppended(Edit edit) {
    list_.append(std::move(edit));
    before_.push_back(deferred_ ? nullptr : std::make_unique<voxel::LeafSnapshot>());
    const voxel::IndexBox box = voxelsOf(list_.edits().back().reach);
    capture(box);
    applyOnTop(box, 0);
    return box;
}

voxel::IndexBox SculptureEdits::extendLastStroke(const std::vector<ModelPoint>& points) {
    settle();
    Stroke& stroke = list_.lastStroke();
    const std::size_t firstPoint = stroke.path.size();
    stroke.path.insert(stroke.path.end(), points.begin(), points.end());
    const std::size_t firstPiece = extendStrokeSegments(stroke, firstPoint, list_.units());
    if (firstPiece == stroke.segments.size()) return {};
    fitNewSegments(stroke);
    const voxel::IndexBox box = voxelsOf(list_.extendLast(firstPiece));
    capture(box);
    // Carving and adding fold their segments with min and max, which
    // associate: the new segments go on top of the grid. Melt and inflate
    // combine all their segments before touching the field, and smooth's
    // arithmetic must run as a rebuild runs it: recomputed.
    if (stroke.tool == StrokeTool::Melt || stroke.tool == StrokeTool::Inflate || stroke.tool == StrokeTool::Smooth)
        update(box);
    else applyOnTop(box, firstPiece);
    return box;
}

voxel::IndexBox SculptureEdits::replace(std::size_t index, Edit edit, Edit& replaced) {
    settle();
    edit.id = list_.edits()[index].id;
    const frep::Box3 before = list_.edits()[index].reach;
    replaced = list_.replace(index, std::move(edit));
    const frep::Box3& after = list_.edits()[index].reach;
    frep::Box3 both;
    for (int a = 0; a < 3; ++a) {
        both.lo[a] = std::min(before.lo[a], after.lo[a]);
        both.hi[a] = std::max(before.hi[a], after.hi[a]);
    }
    const voxel::IndexBox box = voxelsOf(both);
    // The edits after this one were applied over what it changes: their
    // copies no longer hold the grid before them.
    dropCopies();
    update(box);
    return box;
}

std::optional<voxel::IndexBox> SculptureEdits::undo() {
    settle();
    if (list_.empty()) return std::nullopt;
    Edit removed = list_.removeLast();
    const voxel::IndexBox box = voxelsOf(removed.reach);
    redo_.push_back(std::move(removed));
    std::unique_ptr<voxel::LeafSnapshot> copy = before_.empty() ? nullptr : std::move(before_.back());
    if (!before_.empty()) before_.pop_back();
    // The grid before the edit, as it was copied; else recomputed.
    if (copy && !deferred_) copy->restore(shown_);
    else update(box);
    return box;
}

std::vector<Edit> SculptureEdits::takeAll(std::vector<voxel::IndexBox>& changed) {
    settle();
    // Deferred, so that each voxel is recomputed once however many edits go.
    const bool wasDeferred = deferred_;
    deferred_ = true;
    std::vector<Edit> taken;
    while (!list_.empty()) {
        taken.push_back(list_.removeLast());
        update(voxelsOf(taken.back().reach));
    }
    before_.clear();
    std::reverse(taken.begin(), taken.end());
    if (!wasDeferred) changed = flush();
    return taken;
}

std::vector<voxel::IndexBox> SculptureEdits::rebase() {
    settle();
    base_ = std::make_unique<voxel::Volume>(shown_.clone());
    dropCopies();  // they hold the old grid
    const bool wasDeferred = deferred_;
    deferred_ = true;
    for (const Edit& e : list_.edits()) update(voxelsOf(e.reach));
    return wasDeferred ? std::vector<voxel::IndexBox>{} : flush();
}

std::vector<voxel::IndexBox> SculptureEdits::reframe(const std::function<void(Edit&)>& rederive) {
    settle();
    std::vector<Edit> edits = list_.edits();
    list_ = EditList(unitsOf(shown_), kEditIndexCellVoxels * shown_.frame.voxelSize);
    for (Edit& e : edits) rederive(e);
    for (Edit& e : redo_) rederive(e);
    base_ = std::make_unique<voxel::Volume>(shown_.clone());
    before_.clear();  // copies of the old frame's leaves
    pending_.clear();
    return putBack(std::move(edits));
}

std::vector<voxel::IndexBox> SculptureEdits::putBack(std::vector<Edit> edits) {
    settle();
    const bool wasDeferred = deferred_;
    deferred_ = true;
    for (Edit& e : edits) applyAppended(std::move(e));
    return wasDeferred ? std::vector<voxel::IndexBox>{} : flush();
}

std::optional<voxel::IndexBox> SculptureEdits::redo() {
    settle();
    if (redo_.empty()) return std::nullopt;
    Edit again = std::move(redo_.back());
    redo_.pop_back();
    return applyAppended(std::move(again));
}

std::vector<voxel::IndexBox> SculptureEdits::flush() {
    settle();
    deferred_ = false;
    // The cells the pending boxes touch, each recomputed once.
    std::vector<std::array<int, 3>> cells;
    for (const voxel::IndexBox& b : pending_)
        for (const auto& o : voxel::alignedBoxes(b, kEditIndexCellVoxels)) cells.push_back(o);
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    std::vector<voxel::IndexBox> done, parts;
    for (const auto& o : cells) {
        const int n = kEditIndexCellVoxels - 1;
        const voxel::IndexBox cell =
            voxel::intersect(voxel::IndexBox::fromCorners(o[0], o[1], o[2], o[0] + n, o[1] + n, o[2] + n), shown_.frame.indexBox);
        // Thousands of edits crowd a cell: its eighths pick fewer pieces each.
        for (const voxel::IndexBox& part : cellsOf(cell, kFlushCellVoxels)) parts.push_back(part);
        done.push_back(cell);
    }
    pending_.clear();
    // Each part from the base and the edits that reach it, side by side.
    lastStats_ = voxel::applyEditTapes(*base_, shown_, parts, [&](std::size_t i) {
        return editTape(list_, list_.reaching(modelBoxOf(shown_.frame, parts[i])));
    });
    return done;
}

voxel::IndexBox SculptureEdits::appendSpread(Edit edit) {
    settle();
    queueing_ = true;
    const voxel::IndexBox box = append(std::move(edit));
    queueing_ = false;
    return box;
}

voxel::IndexBox SculptureEdits::extendLastStrokeSpread(const std::vector<ModelPoint>& points) {
    settle();
    queueing_ = true;
    const voxel::IndexBox box = extendLastStroke(points);
    queueing_ = false;
    return box;
}

void SculptureEdits::queue(const voxel::IndexBox& clip, std::uint32_t firstPiece, bool fromBase) {
    for (const voxel::IndexBox& cell : cellsOf(clip, kFlushCellVoxels)) spread_.push_back({cell, firstPiece, fromBase});
}

// One waiting cell, as update() (from the base) or applyOnTop() (the last
// edit's pieces from firstPiece on, on top) computes it.
void SculptureEdits::computeSpreadCell(const SpreadCell& c, voxel::Volume& grid) const {
    if (c.fromBase) {
        voxel::applyEditTape(*base_, grid, c.box, editTape(list_, list_.reaching(modelBoxOf(grid.frame, c.box))));
        return;
    }
    const EditPick pick = lastEditPieces(list_, grid.frame, c.box, c.firstPiece);
    if (!pick.pieces.empty()) voxel::applyEditTape(grid, grid, c.box, editTape(list_, {pick}));
}

voxel::Volume SculptureEdits::settledGrid() const {
    voxel::Volume out = shown_.clone();
    for (std::size_t i = spreadNext_; i < spread_.size(); ++i) computeSpreadCell(spread_[i], out);
    return out;
}

std::vector<voxel::IndexBox> SculptureEdits::advance(double milliseconds) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    std::vector<voxel::IndexBox> changed = std::move(settled_);
    settled_.clear();
    while (milliseconds > 0.0 && spreadNext_ < spread_.size()) {
        const SpreadCell& cell = spread_[spreadNext_++];
        computeSpreadCell(cell, shown_);
        changed.push_back(cell.box);
        if (std::chrono::duration<double, std::milli>(Clock::now() - start).count() >= milliseconds) break;
    }
    if (spreadNext_ == spread_.size()) {
        spread_.clear();
        spreadNext_ = 0;
    }
    return changed;
}

void SculptureEdits::settle() {
    if (spreadNext_ >= spread_.size()) return;
    for (; spreadNext_ < spread_.size(); ++spreadNext_) {
        computeSpreadCell(spread_[spreadNext_], shown_);
        settled_.push_back(spread_[spreadNext_].box);
    }
    spread_.clear();
    spreadNext_ = 0;
}

std::unique_ptr<voxel::Volume> SculptureEdits::rebuild() const {
    auto out = std::make_unique<voxel::Volume>(base_->clone());
    if (list_.empty()) return out;
    // Outside every reach the edits change nothing: the base stands there.
    const frep::Tape tape = editTape(list_, list_.all());
    for (const Edit& e : list_.edits()) voxel::applyEditTape(*base_, *out, voxelsOf(e.reach), tape);
    return out;
}

}  // namespace hg::garden
