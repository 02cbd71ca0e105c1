// The arena's sub-allocator: first fit, merging of freed neighbours,
// growth, and refusal of ranges it never gave out.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "garden/render/range_allocator.h"

namespace hg::garden::test {
namespace {

TEST(RangeAllocator, TakesTheLowestRangeThatFitsAndMergesFreedNeighbours) {
    RangeAllocator a(100);
    EXPECT_EQ(a.allocate(30), 0u);
    EXPECT_EQ(a.allocate(30), 30u);
    EXPECT_EQ(a.allocate(30), 60u);
    EXPECT_FALSE(a.allocate(20)) << "10 left";
    EXPECT_EQ(a.used(), 90u);

    a.release(30, 30);
    EXPECT_EQ(a.allocate(40), std::nullopt) << "the hole is 30 long, the end 10";
    a.release(0, 30);
    EXPECT_EQ(a.freeRanges(), 2u) << "[0, 60) merged, [90, 100) apart";
    EXPECT_EQ(a.largestFree(), 60u);
    EXPECT_EQ(a.allocate(50), 0u);
    a.release(60, 30);
    EXPECT_EQ(a.freeRanges(), 1u) << "[50, 60), [60, 90) and [90, 100) merged into [50, 100)";
    EXPECT_EQ(a.largestFree(), 50u);
    EXPECT_EQ(a.allocate(0), 0u) << "nothing takes no space";
    EXPECT_EQ(a.used(), 50u);
}

TEST(RangeAllocator, GrowsAtTheEndMergingWithTheFreeTail) {
    RangeAllocator a(10);
    EXPECT_EQ(a.allocate(6), 0u);
    a.grow(20);
    EXPECT_EQ(a.freeRanges(), 1u);
    EXPECT_EQ(a.allocate(14), 6u);
    a.grow(5);
    EXPECT_EQ(a.capacity(), 20u) << "never shrinks";
    a.grow(30);
    EXPECT_EQ(a.allocate(10), 20u);
}

TEST(RangeAllocator, RefusesToFreeWhatItDidNotGive) {
    RangeAllocator a(100);
    ASSERT_EQ(a.allocate(10), 0u);
    EXPECT_THROW(a.release(10, 5), std::invalid_argument) << "free already";
    EXPECT_THROW(a.release(5, 10), std::invalid_argument) << "half free";
    EXPECT_THROW(a.release(95, 10), std::invalid_argument) << "past the end";
    a.release(0, 10);
    EXPECT_THROW(a.release(0, 10), std::invalid_argument) << "twice";
    EXPECT_EQ(a.used(), 0u);
    EXPECT_EQ(a.freeRanges(), 1u);
}

// Random churn against a model of which elements are taken: no range is
// given twice, and freeing everything leaves one free range.
TEST(RangeAllocator, RandomChurnNeverOverlapsAndFreesBackToOneRange) {
    std::mt19937 rng(7);
    RangeAllocator a(10000);
    std::vector<std::pair<std::size_t, std::size_t>> live;
    std::vector<bool> taken(10000, false);
    for (int step = 0; step < 5000; ++step) {
        if (live.empty() || rng() % 3 != 0) {
            const std::size_t n = 1 + rng() % 200;
            const auto offset = a.allocate(n);
            if (!offset) continue;
            for (std::size_t k = *offset; k < *offset + n; ++k) {
                ASSERT_FALSE(taken[k]) << "element " << k << " given twice";
                taken[k] = true;
            }
            live.emplace_back(*offset, n);
        } else {
            const std::size_t pick = rng() % live.size();
            const auto [offset, n] = live[pick];
            a.release(offset, n);
            for (std::size_t k = offset; k < offset + n; ++k) taken[k] = false;
            live.erase(live.begin() + static_cast<std::ptrdiff_t>(pick));
        }
    }
    for (const auto& [offset, n] : live) a.release(offset, n);
    EXPECT_EQ(a.used(), 0u);
    EXPECT_EQ(a.freeRanges(), 1u);
    EXPECT_EQ(a.largestFree(), 10000u);
}

}  // namespace
}  // namespace hg::garden::test
