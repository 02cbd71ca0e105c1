#include "polygonizer/realtime/chunk_errors.h"

#include <algorithm>
#include <chrono>
#include <utility>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "polygonizer/realtime/lod_pyramid.h"
#include "polygonizer/realtime/lod_selection.h"
#include "voxel/volume_vdb.h"

namespace hg::poly {

namespace {

// Level-0 voxels this near the surface (in voxels) are where the surfaces
// are compared: a coarse surface that strays further from the fine one
// than this is still seen, from the fine surface's side.
constexpr float kNear = 2.0f;
// The least slope a distance is measured with (value per voxel): where a
// field is flatter, its surface is ill-defined, and its errors count as
// if it were this steep.
constexpr float kFlattest = 0.25f;

// Whether any voxel of the level-0 box (the chunk and the samples on its
// far faces) lies within kNear of the surface: only leaves can (tiles hold
// the band's clamped value), so this is one probe per 8^3 block.
bool nearSurface(const openvdb::FloatTree& tree, const voxel::IndexBox& box, float near) {
    for (int z = box.lo[2] & ~7; z <= box.hi[2]; z += 8)
        for (int y = box.lo[1] & ~7; y <= box.hi[1]; y += 8)
            for (int x = box.lo[0] & ~7; x <= box.hi[0]; x += 8) {
                const openvdb::Coord origin(x, y, z);
                if (const auto* leaf = tree.probeConstLeaf(origin)) {
                    for (auto v = leaf->cbeginValueOn(); v; ++v)
                        if (std::fabs(*v) < near) return true;
                } else if (std::fabs(tree.getValue(origin)) < near) {
                    return true;
                }
            }
    return false;
}

}  // namespace

ChunkErrors::ChunkErrors(const LodPyramid& pyramid, const ChunkLayout& layout)
    : pyramid_(pyramid), layout_(layout), levels_(pyramid.levels()), count_(layout.count()) {
    errors_.assign(count_ * static_cast<std::size_t>(std::max(levels_ - 1, 0)), 0.0f);
    isUnknown_.assign(count_, false);
    std::vector<std::size_t> all(count_);
    for (std::size_t c = 0; c < count_; ++c) all[c] = c;
    measure(all);
    summarize();
}

ChunkErrors::ChunkErrors(const ChunkErrors& source, const LodPyramid& pyramid, const ChunkLayout& layout)
    : pyramid_(pyramid),
      layout_(layout),
      levels_(source.levels_),
      count_(source.count_),
      version_(source.version_),
      errors_(source.errors_),
      largest_(source.largest_),
      smallest_(source.smallest_),
      unknown_(source.unknown_),
      isUnknown_(source.isUnknown_) {
    if (pyramid.levels() != levels_ || layout.count() != count_)
        throw std::invalid_argument("level errors copied onto a pyramid or layout of another shape");
}

std::size_t ChunkErrors::update(const voxel::IndexBox& box) {
    if (box.empty() || levels_ < 2) return 0;
    // A changed voxel moves the coarse samples it is, and the blends of
    // every level-0 voxel within one coarsest cell of it.
    const int reach = 1 << (levels_ - 1);
    const ChunkKey lo = layout_.keyOf(box.lo[0] - reach, box.lo[1] - reach, box.lo[2] - reach);
    const ChunkKey hi = layout_.keyOf(box.hi[0] + reach, box.hi[1] + reach, box.hi[2] + reach);
    const std::size_t perChunk = static_cast<std::size_t>(levels_ - 1);
    std::size_t changed = 0;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                if (!layout_.contains({x, y, z})) continue;
                const std::size_t c = layout_.index({x, y, z});
                std::fill_n(errors_.begin() + static_cast<std::ptrdiff_t>(c * perChunk), perChunk, INFINITY);
                if (!isUnknown_[c]) {
                    isUnknown_[c] = true;
                    unknown_.push_back(c);
                }
                ++changed;
            }
    summarize();
    ++version_;
    return changed;
}

std::size_t ChunkErrors::refresh(const std::array<double, 3>& viewer, double milliseconds) {
    if (unknown_.empty()) return 0;
    const auto start = std::chrono::steady_clock::now();
    // Nearest last in the list: taken from the back.
    std::vector<std::pair<double, std::size_t>> order;
    order.reserve(unknown_.size());
    for (std::size_t c : unknown_) order.emplace_back(distanceToChunk(layout_, c, viewer), c);
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    // Two chunks a worker a batch (a chunk takes a tenth of a millisecond or so).
    const std::size_t batch = 2 * static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    std::size_t measured = 0;
    std::vector<std::size_t> chunks;
    while (!order.empty()) {
        chunks.clear();
        while (!order.empty() && chunks.size() < batch) {
            chunks.push_back(order.back().second);
            order.pop_back();
        }
        measure(chunks);
        for (std::size_t c : chunks) isUnknown_[c] = false;
        measured += chunks.size();
        if (milliseconds > 0.0 &&
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() >= milliseconds)
            break;
    }
    unknown_.clear();
    for (auto it = order.rbegin(); it != order.rend(); ++it) unknown_.push_back(it->second);
    summarize();
    ++version_;
    return measured;
}

void ChunkErrors::measure(const std::vector<std::size_t>& chunks) {
    const std::size_t perChunk = static_cast<std::size_t>(levels_ - 1);
    if (perChunk == 0) return;
    const voxel::Volume& volume = pyramid_.volume();
    const float near = std::min(kNear, volume.frame.band);
    const int size = layout_.chunkSize();
    const int side = size + 1;  // the chunk's voxels and the samples on its far faces
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size()), [&](const tbb::blocked_range<std::size_t>& r) {
        const openvdb::FloatTree& tree = voxel::vdb(volume).tree();
        std::vector<float> block(static_cast<std::size_t>(side) * static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
        for (std::size_t n = r.begin(); n != r.end(); ++n) {
            const std::size_t chunk = chunks[n];
            float* out = errors_.data() + chunk * perChunk;
            std::fill(out, out + perChunk, 0.0f);
            const voxel::IndexBox voxels = layout_.voxels(chunk);
            const voxel::IndexBox box = voxel::IndexBox::fromCorners(voxels.lo[0], voxels.lo[1], voxels.lo[2],
                                                                     voxels.hi[0] + 1, voxels.hi[1] + 1, voxels.hi[2] + 1);
            if (!nearSurface(tree, box, near)) continue;
            pyramid_.gather(0, box, block.data());
            const auto at = [&](int i, int j, int k) {
                return block[(static_cast<std::size_t>(k) * static_cast<std::size_t>(side) + static_cast<std::size_t>(j)) *
                                 static_cast<std::size_t>(side) +
                             static_cast<std::size_t>(i)];
            };
            // The field's slope (value per voxel) at a voxel of the chunk:
            // a value apart is 1 / slope voxels apart. HyperFun fields are
            // not distances; a nearly flat one is held at kFlattest.
            const auto slope = [&](int i, int j, int k) {
                const auto diff = [&](int a) {
                    const int d[3] = {a == 0, a == 1, a == 2};
                    const int lo[3] = {std::max(i - d[0], 0), std::max(j - d[1], 0), std::max(k - d[2], 0)};
                    const int hi[3] = {i + d[0], j + d[1], k + d[2]};  // at most `size`: in the block
                    return (at(hi[0], hi[1], hi[2]) - at(lo[0], lo[1], lo[2])) /
                           static_cast<float>(hi[a] - lo[a]);
                };
                const float gx = diff(0), gy = diff(1), gz = diff(2);
                return std::max(std::sqrt(gx * gx + gy * gy + gz * gz), kFlattest);
            };
            // The chunk's low corner is a multiple of its size, so every
            // level's lattice starts at the block's origin.
            for (int k = 0; k < size; ++k)
                for (int j = 0; j < size; ++j)
                    for (int i = 0; i < size; ++i) {
                        const float fine = at(i, j, k);
                        if (!(std::fabs(fine) < near)) continue;
                        for (int level = 1; level < levels_; ++level) {
                            const int s = 1 << level;
                            const int i0 = i & ~(s - 1), j0 = j & ~(s - 1), k0 = k & ~(s - 1);
                            const float tx = static_cast<float>(i - i0) / static_cast<float>(s);
                            const float ty = static_cast<float>(j - j0) / static_cast<float>(s);
                            const float tz = static_cast<float>(k - k0) / static_cast<float>(s);
                            const auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
                            const auto edge = [&](int jj, int kk) { return lerp(at(i0, jj, kk), at(i0 + s, jj, kk), tx); };
                            const float coarse = lerp(lerp(edge(j0, k0), edge(j0 + s, k0), ty),
                                                      lerp(edge(j0, k0 + s), edge(j0 + s, k0 + s), ty), tz);
                            if (std::fabs(fine) < 1.0f || std::fabs(coarse) < 1.0f) {
                                float& e = out[static_cast<std::size_t>(level - 1)];
                                e = std::max(e, std::fabs(fine - coarse) / slope(i, j, k));
                            }
                        }
                    }
            for (std::size_t l = 1; l < perChunk; ++l) out[l] = std::max(out[l], out[l - 1]);
        }
    });
}

void ChunkErrors::summarize() {
    const std::size_t perChunk = static_cast<std::size_t>(std::max(levels_ - 1, 0));
    largest_.assign(perChunk, 0.0f);
    smallest_.assign(perChunk, count_ > 0 ? INFINITY : 0.0f);
    for (std::size_t c = 0; c < count_; ++c)
        for (std::size_t l = 0; l < perChunk; ++l) {
            largest_[l] = std::max(largest_[l], errors_[c * perChunk + l]);
            smallest_[l] = std::min(smallest_[l], errors_[c * perChunk + l]);
        }
}

}  // namespace hg::poly
