// Device failures on Vulkan, injected through grass's own dispatch table (the host hands
// grass a vkGetInstanceProcAddr that wraps some device functions; vk_intercept.hpp):
// - a call that fails mid-frame with VK_ERROR_DEVICE_LOST returns GRASS_ERROR_BACKEND with
//   GRASS_MSG_DEVICE_LOST, records nothing into the host's command buffer (which the host
//   still ends and submits, under the validation layers), and the context stays destroyable
//   with every Vulkan object it made destroyed;
// - every device-memory allocation of a scenario (context, patch, field, frames) failing in
//   turn with VK_ERROR_OUT_OF_DEVICE_MEMORY gives GRASS_ERROR_OUT_OF_MEMORY from that call
//   alone; the call repeated succeeds, the frame still draws grass, nothing leaks.
#include "render_fixture.hpp"
#include "vk_intercept.hpp"

#include <grass/grass_vk.h>

#include <vulkan/vulkan.h>

#include <functional>

namespace grass_test {
namespace {

namespace vi = vk_intercept;

struct Log {
    grass_message_id last_error = GRASS_MSG_NONE;
    std::string text;
};

grass_context_desc logged_desc(Log* log) {
    grass_context_desc cd = grass_default_context_desc();
    cd.log_user_data = log;
    cd.log_fn = [](void* user, grass_log_level level, grass_message_id id, const char* message) {
        auto* l = static_cast<Log*>(user);
        if (level == GRASS_LOG_ERROR) l->last_error = id;
        if (level != GRASS_LOG_INFO) l->text += std::string(message) + "\n";
    };
    return cd;
}

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
    Log log;
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

// One run of the scenario with the `fail_at`th vkAllocateMemory failing (0: none). Returns
// the allocations it made, or -1 after a failed expectation. `responsive`: with wind and a
// collider (blade curves, the interaction map, its pipeline and per-frame buffer).
// *setup_allocations: the allocations made before the first frame.
int allocation_scenario(grass_host::Host& host, int fail_at, bool responsive = false,
                        int* setup_allocations = nullptr) {
    vi::clear_failures();
    if (fail_at > 0) vi::fail_calls("vkAllocateMemory", VK_ERROR_OUT_OF_DEVICE_MEMORY, 1, fail_at - 1);
    const int injected_before = vi::failures_injected();
    const int64_t made_before = vi::live().memory_made;
    Log log;
    std::string error;
    // A call either succeeds, or fails with out of memory because of the injected failure
    // and then succeeds when repeated.
    auto call = [&](const char* what, const std::function<grass_result()>& f) {
        const bool failed_before = vi::failures_injected() > injected_before;
        grass_result r = f();
        if (r == GRASS_SUCCESS) return true;
        EXPECT_EQ(r, GRASS_ERROR_OUT_OF_MEMORY) << what << " (allocation " << fail_at << "): " << log.text << error;
        EXPECT_FALSE(failed_before) << what << " failed after the injected failure: " << log.text << error;
        EXPECT_EQ(log.last_error, GRASS_MSG_OUT_OF_MEMORY) << log.text;
        r = f();
        EXPECT_EQ(r, GRASS_SUCCESS) << what << " repeated: " << log.text << error;
        return r == GRASS_SUCCESS;
    };
    grass_context* ctx = nullptr;
    const grass_context_desc cd = logged_desc(&log);
    if (!call("grass_vk_create_context", [&] { return host.create_context(cd, &ctx); })) return -1;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 128;
    grass_patch_id patch{};
    if (!call("grass_create_patch", [&] { return grass_create_patch(ctx, &pd, &patch); })) return -1;
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 64;
    grass_field_id field{};
    if (!call("grass_create_field", [&] { return grass_create_field(ctx, &fd, &field); })) return -1;
    if (responsive) {
        grass_wind_desc wind = grass_default_wind_desc();
        wind.speed = 4.0f;
        EXPECT_EQ(grass_set_wind(ctx, &wind), GRASS_SUCCESS) << log.text;
        grass_collider ball{};
        ball.radius = 0.4f;
        ball.centre[0] = 8.0;
        ball.centre[1] = 0.2;
        ball.centre[2] = 3.0;
        EXPECT_EQ(grass_set_colliders(ctx, &ball, 1), GRASS_SUCCESS) << log.text;
    }
    if (setup_allocations) *setup_allocations = static_cast<int>(vi::live().memory_made - made_before);
    const grass_view_desc v = scene_view(host);
    grass_host::Image image;
    for (int frame = 0; frame < 2; ++frame) {
        if (!call("a frame", [&] { return host.render(ctx, v, nullptr, &image, &error); })) return -1;
    }
    expect_grass(image, host.target(), 0.2, "the last frame");
    const int64_t allocations = vi::live().memory_made - made_before;
    grass_destroy_context(ctx);
    EXPECT_EQ(vi::live().total(), 0) << "allocation " << fail_at << ": left behind: " << vi::live().describe();
    EXPECT_EQ(host.validation_messages(), 0u) << host.validation_log();
    if (fail_at > 0) {
        EXPECT_EQ(vi::failures_injected(), injected_before + 1) << "allocation " << fail_at;
    }
    return static_cast<int>(allocations);
}

TEST(DeviceFailure, EveryDeviceMemoryAllocationFailingInTurnGivesOutOfMemory) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, intercepted_target(), &error);
    ASSERT_TRUE(host) << error;
    const int total = allocation_scenario(*host, 0);
    ASSERT_GT(total, 3);
    for (int n = 1; n <= total && !::testing::Test::HasFailure(); ++n) allocation_scenario(*host, n);
    std::printf("[ device   ] %d device-memory allocations, each failed once\n", total);
}

TEST(DeviceFailure, EveryAllocationOfResponsiveGrassFailingInTurnGivesOutOfMemory) {
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_VULKAN, intercepted_target(), &error);
    ASSERT_TRUE(host) << error;
    const int still = allocation_scenario(*host, 0);
    int setup = 0;
    const int total = allocation_scenario(*host, 0, true, &setup);
    ASSERT_GT(total, still) << "wind and a collider allocate more";
    // Responsive grass allocates in its frames; the setup is that of still grass, tested above.
    for (int n = setup + 1; n <= total && !::testing::Test::HasFailure(); ++n) allocation_scenario(*host, n, true);
    std::printf("[ device   ] %d device-memory allocations with wind and a collider (%d more); the %d of its frames "
                "each failed once\n",
                total, total - still, total - setup);
}

} // namespace
} // namespace grass_test
