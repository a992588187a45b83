// Vulkan device memory (backend_vk/src/vk_memory_blocks.hpp) through the headless host, under
// the validation layers:
// - the number of vkAllocateMemory calls stays at or below a small constant whatever the
//   number of fields and maps, and an emptied scene gives its blocks back but a spare;
// - grass_memory_stats reports the device's heaps, what grass allocated and uses on each,
//   and the budget where the device has VK_EXT_memory_budget (emulated by the intercept where
//   the driver lacks it);
// - the host's VkAllocationCallbacks are used for grass's objects and every allocation made
//   through them is freed; callbacks missing a function are refused.
// GL reports no heap (grass.h): checked here too.
#include "allocation_scenario.hpp"
#include "vk_intercept.hpp"

#include <grass/grass_vk.h>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <vector>

namespace grass_test {
namespace {

namespace vi = vk_intercept;

// The most vkAllocateMemory calls a scene may make, however many fields and maps it has: a
// few blocks per memory type (their sizes grow 1/4, 1/2, 1 of a block) and the dedicated
// allocations of resources over half a block (none in these scenes).
constexpr int64_t kMaxDeviceAllocations = 6;

grass_host::TargetDesc small_target() {
    grass_host::TargetDesc t;
    t.width = t.height = 64;
    t.vk_get_instance_proc_addr = vi::get_instance_proc_addr();
    return t;
}

// A scene of `fields` fields of one patch, each with its own density and ambient maps, two
// frames drawn; returns the vkAllocateMemory calls it made (the context's setup included).
// The context is left in *ctx with the ids in *field_ids and *map_ids.
int64_t draw_fields(grass_host::Host& host, int fields, FailureLog* log, grass_context** ctx,
                    std::vector<grass_field_id>* field_ids, std::vector<grass_map_id>* map_ids) {
    const int64_t before = vi::live().memory_made;
    EXPECT_EQ(host.create_context(logged_desc(log), ctx), GRASS_SUCCESS) << log->text;
    if (!*ctx) return -1;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 128;
    grass_patch_id patch{};
    EXPECT_EQ(grass_create_patch(*ctx, &pd, &patch), GRASS_SUCCESS) << log->text;
    std::vector<uint8_t> texels(32 * 32);
    for (int f = 0; f < fields; ++f) {
        grass_field_desc fd = grass_default_field_desc();
        fd.patch = patch;
        fd.cells_x = fd.cells_z = 8;
        fd.base_transform[12] = 2.0 * (f % 5); // column-major: the translation
        fd.base_transform[14] = 2.0 * (f / 5);
        grass_map_id maps[2]{};
        for (int m = 0; m < 2; ++m) {
            for (size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<uint8_t>(100 + (i * 7 + f + m) % 150);
            grass_map_desc md = grass_default_map_desc();
            md.pixels = texels.data();
            md.width = md.height = 32;
            EXPECT_EQ(grass_create_map(*ctx, &md, &maps[m]), GRASS_SUCCESS) << log->text;
            map_ids->push_back(maps[m]);
        }
        fd.maps.density = maps[0];
        fd.maps.ambient = maps[1];
        grass_field_id field{};
        EXPECT_EQ(grass_create_field(*ctx, &fd, &field), GRASS_SUCCESS) << log->text;
        field_ids->push_back(field);
    }
    const double eye[3] = {5.0, 3.0, -4.0}, look[3] = {5.0, 0.0, 4.0};
    const grass_view_desc v = grass_host::make_view(host, eye, look, 50.0f, 0.05f, 200.0f);
    grass_host::Image image;
    std::string error;
    for (int frame = 0; frame < 2; ++frame) {
        EXPECT_EQ(host.render(*ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error << log->text;
    }
    return vi::live().memory_made - before;
}

grass_memory_stats memory_stats(grass_context* ctx) {
    grass_memory_stats s{};
    EXPECT_EQ(grass_get_memory_stats(ctx, &s), GRASS_SUCCESS);
    return s;
}

TEST(VkMemory, DeviceAllocationsStayBoundedWhateverTheFieldsAndMaps) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, small_target(), &error);
    ASSERT_TRUE(host) << error;
    int64_t made[2] = {};
    const int counts[2] = {1, 20};
    for (int i = 0; i < 2; ++i) {
        FailureLog log;
        grass_context* ctx = nullptr;
        std::vector<grass_field_id> fields;
        std::vector<grass_map_id> maps;
        made[i] = draw_fields(*host, counts[i], &log, &ctx, &fields, &maps);
        ASSERT_NE(ctx, nullptr);
        EXPECT_GE(made[i], 1);
        EXPECT_LE(made[i], kMaxDeviceAllocations) << counts[i] << " fields with two maps each";
        const grass_memory_stats s = memory_stats(ctx);
        EXPECT_EQ(static_cast<int64_t>(s.device_allocations), vi::live().memory) << "the stats count every allocation";
        std::printf("[ memory   ] %d fields, %zu maps: %lld vkAllocateMemory calls, %llu bytes in use\n", counts[i],
                    maps.size(), static_cast<long long>(made[i]), static_cast<unsigned long long>(s.gpu_bytes));

        // Everything the scene made goes; its blocks are released but a spare per type, so
        // the context holds no more allocations than it made for the one-field scene.
        for (const grass_field_id& f : fields) EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS) << log.text;
        for (const grass_map_id& m : maps) EXPECT_EQ(grass_destroy_map(ctx, m), GRASS_SUCCESS) << log.text;
        const double eye[3] = {5.0, 3.0, -4.0}, look[3] = {5.0, 0.0, 4.0};
        const grass_view_desc v = grass_host::make_view(*host, eye, look, 50.0f, 0.05f, 200.0f);
        grass_host::Image image;
        for (int frame = 0; frame < 3; ++frame) { // past the frames in flight: retired resources go
            EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error << log.text;
        }
        EXPECT_LE(static_cast<int64_t>(memory_stats(ctx).device_allocations), made[0])
            << "emptied blocks are released (one spare per memory type is kept)";
        grass_destroy_context(ctx);
        EXPECT_EQ(vi::live().total(), 0) << "left behind: " << vi::live().describe();
    }
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
}

TEST(VkMemory, StatsReportTheHeapsAndTheBudget) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, small_target(), &error);
    ASSERT_TRUE(host) << error;
    FailureLog log;
    grass_context* ctx = nullptr;
    std::vector<grass_field_id> fields;
    std::vector<grass_map_id> maps;
    draw_fields(*host, 2, &log, &ctx, &fields, &maps);
    ASSERT_NE(ctx, nullptr);
    const grass_memory_stats s = memory_stats(ctx);
    ASSERT_GE(s.heap_count, 1u);
    ASSERT_LE(s.heap_count, static_cast<uint32_t>(GRASS_MAX_MEMORY_HEAPS));
    uint64_t in_use = 0, allocated = 0;
    for (uint32_t h = 0; h < GRASS_MAX_MEMORY_HEAPS; ++h) {
        if (h >= s.heap_count) {
            EXPECT_EQ(s.heap_size[h] | s.heap_allocated[h] | s.heap_in_use[h] | s.heap_budget[h] | s.heap_usage[h], 0u)
                << "heap " << h << " does not exist";
            continue;
        }
        EXPECT_GT(s.heap_size[h], 0u) << "heap " << h;
        EXPECT_GE(s.heap_allocated[h], s.heap_in_use[h]) << "heap " << h;
        EXPECT_LE(s.heap_allocated[h], s.heap_size[h]) << "heap " << h;
        in_use += s.heap_in_use[h];
        allocated += s.heap_allocated[h];
        if (s.heap_budget_known) {
            EXPECT_GT(s.heap_budget[h], 0u) << "heap " << h;
            EXPECT_GE(s.heap_usage[h], s.heap_allocated[h]) << "heap " << h << ": the process's usage includes grass's";
        }
        std::printf("[ memory   ] heap %u: %llu MiB, grass allocated %llu KiB, uses %llu KiB; budget %llu MiB, usage "
                    "%llu KiB\n",
                    h, static_cast<unsigned long long>(s.heap_size[h] >> 20),
                    static_cast<unsigned long long>(s.heap_allocated[h] >> 10),
                    static_cast<unsigned long long>(s.heap_in_use[h] >> 10),
                    static_cast<unsigned long long>(s.heap_budget[h] >> 20),
                    static_cast<unsigned long long>(s.heap_usage[h] >> 10));
    }
    EXPECT_EQ(in_use, s.gpu_bytes) << "gpu_bytes is what grass's resources take, spread over the heaps";
    EXPECT_GT(allocated, 0u);
    EXPECT_GT(s.device_allocations, 0u);
    EXPECT_EQ(s.heap_budget_known != 0, vi::driver_has_memory_budget())
        << "the budget is known exactly where the device lists VK_EXT_memory_budget";
    grass_destroy_context(ctx);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
}

// A device with VK_EXT_memory_budget (emulated where the driver lacks it, as lavapipe 22.3
// does): its budget and usage per heap are reported as the device gives them, queried at each
// call, though the host did not enable the extension on its device.
TEST(VkMemory, TheBudgetIsReportedWhereTheDeviceHasIt) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, small_target(), &error);
    ASSERT_TRUE(host) << error;
    vi::emulate_memory_budget(true);
    FailureLog log;
    grass_context* ctx = nullptr;
    std::vector<grass_field_id> fields;
    std::vector<grass_map_id> maps;
    draw_fields(*host, 1, &log, &ctx, &fields, &maps);
    ASSERT_NE(ctx, nullptr);
    const grass_memory_stats s = memory_stats(ctx);
    vi::emulate_memory_budget(false);
    EXPECT_EQ(s.heap_budget_known, 1u);
    for (uint32_t h = 0; h < s.heap_count; ++h) {
        EXPECT_EQ(s.heap_budget[h], vi::emulated_budget(h)) << "heap " << h;
        EXPECT_EQ(s.heap_usage[h], vi::emulated_usage(h)) << "heap " << h;
    }
    grass_destroy_context(ctx);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
}

// GL has no portable query of device memory: no heap, no numbers made up.
TEST(GlMemory, ReportsNoHeap) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_GL, grass_host::TargetDesc{}, &error);
    if (!host) GTEST_SKIP() << "no GL host in this build: " << error;
    FailureLog log;
    grass_context* ctx = nullptr;
    std::vector<grass_field_id> fields;
    std::vector<grass_map_id> maps;
    ASSERT_EQ(host->create_context(logged_desc(&log), &ctx), GRASS_SUCCESS) << log.text;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 64;
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS) << log.text;
    grass_memory_stats s;
    std::memset(&s, 0xab, sizeof s);
    ASSERT_EQ(grass_get_memory_stats(ctx, &s), GRASS_SUCCESS);
    EXPECT_GT(s.gpu_bytes, 0u) << "the patch's buffers";
    EXPECT_EQ(s.heap_count, 0u);
    EXPECT_EQ(s.heap_budget_known, 0u);
    EXPECT_EQ(s.device_allocations, 0u);
    for (uint32_t h = 0; h < GRASS_MAX_MEMORY_HEAPS; ++h) {
        EXPECT_EQ(s.heap_size[h] | s.heap_allocated[h] | s.heap_in_use[h] | s.heap_budget[h] | s.heap_usage[h], 0u);
    }
    grass_destroy_context(ctx);
}

// A host allocator that counts: every block it hands out, by address.
struct CountingCallbacks {
    std::map<void*, size_t> live;
    int64_t allocations = 0, reallocations = 0, frees = 0, internal = 0;
    bool foreign_user_data = false;

    static CountingCallbacks* self(void* user, CountingCallbacks* expected) {
        if (user != expected) expected->foreign_user_data = true;
        return expected;
    }
    static CountingCallbacks* the;
    static void* VKAPI_PTR allocate(void* user, size_t size, size_t alignment, VkSystemAllocationScope) {
        CountingCallbacks* c = self(user, the);
        if (size == 0) return nullptr;
        void* p = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
        if (p) {
            c->live[p] = size;
            c->allocations += 1;
        }
        return p;
    }
    static void* VKAPI_PTR reallocate(void* user, void* original, size_t size, size_t alignment,
                                      VkSystemAllocationScope scope) {
        CountingCallbacks* c = self(user, the);
        c->reallocations += 1;
        if (!original) return allocate(user, size, alignment, scope);
        if (size == 0) {
            release(user, original);
            return nullptr;
        }
        void* p = allocate(user, size, alignment, scope);
        if (!p) return nullptr;
        std::memcpy(p, original, std::min(size, c->live[original]));
        release(user, original);
        return p;
    }
    static void VKAPI_PTR release(void* user, void* memory) {
        CountingCallbacks* c = self(user, the);
        if (!memory) return;
        auto it = c->live.find(memory);
        if (it == c->live.end()) {
            c->foreign_user_data = true; // freeing what this allocator never gave
            return;
        }
        c->live.erase(it);
        c->frees += 1;
        std::free(memory);
    }
    static void VKAPI_PTR internal_allocation(void* user, size_t, VkInternalAllocationType, VkSystemAllocationScope) {
        self(user, the)->internal += 1;
    }
    static void VKAPI_PTR internal_free(void* user, size_t, VkInternalAllocationType, VkSystemAllocationScope) {
        self(user, the)->internal -= 1;
    }
    VkAllocationCallbacks callbacks() {
        VkAllocationCallbacks c{};
        c.pUserData = this;
        c.pfnAllocation = &allocate;
        c.pfnReallocation = &reallocate;
        c.pfnFree = &release;
        c.pfnInternalAllocation = &internal_allocation;
        c.pfnInternalFree = &internal_free;
        return c;
    }
};
CountingCallbacks* CountingCallbacks::the = nullptr;

TEST(VkMemory, HostAllocationCallbacksAreUsedAndEveryAllocationIsFreed) {
    CountingCallbacks counting;
    CountingCallbacks::the = &counting;
    const VkAllocationCallbacks callbacks = counting.callbacks();
    grass_host::TargetDesc t = small_target();
    t.vk_allocation_callbacks = &callbacks;
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, t, &error);
    ASSERT_TRUE(host) << error;
    FailureLog log;
    grass_context* ctx = nullptr;
    std::vector<grass_field_id> fields;
    std::vector<grass_map_id> maps;
    draw_fields(*host, 3, &log, &ctx, &fields, &maps);
    ASSERT_NE(ctx, nullptr);
    EXPECT_GT(counting.allocations, 0) << "the driver allocated grass's objects through the host's callbacks";
    EXPECT_GT(counting.live.size(), 0u) << "grass's live objects hold host memory of the callbacks";
    grass_destroy_context(ctx);
    EXPECT_EQ(vi::live().total(), 0) << "left behind: " << vi::live().describe();
    EXPECT_EQ(counting.live.size(), 0u) << "host memory of the callbacks not freed when the context was destroyed";
    EXPECT_EQ(counting.internal, 0) << "internal allocations reported but not freed";
    EXPECT_FALSE(counting.foreign_user_data) << "a callback got another pUserData, or freed what it never gave";
    std::printf("[ memory   ] host callbacks: %lld allocations, %lld reallocations, %lld frees\n",
                static_cast<long long>(counting.allocations), static_cast<long long>(counting.reallocations),
                static_cast<long long>(counting.frees));
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    CountingCallbacks::the = nullptr;
}

TEST(VkMemory, CallbacksMissingAFunctionAreRefused) {
    CountingCallbacks counting;
    CountingCallbacks::the = &counting;
    struct Case {
        const char* name;
        void (*spoil)(VkAllocationCallbacks*);
    } cases[] = {
        {"pfnAllocation", [](VkAllocationCallbacks* c) { c->pfnAllocation = nullptr; }},
        {"pfnReallocation", [](VkAllocationCallbacks* c) { c->pfnReallocation = nullptr; }},
        {"pfnFree", [](VkAllocationCallbacks* c) { c->pfnFree = nullptr; }},
        {"pfnInternalFree", [](VkAllocationCallbacks* c) { c->pfnInternalAllocation = nullptr; }},
    };
    for (const Case& k : cases) {
        VkAllocationCallbacks callbacks = counting.callbacks();
        k.spoil(&callbacks);
        grass_host::TargetDesc t = small_target();
        t.vk_allocation_callbacks = &callbacks;
        std::string error;
        auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, t, &error);
        ASSERT_TRUE(host) << error;
        FailureLog log;
        grass_context* ctx = nullptr;
        EXPECT_EQ(host->create_context(logged_desc(&log), &ctx), GRASS_ERROR_INVALID_ARGUMENT) << k.name;
        EXPECT_EQ(ctx, nullptr);
        EXPECT_NE(log.text.find(std::string("allocation_callbacks")), std::string::npos) << log.text;
        EXPECT_NE(log.text.find(k.name), std::string::npos) << log.text;
        EXPECT_EQ(vi::live().total(), 0) << k.name << ": left behind: " << vi::live().describe();
    }
    EXPECT_EQ(counting.allocations, 0) << "a refused context made nothing";
    CountingCallbacks::the = nullptr;
}

// grass_vk_desc never changes layout (grass_default_vk_desc returns it by value): what else the
// host lends comes chained through its next (grass_vk_host_objects_desc), once. Anything else
// there is refused by its type tag, before any Vulkan call (the handles here are not Vulkan's).
TEST(VkMemory, TheVkDescsChainTakesTheHostObjectsOnceAndNothingElse) {
    int not_vulkan = 0;
    grass_vk_desc vk = grass_default_vk_desc();
    vk.get_instance_proc_addr = vi::get_instance_proc_addr();
    vk.instance = vk.physical_device = vk.device = &not_vulkan;
    vk.color_format = VK_FORMAT_R8G8B8A8_UNORM;
    vk.depth_format = VK_FORMAT_D32_SFLOAT;
    grass_wind_desc wind = grass_default_wind_desc();
    grass_vk_host_objects_desc first = grass_default_vk_host_objects_desc();
    grass_vk_host_objects_desc second = grass_default_vk_host_objects_desc();
    first.next = &second;
    struct Case {
        const char* what;
        const void* next;
        const char* named;
    } cases[] = {
        {"another struct", &wind, "0x67720009"},
        {"the host objects twice", &first, "once"},
    };
    for (const Case& k : cases) {
        vk.next = k.next;
        FailureLog log;
        grass_context* ctx = nullptr;
        const grass_context_desc cd = logged_desc(&log);
        EXPECT_EQ(grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &vk, &ctx), GRASS_ERROR_INVALID_ARGUMENT)
            << k.what;
        EXPECT_EQ(ctx, nullptr) << k.what;
        EXPECT_EQ(log.last_error, GRASS_MSG_NEXT_NOT_NULL) << k.what << ": " << log.text;
        EXPECT_NE(log.text.find("vk_desc->next"), std::string::npos) << log.text;
        EXPECT_NE(log.text.find(k.named), std::string::npos) << log.text;
    }
    EXPECT_EQ(vi::live().total(), 0) << "left behind: " << vi::live().describe();
}

} // namespace
} // namespace grass_test
