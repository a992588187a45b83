// Allocation hooks: every host allocation of a context goes through them and is counted.
#include <grass/grass.h>

#include <gtest/gtest.h>

#include <cstdlib>

namespace {

struct Counter {
    long live = 0;
    long total = 0;
};

TEST(AllocatorHooks, SeeEveryAllocationAndAllAreFreedWithTheContext) {
    Counter counter;
    grass_context_desc d = grass_default_context_desc();
    d.allocator.alloc_fn = [](void* user, size_t size, size_t alignment) -> void* {
        auto* c = static_cast<Counter*>(user);
        c->live += 1;
        c->total += 1;
        return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    };
    d.allocator.free_fn = [](void* user, void* p) {
        static_cast<Counter*>(user)->live -= 1;
        std::free(p);
    };
    d.allocator.user_data = &counter;
    grass_context* ctx = nullptr;
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &ctx), GRASS_SUCCESS);
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id p{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &p), GRASS_SUCCESS);
    grass_memory_stats stats{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &stats), GRASS_SUCCESS);
    EXPECT_GT(stats.host_bytes, 384u * 10u * 48u) << "the patch's vertices are held";
    EXPECT_GT(counter.live, 1);
    ASSERT_EQ(grass_destroy_patch(ctx, p), GRASS_SUCCESS);
    grass_memory_stats after{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &after), GRASS_SUCCESS);
    EXPECT_LT(after.host_bytes, stats.host_bytes / 4);
    grass_destroy_context(ctx);
    EXPECT_EQ(counter.live, 0);
    EXPECT_GT(counter.total, 3);
}

TEST(AllocatorHooks, HalfSetHooksAreRefused) {
    grass_context_desc d = grass_default_context_desc();
    d.allocator.alloc_fn = [](void*, size_t, size_t) -> void* { return nullptr; };
    grass_context* ctx = nullptr;
    EXPECT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &ctx), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ctx, nullptr);
}

TEST(AllocatorHooks, AFailingAllocatorGivesOutOfMemoryNotACrash) {
    struct Budget {
        int left;
    } budget{3};
    grass_context_desc d = grass_default_context_desc();
    d.allocator.alloc_fn = [](void* user, size_t size, size_t alignment) -> void* {
        auto* b = static_cast<Budget*>(user);
        if (b->left-- <= 0) return nullptr;
        return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    };
    d.allocator.free_fn = [](void*, void* p) { std::free(p); };
    d.allocator.user_data = &budget;
    grass_context* ctx = nullptr;
    const grass_result r = grass_create_context(GRASS_HEADER_VERSION, &d, &ctx);
    if (r == GRASS_SUCCESS) {
        grass_patch_desc pd = grass_default_patch_desc();
        grass_patch_id p{};
        EXPECT_EQ(grass_create_patch(ctx, &pd, &p), GRASS_ERROR_OUT_OF_MEMORY);
        grass_destroy_context(ctx);
    } else {
        EXPECT_EQ(r, GRASS_ERROR_OUT_OF_MEMORY);
    }
}

} // namespace
