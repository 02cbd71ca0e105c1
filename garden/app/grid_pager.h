// Keeps what the garden holds within a memory budget by keeping far
// sculptures' full-resolution grids on disk (issue 25; docs/design.md §5,
// "Far grids on disk"). Once a frame, after level selection, the session
// tells the pager which sculptures want their grid (a chunk at level 0, or
// soon: the viewer, a tool or the detail sphere is near) and which are far
// enough to let go; the pager then
//
//   - adopts the grids its reader thread has read back, and hands it the
//     wanted ones that are out (nearest first; a grid whose write has not
//     begun is simply taken back);
//   - when the memory held is over the budget, hands the farthest grids
//     that may go to its writer thread (voxel/grid_page.h), which writes
//     each to a file named by its content in the page folder and lets it go.
//
// A paged-out sculpture keeps its coarse levels and meshes, so it stays on
// show; the session keeps its chunks at level 1 or coarser until its grid
// is back. Whatever else needs the grid (an edit, an export) brings it back
// at once through voxel::Volume::grid(). Edited sculptures and morphs stay
// in memory: their grids are not a pure function of their source. A write
// that fails (a full disk) keeps the grid and is reported (problem());
// paging then pauses a while. The folder is removed when the pager goes.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "garden/app/memory_report.h"

namespace hg::jobs {
class JobThread;
}
namespace hg::garden {

struct Sculpture;

// What the session's level selection says of a sculpture this frame.
struct GridNeed {
    bool wanted = false;     // its grid is needed now or soon: bring it back
    bool mayGo = false;      // far enough, and idle: it may be paged out
    double distance = 0.0;   // metres from the viewer (the farthest go first)
};

class GridPager {
public:
    // `budgetBytes` 0: no budget (nothing is paged out). `folder` "": a
    // folder of this process's own under the user's cache folder
    // (defaultPageFolder()).
    explicit GridPager(std::size_t budgetBytes = 0, std::string folder = "");
    ~GridPager();
    GridPager(const GridPager&) = delete;
    GridPager& operator=(const GridPager&) = delete;

    // Once a frame on the session's thread; `needs` by sculpture index.
    void step(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs);
    // Waits until every write and read handed over is done and taken
    // (tests, benches: a state that no thread still changes).
    void settle(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs);

    std::size_t budget() const { return budget_; }
    void setBudget(std::size_t bytes) { budget_ = bytes; }
    // What the sculptures hold, from figures kept per sculpture (with a
    // budget, one refreshed each frame in turn, and each one whose grid came
    // or went), with the grids on disk and the budget: cheap enough for
    // every frame.
    MemoryReport report() const;
    // Why paging stopped last ("" : it did not).
    const std::string& problem() const { return problem_; }
    // Over the budget with writes under way: memory is about to come down,
    // so a loading garden waits before it takes more grids in (else a
    // garden of copies, sampled in moments, peaks far above the budget).
    bool backlog() const { return backlog_; }
    const std::string& folder() const { return folder_; }
    std::size_t pagedOutTotal() const { return pagedOut_; }  // grids let go, over the session
    std::size_t broughtBackTotal() const { return broughtBack_; }

    // Where pages go by default: $XDG_CACHE_HOME (else ~/.cache, else the
    // temporary folder)/hypergarden/pages-<pid>.
    static std::string defaultPageFolder();

private:
    struct WriteJob;
    struct ReadJob;
    struct Entry {
        std::shared_ptr<WriteJob> writing;
        std::shared_ptr<ReadJob> reading;
        MemoryReport held;   // this sculpture's figures, as last read
        bool counted = false;
        bool hadGrid = false;  // when they were read: a grid arriving (loading) is counted at once
    };

    void takeFinished(std::vector<Sculpture>& sculptures);
    void bringBackWanted(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs);
    void pageOutFarthest(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs);
    void refresh(const Sculpture& s, Entry& e);
    bool ensureFolder();
    void pause(const std::string& why);

    std::size_t budget_;
    std::string folder_;
    bool ownFolder_ = false;   // made by this pager: removed when it goes
    bool folderReady_ = false;
    std::vector<Entry> entries_;
    std::size_t nextRefresh_ = 0;
    std::string problem_;
    std::chrono::steady_clock::time_point pausedUntil_{};
    std::size_t pagedOut_ = 0, broughtBack_ = 0;
    bool backlog_ = false;
    // Declared last: they stop (finishing the job under way) before the
    // entries and the folder go.
    std::unique_ptr<jobs::JobThread> writer_, reader_;
};

}  // namespace hg::garden
