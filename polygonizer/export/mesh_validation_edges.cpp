#include "polygonizer/export/mesh_validation_edges.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <limits>
#include <memory>

namespace hg::poly {

namespace {

// Parts by union-find over triangle numbers, on many threads at once. A
// root is only ever linked under a smaller number, by compare-and-swap (so
// two threads cannot both link it), which keeps every parent below its
// child: no cycles. A path is halved by storing a grandparent without a
// swap: a racing thread may store an older one, but any ancestor stays an
// ancestor, so only the compression is lost. The roots left at the end are
// the parts, whatever order the unions came in.
template <class Id>
class ConcurrentUnionFind {
public:
    explicit ConcurrentUnionFind(std::size_t n) : parent_(new std::atomic<Id>[n]) {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) parent_[i].store(static_cast<Id>(i), kRelaxed);
        });
    }

    Id find(Id x) {
        while (true) {
            const Id p = parent_[x].load(kRelaxed);
            if (p == x) return x;
            const Id g = parent_[p].load(kRelaxed);
            if (g != p) parent_[x].store(g, kRelaxed);
            x = g;
        }
    }

    void unite(Id a, Id b) {
        while (true) {
            a = find(a);
            b = find(b);
            if (a == b) return;
            if (a < b) std::swap(a, b);
            Id expected = a;
            if (parent_[a].compare_exchange_weak(expected, b, kRelaxed)) return;
        }
    }

    bool isRoot(std::size_t x) const { return parent_[x].load(kRelaxed) == static_cast<Id>(x); }

private:
    static constexpr std::memory_order kRelaxed = std::memory_order_relaxed;
    std::unique_ptr<std::atomic<Id>[]> parent_;
};

// One thread's hash table of a bucket's edges (open addressing, linear
// probing), and what a pass over the bucket's uses leaves to do. The table
// has at least one and a half times as many slots as the bucket has uses,
// so it is never full, and about three times as many as a welded mesh's
// bucket has edges, so a probe nearly always ends at its first slot. It is
// not cleared between buckets: a slot belongs to the bucket whose stamp
// (bucket + 1) it carries.
template <class Id>
struct EdgeTable {
    struct Slot {
        std::uint64_t key;  // lower << 32 | upper
        Id firstTriangle;   // of the edge's first use
        std::uint32_t stamp;
        std::uint32_t uses;
        std::uint32_t forward;  // uses from the lower vertex to the upper one
    };
    std::vector<Slot> slots;
    std::size_t mask = 0;
    int bits = 0;
    std::vector<std::size_t> edges;        // the slot of each edge, in order of first use
    std::vector<std::array<Id, 2>> joins;  // triangles sharing an edge

    void start(std::size_t uses) {
        bits = 4;
        while ((std::size_t{1} << bits) < uses + uses / 2 + 1) ++bits;
        if (slots.size() < (std::size_t{1} << bits)) slots.assign(std::size_t{1} << bits, Slot{});
        mask = (std::size_t{1} << bits) - 1;
        edges.resize(uses);
        joins.resize(uses);
    }
};

// Edge uses are numbered 4t + k: corner k (0..2) of triangle t to the next
// corner.
template <class Id>
Id useOf(std::size_t t, int k) {
    return static_cast<Id>(4 * t + static_cast<std::size_t>(k));
}

template <class Id>
EdgeCensus census(const Mesh& mesh, const std::vector<std::uint8_t>& live, const EdgeLayout& layout) {
    const std::size_t triangles = mesh.triangleCount();
    const std::size_t vertices = mesh.vertexCount();
    const std::uint32_t* idx = mesh.indices.data();
    const std::size_t chunkSize = std::max<std::size_t>(1, layout.chunkTriangles);
    const std::size_t chunks = (triangles + chunkSize - 1) / chunkSize;
    const int shift = layout.bucketShift;
    const std::size_t buckets = (vertices >> shift) + 1;

    // Calls use(row, t, k, bucket) for edge k of each counted triangle t.
    // Each chunk has a row of counts per corner k: consecutive triangles
    // then rarely add to one counter twice in a row, which would wait on
    // the previous addition.
    const std::size_t rows = 3 * chunks;
    auto forChunks = [&](auto use) {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t c = r.begin(); c != r.end(); ++c)
                for (std::size_t t = c * chunkSize; t < std::min(triangles, (c + 1) * chunkSize); ++t) {
                    if (!live[t]) continue;
                    const std::uint32_t* v = idx + 3 * t;
                    use(3 * c, t, 0, std::min(v[0], v[1]) >> shift);
                    use(3 * c + 1, t, 1, std::min(v[1], v[2]) >> shift);
                    use(3 * c + 2, t, 2, std::min(v[2], v[0]) >> shift);
                }
        });
    };

    // Uses per row and bucket, then where each row's go in each bucket:
    // bucket by bucket, row by row, so every use has one fixed place.
    std::vector<Id> place(rows * buckets, 0);
    forChunks([&](std::size_t row, std::size_t, int, std::size_t b) { ++place[row * buckets + b]; });
    std::vector<Id> bucketStart(buckets + 1);
    Id total = 0;
    for (std::size_t b = 0; b < buckets; ++b) {
        bucketStart[b] = total;
        for (std::size_t row = 0; row < rows; ++row) {
            const Id n = place[row * buckets + b];
            place[row * buckets + b] = total;
            total += n;
        }
    }
    bucketStart[buckets] = total;
    std::unique_ptr<Id[]> uses(new Id[total]);
    forChunks([&](std::size_t row, std::size_t t, int k, std::size_t b) {
        uses[place[row * buckets + b]++] = useOf<Id>(t, k);
    });

    // Per bucket: its edges in the table, then their counts, then the
    // triangles sharing an edge joined. Whether a use is its edge's first
    // is a coin toss to the processor (exactly half are, in a closed mesh),
    // so the pass over the uses selects instead of branching on it.
    ConcurrentUnionFind<Id> parts(triangles);
    std::vector<EdgeCensus> perBucket(buckets);
    tbb::enumerable_thread_specific<EdgeTable<Id>> tables;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, buckets, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        EdgeTable<Id>& table = tables.local();
        for (std::size_t b = r.begin(); b != r.end(); ++b) {
            const std::size_t first = bucketStart[b], last = bucketStart[b + 1];
            if (first == last) continue;
            const auto stamp = static_cast<std::uint32_t>(b + 1);
            table.start(last - first);
            std::size_t edges = 0, joins = 0;
            for (std::size_t i = first; i < last; ++i) {
                const Id t = uses[i] >> 2;
                const auto k = static_cast<std::size_t>(uses[i] & 3);
                const std::uint32_t a = idx[3 * std::size_t{t} + k], c = idx[3 * std::size_t{t} + (k == 2 ? 0 : k + 1)];
                const std::uint64_t key = std::uint64_t{std::min(a, c)} << 32 | std::max(a, c);
                std::size_t h = static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> (64 - table.bits));
                while (table.slots[h].stamp == stamp && table.slots[h].key != key) h = (h + 1) & table.mask;
                typename EdgeTable<Id>::Slot& slot = table.slots[h];
                const bool fresh = slot.stamp != stamp;
                const Id firstTriangle = fresh ? t : slot.firstTriangle;
                slot = {key, firstTriangle, stamp, (fresh ? 0 : slot.uses) + 1,
                        (fresh ? 0 : slot.forward) + (a < c ? 1 : 0)};
                table.edges[edges] = h;
                edges += fresh ? 1 : 0;
                table.joins[joins] = {firstTriangle, t};
                joins += fresh ? 0 : 1;
            }
            EdgeCensus out;
            for (std::size_t e = 0; e < edges; ++e) {
                const auto& slot = table.slots[table.edges[e]];
                out.boundaryEdges += slot.uses == 1 ? 1 : 0;
                out.nonManifoldEdges += slot.uses > 2 ? 1 : 0;
                out.inconsistentEdges += slot.uses == 2 && slot.forward != 1 ? 1 : 0;
            }
            perBucket[b] = out;
            for (std::size_t j = 0; j < joins; ++j) parts.unite(table.joins[j][0], table.joins[j][1]);
        }
    });

    EdgeCensus result;
    for (const EdgeCensus& c : perBucket) {
        result.boundaryEdges += c.boundaryEdges;
        result.nonManifoldEdges += c.nonManifoldEdges;
        result.inconsistentEdges += c.inconsistentEdges;
    }
    result.components = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, triangles), std::size_t{0},
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t n) {
            for (std::size_t t = r.begin(); t != r.end(); ++t) n += live[t] && parts.isRoot(t) ? 1 : 0;
            return n;
        },
        std::plus<>());
    return result;
}

}  // namespace

EdgeLayout defaultEdgeLayout(std::size_t triangles, std::size_t vertices) {
    EdgeLayout layout;
    layout.chunkTriangles = std::max<std::size_t>(std::size_t{1} << 15, (triangles + 255) / 256);
    layout.bucketShift = 8;
    while ((vertices >> layout.bucketShift) + 1 > 16384) ++layout.bucketShift;
    return layout;
}

EdgeCensus censusEdges(const Mesh& mesh, const std::vector<std::uint8_t>& live, const EdgeLayout& layout) {
    // 32-bit numbers while every edge use (4t + k) fits.
    const bool narrow = 4 * mesh.triangleCount() <= std::numeric_limits<std::uint32_t>::max();
    return narrow && !layout.wideIds ? census<std::uint32_t>(mesh, live, layout)
                                     : census<std::uint64_t>(mesh, live, layout);
}

}  // namespace hg::poly
