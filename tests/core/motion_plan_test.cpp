// The plan of a view that writes motion vectors (grass_view_motion_desc), without a GPU: the
// core decides once that every draw of such a colour view runs the motion variant
// (kFeatureMotion) and hands the backend this view's and the previous frame's
// view-projections without their jitter, both taking this view's camera-relative positions,
// and the wind's gust phases at the previous time; a view without it, and a depth pass with
// it, get none of it.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "foundation/shader_interface.hpp"

#include <cmath>
#include <cstring>

namespace {

class MotionPlanTest : public CoreTest {};

// Column-major m * (p, 1), in double.
void transform(const float m[16], const double p[3], double out[4]) {
    for (int r = 0; r < 4; ++r) out[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
}

// Jitters a projection by `j` in NDC: clip.xy += j clip.w.
void jitter(float projection[16], const float j[2]) {
    for (int c = 0; c < 4; ++c) {
        projection[4 * c + 0] += j[0] * projection[4 * c + 3];
        projection[4 * c + 1] += j[1] * projection[4 * c + 3];
    }
}

TEST_F(MotionPlanTest, EveryDrawOfAMotionColourViewAndNoOtherRunsTheMotionVariant) {
    const grass_patch_id patch = make_patch();
    const grass_tier_desc tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test band{};
    band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    band.end = INFINITY;
    const grass_field_desc d = one_tier_field(patch, 16, &tier, &band);
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 3.0f;
    ASSERT_EQ(grass_set_wind(ctx, &wind), GRASS_SUCCESS) << last_message();

    const double eye[3] = {2.0, 1.5, -1.0}, look[3] = {2.0, 0.0, 2.0};
    const double before_eye[3] = {1.7, 1.4, -1.2}, before_look[3] = {2.2, 0.0, 2.0};
    grass_view_desc plain = test_view(eye, look);
    plain.time = 10.0;
    grass_view_desc earlier = plain; // what the previous frame's wind phases were
    earlier.time = 9.75;
    const grass_view_desc previous = test_view(before_eye, before_look);
    grass_view_motion_desc motion = grass_default_view_motion_desc();
    for (int c = 0; c < 3; ++c) motion.previous_camera_position[c] = before_eye[c];
    std::memcpy(motion.previous_view, previous.view, sizeof motion.previous_view);
    std::memcpy(motion.previous_projection, previous.projection, sizeof motion.previous_projection);
    motion.previous_jitter[0] = 0.01f; // jittered by (0.01, -0.02) in NDC
    motion.previous_jitter[1] = -0.02f;
    jitter(motion.previous_projection, motion.previous_jitter);
    motion.previous_time = 9.75;
    grass_view_desc moving = plain;
    motion.jitter[0] = -0.03f; // this one by (-0.03, 0.005)
    motion.jitter[1] = 0.005f;
    jitter(moving.projection, motion.jitter);
    moving.next = &motion;
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_DEPTH;
    pass.next = &motion;
    grass_view_desc depth = plain;
    depth.next = &pass;

    grass_frame_desc frame = grass_default_frame_desc();
    frame.time = 9.75;
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << last_message();
    uint32_t index = 0;
    ASSERT_EQ(grass_plan_view(ctx, &earlier, &index), GRASS_SUCCESS) << last_message();
    float earlier_phase[4];
    std::memcpy(earlier_phase, ctx->views.plan(0).frame.wind_phase, sizeof earlier_phase);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);

    frame.time = 10.0;
    frame.frame_index += 1;
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_plan_view(ctx, &plain, &index), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_plan_view(ctx, &moving, &index), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_plan_view(ctx, &depth, &index), GRASS_SUCCESS) << last_message();
    const grass::FramePlan& a = ctx->views.plan(0);
    const grass::FramePlan& b = ctx->views.plan(1);
    const grass::FramePlan& c = ctx->views.plan(2);
    EXPECT_FALSE(a.motion);
    EXPECT_TRUE(b.motion);
    EXPECT_FALSE(c.motion) << "a depth pass ignores the struct";
    EXPECT_EQ(b.velocity_attachment, 1u);
    for (int k = 0; k < 4; ++k) {
        EXPECT_FLOAT_EQ(b.motion_uniforms.previous_wind_phase[k], earlier_phase[k]) << "gust phase " << k;
    }
    EXPECT_NE(std::memcmp(a.frame.wind_phase, earlier_phase, sizeof earlier_phase), 0) << "the gusts moved";
    EXPECT_FLOAT_EQ(b.motion_uniforms.times[0], 0.25f) << "the trails' age at the previous time: 10 - 9.75 s younger";

    // A world point: its camera-relative position through the plan's matrices lands where the
    // unjittered projections put it, in this frame and in the previous one.
    const double world[3] = {2.3, 0.2, 1.1};
    const double now_rel[3] = {world[0] - eye[0], world[1] - eye[1], world[2] - eye[2]};
    const double before_rel[3] = {world[0] - before_eye[0], world[1] - before_eye[1], world[2] - before_eye[2]};
    double got[4], expected[4];
    transform(b.motion_uniforms.view_projection, now_rel, got);
    transform(a.frame.view_projection, now_rel, expected); // `plain` has no jitter
    for (int r = 0; r < 2; ++r) EXPECT_NEAR(got[r] / got[3], expected[r] / expected[3], 1e-5) << "now, row " << r;
    transform(b.motion_uniforms.previous_view_projection, now_rel, got);
    grass_view_desc unjittered = previous;
    unjittered.next = nullptr;
    double rotated[3];
    for (int r = 0; r < 3; ++r) {
        rotated[r] = unjittered.view[r] * before_rel[0] + unjittered.view[4 + r] * before_rel[1] +
                     unjittered.view[8 + r] * before_rel[2];
    }
    transform(unjittered.projection, rotated, expected);
    for (int r = 0; r < 2; ++r) EXPECT_NEAR(got[r] / got[3], expected[r] / expected[3], 1e-5) << "before, row " << r;

    ASSERT_EQ(a.draws.size(), b.draws.size());
    ASSERT_GT(a.draws.size(), 0u);
    for (size_t i = 0; i < a.draws.size(); ++i) {
        EXPECT_EQ(a.draws[i].features & grass::kFeatureMotion, 0u) << "plain draw " << i;
        EXPECT_EQ(c.draws[i].features & grass::kFeatureMotion, 0u) << "depth draw " << i;
        EXPECT_EQ(b.draws[i].features, a.draws[i].features | grass::kFeatureMotion) << "motion draw " << i;
        EXPECT_EQ(b.draws[i].uniforms.tiling[3], b.draws[i].features) << "motion draw " << i;
    }
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

} // namespace
