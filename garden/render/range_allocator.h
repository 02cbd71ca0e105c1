// First-fit sub-allocation of ranges of a fixed-capacity array (the chunk
// arena's vertex and index buffers: docs/rendering.md, "Batched drawing").
// Freed ranges merge with free neighbours, so a garden that remeshes the
// same chunks over and over reuses the same space. No GL here: the arena
// decides when to grow or compact by what this says.
#pragma once

#include <cstddef>
#include <map>
#include <optional>

namespace hg::garden {

class RangeAllocator {
public:
    explicit RangeAllocator(std::size_t capacity = 0);

    // The offset of `count` free elements (the lowest that fits), or nothing
    // when no free range is long enough. A count of 0 takes no space and
    // answers offset 0.
    std::optional<std::size_t> allocate(std::size_t count);
    // Returns [offset, offset + count) to the free space. Throws
    // std::invalid_argument for a range that is not wholly allocated.
    void release(std::size_t offset, std::size_t count);

    // More capacity at the end (never less than now).
    void grow(std::size_t capacity);

    std::size_t capacity() const { return capacity_; }
    std::size_t used() const { return used_; }
    std::size_t unused() const { return capacity_ - used_; }  // free, in however many pieces
    std::size_t largestFree() const;
    std::size_t freeRanges() const { return free_.size(); }

private:
    std::size_t capacity_ = 0;
    std::size_t used_ = 0;
    std::map<std::size_t, std::size_t> free_;  // offset -> length, never adjacent to each other
};

}  // namespace hg::garden
