#include "garden/render/range_allocator.h"

#include <iterator>
#include <stdexcept>
#include <string>

namespace hg::garden {

RangeAllocator::RangeAllocator(std::size_t capacity) : capacity_(capacity) {
    if (capacity > 0) free_.emplace(0, capacity);
}

std::optional<std::size_t> RangeAllocator::allocate(std::size_t count) {
    if (count == 0) return std::size_t{0};
    for (auto it = free_.begin(); it != free_.end(); ++it) {
        if (it->second < count) continue;
        const std::size_t offset = it->first;
        const std::size_t rest = it->second - count;
        free_.erase(it);
        if (rest > 0) free_.emplace(offset + count, rest);
        used_ += count;
        return offset;
    }
    return std::nullopt;
}

void RangeAllocator::release(std::size_t offset, std::size_t count) {
    if (count == 0) return;
    auto refuse = [&] {
        throw std::invalid_argument("range [" + std::to_string(offset) + ", " + std::to_string(offset + count) +
                                    ") is not allocated");
    };
    if (offset + count > capacity_ || offset + count < offset) refuse();
    auto next = free_.lower_bound(offset);
    if (next != free_.end() && next->first < offset + count) refuse();
    if (next != free_.begin()) {
        auto before = std::prev(next);
        if (before->first + before->second > offset) refuse();
    }
    used_ -= count;
    std::size_t start = offset, length = count;
    if (next != free_.begin()) {
        auto before = std::prev(next);
        if (before->first + before->second == offset) {
            start = before->first;
            length += before->second;
            free_.erase(before);
        }
    }
    if (next != free_.end() && next->first == offset + count) {
        length += next->second;
        free_.erase(next);
    }
    free_.emplace(start, length);
}

void RangeAllocator::grow(std::size_t capacity) {
    if (capacity <= capacity_) return;
    const std::size_t added = capacity - capacity_;
    // Merge with a free range that ends at the old capacity.
    if (!free_.empty()) {
        auto last = std::prev(free_.end());
        if (last->first + last->second == capacity_) {
            last->second += added;
            capacity_ = capacity;
            return;
        }
    }
    free_.emplace(capacity_, added);
    capacity_ = capacity;
}

std::size_t RangeAllocator::largestFree() const {
    std::size_t best = 0;
    for (const auto& [offset, length] : free_) best = length > best ? length : best;
    return best;
}

}  // namespace hg::garden
