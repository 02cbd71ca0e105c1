#include "voxel/leaf_snapshot.h"

#include <array>
#include <bitset>

#include "voxel/volume_vdb.h"

namespace hg::voxel {

struct LeafSnapshot::Leaf {
    openvdb::Coord origin;
    std::array<float, FloatLeaf::SIZE> values;
    std::bitset<FloatLeaf::SIZE> active;
};

namespace {

std::uint64_t keyOf(const std::array<int, 3>& o) {
    const auto f = [](int v) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v + (1 << 20)) & 0x1fffffu); };
    return f(o[0]) | (f(o[1]) << 21) | (f(o[2]) << 42);
}

}  // namespace

LeafSnapshot::LeafSnapshot() = default;
LeafSnapshot::~LeafSnapshot() = default;
LeafSnapshot::LeafSnapshot(LeafSnapshot&&) noexcept = default;
LeafSnapshot& LeafSnapshot::operator=(LeafSnapshot&&) noexcept = default;

void LeafSnapshot::capture(const Volume& volume, const IndexBox& box) {
    const IndexBox clip = intersect(box, volume.frame.indexBox);
    const openvdb::FloatTree& tree = vdb(volume).tree();
    for (const auto& o : alignedBoxes(clip, static_cast<int>(FloatLeaf::DIM))) {
        const std::uint64_t key = keyOf(o);
        if (index_.count(key)) continue;
        Leaf leaf;
        leaf.origin = openvdb::Coord(o[0], o[1], o[2]);
        if (const FloatLeaf* l = tree.probeConstLeaf(leaf.origin)) {
            for (openvdb::Index i = 0; i < FloatLeaf::SIZE; ++i) {
                leaf.values[i] = l->getValue(i);
                leaf.active[i] = l->isValueOn(i);
            }
        } else {
            // A tile (or the background): one value and state for the leaf.
            const float v = tree.getValue(leaf.origin);
            const bool on = tree.isValueOn(leaf.origin);
            leaf.values.fill(v);
            if (on) leaf.active.set();
        }
        index_.emplace(key, leaves_.size());
        leaves_.push_back(leaf);
    }
}

void LeafSnapshot::restore(Volume& volume) const {
    openvdb::FloatTree& tree = vdb(volume).tree();
    for (const Leaf& leaf : leaves_) {
        FloatLeaf* l = tree.touchLeaf(leaf.origin);
        for (openvdb::Index i = 0; i < FloatLeaf::SIZE; ++i) {
            if (leaf.active[i]) l->setValueOn(i, leaf.values[i]);
            else l->setValueOff(i, leaf.values[i]);
        }
    }
}

std::size_t LeafSnapshot::bytes() const { return leaves_.size() * (sizeof(Leaf) + 16); }

}  // namespace hg::voxel
