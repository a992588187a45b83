// Ids that cannot lie (grass.h "Ids"): owner tags are unique among live contexts and do
// not come back soon after a context dies, and a slot whose generation would wrap is
// retired. (Before, the tag was a 16-bit hash of the context's address: among 2,000 live
// contexts some shared a tag and one destroyed another's patch; a context made at a dead
// one's address accepted its ids; and after 65,536 cycles on a slot a stale id was
// accepted again.)
#include <grass/grass.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <set>
#include <vector>

namespace {

struct Counted {
    int errors = 0;
    grass_message_id last = GRASS_MSG_NONE;
};

// Host memory that hands a freed block of the same size back first (as many allocators
// do), so that a new context lands at the address of the one destroyed before it.
struct ReusingAllocator {
    std::map<size_t, std::vector<void*>> free_blocks;
    std::map<void*, size_t> sizes;
    ~ReusingAllocator() {
        for (auto& [size, blocks] : free_blocks) {
            for (void* p : blocks) std::free(p);
        }
    }
    static void* alloc(void* user, size_t size, size_t alignment) {
        auto* a = static_cast<ReusingAllocator*>(user);
        std::vector<void*>& blocks = a->free_blocks[size];
        void* p = nullptr;
        if (!blocks.empty()) {
            p = blocks.back();
            blocks.pop_back();
        } else {
            p = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
        }
        a->sizes[p] = size;
        return p;
    }
    static void release(void* user, void* p) {
        auto* a = static_cast<ReusingAllocator*>(user);
        a->free_blocks[a->sizes[p]].push_back(p);
    }
};

grass_context* make_context(Counted* log, ReusingAllocator* memory = nullptr) {
    grass_context_desc d = grass_default_context_desc();
    if (memory) {
        d.allocator.alloc_fn = ReusingAllocator::alloc;
        d.allocator.free_fn = ReusingAllocator::release;
        d.allocator.user_data = memory;
    }
    d.log_user_data = log;
    d.log_fn = [](void* user, grass_log_level level, grass_message_id id, const char*) {
        auto* c = static_cast<Counted*>(user);
        if (level == GRASS_LOG_ERROR) c->errors += 1;
        c->last = id;
    };
    grass_context* ctx = nullptr;
    EXPECT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &ctx), GRASS_SUCCESS);
    return ctx;
}

const unsigned char kTexel[1] = {200};

grass_map_id make_map(grass_context* ctx) {
    grass_map_desc d = grass_default_map_desc();
    d.width = d.height = 1;
    d.row_pitch = 1;
    d.pixels = kTexel;
    grass_map_id m{};
    EXPECT_EQ(grass_create_map(ctx, &d, &m), GRASS_SUCCESS) << grass_get_last_error(ctx);
    return m;
}

// A map update is a cheap call that takes an id.
grass_result touch(grass_context* ctx, grass_map_id map) {
    grass_map_desc d = grass_default_map_desc();
    d.width = d.height = 1;
    d.row_pitch = 1;
    d.pixels = kTexel;
    return grass_update_map(ctx, map, 0, 0, &d);
}

TEST(IdGuarantees, TwoThousandLiveContextsHaveDistinctOwnersAndRefuseEachOthersIds) {
    constexpr int kContexts = 2000;
    std::vector<Counted> logs(kContexts);
    std::vector<grass_context*> contexts(kContexts);
    std::vector<grass_map_id> maps(kContexts);
    std::set<uint16_t> owners;
    for (int i = 0; i < kContexts; ++i) {
        contexts[i] = make_context(&logs[i]);
        ASSERT_NE(contexts[i], nullptr);
        maps[i] = make_map(contexts[i]);
        owners.insert(maps[i].owner);
    }
    EXPECT_EQ(owners.size(), static_cast<size_t>(kContexts)) << "every live context has its own owner tag";
    // Every context holds a map in slot 1, generation 1: only the owner tells them apart.
    for (int i = 0; i < kContexts; ++i) {
        for (int step : {1, 7, 149, 1000}) {
            const int other = (i + step) % kContexts;
            ASSERT_EQ(grass_destroy_map(contexts[i], maps[other]), GRASS_ERROR_INVALID_HANDLE) << i << " " << other;
            ASSERT_EQ(logs[i].last, GRASS_MSG_FOREIGN_HANDLE);
        }
        ASSERT_EQ(touch(contexts[i], maps[i]), GRASS_SUCCESS) << "its own map is still there";
    }
    for (grass_context* ctx : contexts) grass_destroy_context(ctx);
}

TEST(IdGuarantees, AContextMadeAfterAnotherDiedRefusesTheDeadOnesIds) {
    // The new context is often made at the dead one's address: its ids must still differ.
    Counted log;
    ReusingAllocator memory;
    grass_context* ctx = make_context(&log, &memory);
    grass_map_id old = make_map(ctx);
    int same_address = 0;
    for (int cycle = 0; cycle < 10000; ++cycle) {
        const grass_context* dead = ctx;
        grass_destroy_context(ctx);
        ctx = make_context(&log, &memory);
        ASSERT_NE(ctx, nullptr);
        same_address += ctx == dead;
        const grass_map_id mine = make_map(ctx); // same slot and generation as `old`
        ASSERT_NE(mine.owner, old.owner) << "cycle " << cycle;
        ASSERT_EQ(grass_destroy_map(ctx, old), GRASS_ERROR_INVALID_HANDLE) << "cycle " << cycle;
        ASSERT_EQ(log.last, GRASS_MSG_FOREIGN_HANDLE);
        ASSERT_EQ(touch(ctx, mine), GRASS_SUCCESS) << "its own map is untouched";
        old = mine;
    }
    EXPECT_EQ(same_address, 10000) << "each new context sat at the dead one's address";
    grass_destroy_context(ctx);
}

TEST(IdGuarantees, ASlotWhoseGenerationWouldWrapIsRetiredAndNoStaleIdComesBack) {
    Counted log;
    grass_context* ctx = make_context(&log);
    const grass_map_id first = make_map(ctx);
    ASSERT_EQ(grass_destroy_map(ctx, first), GRASS_SUCCESS);
    std::set<uint32_t> indices;
    for (int cycle = 1; cycle < 70000; ++cycle) {
        const grass_map_id m = make_map(ctx);
        indices.insert(m.index);
        // The first id (generation 1 of slot 1) stays stale however often the slot is reused.
        ASSERT_EQ(touch(ctx, first), GRASS_ERROR_INVALID_HANDLE)
            << "cycle " << cycle << " index " << m.index << " generation " << m.generation;
        ASSERT_EQ(log.last, GRASS_MSG_STALE_HANDLE);
        ASSERT_EQ(grass_destroy_map(ctx, m), GRASS_SUCCESS);
        ASSERT_EQ(touch(ctx, m), GRASS_ERROR_INVALID_HANDLE) << "cycle " << cycle;
    }
    EXPECT_EQ(indices.size(), 2u) << "slot 1 served 65,535 generations, then slot 2 took over";
    grass_destroy_context(ctx);
}

} // namespace
