// Device failures on Vulkan, injected through grass's own dispatch table (the host hands
// grass a vkGetInstanceProcAddr that wraps some device functions; vk_intercept.hpp):
// - a call that fails mid-frame with VK_ERROR_DEVICE_LOST returns GRASS_ERROR_BACKEND with
//   GRASS_MSG_DEVICE_LOST, records nothing into the host's command buffer (which the host
//   still ends and submits, under the validation layers), and the context stays destroyable
//   with every Vulkan object it made destroyed;
// - every device-memory allocation of a scenario (context, patch, field, frames) failing in
//   turn with VK_ERROR_OUT_OF_DEVICE_MEMORY gives GRASS_ERROR_OUT_OF_MEMORY from that call
//   alone, after which grass holds the allocations it counts; the call repeated succeeds, the
//   frame still draws grass, nothing leaks. grass allocates device memory in blocks
//   (vk_memory_blocks.hpp), so the scenario runs on a device with small heaps (kSmallHeap):
//   its resources then need several blocks and dedicated allocations, made at the context,
//   the patch, the map, the field and the frames, and each of those fails in turn.
#include "allocation_scenario.hpp"
#include "vk_intercept.hpp"

#include <grass/grass_vk.h>

#include <vulkan/vulkan.h>

#include <functional>
#include <map>
#include <string>

namespace grass_test {
namespace {

namespace vi = vk_intercept;

grass_host::TargetDesc intercepted_target() {
    grass_host::TargetDesc t;
    t.width = t.height = 96;
    t.ground = true;
    t.vk_get_instance_proc_addr = vi::get_instance_proc_addr();
    return t;
}

// A field whose frame uses every tier, seen from 2 m (the volume and image draws allocate
// descriptor sets while recording).
grass_result make_field(grass_context* ctx, grass_field_id* field) {
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 128;
    grass_patch_id patch{};
    grass_result r = grass_create_patch(ctx, &pd, &patch);
    if (r != GRASS_SUCCESS) return r;
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 64;
    return grass_create_field(ctx, &fd, field);
}

grass_view_desc scene_view(const grass_host::Host& host) {
    const double eye[3] = {8.0, 2.0, -1.0}, look[3] = {8.0, 0.0, 10.0};
    return grass_host::make_view(host, eye, look, 50.0f, 0.05f, 200.0f);
}

TEST(DeviceFailure, ADeviceLostMidFrameIsReportedAndTheContextStaysDestroyable) {
    std::string error;
    const grass_host::TargetDesc t = intercepted_target();
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, t, &error);
    ASSERT_TRUE(host) << error;
    FailureLog log;
    grass_context* ctx = nullptr;
    ASSERT_EQ(host->create_context(logged_desc(&log), &ctx), GRASS_SUCCESS) << log.text;
    grass_field_id field{};
    ASSERT_EQ(make_field(ctx, &field), GRASS_SUCCESS) << log.text;
    const grass_view_desc v = scene_view(*host);
    grass_host::Image good;
    ASSERT_EQ(host->render(ctx, v, nullptr, &good, &error), GRASS_SUCCESS) << error << log.text;
    expect_grass(good, t, 0.2, "the frame before the failure");

    vi::fail_calls("vkAllocateDescriptorSets", VK_ERROR_DEVICE_LOST, 1000);
    const int before = vi::failures_injected();
    grass_host::Image lost;
    EXPECT_EQ(host->render(ctx, v, nullptr, &lost, &error), GRASS_ERROR_BACKEND) << log.text;
    EXPECT_GT(vi::failures_injected(), before) << "the frame allocated descriptor sets";
    EXPECT_EQ(log.last_error, GRASS_MSG_DEVICE_LOST) << log.text;
    EXPECT_NE(log.text.find("VK_ERROR_DEVICE_LOST"), std::string::npos) << log.text;
    // The host ended and submitted its command buffer with grass's failed record in it.
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    vi::clear_failures();

    grass_destroy_context(ctx);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    EXPECT_EQ(vi::live().total(), 0) << "left behind: " << vi::live().describe();
}

// Heaps of 16 MiB as grass sees them: full blocks of 2 MiB (vk_memory_blocks.hpp: an eighth of
// the heap), the first two of 512 KiB and 1 MiB, resources over 1 MiB dedicated. The context
// makes the first block; the field's setup (its buffers and the patch's baked slices) makes
// blocks and dedicated allocations; responsive grass's frames make more.
constexpr uint64_t kSmallHeap = uint64_t{16} << 20;

// One run of the scenario (allocation_scenario.hpp) with the `fail_at`th vkAllocateMemory
// failing (0: none), on a device whose heaps are kSmallHeap; then every Vulkan object grass
// made is destroyed with the context.
ScenarioResult allocation_scenario(grass_host::Host& host, int fail_at, bool responsive = false) {
    vi::clear_failures();
    vi::limit_heaps(kSmallHeap);
    if (fail_at > 0) vi::fail_calls("vkAllocateMemory", VK_ERROR_OUT_OF_DEVICE_MEMORY, 1, fail_at - 1);
    AllocationProbe probe;
    probe.failures_injected = [] { return vi::failures_injected(); };
    probe.allocations_made = [] { return vi::live().memory_made; };
    probe.create_function = "grass_vk_create_context";
    // A failed allocation leaves grass's accounting true: it holds the allocations it counts
    // (no block half made), and its resources' bytes are spread over the heaps.
    probe.after_failure = [](grass_context* ctx, const char* what) {
        if (!ctx) return;
        grass_memory_stats s{};
        ASSERT_EQ(grass_get_memory_stats(ctx, &s), GRASS_SUCCESS);
        EXPECT_EQ(static_cast<int64_t>(s.device_allocations), vi::live().memory) << what;
        uint64_t in_use = 0;
        for (uint32_t h = 0; h < s.heap_count; ++h) {
            EXPECT_LE(s.heap_in_use[h], s.heap_allocated[h]) << what << ", heap " << h;
            in_use += s.heap_in_use[h];
        }
        EXPECT_EQ(in_use, s.gpu_bytes) << what;
    };
    ScenarioResult result = run_allocation_scenario(host, probe, fail_at, responsive);
    if (result.context) grass_destroy_context(result.context);
    vi::limit_heaps(0);
    EXPECT_EQ(vi::live().total(), 0) << "allocation " << fail_at << ": left behind: " << vi::live().describe();
    EXPECT_EQ(host.validation_messages(), 0u) << host.validation_log();
    return result;
}

TEST(DeviceFailure, EveryDeviceMemoryAllocationFailingInTurnGivesOutOfMemory) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, intercepted_target(), &error);
    ASSERT_TRUE(host) << error;
    const int total = allocation_scenario(*host, 0).allocations;
    ASSERT_GT(total, 3) << "small heaps: several blocks";
    std::map<std::string, int> failed_in; // the calls whose allocation failed, and how many times
    for (int n = 1; n <= total && !::testing::Test::HasFailure(); ++n) {
        failed_in[allocation_scenario(*host, n).failed_call] += 1;
    }
    std::string calls;
    for (const auto& [call, count] : failed_in) calls += " " + call + " x" + std::to_string(count);
    std::printf("[ device   ] %d device-memory allocations, each failed once, in:%s\n", total, calls.c_str());
    // Blocks are made as the setup grows, not all at the context's creation.
    EXPECT_GE(failed_in.size(), 2u) << calls;
}

TEST(DeviceFailure, EveryAllocationOfResponsiveGrassFailingInTurnGivesOutOfMemory) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, intercepted_target(), &error);
    ASSERT_TRUE(host) << error;
    const int still = allocation_scenario(*host, 0).allocations;
    const ScenarioResult responsive = allocation_scenario(*host, 0, true);
    const int total = responsive.allocations, setup = responsive.setup_allocations;
    ASSERT_GT(total, still) << "wind and a collider allocate more";
    // Responsive grass allocates in its frames; the setup is that of still grass, tested above.
    for (int n = setup + 1; n <= total && !::testing::Test::HasFailure(); ++n) allocation_scenario(*host, n, true);
    std::printf("[ device   ] %d device-memory allocations with wind and a collider (%d more); the %d of its frames "
                "each failed once\n",
                total, total - still, total - setup);
}

} // namespace
} // namespace grass_test
