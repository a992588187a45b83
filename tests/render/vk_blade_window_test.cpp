// The blade window pass on Vulkan (grass_vk.h, docs/responsive.md "The blade window"),
// through grass's own dispatch table (vk_intercept.hpp counts the dispatches grass records
// and the objects it makes and names):
// - grass_vk_prepare records the window pass for a frame with wind, labelled, and none for
//   still grass, which makes no window pipeline and holds no window buffer; once the wind
//   stops the window's buffers are given back;
// - the barriers of grass_vk.h satisfy the synchronization validation of
//   VK_LAYER_KHRONOS_validation over frames in two frame slots (the test host's two frames
//   in flight) with wind and a moving collider, while the window grows;
// - grass_vk_record refuses a frame of the window variant whose pass was not recorded.
// The pictures (window against per-vertex poses, GL against Vulkan) are BladeWindowRenderTest's
// and BackendAgreement's.
#include "vk_small_scene.hpp"

#include <grass/grass_vk.h>

#include <cstdlib>
#include <string>

namespace grass_test {
namespace {

namespace vi = vk_intercept;

using Scene = VkSmallScene;
void make_scene(Scene* s) { make_small_scene(s); }

grass_view_desc scene_view(const Scene& s, double time, double back = 0.4) {
    const double eye[3] = {2.0, 1.2, -back}, look[3] = {2.0, 0.0, 2.0};
    grass_view_desc v = grass_host::make_view(*s.host, eye, look, 50.0f, 0.05f, 100.0f);
    v.time = time;
    return v;
}

grass_host::Image frame(Scene& s, double time, double back = 0.4) {
    grass_host::Image image;
    std::string error;
    EXPECT_EQ(s.host->render(s.ctx, scene_view(s, time, back), nullptr, &image, &error), GRASS_SUCCESS)
        << error << s.log;
    return image;
}

uint64_t dynamics_bytes(grass_context* ctx) {
    grass_memory_stats m{};
    EXPECT_EQ(grass_get_memory_stats(ctx, &m), GRASS_SUCCESS);
    return m.dynamics_gpu_bytes;
}

int count_named(const std::string& name) {
    int n = 0;
    for (const auto& [handle, named] : vi::names()) n += named == name ? 1 : 0;
    return n;
}

int count_label(const std::string& label) {
    int n = 0;
    for (const std::string& e : vi::label_events()) n += e == "+" + label ? 1 : 0;
    return n;
}

TEST(VkBladeWindow, ThePassRunsForWindAndStillGrassMakesAndHoldsNothingForIt) {
    vi::clear_debug_records();
    Scene s;
    make_scene(&s);
    ASSERT_FALSE(HasFatalFailure());
    frame(s, 1.0); // the uploads and the first pipelines
    int64_t dispatches = vi::live().dispatches;
    int64_t pipelines = vi::live().pipelines_made;
    const grass_host::Image still = frame(s, 1.1);
    expect_grass(still, s.host->target(), 0.3, "still grass");
    EXPECT_EQ(vi::live().dispatches - dispatches, 0) << "still grass records no pass";
    EXPECT_EQ(vi::live().pipelines_made - pipelines, 0) << "still grass makes no window pipeline";
    EXPECT_EQ(dynamics_bytes(s.ctx), 0u) << "still grass holds no window";
    EXPECT_EQ(count_label("grass blade window pass"), 0);
    EXPECT_EQ(count_named("grass blade window poses") + count_named("grass blade window table"), 0);

    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 6.0f;
    ASSERT_EQ(grass_set_wind(s.ctx, &wind), GRASS_SUCCESS) << s.log;
    dispatches = vi::live().dispatches;
    const grass_host::Image windy = frame(s, 1.2);
    const int64_t window_dispatches = vi::live().dispatches - dispatches;
    // Wind alone: no interaction map, so every dispatch is the window's, one per geometry draw.
    EXPECT_GE(window_dispatches, 1) << "a frame with wind runs the window pass";
    EXPECT_EQ(count_label("grass blade window pass"), 1) << "once per frame";
    EXPECT_EQ(count_named("grass blade window poses"), 1);
    EXPECT_EQ(count_named("grass blade window table"), 2) << "one per frame slot (the test host's 2 in flight)";
    const uint64_t windy_bytes = dynamics_bytes(s.ctx);
    const uint64_t pose_bytes = uint64_t(grass_default_patch_desc().blade_count) * 32u; // one cell's
    EXPECT_GE(windy_bytes, pose_bytes) << "the window's poses are counted";
    EXPECT_GT(mean_difference(still, windy), 2.0) << "the wind must move the grass";

    ASSERT_EQ(grass_set_wind(s.ctx, nullptr), GRASS_SUCCESS) << s.log;
    dispatches = vi::live().dispatches;
    const grass_host::Image calm = frame(s, 1.3);
    EXPECT_EQ(vi::live().dispatches - dispatches, 0) << "no wind, no pass";
    EXPECT_LE(dynamics_bytes(s.ctx) + pose_bytes, windy_bytes) << "the window's buffers were given back";
    EXPECT_EQ(mean_difference(still, calm), 0.0) << "still grass again draws what it drew";
    vi::clear_debug_records();
}

TEST(VkBladeWindow, RecordRefusesAWindowFrameWhosePassWasNotPrepared) {
    Scene s;
    make_scene(&s);
    ASSERT_FALSE(HasFatalFailure());
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 6.0f;
    ASSERT_EQ(grass_set_wind(s.ctx, &wind), GRASS_SUCCESS) << s.log;
    frame(s, 1.0); // the uploads and the first pass
    grass_view_desc v = scene_view(s, 1.1);
    ASSERT_EQ(grass_begin_frame(s.ctx, &v), GRASS_SUCCESS) << s.log;
    grass_vk_record_desc record = grass_default_vk_record_desc();
    record.command_buffer = reinterpret_cast<void*>(uintptr_t(1)); // never used: refused before recording
    EXPECT_EQ(grass_vk_record(s.ctx, &record), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(s.log.find("blade window pass"), std::string::npos) << s.log;
    EXPECT_EQ(grass_end_frame(s.ctx), GRASS_SUCCESS);
}

// Synchronization validation reads VK_LAYER_ENABLES when the host makes its instance. The
// test host's frames alternate between two frame slots (frames_in_flight 2): each frame's
// pass writes the poses the frame before drew with. The camera backs away half-way, so the
// window grows (new poses, the old retired while a frame may read them).
TEST(VkBladeWindow, SynchronizationValidationIsSilentWithTwoFramesInFlightAndAMovingCollider) {
    ASSERT_EQ(setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 1), 0);
    Scene s;
    make_scene(&s);
    unsetenv("VK_LAYER_ENABLES");
    ASSERT_FALSE(HasFatalFailure());
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 6.0f;
    ASSERT_EQ(grass_set_wind(s.ctx, &wind), GRASS_SUCCESS) << s.log;
    const uint64_t before = vi::live().dispatches;
    grass_host::Image first, last;
    for (int k = 0; k < 6; ++k) {
        grass_collider ball{};
        ball.shape = GRASS_COLLIDER_SPHERE;
        ball.radius = 0.35f;
        ball.center[0] = 1.0 + 0.4 * k;
        ball.center[1] = 0.2;
        ball.center[2] = 1.6;
        ball.velocity[0] = 4.0f;
        ASSERT_EQ(grass_set_colliders(s.ctx, &ball, 1), GRASS_SUCCESS) << s.log;
        last = frame(s, 1.0 + 0.1 * k, k < 3 ? 0.4 : 2.0);
        if (k == 0) first = last;
    }
    EXPECT_GE(vi::live().dispatches - before, 6u * 2u) << "the map's and the window's passes every frame";
    expect_grass(last, s.host->target(), 0.3, "the last frame");
    EXPECT_GT(mean_difference(first, last), 2.0) << "the frames must differ";
    EXPECT_EQ(s.host->validation_messages(), 0u) << s.host->validation_log();
}

} // namespace
} // namespace grass_test
