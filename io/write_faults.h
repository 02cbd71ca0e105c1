// The seam through which every file write of the program passes
// (docs/session-format.md, "How it is tested"): each low-level step that
// puts bytes on disk (write, fsync, rename, truncate) first asks
// injectedFailure() for its site, so a test can make the n-th step at any
// site fail with a chosen errno, or kill the process there with SIGKILL,
// and check that nothing saved is lost. With no plan set it costs one
// relaxed atomic load.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace hg::io {

// Where a write happens; the seam counts steps per site.
enum class WriteSite {
    Journal,           // the session journal's appends (and cutting a torn tail)
    SnapshotGrid,      // a snapshot's grids
    SnapshotManifest,  // snapshots/snapshot.json
    SessionFile,       // session.json, garden.json, sources/, the lock's holder note
    Settings,          // kept settings (the headset's)
    Export,            // exported HyperFun, meshes and volumes
    Screenshot,        // screenshots
    Stats,             // replay statistics
    PageFile,          // far sculptures' grids paged to disk (voxel/grid_page.h)
    Count
};
const char* writeSiteName(WriteSite site);

// Which steps fail: the `first`-th to the `last`-th step (1-based) at
// `site` (or at any site when `anySite`), with `error` (an errno), or the
// process is killed there (`kill`).
struct FaultPlan {
    bool anySite = true;
    WriteSite site = WriteSite::Journal;
    std::size_t first = 1, last = 1;  // last = SIZE_MAX: every step from `first` on
    int error = 0;
    bool kill = false;
};

// Reads HG_FAIL_WRITE: "[SITE:]N[-[M]]:ERROR", ERROR one of ENOSPC, EIO,
// EDQUOT, EROFS, EFBIG or KILL; SITE one of writeSiteName's names.
// "journal:3:ENOSPC" fails the third journal step, "5-:EIO" every step from
// the fifth on. A malformed value is a message (the caller stops).
std::optional<FaultPlan> parseFaultPlan(const std::string& text, std::string& why);

// The plan in force (from HG_FAIL_WRITE at first use, or set by a test);
// setting one resets the counters.
void setFaultPlan(std::optional<FaultPlan> plan);

// 0, or the errno the step at `site` must fail with; raises SIGKILL for a
// kill plan. Counts the step.
int injectedFailure(WriteSite site);

}  // namespace hg::io
