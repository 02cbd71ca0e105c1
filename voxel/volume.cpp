#include "voxel/volume.h"

#include <mutex>

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
Volume::Volume(Volume&&) noexcept = default;
Volume& Volume::operator=(Volume&&) noexcept = default;

Volume Volume::clone() const {
    Volume c;
    c.frame = frame;
    c.normalization = normalization;
    c.boxOrigin = boxOrigin;
    c.kind = kind;
    c.source = source;
    c.grid_->grid = grid_->grid->deepCopy();
    return c;
}

float Volume::value(int i, int j, int k) const { return grid_->grid->tree().getValue(openvdb::Coord(i, j, k)); }

bool Volume::active(int i, int j, int k) const { return grid_->grid->tree().isValueOn(openvdb::Coord(i, j, k)); }

std::size_t Volume::activeVoxelCount() const { return static_cast<std::size_t>(grid_->grid->activeVoxelCount()); }

std::size_t Volume::leafCount() const { return static_cast<std::size_t>(grid_->grid->tree().leafCount()); }

std::size_t Volume::memoryBytes() const { return static_cast<std::size_t>(grid_->grid->memUsage()); }

}  // namespace hg::voxel
