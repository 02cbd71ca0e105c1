#include "garden/app/grid_pager.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <signal.h>
#include <unistd.h>

#include "garden/app/sculpture.h"
#include "jobs/job_thread.h"
#include "voxel/grid_page.h"
#include "voxel/volume.h"

namespace hg::garden {

namespace fs = std::filesystem;

namespace {
// Writes in flight at once: each holds its grid until written, so more
// would only hold memory the budget already counts as gone.
constexpr std::size_t kWritesInFlight = 4;
// Sculptures whose figures are read again each frame, in turn: a grid's
// memory is a parallel walk over its tree (OpenVDB's memUsage), about
// 10 us at 64^3, and the rest only changes when the viewer moves or an
// edit lands. A grid that comes or goes is read at once.
constexpr std::size_t kRefreshPerFrame = 1;
// After a failed write (a full disk), the pause before paging again.
constexpr std::chrono::seconds kPauseAfterFailure(10);
}  // namespace

struct GridPager::WriteJob final : jobs::BackgroundJob {
    explicit WriteJob(std::shared_ptr<voxel::GridPage> p) : page(std::move(p)) {}
    void run() override { page->write(); }
    std::shared_ptr<voxel::GridPage> page;
};

struct GridPager::ReadJob final : jobs::BackgroundJob {
    explicit ReadJob(std::shared_ptr<voxel::GridPage> p) : page(std::move(p)) {}
    void run() override { page->readAhead(); }  // what it throws is kept in `error`
    std::shared_ptr<voxel::GridPage> page;
};

GridPager::GridPager(std::size_t budgetBytes, std::string folder) : budget_(budgetBytes), folder_(std::move(folder)) {
    if (folder_.empty()) {
        folder_ = defaultPageFolder();
        ownFolder_ = true;
    }
}

GridPager::~GridPager() {
    // The threads finish the job under way first; no job then reads the folder.
    reader_.reset();
    writer_.reset();
    if (ownFolder_ && folderReady_) {
        std::error_code ec;
        fs::remove_all(folder_, ec);
    }
}

std::string GridPager::defaultPageFolder() {
    fs::path base;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) base = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home) base = fs::path(home) / ".cache";
    else {
        std::error_code ec;
        base = fs::temp_directory_path(ec);
        if (ec) base = "/tmp";
    }
    return (base / "hypergarden" / ("pages-" + std::to_string(::getpid()))).string();
}

namespace {
// Page folders of processes that are gone (killed, crashed): nothing reads
// them any more. Only names this pager's own scheme makes are touched.
void removeOrphanedFolders(const fs::path& parent) {
    std::error_code ec;
    for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.rfind("pages-", 0) != 0) continue;
        char* stop = nullptr;
        const long pid = std::strtol(name.c_str() + 6, &stop, 10);
        if (pid <= 0 || !stop || *stop != '\0' || pid == ::getpid()) continue;
        if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
            std::error_code ignored;
            fs::remove_all(it->path(), ignored);
        }
    }
}
}  // namespace

bool GridPager::ensureFolder() {
    if (folderReady_) return true;
    std::error_code ec;
    if (ownFolder_) removeOrphanedFolders(fs::path(folder_).parent_path());
    fs::create_directories(folder_, ec);
    if (ec || !fs::is_directory(folder_, ec)) {
        pause("cannot make the page folder " + folder_ + ": " + (ec ? ec.message() : "not a folder"));
        return false;
    }
    folderReady_ = true;
    return true;
}

void GridPager::pause(const std::string& why) {
    problem_ = why + "; far grids stay in memory for now";
    pausedUntil_ = std::chrono::steady_clock::now() + kPauseAfterFailure;
}

void GridPager::refresh(const Sculpture& s, Entry& e) {
    e.held = sculptureMemory(s);
    e.counted = true;
    e.hadGrid = s.hasGrid();
}

MemoryReport GridPager::report() const {
    MemoryReport r;
    for (const Entry& e : entries_) r += e.held;
    r.budget = budget_;
    r.pagingProblem = problem_;
    return r;
}

void GridPager::step(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs) {
    entries_.resize(sculptures.size());
    takeFinished(sculptures);
    bringBackWanted(sculptures, needs);
    // With no budget nothing reads the figures but a report (which reads
    // the sculptures itself): they are kept only for what changed here.
    if (budget_ > 0 && !sculptures.empty()) {
        for (std::size_t n = 0; n < std::min(kRefreshPerFrame, sculptures.size()); ++n) {
            nextRefresh_ = (nextRefresh_ + 1) % sculptures.size();
            refresh(sculptures[nextRefresh_], entries_[nextRefresh_]);
        }
        for (std::size_t i = 0; i < sculptures.size(); ++i)
            if (!entries_[i].counted || entries_[i].hadGrid != sculptures[i].hasGrid())
                refresh(sculptures[i], entries_[i]);
    }
    pageOutFarthest(sculptures, needs);
    std::size_t held = 0;
    bool writing = false;
    for (const Entry& e : entries_) {
        held += e.held.total();
        writing = writing || e.writing;
    }
    backlog_ = budget_ > 0 && writing && held > budget_;
}

void GridPager::settle(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs) {
    for (;;) {
        step(sculptures, needs);
        bool busy = false;
        for (Entry& e : entries_) {
            if (e.writing) e.writing->wait(), busy = true;
            if (e.reading) e.reading->wait(), busy = true;
        }
        if (!busy) break;
    }
    for (std::size_t i = 0; i < sculptures.size(); ++i) refresh(sculptures[i], entries_[i]);
}

void GridPager::takeFinished(std::vector<Sculpture>& sculptures) {
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        Entry& e = entries_[i];
        Sculpture& s = sculptures[i];
        if (e.writing && e.writing->done()) {
            const std::shared_ptr<voxel::GridPage> page = e.writing->page;
            e.writing.reset();
            if (page->state() == voxel::GridPage::State::Failed) {
                pause("cannot keep '" + s.name + "' on disk: " + page->problem());
                // The grid is still the page's: the volume takes it back now.
                if (s.volume && s.volume->page() == page) (void)s.volume->grid();
            } else if (page->state() == voxel::GridPage::State::Written && s.volume && s.volume->page() == page) {
                ++pagedOut_;
            }
            refresh(s, e);
        }
        if (e.reading && e.reading->done()) {
            const std::shared_ptr<ReadJob> job = e.reading;
            e.reading.reset();
            if (job->error) {
                // The file went (or went bad): read it on demand, which
                // reports the same error to whoever needs the grid.
                try {
                    std::rethrow_exception(job->error);
                } catch (const std::exception& ex) {
                    problem_ = ex.what();
                }
            } else if (s.volume && s.volume->page() == job->page && s.volume->adoptReadAhead()) {
                ++broughtBack_;
            }
            refresh(s, e);
        }
    }
}

void GridPager::bringBackWanted(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs) {
    std::vector<std::pair<double, std::size_t>> wanted;
    for (std::size_t i = 0; i < sculptures.size() && i < needs.size(); ++i) {
        const Sculpture& s = sculptures[i];
        if (needs[i].wanted && s.volume && !s.volume->resident() && !entries_[i].reading)
            wanted.emplace_back(needs[i].distance, i);
    }
    std::sort(wanted.begin(), wanted.end());
    for (const auto& [distance, i] : wanted) {
        Sculpture& s = sculptures[i];
        const std::shared_ptr<voxel::GridPage> page = s.volume->page();
        switch (page->state()) {
            case voxel::GridPage::State::Holding:
            case voxel::GridPage::State::Failed:
                (void)s.volume->grid();  // still in memory: taken back at once
                refresh(s, entries_[i]);
                break;
            case voxel::GridPage::State::Written: {
                if (!reader_) reader_ = std::make_unique<jobs::JobThread>();
                entries_[i].reading = std::make_shared<ReadJob>(page);
                reader_->submit(entries_[i].reading);
                break;
            }
            default: break;  // being written: read back once it is
        }
    }
}

void GridPager::pageOutFarthest(std::vector<Sculpture>& sculptures, const std::vector<GridNeed>& needs) {
    if (budget_ == 0 || std::chrono::steady_clock::now() < pausedUntil_) return;
    // The grids already handed over count as gone.
    std::size_t held = 0, inFlight = 0;
    for (const Entry& e : entries_) {
        held += e.held.total();
        if (e.writing) {
            ++inFlight;
            held -= std::min(held, e.held.grids);
        }
    }
    if (held <= budget_ || inFlight >= kWritesInFlight) return;
    std::vector<std::pair<double, std::size_t>> far;
    for (std::size_t i = 0; i < sculptures.size() && i < needs.size(); ++i) {
        const Sculpture& s = sculptures[i];
        if (needs[i].mayGo && !needs[i].wanted && !entries_[i].writing && !entries_[i].reading && s.volume &&
            s.volume->resident() && entries_[i].held.grids > 0)
            far.emplace_back(-needs[i].distance, i);
    }
    if (far.empty()) return;
    std::sort(far.begin(), far.end());
    if (!ensureFolder()) return;
    if (!writer_) writer_ = std::make_unique<jobs::JobThread>();
    for (const auto& [negDistance, i] : far) {
        if (held <= budget_ || inFlight >= kWritesInFlight) break;
        Entry& e = entries_[i];
        held -= std::min(held, e.held.grids);
        e.writing = std::make_shared<WriteJob>(sculptures[i].volume->pageOut(folder_));
        writer_->submit(e.writing);
        ++inFlight;
    }
    problem_.clear();
}

}  // namespace hg::garden
