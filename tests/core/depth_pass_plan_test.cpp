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
    make_three_tier_field();

    const double eye[3] = {6.0, 1.5, -1.0}, look[3] = {6.0, 0.0, 6.0};
    const grass_view_desc colour = test_view(eye, look);
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_DEPTH;
    pass.depth_bias_constant = 3.0f;
    pass.depth_bias_slope = 1.25f;
    grass_view_desc depth = colour;
    depth.next = &pass;
    plan_frame({&colour, &depth});
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
