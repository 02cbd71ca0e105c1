#include "voxel/grid_page.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <openvdb/io/Stream.h>

#include "io/checked_write.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

namespace fs = std::filesystem;

GridPage::GridPage(std::unique_ptr<VolumeGrid> grid, std::string folder, std::string readFrom)
    : grid_(std::move(grid)), folder_(std::move(folder)), readFrom_(std::move(readFrom)) {}

GridPage::~GridPage() = default;

namespace {

// The grid as a page file's bytes, and the name its content gives it in
// `folder`: "" or why not.
std::string encodePage(const openvdb::FloatGrid::ConstPtr& grid, const std::string& folder, std::string& bytes,
                       std::string& path) {
    std::string tag;
    try {
        // Only the active mask's compression: lossless like the rest, and
        // reading back (what a visitor walking up waits for) needs no inflate.
        std::ostringstream out(std::ios::binary);
        openvdb::io::Stream stream(out);
        stream.setCompression(openvdb::io::COMPRESS_ACTIVE_MASK);
        stream.write(openvdb::GridCPtrVec{grid});
        bytes = out.str();
        tag = stream.getUniqueTag();
    } catch (const std::exception& e) {
        return std::string("cannot encode the grid: ") + e.what();
    }
    // Named by content: an identical grid (a copy of the same sculpture, or
    // this one paged out before) is on disk already. Every archive carries
    // a random tag of its own: hashed as blanks.
    std::string hashed = bytes;
    if (const std::size_t at = tag.empty() ? std::string::npos : hashed.find(tag); at != std::string::npos)
        hashed.replace(at, tag.size(), tag.size(), '-');
    char name[64];
    std::snprintf(name, sizeof name, "%016zx-%zu.vdb", std::hash<std::string_view>{}(hashed), bytes.size());
    path = (fs::path(folder) / name).string();
    return "";
}

}  // namespace

void GridPage::write() {
    openvdb::FloatGrid::ConstPtr grid;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (state_ != State::Holding) return;
        state_ = State::Writing;
        grid = grid_->grid;  // still the page's: takeBack() waits while it is written
    }
    std::string bytes, why, path;
    std::size_t size = 0;
    std::error_code ec;
    if (!readFrom_.empty() && fs::is_regular_file(readFrom_, ec)) {
        // Unchanged since it was read from there: nothing to encode or write.
        path = readFrom_;
        size = static_cast<std::size_t>(fs::file_size(path, ec));
    } else {
        why = encodePage(grid, folder_, bytes, path);
        size = bytes.size();
        const bool there = why.empty() && fs::exists(path, ec) && fs::file_size(path, ec) == size && !ec;
        if (why.empty() && !there) why = io::writeFileAtomically(path, bytes, io::WriteSite::PageFile);
    }
    std::unique_ptr<VolumeGrid> written;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (why.empty()) {
            state_ = State::Written;
            path_ = path;
            fileBytes_ = size;
            written = std::move(grid_);
        } else {
            state_ = State::Failed;
            problem_ = why;
        }
    }
    changed_.notify_all();
    grid.reset();
    written.reset();  // a large tree freed off the lock, on this thread
}

std::unique_ptr<VolumeGrid> GridPage::takeBack() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return state_ != State::Writing; });
    if (state_ == State::Holding || state_ == State::Failed) {
        state_ = State::TakenBack;
        return std::move(grid_);
    }
    if (state_ == State::TakenBack) throw std::logic_error("a grid page taken back twice");
    if (readAhead_) return std::move(readAhead_);
    lock.unlock();
    return readFile();
}

void GridPage::readAhead() {
    std::unique_ptr<VolumeGrid> grid = readFile();
    std::lock_guard<std::mutex> lock(mutex_);
    readAhead_ = std::move(grid);
}

bool GridPage::readAheadReady() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return readAhead_ != nullptr;
}

std::unique_ptr<VolumeGrid> GridPage::readFile() const {
    const std::string file = path();
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read the paged grid " + file + ": " + std::strerror(errno));
    openvdb::FloatGrid::Ptr grid;
    try {
        ensureOpenVdbInitialized();
        openvdb::io::Stream stream(in);
        const openvdb::GridPtrVecPtr grids = stream.getGrids();
        if (grids && !grids->empty()) grid = openvdb::gridPtrCast<openvdb::FloatGrid>(grids->front());
    } catch (const std::exception& e) {
        throw std::runtime_error("cannot read the paged grid " + file + ": " + e.what());
    }
    if (!grid) throw std::runtime_error("cannot read the paged grid " + file + ": it holds no float grid");
    auto out = std::make_unique<VolumeGrid>();
    out->grid = std::move(grid);
    return out;
}

GridPage::State GridPage::state() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return state_;
}

std::string GridPage::problem() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return problem_;
}

std::string GridPage::path() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return path_;
}

std::size_t GridPage::fileBytes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return fileBytes_;
}

}  // namespace hg::voxel
