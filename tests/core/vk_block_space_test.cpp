// The space inside a block of device memory (backend_vk/src/vk_block_space.hpp), without a
// device: alignment, bufferImageGranularity between buffers and optimally tiled images,
// first fit, freeing and merging, a full block.
#include "vk_block_space.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace {

using grass::vk::BlockSpace;
using grass::vk::Tiling;

grass_allocator default_hooks() { return grass_allocator{}; }

struct Taken {
    uint64_t offset, size;
    Tiling tiling;
};

// No two taken ranges overlap, and a buffer and an image never share a page of `granularity`.
void expect_apart(const std::vector<Taken>& taken, uint64_t granularity) {
    for (size_t i = 0; i < taken.size(); ++i) {
        for (size_t j = i + 1; j < taken.size(); ++j) {
            const Taken &a = taken[i], &b = taken[j];
            const bool overlap = a.offset < b.offset + b.size && b.offset < a.offset + a.size;
            EXPECT_FALSE(overlap) << "[" << a.offset << ", +" << a.size << ") and [" << b.offset << ", +" << b.size
                                  << ")";
            if (a.tiling == b.tiling) continue;
            const Taken& lo = a.offset < b.offset ? a : b;
            const Taken& hi = a.offset < b.offset ? b : a;
            EXPECT_LT((lo.offset + lo.size - 1) / granularity, hi.offset / granularity)
                << "a buffer and an image share a " << granularity << "-byte page: [" << lo.offset << ", +" << lo.size
                << ") and [" << hi.offset << ", +" << hi.size << ")";
        }
    }
}

TEST(VkBlockSpace, OffsetsKeepEachAlignment) {
    grass::HostAllocator host(default_hooks());
    BlockSpace space(1 << 20, 1, &host);
    const uint64_t alignments[] = {1, 4, 256, 64, 4096, 16, 65536, 2};
    std::vector<Taken> taken;
    for (int round = 0; round < 3; ++round) {
        for (uint64_t alignment : alignments) {
            uint64_t offset = 1;
            ASSERT_TRUE(space.allocate(100 + alignment / 3, alignment, Tiling::linear, &offset));
            EXPECT_EQ(offset % alignment, 0u) << "alignment " << alignment;
            taken.push_back({offset, 100 + alignment / 3, Tiling::linear});
        }
    }
    expect_apart(taken, 1);
}

TEST(VkBlockSpace, BuffersAndImagesNeverShareAGranularityPage) {
    grass::HostAllocator host(default_hooks());
    const uint64_t page = 1024;
    BlockSpace space(64 * page, page, &host);
    std::vector<Taken> taken;
    uint64_t offset = 0;
    // buffer, image, buffer, image: each small, alignment 16 (so without the rule they would pack).
    for (int i = 0; i < 6; ++i) {
        const Tiling t = i % 2 ? Tiling::optimal : Tiling::linear;
        ASSERT_TRUE(space.allocate(100, 16, t, &offset));
        taken.push_back({offset, 100, t});
    }
    expect_apart(taken, page);
    // Two of a kind pack on one page.
    uint64_t a = 0, b = 0;
    BlockSpace same(64 * page, page, &host);
    ASSERT_TRUE(same.allocate(100, 16, Tiling::linear, &a));
    ASSERT_TRUE(same.allocate(100, 16, Tiling::linear, &b));
    EXPECT_EQ(b, 112u) << "buffers share pages";
}

TEST(VkBlockSpace, AFreedRangeIsReusedAndNeighboursMerge) {
    grass::HostAllocator host(default_hooks());
    BlockSpace space(1000, 1, &host);
    uint64_t a = 0, b = 0, c = 0;
    ASSERT_TRUE(space.allocate(300, 1, Tiling::linear, &a));
    ASSERT_TRUE(space.allocate(300, 1, Tiling::linear, &b));
    ASSERT_TRUE(space.allocate(300, 1, Tiling::linear, &c));
    uint64_t d = 0;
    EXPECT_FALSE(space.allocate(200, 1, Tiling::linear, &d)) << "100 bytes are left";
    EXPECT_EQ(space.used(), 900u);
    space.free(b);
    ASSERT_TRUE(space.allocate(200, 1, Tiling::linear, &d));
    EXPECT_EQ(d, b) << "first fit reuses the freed range";
    space.free(d);
    space.free(a);
    EXPECT_TRUE(space.allocate(600, 1, Tiling::linear, &d)) << "a and b merged into 600 bytes";
    EXPECT_EQ(d, 0u);
    space.free(d);
    space.free(c);
    EXPECT_TRUE(space.empty());
    EXPECT_EQ(space.ranges(), 1u) << "all free ranges merged into one";
    EXPECT_TRUE(space.allocate(1000, 1, Tiling::linear, &d));
    EXPECT_FALSE(space.allocate(1, 1, Tiling::linear, &d)) << "full";
}

// Random allocations and frees of both kinds: the rules hold throughout and an emptied block
// is one free range again.
TEST(VkBlockSpace, RandomUseKeepsTheRules) {
    grass::HostAllocator host(default_hooks());
    const uint64_t page = 256;
    BlockSpace space(1 << 20, page, &host);
    std::mt19937 rng(34);
    std::vector<Taken> taken;
    for (int step = 0; step < 2000; ++step) {
        if (!taken.empty() && rng() % 3 == 0) {
            const size_t i = rng() % taken.size();
            space.free(taken[i].offset);
            taken.erase(taken.begin() + static_cast<std::ptrdiff_t>(i));
            continue;
        }
        const uint64_t size = 1 + rng() % 5000, alignment = uint64_t{1} << (rng() % 10);
        const Tiling t = rng() % 2 ? Tiling::optimal : Tiling::linear;
        uint64_t offset = 0;
        if (!space.allocate(size, alignment, t, &offset)) continue;
        ASSERT_EQ(offset % alignment, 0u);
        ASSERT_LE(offset + size, space.size());
        taken.push_back({offset, size, t});
    }
    expect_apart(taken, page);
    for (const Taken& t : taken) space.free(t.offset);
    EXPECT_TRUE(space.empty());
    EXPECT_EQ(space.ranges(), 1u);
}

} // namespace
