#include "polygonizer/realtime/chunk_mesher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "polygonizer/cell_table.h"
#include "polygonizer/realtime/transition_table.h"

namespace hg::poly {

std::vector<ChunkLod> chunkLods(const ChunkLayout& layout, const std::vector<int>& levels) {
    if (levels.size() != layout.count()) throw std::invalid_argument("one level per chunk expected");
    std::vector<ChunkLod> out(levels.size());
    // The layout's own neighbour walk (no key and six lookups a chunk):
    // the LOD stage asks this for every sculpture that takes new levels.
    for (std::size_t i = 0; i < levels.size(); ++i) {
        out[i].level = levels[i];
        layout.forEachFaceNeighbour(i, [&](std::size_t j, int f) {
            const int ln = levels[j];
            if (std::abs(ln - levels[i]) > 1)
                throw std::invalid_argument("chunks " + std::to_string(i) + " and " + std::to_string(j) +
                                            " are face neighbours " + std::to_string(std::abs(ln - levels[i])) +
                                            " levels apart (at most 1)");
            if (ln == levels[i] - 1) out[i].transitionFaces = static_cast<std::uint8_t>(out[i].transitionFaces | (1 << f));
        });
    }
    return out;
}

namespace {

using Vec3 = std::array<double, 3>;

void fillBlock(SampleBlock& block, const LodPyramid& pyramid, int level, const voxel::IndexBox& box) {
    block.box = box;
    block.values.resize(static_cast<std::size_t>(box.volume()));
    pyramid.gather(level, box, block.values.data());
}

// A gathered block read in chunk-local sample indices of its level (0 at
// the chunk's low corner).
class LocalBlock {
public:
    LocalBlock() = default;
    LocalBlock(const SampleBlock& block, int level, const int chunkOrigin[3]) : block_(&block) {
        for (int a = 0; a < 3; ++a) local_[a] = chunkOrigin[a] >> level;
    }
    float at(const int p[3]) const {
        const int q[3] = {p[0] + local_[0], p[1] + local_[1], p[2] + local_[2]};
        return block_->at(q);
    }
    // Central differences, in this level's sample units.
    Vec3 gradient(const int p[3]) const {
        Vec3 g{};
        for (int a = 0; a < 3; ++a) {
            int lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
            --lo[a];
            ++hi[a];
            g[static_cast<std::size_t>(a)] = 0.5 * (static_cast<double>(at(hi)) - static_cast<double>(at(lo)));
        }
        return g;
    }

private:
    const SampleBlock* block_ = nullptr;
    int local_[3] = {0, 0, 0};
};

// The crossing vertex of each coarse edge, kept per thread and reused by
// every chunk it meshes: a generation stamp says which entries belong to
// the chunk at hand, so no chunk pays for clearing its 3 (n + 1)^3 slots
// (that clearing was a tenth of a remesh).
class EdgeVertexTable {
public:
    void begin(std::size_t size) {
        if (entries_.size() < size) entries_.resize(size, 0);
        if (++generation_ == 0) {  // wrapped: stale stamps could match again
            std::fill(entries_.begin(), entries_.end(), 0);
            generation_ = 1;
        }
    }
    bool find(std::size_t slot, std::uint32_t& vertex) const {
        const std::uint64_t e = entries_[slot];
        if ((e >> 32) != generation_) return false;
        vertex = static_cast<std::uint32_t>(e);
        return true;
    }
    void set(std::size_t slot, std::uint32_t vertex) {
        entries_[slot] = (static_cast<std::uint64_t>(generation_) << 32) | vertex;
    }

private:
    std::vector<std::uint64_t> entries_;
    std::uint32_t generation_ = 0;
};

thread_local EdgeVertexTable tEdgeVertices;

class ChunkMesher {
public:
    explicit ChunkMesher(const ChunkSamples& samples) : frame_(samples.frame), lod_(samples.lod) {
        cell_ = 1 << lod_.level;
        n_ = samples.chunkSize >> lod_.level;
        for (int a = 0; a < 3; ++a) origin_[a] = samples.origin[a];
        coarse_ = LocalBlock(samples.coarse, lod_.level, origin_);
        for (int f = 0; f < kChunkFaces; ++f)
            if (lod_.transitionFaces & (1 << f)) fine_[f] = LocalBlock(samples.fine[f], lod_.level - 1, origin_);
        tEdgeVertices.begin(3 * static_cast<std::size_t>(n_ + 1) * static_cast<std::size_t>(n_ + 1) *
                            static_cast<std::size_t>(n_ + 1));
    }

    Mesh run(ChunkMeshStats& stats) {
        regularCells(stats);
        for (int f = 0; f < kChunkFaces; ++f)
            if (lod_.transitionFaces & (1 << f)) transitionFace(f, stats);
        return std::move(mesh_);
    }

private:
    // --- coarse (the chunk's level) samples, chunk-local indices 0..n -----
    float coarseValue(const int p[3]) const { return coarse_.at(p); }
    // Level-0 index position, shrunk away from transition faces unless the
    // sample also lies on a face without transitions (pinned).
    Vec3 coarsePosition(const int p[3]) const {
        Vec3 pos{};
        std::uint8_t on = 0;
        for (int a = 0; a < 3; ++a) {
            pos[static_cast<std::size_t>(a)] = static_cast<double>(origin_[a] + p[a] * cell_);
            if (p[a] == 0) on = static_cast<std::uint8_t>(on | (1 << (2 * a)));
            if (p[a] == n_) on = static_cast<std::uint8_t>(on | (1 << (2 * a + 1)));
        }
        if (on == 0 || (on & ~lod_.transitionFaces)) return pos;
        const double w = 0.5 * cell_;
        for (int f = 0; f < kChunkFaces; ++f)
            if (on & (1 << f)) pos[static_cast<std::size_t>(f / 2)] += f % 2 ? -w : w;
        return pos;
    }
    Vec3 coarseGradient(const int p[3]) const { return coarse_.gradient(p); }

    // The crossing on the coarse edge from sample p along `axis`.
    std::uint32_t coarseVertex(const int p[3], int axis) {
        const std::size_t m = static_cast<std::size_t>(n_ + 1);
        const std::size_t slot = ((static_cast<std::size_t>(axis) * m + static_cast<std::size_t>(p[2])) * m +
                                  static_cast<std::size_t>(p[1])) * m + static_cast<std::size_t>(p[0]);
        std::uint32_t found = 0;
        if (tEdgeVertices.find(slot, found)) return found;
        int q[3] = {p[0], p[1], p[2]};
        ++q[axis];
        const std::uint32_t id = addVertex(coarsePosition(p), coarsePosition(q), coarseValue(p), coarseValue(q),
                                           coarseGradient(p), coarseGradient(q));
        tEdgeVertices.set(slot, id);
        return id;
    }

    // --- fine (level - 1) samples on transition faces, chunk-local 0..2n --
    std::uint32_t fineVertex(const LocalBlock& b, const int p[3], int axis) {
        const std::uint32_t m = static_cast<std::uint32_t>(2 * n_ + 1);
        const std::uint32_t key = ((static_cast<std::uint32_t>(axis) * m + static_cast<std::uint32_t>(p[2])) * m +
                                   static_cast<std::uint32_t>(p[1])) * m + static_cast<std::uint32_t>(p[0]);
        auto it = fineVertex_.find(key);
        if (it != fineVertex_.end()) return it->second;
        int q[3] = {p[0], p[1], p[2]};
        ++q[axis];
        const int half = cell_ / 2;
        Vec3 pp{}, pq{};
        for (int a = 0; a < 3; ++a) {
            pp[static_cast<std::size_t>(a)] = static_cast<double>(origin_[a] + p[a] * half);
            pq[static_cast<std::size_t>(a)] = static_cast<double>(origin_[a] + q[a] * half);
        }
        const std::uint32_t id =
            addVertex(pp, pq, b.at(p), b.at(q), b.gradient(p), b.gradient(q));
        fineVertex_.emplace(key, id);
        return id;
    }

    // The crossing between p (the lower end) and q, in model units. Clamped
    // away from the ends like the export mesher's, for the same reason
    // (zero-area triangles at grid points).
    std::uint32_t addVertex(const Vec3& p, const Vec3& q, float vp, float vq, const Vec3& gp, const Vec3& gq) {
        const double d0 = vp, d1 = vq;
        const double t = std::clamp(d0 / (d0 - d1), 1e-3, 1.0 - 1e-3);
        Vec3 g{};
        double len2 = 0.0;
        for (std::size_t a = 0; a < 3; ++a) {
            const double x = p[a] + t * (q[a] - p[a]);
            mesh_.positions.push_back(static_cast<float>(frame_.modelBox.lo[a] + x * frame_.voxelSize));
            g[a] = gp[a] * (1.0 - t) + gq[a] * t;
            len2 += g[a] * g[a];
        }
        const double inv = len2 > 0.0 ? -1.0 / std::sqrt(len2) : 0.0;  // f grows inwards
        for (std::size_t a = 0; a < 3; ++a) mesh_.normals.push_back(static_cast<float>(g[a] * inv));
        return static_cast<std::uint32_t>(mesh_.positions.size() / 3 - 1);
    }

    void regularCells(ChunkMeshStats& stats) {
        const auto& table = cellTable();
        const int m = n_ + 1;
        stats.regularCells += static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
        // Signs first, one byte per sample: the cell loop then reads bytes.
        std::vector<std::uint8_t> inside(static_cast<std::size_t>(m) * static_cast<std::size_t>(m) * static_cast<std::size_t>(m));
        std::size_t count = 0;
        for (int z = 0; z < m; ++z)
            for (int y = 0; y < m; ++y)
                for (int x = 0; x < m; ++x) {
                    const int p[3] = {x, y, z};
                    const bool in = coarseValue(p) > 0.0f;
                    inside[static_cast<std::size_t>((z * m + y) * m + x)] = in;
                    count += in;
                }
        if (count == 0 || count == inside.size()) return;
        const std::size_t corner[8] = {0, 1, static_cast<std::size_t>(m), static_cast<std::size_t>(m + 1),
                                       static_cast<std::size_t>(m * m), static_cast<std::size_t>(m * m + 1),
                                       static_cast<std::size_t>(m * m + m), static_cast<std::size_t>(m * m + m + 1)};
        for (int z = 0; z < n_; ++z)
            for (int y = 0; y < n_; ++y)
                for (int x = 0; x < n_; ++x) {
                    const std::uint8_t* c = &inside[static_cast<std::size_t>((z * m + y) * m + x)];
                    int mask = 0;
                    for (int k = 0; k < 8; ++k) mask |= c[corner[k]] << k;
                    if (mask == 0 || mask == 255) continue;
                    ++stats.surfaceCells;
                    const CellCase& cc = table[static_cast<std::size_t>(mask)];
                    for (int i = 0; i < 3 * cc.triangleCount; ++i) {
                        const int e = cc.edges[static_cast<std::size_t>(i)];
                        const int c0 = kEdgeCorners[static_cast<std::size_t>(e)][0];
                        const int p[3] = {x + (c0 & 1), y + ((c0 >> 1) & 1), z + ((c0 >> 2) & 1)};
                        mesh_.indices.push_back(coarseVertex(p, kEdgeAxis[static_cast<std::size_t>(e)]));
                    }
                }
    }

    // Face f: axis a = f / 2, on the low (f even) or high side. Cell-local
    // (u, v, w) maps to axes (a + 1, a + 2, a) with w pointing into the
    // chunk: right-handed on the low side; on the high side w flips, and so
    // does the winding.
    void transitionFace(int f, ChunkMeshStats& stats) {
        const int a = f / 2, u = (a + 1) % 3, v = (a + 2) % 3;
        const bool high = f % 2 != 0;
        const int finePlane = high ? 2 * n_ : 0;
        const LocalBlock& fine = fine_[f];

        const TransitionGeometry& g = transitionGeometry();
        const auto& table = transitionTable();
        static constexpr int kBackOf[4] = {0, 2, 6, 8};
        stats.transitionCells += static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
        for (int cv = 0; cv < n_; ++cv)
            for (int cu = 0; cu < n_; ++cu) {
                int fineAt[9][3];
                int mask = 0;
                for (int t = 0; t < 9; ++t) {
                    fineAt[t][a] = finePlane;
                    fineAt[t][u] = 2 * cu + t % 3;
                    fineAt[t][v] = 2 * cv + t / 3;
                    if (fine.at(fineAt[t]) > 0.0f) mask |= 1 << t;
                }
                if (mask == 0 || mask == 511) continue;
                ++stats.surfaceCells;
                const TransitionCase& tc = table[static_cast<std::size_t>(mask)];
                for (int tri = 0; tri < tc.triangleCount; ++tri) {
                    std::uint32_t idx[3];
                    for (int k = 0; k < 3; ++k) {
                        const auto& edge = g.edges[tc.edges[static_cast<std::size_t>(3 * tri + k)]];
                        if (edge[0] < 9) {  // both on the fine side (fine-back edges never cross)
                            const int* p = fineAt[edge[0]];
                            const int* q = fineAt[edge[1]];
                            int axis = p[u] != q[u] ? u : v;
                            idx[k] = fineVertex(fine, p[axis] < q[axis] ? p : q, axis);
                        } else {  // both on the back: a coarse edge of the shrunk cells
                            const int t0 = kBackOf[edge[0] - 9], t1 = kBackOf[edge[1] - 9];
                            int p[3], q[3];
                            p[a] = q[a] = high ? n_ : 0;
                            p[u] = cu + (t0 % 3) / 2;
                            p[v] = cv + (t0 / 3) / 2;
                            q[u] = cu + (t1 % 3) / 2;
                            q[v] = cv + (t1 / 3) / 2;
                            int axis = p[u] != q[u] ? u : v;
                            idx[k] = coarseVertex(p[axis] < q[axis] ? p : q, axis);
                        }
                    }
                    if (high) std::swap(idx[1], idx[2]);
                    mesh_.indices.insert(mesh_.indices.end(), idx, idx + 3);
                }
            }
    }

    const voxel::VolumeFrame& frame_;
    ChunkLod lod_;
    int cell_ = 1, n_ = 0;
    int origin_[3] = {0, 0, 0};  // level-0 index of the chunk's low corner
    LocalBlock coarse_;
    LocalBlock fine_[kChunkFaces];
    std::unordered_map<std::uint32_t, std::uint32_t> fineVertex_;
    Mesh mesh_;
};

}  // namespace

ChunkSamples gatherChunk(const LodPyramid& pyramid, const ChunkLayout& layout, std::size_t chunk, const ChunkLod& lod) {
    if (lod.level < 0 || lod.level >= pyramid.levels())
        throw std::invalid_argument("chunk level " + std::to_string(lod.level) + " is not in the pyramid");
    if (lod.level == 0 && lod.transitionFaces)
        throw std::invalid_argument("a level-0 chunk has no finer neighbour to stitch to");
    ChunkSamples s;
    s.frame = layout.frame();
    s.lod = lod;
    s.chunkSize = layout.chunkSize();
    const ChunkKey k = layout.key(chunk);
    const int key[3] = {k.x, k.y, k.z};
    for (int a = 0; a < 3; ++a) s.origin[a] = key[a] * layout.chunkSize();
    const int n = layout.chunkSize() >> lod.level;
    voxel::IndexBox coarse;
    for (int a = 0; a < 3; ++a) {
        coarse.lo[a] = (s.origin[a] >> lod.level) - 1;
        coarse.hi[a] = (s.origin[a] >> lod.level) + n + 1;
    }
    fillBlock(s.coarse, pyramid, lod.level, coarse);
    // Each transition face's fine samples: the face's plane of the finer
    // level, one sample deep on either side (for gradients).
    const int fl = lod.level - 1;
    for (int f = 0; f < kChunkFaces; ++f) {
        if (!(lod.transitionFaces & (1 << f))) continue;
        const int a = f / 2;
        const int finePlane = f % 2 != 0 ? 2 * n : 0;
        voxel::IndexBox box;
        for (int b = 0; b < 3; ++b) {
            const int base = s.origin[b] >> fl;
            box.lo[b] = base - 1;
            box.hi[b] = base + 2 * n + 1;
        }
        box.lo[a] = (s.origin[a] >> fl) + finePlane - 1;
        box.hi[a] = (s.origin[a] >> fl) + finePlane + 1;
        fillBlock(s.fine[f], pyramid, fl, box);
    }
    return s;
}

Mesh meshChunk(const ChunkSamples& samples, ChunkMeshStats* stats) {
    ChunkMesher mesher(samples);
    ChunkMeshStats local;
    Mesh m = mesher.run(local);
    if (stats) *stats = local;
    return m;
}

Mesh meshChunk(const LodPyramid& pyramid, const ChunkLayout& layout, std::size_t chunk, const ChunkLod& lod,
               ChunkMeshStats* stats) {
    return meshChunk(gatherChunk(pyramid, layout, chunk, lod), stats);
}

}  // namespace hg::poly
