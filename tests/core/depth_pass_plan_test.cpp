// The plan of a depth pass (grass_view_pass_desc, GRASS_PASS_DEPTH), without a GPU: the core
// decides once that every draw of a depth view runs the depth pass's shader variant
// (kFeatureDepthPass) and carries its bias, and that no draw of a colour view does, so a
// frame without a depth view asks no backend for it.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "foundation/shader_interface.hpp"

namespace {

class DepthPassPlanTest : public CoreTest {};

TEST_F(DepthPassPlanTest, EveryDrawOfADepthViewAndNoOtherRunsTheDepthVariant) {
    const grass_patch_id patch = make_patch();
    const grass_tier_desc tiers[3] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 2}, {GRASS_TIER_IMAGE, 0}};
    grass_lod_test bands[3] = {};
    const float ends[3] = {3.0f, 7.0f, INFINITY};
    for (uint32_t t = 0; t < 3; ++t) {
        bands[t].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        bands[t].tier = t;
        bands[t].begin = t == 0 ? 0.0f : ends[t - 1];
        bands[t].end = ends[t];
    }
    grass_field_desc d = one_tier_field(patch, 48, &tiers[0], &bands[0]);
    d.tiers = tiers;
    d.tier_count = 3;
    d.lod_tests = bands;
    d.lod_test_count = 3;
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();

    const double eye[3] = {6.0, 1.5, -1.0}, look[3] = {6.0, 0.0, 6.0};
    const grass_view_desc colour = test_view(eye, look);
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_DEPTH;
    pass.depth_bias_constant = 3.0f;
    pass.depth_bias_slope = 1.25f;
    grass_view_desc depth = colour;
    depth.next = &pass;
    grass_frame_desc frame = grass_default_frame_desc();
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << last_message();
    uint32_t index = 0;
    ASSERT_EQ(grass_plan_view(ctx, &colour, &index), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_plan_view(ctx, &depth, &index), GRASS_SUCCESS) << last_message();
    const grass::FramePlan& a = ctx->views.plan(0);
    const grass::FramePlan& b = ctx->views.plan(1);
    EXPECT_FALSE(a.depth_pass);
    EXPECT_TRUE(b.depth_pass);
    EXPECT_EQ(b.depth_bias[0], 3.0f);
    EXPECT_EQ(b.depth_bias[1], 1.25f);
    // The same draws, the depth view's with the depth pass's bit and no other change.
    ASSERT_EQ(a.draws.size(), b.draws.size());
    uint32_t kinds = 0;
    for (size_t i = 0; i < a.draws.size(); ++i) {
        EXPECT_EQ(a.draws[i].features & grass::kFeatureDepthPass, 0u) << "colour draw " << i;
        EXPECT_EQ(b.draws[i].features, a.draws[i].features | grass::kFeatureDepthPass) << "depth draw " << i;
        EXPECT_EQ(b.draws[i].uniforms.tiling[3], b.draws[i].features) << "depth draw " << i;
        kinds |= 1u << a.draws[i].kind;
    }
    EXPECT_EQ(kinds, 7u) << "every tier kind draws";
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

} // namespace
