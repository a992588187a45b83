// G-buffer views (GRASS_PASS_GBUFFER, grass_view_gbuffer_desc), without a GPU: the core
// decides once that every draw of such a view runs the G-buffer variant (kFeatureGBuffer),
// where each output location goes (the host's attachment of its semantic) with which colour
// mask, and how the normal is encoded; it receives no shadows nor lights, and writes velocity
// only with a VELOCITY attachment. Bad layouts are refused naming the field and the value,
// and begin no frame.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "foundation/shader_interface.hpp"

#include <cmath>
#include <cstring>
#include <string>

namespace {

class GBufferPlanTest : public CoreTest {
protected:
    void make_field() {
        const grass_patch_id patch = make_patch();
        band_.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band_.end = INFINITY;
        const grass_field_desc d = one_tier_field(patch, 16, &tier_, &band_);
        grass_field_id field{};
        ASSERT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();
    }
    grass_tier_desc tier_{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test band_{};
};

const double kEye[3] = {2.0, 1.5, -1.0}, kLook[3] = {2.0, 0.0, 2.0};

TEST_F(GBufferPlanTest, EveryDrawOfAGBufferViewAndNoOtherRunsTheGBufferVariant) {
    make_field();
    const grass_view_desc plain = test_view(kEye, kLook);
    grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
    layout.attachment_count = 5;
    layout.attachments[0].semantic = GRASS_GBUFFER_NONE;
    layout.attachments[1].semantic = GRASS_GBUFFER_NORMAL; // UNORM: n * 0.5 + 0.5
    layout.attachments[2].semantic = GRASS_GBUFFER_ALBEDO;
    layout.attachments[2].write_mask = 0xf;
    layout.attachments[3].semantic = GRASS_GBUFFER_MATERIAL;
    layout.attachments[4].semantic = GRASS_GBUFFER_VELOCITY;
    layout.attachments[4].format = GRASS_GBUFFER_FORMAT_FLOAT;
    grass_view_motion_desc motion = grass_default_view_motion_desc();
    std::memcpy(motion.previous_camera_position, plain.camera_position, sizeof motion.previous_camera_position);
    std::memcpy(motion.previous_view, plain.view, sizeof motion.previous_view);
    std::memcpy(motion.previous_projection, plain.projection, sizeof motion.previous_projection);
    grass_view_lights_desc lights = grass_default_view_lights_desc();
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = &layout;
    layout.next = &motion;
    motion.next = &lights;
    grass_view_desc deferred = plain;
    deferred.next = &pass;
    // The layout on a colour view is ignored.
    grass_view_desc colour = plain;
    colour.next = &layout;
    layout.next = nullptr;

    grass_frame_desc frame = grass_default_frame_desc();
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << last_message();
    uint32_t index = 0;
    ASSERT_EQ(grass_plan_view(ctx, &plain, &index), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_plan_view(ctx, &colour, &index), GRASS_SUCCESS) << last_message();
    layout.next = &motion;
    ASSERT_EQ(grass_plan_view(ctx, &deferred, &index), GRASS_SUCCESS) << last_message();
    const grass::FramePlan& a = ctx->views.plan(0);
    const grass::FramePlan& b = ctx->views.plan(1);
    const grass::FramePlan& g = ctx->views.plan(2);
    EXPECT_FALSE(a.gbuffer);
    EXPECT_FALSE(b.gbuffer) << "a colour view ignores the layout";
    EXPECT_TRUE(g.gbuffer);
    EXPECT_TRUE(g.motion) << "a VELOCITY attachment writes the motion desc's velocity";
    EXPECT_FALSE(g.host_lights) << "a G-buffer view is lit by the host, not by grass";
    EXPECT_FALSE(g.depth_pass);
    // Locations: 0 albedo, 1 velocity, 2 normal, 3 material.
    const uint32_t attachment[4] = {2, 4, 1, 3};
    const uint32_t mask[4] = {0xf, 3, 7, 3};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(g.gbuffer_attachment[i], attachment[i]) << "output " << i;
        EXPECT_EQ(g.gbuffer_mask[i], mask[i]) << "output " << i;
        EXPECT_EQ(a.gbuffer_attachment[i], grass::kNoGBufferOutput) << "output " << i;
    }
    EXPECT_FLOAT_EQ(g.gbuffer_uniforms.normal_encode[0], 0.5f);
    EXPECT_FLOAT_EQ(g.gbuffer_uniforms.normal_encode[1], 0.5f);
    ASSERT_EQ(a.draws.size(), g.draws.size());
    ASSERT_GT(a.draws.size(), 0u);
    for (size_t i = 0; i < a.draws.size(); ++i) {
        EXPECT_EQ(a.draws[i].features & grass::kFeatureGBuffer, 0u) << "plain draw " << i;
        EXPECT_EQ(b.draws[i].features, a.draws[i].features) << "colour draw " << i;
        EXPECT_EQ(g.draws[i].features, a.draws[i].features | grass::kFeatureGBuffer | grass::kFeatureMotion)
            << "G-buffer draw " << i;
        EXPECT_EQ(g.draws[i].uniforms.tiling[3], g.draws[i].features) << "G-buffer draw " << i;
    }
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);

    // A signed normal, and no velocity without a VELOCITY attachment (the motion desc stays).
    layout.attachments[1].format = GRASS_GBUFFER_FORMAT_SNORM;
    layout.attachments[4].semantic = GRASS_GBUFFER_NONE;
    frame.frame_index += 1;
    ASSERT_EQ(grass_begin_host_frame(ctx, &frame), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_plan_view(ctx, &deferred, &index), GRASS_SUCCESS) << last_message();
    const grass::FramePlan& s = ctx->views.plan(0);
    EXPECT_FALSE(s.motion);
    EXPECT_EQ(s.gbuffer_attachment[1], grass::kNoGBufferOutput);
    EXPECT_FLOAT_EQ(s.gbuffer_uniforms.normal_encode[0], 1.0f);
    EXPECT_FLOAT_EQ(s.gbuffer_uniforms.normal_encode[1], 0.0f);
    EXPECT_EQ(s.draws[0].features & grass::kFeatureMotion, 0u);
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

TEST_F(GBufferPlanTest, BadLayoutsAreRefusedNamingTheField) {
    make_field();
    const grass_view_desc plain = test_view(kEye, kLook);
    grass_view_gbuffer_desc good = grass_default_view_gbuffer_desc();
    good.attachment_count = 2;
    good.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    good.attachments[1].semantic = GRASS_GBUFFER_NORMAL;
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    const auto refused = [&](const grass_view_gbuffer_desc* layout, const std::string& message) {
        log.clear();
        grass_view_desc v = plain;
        pass.next = layout;
        v.next = &pass;
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT) << message;
        EXPECT_NE(last_message().find(message), std::string::npos) << last_message();
        EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "a refused view begins no frame";
    };
    refused(nullptr, "grass_view_pass_desc->pass is GRASS_PASS_GBUFFER, but view->next chains no "
                     "grass_view_gbuffer_desc");
    grass_view_gbuffer_desc bad = good;
    bad.attachment_count = 0;
    refused(&bad, "grass_view_gbuffer_desc->attachment_count is 0; expected 1 to 8");
    bad.attachment_count = 9;
    refused(&bad, "grass_view_gbuffer_desc->attachment_count is 9; expected 1 to 8");
    bad = good;
    const int32_t five = 5;
    std::memcpy(&bad.attachments[1].semantic, &five, sizeof five);
    refused(&bad, "grass_view_gbuffer_desc->attachments[1].semantic is 5; expected");
    bad = good;
    const int32_t seven = 7;
    std::memcpy(&bad.attachments[0].format, &seven, sizeof seven);
    refused(&bad, "grass_view_gbuffer_desc->attachments[0].format is 7; expected");
    bad = good;
    bad.attachments[1].write_mask = 16;
    refused(&bad, "grass_view_gbuffer_desc->attachments[1].write_mask is 0x10; expected 0 to 15");
    bad = good;
    bad.attachment_count = 3;
    bad.attachments[2].semantic = GRASS_GBUFFER_ALBEDO;
    refused(&bad, "grass_view_gbuffer_desc->attachments[2].semantic is GRASS_GBUFFER_ALBEDO, as attachments[0]'s is");
    bad.attachments[2].semantic = GRASS_GBUFFER_VELOCITY;
    refused(&bad, "grass_view_gbuffer_desc->attachments[2].semantic is GRASS_GBUFFER_VELOCITY, but view->next "
                  "chains no grass_view_motion_desc");
    // NONE may repeat; a pass kind past GBUFFER is refused naming the three.
    bad.attachments[2].semantic = GRASS_GBUFFER_NONE;
    bad.attachments[0].semantic = GRASS_GBUFFER_NONE;
    grass_view_desc v = plain;
    pass.next = &bad;
    v.next = &pass;
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    const int32_t three = 3;
    std::memcpy(&pass.pass, &three, sizeof three);
    log.clear();
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("grass_view_pass_desc->pass is 3; expected GRASS_PASS_COLOR (0), GRASS_PASS_DEPTH "
                                  "(1) or GRASS_PASS_GBUFFER (2)"),
              std::string::npos)
        << last_message();
    // A G-buffer pass takes no debug view.
    pass.pass = GRASS_PASS_GBUFFER;
    v.flags = GRASS_VIEW_FLAG_DEBUG_TIERS;
    log.clear();
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("with grass_view_pass_desc->pass GRASS_PASS_GBUFFER; a G-buffer pass takes no "
                                  "debug view flag"),
              std::string::npos)
        << last_message();
}

} // namespace
