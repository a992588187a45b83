// The variants grass_prepare_pipelines makes for the views of an engine's frame
// (GRASS_PIPELINE_FEATURE_DEPTH_PASS ... _GBUFFER; foundation/shader_variants.hpp), without a
// GPU: which view modes the declared bits bring, which of them a context's targets can draw,
// how many variants they multiply the responsive ones into (the counts grass.h gives), and
// that a frame's every draw, in each view mode, runs a variant of the prepared set. Bad
// declarations are refused naming the argument and the value, and change nothing.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "foundation/shader_variants.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace grass;

constexpr uint32_t kAllTiers = (1u << GRASS_TIER_GEOMETRY) | (1u << GRASS_TIER_VOLUME) | (1u << GRASS_TIER_IMAGE);

uint32_t count_of(uint32_t pipeline_features, const RenderTarget& target, bool fixed_targets, uint32_t gbuffer_mode,
                  uint32_t tier_kinds = kAllTiers) {
    const uint32_t declared = declared_feature_bits(pipeline_features);
    uint32_t modes[kMaxViewModes];
    const uint32_t mode_count = view_modes(drawable_view_bits(declared, target, fixed_targets), modes);
    ShaderVariant out[kMaxFieldVariants];
    uint32_t count = field_variants(declared, modes, mode_count, 0, tier_kinds, out);
    if (gbuffer_mode != 0) count += field_variants(declared, &gbuffer_mode, 1, 0, tier_kinds, out);
    return count;
}

TEST(ViewVariants, TheCountsGrassHGives) {
    const RenderTarget gl; // depth pass, one view: every mode
    EXPECT_EQ(count_of(GRASS_PIPELINE_FEATURE_ALL, gl, false, 0), 49u) << "the five responsive features";
    EXPECT_EQ(count_of(GRASS_PIPELINE_FEATURE_ALL | GRASS_PIPELINE_FEATURE_ALL_VIEWS, gl, false, 0), 409u)
        << "nine view modes: eight colour ones of 48 variants, the depth pass's 24 (no debug view), the debug boxes";
    EXPECT_EQ(count_of(GRASS_PIPELINE_FEATURE_ALL | GRASS_PIPELINE_FEATURE_ALL_VIEWS, gl, false, kFeatureGBuffer), 433u)
        << "a G-buffer layout adds 24 (no debug view)";
    EXPECT_EQ(count_of(GRASS_PIPELINE_FEATURE_WIND | GRASS_PIPELINE_FEATURE_ALL_VIEWS, gl, false, kFeatureGBuffer), 60u)
        << "the view bits with wind: ten modes of two wind states and three programs";
    EXPECT_EQ(count_of(GRASS_PIPELINE_FEATURE_ALL_VIEWS, gl, false, kFeatureGBuffer, 1u << GRASS_TIER_GEOMETRY), 10u)
        << "the view bits alone on a field of blades: one pipeline per mode";
    EXPECT_LE(433u, kMaxFieldVariants);
}

TEST(ViewVariants, AModeTheTargetsCannotDrawIsSkipped) {
    const uint32_t all = declared_feature_bits(GRASS_PIPELINE_FEATURE_ALL_VIEWS);
    EXPECT_EQ(all, kViewModeBits);
    RenderTarget vk;
    vk.depth_pass = false; // no grass_vk_depth_pass_desc, velocity or G-buffer target
    EXPECT_EQ(drawable_view_bits(all, vk, true), kFeatureShadowReceive | kFeatureHostLights);
    EXPECT_EQ(drawable_view_bits(all, vk, false), all & ~kFeatureDepthPass) << "GL keeps motion and G-buffers";
    vk.depth_pass = true;
    vk.velocity_attachment = 2;
    vk.gbuffer_attachments = 3;
    EXPECT_EQ(drawable_view_bits(all, vk, true), all);
    vk.views = 2; // multiview: the depth pass alone
    EXPECT_EQ(drawable_view_bits(all, vk, true), kFeatureDepthPass);
    uint32_t modes[kMaxViewModes];
    EXPECT_EQ(view_modes(0, modes), 1u);
    EXPECT_EQ(modes[0], 0u) << "a plain colour view's";
    EXPECT_EQ(view_modes(kFeatureShadowReceive | kFeatureMotion, modes), 4u) << "plain, R, M, R+M";
}

TEST(ViewVariants, AGBufferLayoutWithVelocityWritesMotion) {
    GBufferLayout layout;
    layout.attachment[kGBufferOutput[GRASS_GBUFFER_ALBEDO]] = 0;
    EXPECT_EQ(gbuffer_view_mode(layout), kFeatureGBuffer);
    layout.attachment[kGBufferOutput[GRASS_GBUFFER_VELOCITY]] = 1;
    EXPECT_EQ(gbuffer_view_mode(layout), kFeatureGBuffer | kFeatureMotion);
}

class ViewVariantsPlanTest : public CoreTest {
protected:
    // Every variant prepared for a field of the three tiers without maps with every feature.
    std::vector<ShaderVariant> prepared(uint32_t gbuffer_mode) const {
        const uint32_t declared = declared_feature_bits(GRASS_PIPELINE_FEATURE_ALL | GRASS_PIPELINE_FEATURE_ALL_VIEWS);
        uint32_t modes[kMaxViewModes];
        const uint32_t mode_count = view_modes(declared & kViewModeBits, modes);
        ShaderVariant out[kMaxFieldVariants];
        uint32_t count = field_variants(declared, modes, mode_count, 0, kAllTiers, out);
        std::vector<ShaderVariant> all(out, out + count);
        count = field_variants(declared, &gbuffer_mode, 1, 0, kAllTiers, out);
        all.insert(all.end(), out, out + count);
        return all;
    }
};

// Each view of an engine's frame (a depth pass, receiving, motion and lit views alone and
// together, a G-buffer view with velocity) with wind and a debug view where it takes one:
// every draw of its plan runs a prepared variant, and its draws carry the view's bits.
TEST_F(ViewVariantsPlanTest, EveryDrawOfEachViewRunsAPreparedVariant) {
    make_three_tier_field();
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 3.0f;
    ASSERT_EQ(grass_set_wind(ctx, &wind), GRASS_SUCCESS) << last_message();
    const double eye[3] = {6.0, 1.5, 1.0}, look[3] = {6.0, 0.0, 9.0};
    const grass_view_desc plain = test_view(eye, look);

    grass_view_pass_desc depth = grass_default_view_pass_desc();
    depth.pass = GRASS_PASS_DEPTH;
    grass_shadow_receive_desc shadow = grass_default_shadow_receive_desc();
    shadow.shadow_map = 1;
    grass_view_motion_desc motion = grass_default_view_motion_desc();
    motion.velocity_attachment = 1;
    grass_view_lights_desc lights = grass_default_view_lights_desc();
    motion.next = &shadow;
    shadow.next = &lights; // all three at once
    grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
    layout.attachment_count = 2;
    layout.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    layout.attachments[1].semantic = GRASS_GBUFFER_VELOCITY;
    grass_view_pass_desc gbuffer = grass_default_view_pass_desc();
    gbuffer.pass = GRASS_PASS_GBUFFER;
    gbuffer.next = &layout;
    grass_view_motion_desc gbuffer_motion = grass_default_view_motion_desc();
    gbuffer_motion.velocity_attachment = 1;
    gbuffer_motion.next = &gbuffer;
    const struct {
        const void* next;
        uint32_t flags;
        uint32_t bits; // the view's bits every draw carries
        const char* name;
    } views[] = {
        {&depth, 0, kFeatureDepthPass, "the depth pass"},
        {&shadow, GRASS_VIEW_FLAG_DEBUG_TIERS, kFeatureShadowReceive | kFeatureHostLights, "receiving and lit"},
        {&motion, 0, kFeatureMotion | kFeatureShadowReceive | kFeatureHostLights, "motion, receiving and lit"},
        {&lights, GRASS_VIEW_FLAG_DEBUG_THRESHOLDS, kFeatureHostLights, "lit"},
        {&gbuffer_motion, 0, kFeatureGBuffer | kFeatureMotion, "the G-buffer with velocity"},
    };
    GBufferLayout routes;
    routes.attachment[kGBufferOutput[GRASS_GBUFFER_VELOCITY]] = 1;
    const std::vector<ShaderVariant> set = prepared(gbuffer_view_mode(routes));
    for (const auto& view : views) {
        grass_view_desc v = plain;
        v.next = view.next;
        v.flags = view.flags;
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << view.name << ": " << last_message();
        ASSERT_FALSE(ctx->plan.draws.empty()) << view.name;
        uint32_t kinds = 0;
        for (const TierDraw& draw : ctx->plan.draws) {
            kinds |= 1u << draw.kind;
            EXPECT_EQ(draw.features & kViewModeBits, view.bits) << view.name;
            EXPECT_NE(draw.features & kFeatureWind, 0u) << view.name;
            const ShaderVariant variant = draw_variant(draw, v.flags);
            bool found = false;
            for (const ShaderVariant& p : set) found = found || p == variant;
            EXPECT_TRUE(found) << view.name << ": program " << variant.program << " features 0x" << std::hex
                               << variant.features << " is not prepared";
        }
        EXPECT_GE(__builtin_popcount(kinds), 2) << view.name << ": the view should draw two tier kinds or more";
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    }
}

TEST_F(ViewVariantsPlanTest, BadDeclarationsAreRefusedNamingTheValue) {
    grass_pipeline_desc d = grass_default_pipeline_desc();
    EXPECT_EQ(d.features, uint32_t(GRASS_PIPELINE_FEATURE_ALL & ~GRASS_PIPELINE_FEATURE_DEBUG_VIEWS))
        << "the default takes in no view bit";
    EXPECT_EQ(GRASS_PIPELINE_FEATURE_ALL, 0x1F) << "an enum's value never changes";
    d.features = 0x400;
    EXPECT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("desc->features is 0x400; only GRASS_PIPELINE_FEATURE_* bits (0x3ff)"),
              std::string::npos)
        << last_message();
    d.features = GRASS_PIPELINE_FEATURE_GBUFFER;
    EXPECT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("has GRASS_PIPELINE_FEATURE_GBUFFER (0x200), but desc->next is NULL"),
              std::string::npos)
        << last_message();
    grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
    layout.attachment_count = 0;
    d.next = &layout;
    EXPECT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("grass_view_gbuffer_desc->attachment_count is 0"), std::string::npos)
        << last_message();
    layout.attachment_count = 1;
    d.features = GRASS_PIPELINE_FEATURE_WIND;
    EXPECT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("lacks GRASS_PIPELINE_FEATURE_GBUFFER"), std::string::npos) << last_message();
    grass_view_pass_desc other = grass_default_view_pass_desc();
    d.next = &other;
    EXPECT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_NE(last_message().find("desc->next->type"), std::string::npos) << last_message();
    EXPECT_EQ(ctx->prepared_features, 0u) << "a refused call declared something";
    EXPECT_TRUE(ctx->prepared_gbuffer_layouts.empty());
    d.features = GRASS_PIPELINE_FEATURE_ALL | GRASS_PIPELINE_FEATURE_ALL_VIEWS;
    d.next = &layout;
    EXPECT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_prepare_pipelines(ctx, &d), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(ctx->prepared_gbuffer_layouts.size(), 1u) << "a layout declared twice is kept once";
}

} // namespace
