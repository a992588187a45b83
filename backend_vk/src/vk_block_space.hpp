// The space inside one block of device memory (vk_memory_blocks.hpp): which byte ranges are
// taken, by what, and where the next resource fits. Plain offsets, no Vulkan call, so it is
// tested without a device (tests/core/vk_block_space_test.cpp).
//
// First fit over a list of ranges that covers the block, sorted by offset; freed ranges merge
// with free neighbours. Two rules place a range:
// - its offset is a multiple of its alignment (VkMemoryRequirements::alignment);
// - a linear resource (a buffer) and an optimally tiled image never share a page of
//   `granularity` bytes (VkPhysicalDeviceLimits::bufferImageGranularity): where the
//   neighbour before or after is of the other kind, the range starts or ends on a page
//   boundary of its own.
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass::vk {

enum class Tiling : uint8_t { linear, optimal };

class BlockSpace {
public:
    // `granularity`: a power of two (1: no rule).
    BlockSpace(uint64_t size, uint64_t granularity, HostAllocator* host);

    // A range of `size` bytes at a multiple of `alignment` (a power of two); false where
    // none fits. May throw std::bad_alloc (then nothing changed).
    bool allocate(uint64_t size, uint64_t alignment, Tiling tiling, uint64_t* offset);
    // Frees the range allocate() returned at `offset`.
    void free(uint64_t offset);

    uint64_t size() const { return size_; }
    uint64_t used() const { return used_; } // bytes of the ranges taken (their sizes as asked)
    bool empty() const { return used_ == 0; }
    uint32_t ranges() const { return static_cast<uint32_t>(ranges_.size()); } // taken and free

private:
    struct Range {
        uint64_t offset;
        uint64_t size;
        Tiling tiling;
        bool taken;
    };
    // Where a range of `size`, `alignment`, `tiling` starts inside free range i; false if
    // it does not fit there.
    bool fit(size_t i, uint64_t size, uint64_t alignment, Tiling tiling, uint64_t* start) const;

    uint64_t size_;
    uint64_t granularity_;
    uint64_t used_ = 0;
    Vector<Range> ranges_;
};

} // namespace grass::vk
