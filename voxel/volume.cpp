#include "voxel/volume.h"

#include <mutex>
#include <stdexcept>

#include "voxel/grid_page.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {

void ensureOpenVdbInitialized() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

openvdb::math::Transform::Ptr frameTransform(const VolumeFrame& frame) {
    auto xform = openvdb::math::Transform::createLinearTransform(frame.voxelSize);
    xform->postTranslate(openvdb::Vec3d(frame.modelBox.lo[0], frame.modelBox.lo[1], frame.modelBox.lo[2]));
    return xform;
}

const char* boxOriginName(BoxOrigin origin) {
    switch (origin) {
        case BoxOrigin::Given: return "given";
        case BoxOrigin::IntervalEstimate: return "interval estimate";
        case BoxOrigin::Sampled: return "sampled";
    }
    return "given";
}

Volume::Volume() : grid_(std::make_unique<VolumeGrid>()) {
    ensureOpenVdbInitialized();
    grid_->grid = openvdb::FloatGrid::create(-frame.band);
}

Volume::~Volume() = default;

Volume::Volume(Volume&& o) noexcept
    : frame(std::move(o.frame)),
      normalization(o.normalization),
      boxOrigin(o.boxOrigin),
      kind(o.kind),
      source(std::move(o.source)),
      grid_(std::move(o.grid_)),
      page_(std::move(o.page_)),
      resident_(o.resident_.load(std::memory_order_acquire)),
      readFrom_(std::move(o.readFrom_)),
      touched_(o.touched_.load(std::memory_order_relaxed)) {
    o.resident_.store(false, std::memory_order_release);
}

Volume& Volume::operator=(Volume&& o) noexcept {
    if (this == &o) return *this;
    frame = std::move(o.frame);
    normalization = o.normalization;
    boxOrigin = o.boxOrigin;
    kind = o.kind;
    source = std::move(o.source);
    grid_ = std::move(o.grid_);
    page_ = std::move(o.page_);
    resident_.store(o.resident_.load(std::memory_order_acquire), std::memory_order_release);
    readFrom_ = std::move(o.readFrom_);
    touched_.store(o.touched_.load(std::memory_order_relaxed), std::memory_order_relaxed);
    o.resident_.store(false, std::memory_order_release);
    return *this;
}

namespace {
// Bringing grids back is rare (a far sculpture edited or exported before
// the pager's job read it back): one lock for every volume keeps Volume
// movable.
std::mutex& pageLock() {
    static std::mutex m;
    return m;
}
}  // namespace

VolumeGrid& Volume::bringBack() const {
    std::lock_guard<std::mutex> lock(pageLock());
    if (!resident_.load(std::memory_order_acquire)) {
        if (!page_) throw std::logic_error("a volume read after it was moved from");
        const bool fromFile = page_->state() == GridPage::State::Written;
        grid_ = page_->takeBack();
        readFrom_ = fromFile ? page_->path() : std::string();
        touched_.store(!fromFile, std::memory_order_relaxed);
        page_.reset();
        resident_.store(true, std::memory_order_release);
    }
    return *grid_;
}

std::shared_ptr<GridPage> Volume::pageOut(const std::string& folder) {
    if (!resident()) return page_;
    std::lock_guard<std::mutex> lock(pageLock());
    page_ = std::make_shared<GridPage>(std::move(grid_), folder,
                                       touched_.load(std::memory_order_relaxed) ? std::string() : readFrom_);
    resident_.store(false, std::memory_order_release);
    return page_;
}

bool Volume::adoptReadAhead() {
    std::lock_guard<std::mutex> lock(pageLock());
    if (resident_.load(std::memory_order_acquire) || !page_ || !page_->readAheadReady()) return false;
    // The file stays on disk for the next time; only the page's claim on
    // this volume ends.
    grid_ = page_->takeBack();
    readFrom_ = page_->path();
    touched_.store(false, std::memory_order_relaxed);
    page_.reset();
    resident_.store(true, std::memory_order_release);
    return true;
}

Volume Volume::clone() const {
    Volume c;
    c.frame = frame;
    c.normalization = normalization;
    c.boxOrigin = boxOrigin;
    c.kind = kind;
    c.source = source;
    c.grid_->grid = grid().grid->deepCopy();
    return c;
}

float Volume::value(int i, int j, int k) const { return grid().grid->tree().getValue(openvdb::Coord(i, j, k)); }

bool Volume::active(int i, int j, int k) const { return grid().grid->tree().isValueOn(openvdb::Coord(i, j, k)); }

std::size_t Volume::activeVoxelCount() const { return static_cast<std::size_t>(grid().grid->activeVoxelCount()); }

std::size_t Volume::leafCount() const { return static_cast<std::size_t>(grid().grid->tree().leafCount()); }

std::size_t Volume::memoryBytes() const { return resident() ? static_cast<std::size_t>(grid_->grid->memUsage()) : 0; }

}  // namespace hg::voxel
