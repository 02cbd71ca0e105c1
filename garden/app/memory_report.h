// What a running garden holds in memory, by kind (issue 25: "a memory
// budget that the user can set and the program reports"; the report comes
// first, so that a budget knows what it would page). Read on the session's
// thread; it walks every chunk, so it is for reports (the stats panel,
// benches), not every frame.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace hg::garden {

class GardenSession;

struct MemoryReport {
    std::size_t grids = 0;         // the sculptures' grids (LOD level 0)
    std::size_t levels = 0;        // the LOD pyramids' coarser levels
    std::size_t meshes = 0;        // chunk meshes held for drawing (shown and staged)
    std::size_t editBases = 0;     // edited sculptures' grids before their edits
    std::size_t morphSources = 0;  // the morphs' source caches
    std::size_t sculptures = 0;    // sculptures with a grid
    // Far grids kept on disk instead (garden/app/grid_pager.h), the budget
    // the rest is kept within (0: none), and why paging stopped ("" : it did not).
    std::size_t pagedOut = 0;
    std::size_t budget = 0;
    std::string pagingProblem;
    std::size_t total() const { return grids + levels + meshes + editBases + morphSources; }
    MemoryReport& operator+=(const MemoryReport& o);
};

struct Sculpture;
// One sculpture's share (its grid counted only while in memory).
MemoryReport sculptureMemory(const Sculpture& s);
// Every sculpture's, read now, with the pager's budget and problem.
MemoryReport memoryReport(const GardenSession& session);

// The report taken again at most every `every` (for a panel drawn every
// frame: a report walks every grid's tree).
class MemoryWatch {
public:
    explicit MemoryWatch(std::chrono::milliseconds every = std::chrono::milliseconds(1000)) : every_(every) {}
    const MemoryReport& read(const GardenSession& session);

private:
    std::chrono::milliseconds every_;
    std::chrono::steady_clock::time_point taken_{};
    bool any_ = false;
    MemoryReport last_;
};

}  // namespace hg::garden
