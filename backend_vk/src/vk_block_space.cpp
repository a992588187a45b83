#include "vk_block_space.hpp"

namespace grass::vk {

namespace {

uint64_t align_up(uint64_t value, uint64_t alignment) { return (value + alignment - 1) & ~(alignment - 1); }
uint64_t page(uint64_t byte, uint64_t granularity) { return byte & ~(granularity - 1); }

} // namespace

BlockSpace::BlockSpace(uint64_t size, uint64_t granularity, HostAllocator* host)
    : size_(size), granularity_(granularity ? granularity : 1), ranges_(StlAllocator<Range>(host)) {
    ranges_.push_back(Range{0, size, Tiling::linear, false});
}

bool BlockSpace::fit(size_t i, uint64_t size, uint64_t alignment, Tiling tiling, uint64_t* start) const {
    const Range& r = ranges_[i];
    uint64_t at = align_up(r.offset, alignment);
    // The taken range before (free ranges are merged, so a neighbour is taken): another
    // kind on the same page pushes the start to the next page.
    if (i > 0 && granularity_ > 1) {
        const Range& before = ranges_[i - 1];
        if (before.tiling != tiling && page(before.offset + before.size - 1, granularity_) == page(at, granularity_)) {
            at = align_up(align_up(at, granularity_), alignment);
        }
    }
    if (at < r.offset || at + size > r.offset + r.size || at + size < at) return false;
    // The taken range after: another kind may not start on this range's last page.
    if (i + 1 < ranges_.size() && granularity_ > 1) {
        const Range& after = ranges_[i + 1];
        if (after.tiling != tiling && page(at + size - 1, granularity_) == page(after.offset, granularity_)) {
            return false;
        }
    }
    *start = at;
    return true;
}

bool BlockSpace::allocate(uint64_t size, uint64_t alignment, Tiling tiling, uint64_t* offset) {
    if (size == 0) size = 1;
    if (alignment == 0) alignment = 1;
    for (size_t i = 0; i < ranges_.size(); ++i) {
        if (ranges_[i].taken) continue;
        uint64_t at = 0;
        if (!fit(i, size, alignment, tiling, &at)) continue;
        const Range free_range = ranges_[i];
        const uint64_t end = at + size, free_end = free_range.offset + free_range.size;
        // Split into [gap before][taken][rest]: reserve first, so a throw changes nothing.
        ranges_.reserve(ranges_.size() + 2);
        size_t taken = i;
        if (at > free_range.offset) {
            ranges_[i].size = at - free_range.offset;
            ranges_.insert(ranges_.begin() + static_cast<std::ptrdiff_t>(i) + 1, Range{at, size, tiling, true});
            taken = i + 1;
        } else {
            ranges_[i] = Range{at, size, tiling, true};
        }
        if (end < free_end) {
            ranges_.insert(ranges_.begin() + static_cast<std::ptrdiff_t>(taken) + 1,
                           Range{end, free_end - end, Tiling::linear, false});
        }
        used_ += size;
        *offset = at;
        return true;
    }
    return false;
}

void BlockSpace::free(uint64_t offset) {
    size_t i = 0;
    while (i < ranges_.size() && !(ranges_[i].taken && ranges_[i].offset == offset)) ++i;
    if (i == ranges_.size()) return;
    used_ -= ranges_[i].size;
    ranges_[i].taken = false;
    // Merge with the free neighbours (the gaps an alignment left are free ranges too).
    if (i + 1 < ranges_.size() && !ranges_[i + 1].taken) {
        ranges_[i].size = ranges_[i + 1].offset + ranges_[i + 1].size - ranges_[i].offset;
        ranges_.erase(ranges_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    }
    if (i > 0 && !ranges_[i - 1].taken) {
        ranges_[i - 1].size = ranges_[i].offset + ranges_[i].size - ranges_[i - 1].offset;
        ranges_.erase(ranges_.begin() + static_cast<std::ptrdiff_t>(i));
    }
}

} // namespace grass::vk
