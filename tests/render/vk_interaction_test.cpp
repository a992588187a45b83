// The interaction pass on Vulkan (grass_vk.h, docs/responsive.md), through grass's own
// dispatch table (vk_intercept.hpp counts the dispatches grass records):
// - grass_vk_prepare records one dispatch per map level for a frame with colliders (and the
//   blade window pass's, vk_blade_window_test.cpp), and
//   none for a frame of still grass, which holds no responsive GPU memory; the frame with a
//   collider shows its trail where the collider is and nothing changes far from it; once the
//   map is dropped (grass_set_interaction) no pass runs and its memory is given back;
// - the barriers of grass_vk.h satisfy the synchronization validation of
//   VK_LAYER_KHRONOS_validation over frames that write and read the map, remake it and
//   scroll it;
// - grass_vk_record refuses a frame whose pass grass_vk_prepare did not record;
// - grass_vk_prepare refuses a bad desc, naming the argument, and records nothing.
#include "vk_small_scene.hpp"

#include "image_io.hpp"

#include <grass/grass_vk.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace grass_test {
namespace {

namespace vi = vk_intercept;

constexpr double kBall[3] = {2.0, 0.2, 1.6}; // on the 4 m x 4 m field, in view
constexpr float kBallRadius = 0.35f;

using Scene = VkSmallScene;
// A 4 m x 4 m field of blades seen at a slant from its near edge.
void make_scene(Scene* s) { make_small_scene(s); }

grass_view_desc scene_view(const Scene& s, double time) {
    const double eye[3] = {2.0, 1.2, -0.4}, look[3] = {2.0, 0.0, 2.0};
    grass_view_desc v = grass_host::make_view(*s.host, eye, look, 50.0f, 0.05f, 100.0f);
    v.time = time;
    return v;
}

grass_host::Image frame(Scene& s, double time) {
    grass_host::Image image;
    std::string error;
    EXPECT_EQ(s.host->render(s.ctx, scene_view(s, time), nullptr, &image, &error), GRASS_SUCCESS) << error << s.log;
    return image;
}

grass_result set_ball(grass_context* ctx, double x, float vx) {
    grass_collider ball{};
    ball.shape = GRASS_COLLIDER_SPHERE;
    ball.radius = kBallRadius;
    ball.center[0] = x;
    ball.center[1] = kBall[1];
    ball.center[2] = kBall[2];
    ball.velocity[0] = vx;
    return grass_set_colliders(ctx, &ball, 1);
}

uint64_t dynamics_bytes(grass_context* ctx) {
    grass_memory_stats m{};
    EXPECT_EQ(grass_get_memory_stats(ctx, &m), GRASS_SUCCESS);
    return m.dynamics_gpu_bytes;
}

// Mean |a - b| (levels) over the pixels within `radius` px of (cx, cy), or beyond it.
double mean_difference_near(const grass_host::Image& a, const grass_host::Image& b, double cx, double cy, double radius,
                            bool inside) {
    double sum = 0.0;
    uint64_t n = 0;
    for (uint32_t y = 0; y < a.height; ++y) {
        for (uint32_t x = 0; x < a.width; ++x) {
            const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            if ((d < radius) != inside) continue;
            for (int c = 0; c < 3; ++c) sum += std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c]));
            n += 3;
        }
    }
    return n ? sum / double(n) : 0.0;
}

TEST(VkInteraction, PrepareFrameRecordsThePassOnlyForFramesWithColliders) {
    Scene s;
    make_scene(&s);
    ASSERT_FALSE(HasFatalFailure());
    const uint32_t levels = grass_default_interaction_desc().level_count;

    int64_t before = vi::live().dispatches;
    const grass_host::Image still = frame(s, 1.0);
    EXPECT_EQ(vi::live().dispatches - before, 0) << "still grass records no interaction pass";
    EXPECT_EQ(dynamics_bytes(s.ctx), 0u) << "still grass holds no responsive GPU memory";
    expect_grass(still, s.host->target(), 0.3, "still grass");

    ASSERT_EQ(set_ball(s.ctx, kBall[0], 0.0f), GRASS_SUCCESS) << s.log;
    before = vi::live().dispatches;
    const grass_host::Image pressed = frame(s, 1.1);
    // One dispatch per level, then the blade window pass's one (the field's one geometry draw).
    EXPECT_EQ(vi::live().dispatches - before, int64_t(levels) + 1) << "one dispatch per level and the window's";
    const grass_interaction_desc id = grass_default_interaction_desc();
    EXPECT_GE(dynamics_bytes(s.ctx), uint64_t(id.level_count) * id.resolution * id.resolution * 16u)
        << "the map's levels are counted";

    // Where the ball presses, the grass lies down; far from it nothing changes.
    double cx = 0.0, cy = 0.0;
    const double eye[3] = {2.0, 1.2, -0.4}, look[3] = {2.0, 0.0, 2.0}, ground[3] = {kBall[0], 0.0, kBall[2]};
    ASSERT_TRUE(project_point(eye, look, 50.0f, pressed.width, pressed.height, ground, &cx, &cy));
    const double near_ball = mean_difference_near(still, pressed, cx, cy, 8.0, true);
    const double far_away = mean_difference_near(still, pressed, cx, cy, 30.0, false);
    std::printf("[ measured ] the ball changes the image by %.2f levels within 8 px of it, %.3f beyond 30 px\n",
                near_ball, far_away);
    // Far from it a blade without force keeps its rest pose (0.000 levels measured).
    EXPECT_GT(near_ball, 6.0) << "no trail where the ball is";
    EXPECT_LT(far_away, 0.5) << "the grass changed far from the ball";

    // Without colliders and with the map dropped, no pass and the map's memory is given back.
    ASSERT_EQ(grass_set_colliders(s.ctx, nullptr, 0), GRASS_SUCCESS) << s.log;
    ASSERT_EQ(grass_set_interaction(s.ctx, nullptr), GRASS_SUCCESS) << s.log;
    before = vi::live().dispatches;
    frame(s, 1.2);
    EXPECT_EQ(vi::live().dispatches - before, 0) << "no map, no pass";
    EXPECT_LT(dynamics_bytes(s.ctx), uint64_t(id.resolution) * id.resolution * 16u) << "the map was released";
    if (const char* dir = std::getenv("GRASS_TEST_IMAGE_DIR")) {
        grass_host::write_png(std::string(dir) + "/vk_interaction_still.png", still, nullptr);
        grass_host::write_png(std::string(dir) + "/vk_interaction_pressed.png", pressed, nullptr);
    }
}

// grass_vk_prepare's desc (0.5; grass_vk_prepare_frame took the command buffer alone) is
// checked as every desc: each refusal names the argument, records nothing, and the frame's
// pass stays pending (grass_vk_record still refuses the frame).
TEST(VkInteraction, PrepareRefusesABadDescAndRecordsNothing) {
    Scene s;
    make_scene(&s);
    ASSERT_FALSE(HasFatalFailure());
    ASSERT_EQ(set_ball(s.ctx, kBall[0], 0.0f), GRASS_SUCCESS) << s.log;
    grass_view_desc v = scene_view(s, 1.0);
    ASSERT_EQ(grass_begin_frame(s.ctx, &v), GRASS_SUCCESS) << s.log;
    const int dispatches = vi::live().dispatches;
    const grass_vk_prepare_desc valid = grass_default_vk_prepare_desc();
    EXPECT_EQ(valid.type, GRASS_STRUCT_TYPE_VK_PREPARE_DESC);
    EXPECT_EQ(valid.next, nullptr);
    EXPECT_EQ(valid.command_buffer, nullptr);
    void* never_used = reinterpret_cast<void*>(uintptr_t(1));
    EXPECT_EQ(grass_vk_prepare(s.ctx, nullptr), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(s.log.find("grass_vk_prepare: prepare is NULL"), std::string::npos) << s.log;
    grass_vk_prepare_desc p = valid;
    p.type = GRASS_STRUCT_TYPE_VK_RECORD_DESC;
    p.command_buffer = never_used;
    EXPECT_EQ(grass_vk_prepare(s.ctx, &p), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_NE(s.log.find("prepare->type is 0x67720202"), std::string::npos) << s.log;
    p = valid;
    p.next = &valid;
    p.command_buffer = never_used;
    EXPECT_EQ(grass_vk_prepare(s.ctx, &p), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(s.log.find("prepare->next must be NULL"), std::string::npos) << s.log;
    p = valid;
    EXPECT_EQ(grass_vk_prepare(s.ctx, &p), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(s.log.find("prepare->command_buffer is NULL"), std::string::npos) << s.log;
    EXPECT_EQ(vi::live().dispatches, dispatches) << "a refused prepare records nothing";
    grass_vk_record_desc record = grass_default_vk_record_desc();
    record.command_buffer = never_used;
    EXPECT_EQ(grass_vk_record(s.ctx, &record), GRASS_ERROR_INVALID_STATE) << "the pass is still pending";
    EXPECT_EQ(grass_end_frame(s.ctx), GRASS_SUCCESS);
}

TEST(VkInteraction, RecordRefusesAFrameWhosePassWasNotPrepared) {
    Scene s;
    make_scene(&s);
    ASSERT_FALSE(HasFatalFailure());
    ASSERT_EQ(set_ball(s.ctx, kBall[0], 0.0f), GRASS_SUCCESS) << s.log;
    frame(s, 1.0); // the uploads and the map's first pass
    // The host's command buffer is not needed: grass_vk_record refuses before recording.
    grass_view_desc v = scene_view(s, 1.1);
    ASSERT_EQ(grass_begin_frame(s.ctx, &v), GRASS_SUCCESS) << s.log;
    grass_vk_record_desc record = grass_default_vk_record_desc();
    record.command_buffer = reinterpret_cast<void*>(uintptr_t(1)); // never used
    EXPECT_EQ(grass_vk_record(s.ctx, &record), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(s.log.find("interaction pass"), std::string::npos) << s.log;
    EXPECT_EQ(grass_end_frame(s.ctx), GRASS_SUCCESS);
}

// Synchronization validation reads VK_LAYER_ENABLES when the host makes its instance.
TEST(VkInteraction, SynchronizationValidationIsSilentOverFramesThatWriteReadAndRemakeTheMap) {
    ASSERT_EQ(setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 1), 0);
    Scene s;
    make_scene(&s);
    unsetenv("VK_LAYER_ENABLES");
    ASSERT_FALSE(HasFatalFailure());
    double x = 1.0;
    for (int k = 0; k < 4; ++k, x += 0.4) {
        ASSERT_EQ(set_ball(s.ctx, x, 4.0f), GRASS_SUCCESS) << s.log;
        frame(s, 1.0 + 0.1 * k);
    }
    // Remade (a new resolution): cleared, written, read.
    grass_interaction_desc id = grass_default_interaction_desc();
    id.resolution = 128;
    ASSERT_EQ(grass_set_interaction(s.ctx, &id), GRASS_SUCCESS) << s.log;
    frame(s, 1.5);
    frame(s, 1.6);
    EXPECT_EQ(s.host->validation_messages(), 0u) << s.host->validation_log();
}

} // namespace
} // namespace grass_test
