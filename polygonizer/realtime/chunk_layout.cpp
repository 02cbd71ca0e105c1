#include "polygonizer/realtime/chunk_layout.h"

#include <stdexcept>

namespace hg::poly {

namespace {

int floorDiv(int v, int d) { return v >= 0 ? v / d : -((-v + d - 1) / d); }

}  // namespace

ChunkLayout::ChunkLayout(const voxel::VolumeFrame& frame, int chunkSize) : frame_(frame), size_(chunkSize) {
    if (chunkSize != 16 && chunkSize != 32) throw std::invalid_argument("chunk size must be 16 or 32");
    for (int a = 0; a < 3; ++a) {
        first_[static_cast<size_t>(a)] = floorDiv(frame.indexBox.lo[a], size_);
        n_[static_cast<size_t>(a)] = floorDiv(frame.indexBox.hi[a], size_) - first_[static_cast<size_t>(a)] + 1;
    }
}

ChunkKey ChunkLayout::key(std::size_t index) const {
    const auto nx = static_cast<std::size_t>(n_[0]), ny = static_cast<std::size_t>(n_[1]);
    ChunkKey k;
    k.x = first_[0] + static_cast<int>(index % nx);
    k.y = first_[1] + static_cast<int>(index / nx % ny);
    k.z = first_[2] + static_cast<int>(index / (nx * ny));
    return k;
}

ChunkKey ChunkLayout::keyOf(int i, int j, int k) const {
    return {floorDiv(i, size_), floorDiv(j, size_), floorDiv(k, size_)};
}

bool ChunkLayout::contains(const ChunkKey& k) const {
    const int c[3] = {k.x, k.y, k.z};
    for (int a = 0; a < 3; ++a)
        if (c[a] < first_[static_cast<size_t>(a)] || c[a] >= first_[static_cast<size_t>(a)] + n_[static_cast<size_t>(a)])
            return false;
    return true;
}

std::size_t ChunkLayout::index(const ChunkKey& k) const {
    return (static_cast<std::size_t>(k.z - first_[2]) * static_cast<std::size_t>(n_[1]) +
            static_cast<std::size_t>(k.y - first_[1])) * static_cast<std::size_t>(n_[0]) +
           static_cast<std::size_t>(k.x - first_[0]);
}

std::vector<std::size_t> ChunkLayout::faceNeighbours(std::size_t i) const {
    std::vector<std::size_t> out;
    forEachFaceNeighbour(i, [&out](std::size_t n, int) { out.push_back(n); });
    return out;
}

voxel::IndexBox ChunkLayout::voxels(std::size_t i) const {
    const ChunkKey k = key(i);
    return voxel::IndexBox::fromCorners(k.x * size_, k.y * size_, k.z * size_, k.x * size_ + size_ - 1,
                                        k.y * size_ + size_ - 1, k.z * size_ + size_ - 1);
}

void ChunkLayout::modelBox(std::size_t i, double lo[3], double hi[3]) const {
    const voxel::IndexBox b = voxels(i);
    for (int a = 0; a < 3; ++a) {
        lo[a] = frame_.coordinate(a, b.lo[a]);
        hi[a] = frame_.coordinate(a, b.hi[a] + 1);  // the cells reach the next chunk's first voxel
    }
}

void ChunkLayout::modelBounds(double lo[3], double hi[3]) const {
    double unused[3];
    modelBox(0, lo, unused);
    modelBox(count() - 1, unused, hi);  // chunks are numbered x fastest: the last is the high corner's
}

}  // namespace hg::poly
