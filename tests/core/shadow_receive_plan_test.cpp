// The plan of a view that receives the host's shadows (grass_shadow_receive_desc), without a
// GPU: the core decides once that every draw of a receiving colour view runs the receiving
// variant (kFeatureShadowReceive) and hands the backend the map, the comparison and the
// cascades' matrices made camera-relative; a view without it, and a depth pass with it, get
// neither, so a frame that does not receive asks no backend for it.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "foundation/shader_interface.hpp"

#include <cmath>

namespace {

class ShadowReceivePlanTest : public CoreTest {};

TEST_F(ShadowReceivePlanTest, EveryDrawOfAReceivingColourViewAndNoOtherRunsTheReceivingVariant) {
    make_three_tier_field();

    const double eye[3] = {6.0, 1.5, -1.0}, look[3] = {6.0, 0.0, 6.0};
    const grass_view_desc plain = test_view(eye, look);
    grass_shadow_receive_desc shadow = grass_default_shadow_receive_desc();
    shadow.shadow_map = 42;
    shadow.cascade_count = 2;
    shadow.compare = GRASS_SHADOW_COMPARE_GREATER_EQUAL;
    shadow.depth_bias = 0.002f;
    shadow.filter_radius = 2.5f;
    shadow.cascade_end[0] = 5.0f;
    shadow.cascade_end[1] = 30.0f;
    shadow.world_to_shadow[1][12] = 0.25f; // a translation: made camera-relative below
    grass_view_desc receiving = plain;
    receiving.next = &shadow;
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_DEPTH;
    pass.next = &shadow;
    grass_view_desc depth = plain;
    depth.next = &pass;
    plan_frame({&plain, &receiving, &depth});
    const grass::FramePlan& a = ctx->views.plan(0);
    const grass::FramePlan& b = ctx->views.plan(1);
    const grass::FramePlan& c = ctx->views.plan(2);
    EXPECT_FALSE(a.shadow_receive);
    EXPECT_TRUE(b.shadow_receive);
    EXPECT_FALSE(c.shadow_receive) << "a depth pass ignores the struct";
    EXPECT_EQ(b.shadow_map, 42u);
    EXPECT_EQ(b.shadow.params[0], -1.0f) << "GREATER_EQUAL";
    EXPECT_EQ(b.shadow.params[1], 0.002f);
    EXPECT_EQ(b.shadow.params[2], 2.5f);
    EXPECT_EQ(b.shadow.axis[3], 2.0f) << "cascade count";
    EXPECT_EQ(b.shadow.cascade_end[1], 30.0f);
    // Camera-relative: the translation column is M * (camera, 1) (M identity plus 0.25 on u).
    EXPECT_FLOAT_EQ(b.shadow.world_to_shadow[1][12], float(0.25 + eye[0]));
    EXPECT_FLOAT_EQ(b.shadow.world_to_shadow[1][13], float(eye[1]));
    EXPECT_FLOAT_EQ(b.shadow.world_to_shadow[1][14], float(eye[2]));
    // The view axis: towards what the camera looks at.
    const double len = std::sqrt(1.5 * 1.5 + 7.0 * 7.0);
    EXPECT_NEAR(b.shadow.axis[1], -1.5 / len, 1e-5);
    EXPECT_NEAR(b.shadow.axis[2], 7.0 / len, 1e-5);
    // The same draws, the receiving view's with the bit and no other change.
    ASSERT_EQ(a.draws.size(), b.draws.size());
    ASSERT_EQ(a.draws.size(), c.draws.size());
    uint32_t kinds = 0;
    for (size_t i = 0; i < a.draws.size(); ++i) {
        EXPECT_EQ(a.draws[i].features & grass::kFeatureShadowReceive, 0u) << "plain draw " << i;
        EXPECT_EQ(c.draws[i].features & grass::kFeatureShadowReceive, 0u) << "depth draw " << i;
        EXPECT_EQ(b.draws[i].features, a.draws[i].features | grass::kFeatureShadowReceive) << "receiving draw " << i;
        EXPECT_EQ(b.draws[i].uniforms.tiling[3], b.draws[i].features) << "receiving draw " << i;
        kinds |= 1u << a.draws[i].kind;
    }
    EXPECT_EQ(kinds, 7u) << "every tier kind draws";
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

} // namespace
