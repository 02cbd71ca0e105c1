// A sculpture's grid kept on disk instead of in memory (issue 25's memory
// budget; docs/design.md §5, "Far grids on disk"). The page takes the grid
// from its volume (Volume::pageOut); a job thread writes it to a file named
// by its content, so copies of one sculpture share a file and a grid paged
// out again unchanged is not written twice, and then lets the grid go. It
// is read back as often as needed. Until its write has begun the grid can
// be taken back at no cost; a write that fails (a full disk) keeps the
// grid, so nothing is lost, and says why.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>

namespace hg::voxel {

struct VolumeGrid;

class GridPage {
public:
    enum class State {
        Holding,    // handed over, not yet written: the grid is still here
        Writing,    // a thread is writing it
        Written,    // on disk, the grid let go
        Failed,     // the write failed (problem()): the grid is still here
        TakenBack,  // taken back before it was written: nothing to write
    };

    // `folder` must exist; the file goes there. `readFrom`: a page file the
    // grid was read from and has not changed since (a far grid going again):
    // while it is still there, write() only lets the grid go.
    GridPage(std::unique_ptr<VolumeGrid> grid, std::string folder, std::string readFrom = "");
    ~GridPage();
    GridPage(const GridPage&) = delete;
    GridPage& operator=(const GridPage&) = delete;

    // On any one thread: the grid encoded, written unless a file of the
    // same content is there already, and let go. Does nothing when the page
    // was taken back first.
    void write();
    // The grid again: the one held, at once, when the write has not begun
    // or failed; else, once the write under way is done, read from the
    // file. Throws std::runtime_error naming the file when it cannot be read.
    std::unique_ptr<VolumeGrid> takeBack();
    // The written file read into a new grid (state() must be Written), on
    // any thread. Throws as takeBack().
    std::unique_ptr<VolumeGrid> readFile() const;
    // readFile() into the page, on any thread: what a job does to bring a
    // grid back off the frame thread; the volume then adopts it
    // (Volume::adoptReadAhead), and takeBack() takes it rather than read
    // the file again. Throws as takeBack().
    void readAhead();
    bool readAheadReady() const;

    State state() const;
    std::string problem() const;  // why the write failed
    std::string path() const;     // the file, once written
    std::size_t fileBytes() const;

private:
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    State state_ = State::Holding;
    std::unique_ptr<VolumeGrid> grid_;
    std::unique_ptr<VolumeGrid> readAhead_;
    std::string folder_, readFrom_, path_, problem_;
    std::size_t fileBytes_ = 0;
};

}  // namespace hg::voxel
