// How a volume's index box is cut into chunks: cubes of 16 or 32 level-0
// voxels aligned with OpenVDB leaves (multiples of 8), each meshed at its
// own level of detail. Chunks are numbered x fastest, then y, then z.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "voxel/volume_frame.h"

namespace hg::poly {

struct ChunkKey {
    int x = 0, y = 0, z = 0;  // chunk index: voxels [key * size, key * size + size)
};

class ChunkLayout {
public:
    // `chunkSize` must be 16 or 32.
    ChunkLayout(const voxel::VolumeFrame& frame, int chunkSize);

    int chunkSize() const { return size_; }
    std::size_t count() const { return static_cast<std::size_t>(n_[0]) * static_cast<std::size_t>(n_[1]) * static_cast<std::size_t>(n_[2]); }
    const std::array<int, 3>& dims() const { return n_; }
    ChunkKey key(std::size_t index) const;
    // The chunk holding level-0 voxel (i, j, k), in the layout or not.
    ChunkKey keyOf(int i, int j, int k) const;
    std::size_t index(const ChunkKey& k) const;
    bool contains(const ChunkKey& k) const;
    // The six face neighbours that exist, as indices.
    std::vector<std::size_t> faceNeighbours(std::size_t index) const;
    // f(neighbour index, face) for each of them, in the same order, the
    // face numbered -x, +x, -y, +y, -z, +z from 0 (no allocation).
    template <class F>
    void forEachFaceNeighbour(std::size_t index, F&& f) const {
        const std::size_t nx = static_cast<std::size_t>(n_[0]), ny = static_cast<std::size_t>(n_[1]);
        const std::size_t x = index % nx, y = index / nx % ny, z = index / (nx * ny);
        if (x > 0) f(index - 1, 0);
        if (x + 1 < nx) f(index + 1, 1);
        if (y > 0) f(index - nx, 2);
        if (y + 1 < ny) f(index + nx, 3);
        if (z > 0) f(index - nx * ny, 4);
        if (z + 1 < static_cast<std::size_t>(n_[2])) f(index + nx * ny, 5);
    }
    // The chunk's voxels (index space) and its extent in the model frame.
    voxel::IndexBox voxels(std::size_t index) const;
    void modelBox(std::size_t index, double lo[3], double hi[3]) const;
    // The extent of every chunk together (the union of their model boxes).
    void modelBounds(double lo[3], double hi[3]) const;
    const voxel::VolumeFrame& frame() const { return frame_; }

private:
    voxel::VolumeFrame frame_;
    int size_;
    std::array<int, 3> first_{};  // key of the chunk holding the index box's low corner
    std::array<int, 3> n_{};
};

}  // namespace hg::poly
