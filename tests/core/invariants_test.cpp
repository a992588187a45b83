// The internal invariants the core checks once for every backend (context/invariants.hpp):
// a broken one is refused with GRASS_ERROR_INVALID_STATE and GRASS_MSG_INTERNAL_ERROR.
// The plan and the objects are corrupted by hand, as only a bug in grass could.
#include "core_fixture.hpp"
#include "test_backend.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "context/invariants.hpp"

#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace {

// A backend that holds and draws nothing but says it draws, so that the core checks the
// plan's slice sets as it does for GL and Vulkan.
class DrawingTestBackend final : public HollowBackend {
public:
    grass_backend kind() const override { return GRASS_BACKEND_VULKAN; }
};

class InvariantsTest : public CoreTest {
protected:
    void SetUp() override {
        // The fixture's log, on a context whose backend is the test backend.
        CoreTest::SetUp();
        remake_with<DrawingTestBackend>(&ctx);
        patch = make_patch();
        // One geometry tier: nothing to bake.
        tier = grass_tier_desc{GRASS_TIER_GEOMETRY, 0};
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.begin = 0.0f;
        band.end = 100.0f;
        const grass_field_desc f = one_tier_field(patch, 8, &tier, &band);
        ASSERT_EQ(grass_create_field(ctx, &f, &field), GRASS_SUCCESS) << last_message();
        const double eye[3] = {4.0, 3.0, -2.0}, target[3] = {4.0, 0.0, 4.0};
        view = test_view(eye, target);
        ASSERT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS) << last_message();
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        ASSERT_FALSE(ctx->plan.draws.empty());
    }
    // check_plan on the corrupted plan: refused as an internal error.
    void expect_plan_refused(const char* what) {
        log.clear();
        EXPECT_EQ(grass::check_plan(ctx, "test", ctx->plan), GRASS_ERROR_INVALID_STATE) << what;
        EXPECT_EQ(last_id(), GRASS_MSG_INTERNAL_ERROR) << what << ": " << last_message();
        ASSERT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS) << "a fresh plan is whole again";
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        EXPECT_EQ(grass::check_plan(ctx, "test", ctx->plan), GRASS_SUCCESS);
    }
    grass_patch_id patch{};
    grass_field_id field{};
    grass_tier_desc tier{};
    grass_lod_test band{};
    grass_view_desc view{};
};

TEST_F(InvariantsTest, AWholePlanPasses) {
    EXPECT_EQ(grass::check_plan(ctx, "test", ctx->plan), GRASS_SUCCESS) << last_message();
}

TEST_F(InvariantsTest, AVolumeDrawWhoseSliceSetWasNeverUploadedIsAnInternalError) {
    ctx->plan.draws[0].kind = GRASS_TIER_VOLUME;
    ctx->plan.draws[0].slices = 4;
    expect_plan_refused("a volume draw without slices");
    EXPECT_NE(last_message().find("slice set"), std::string::npos);
    ctx->plan.draws[0].kind = GRASS_TIER_IMAGE;
    expect_plan_refused("an image draw without the horizontal slice");
}

TEST_F(InvariantsTest, ADrawWhoseFeatureMaskIsNotItsFieldsIsAnInternalError) {
    ctx->plan.draws[0].features ^= 1u << grass::kMapColor;
    expect_plan_refused("a feature mask of another field");
    ctx->plan.draws[0].uniforms.tiling[3] = 1u << 7;
    expect_plan_refused("a feature mask beyond the map roles in the uniforms");
}

TEST_F(InvariantsTest, TheDebugViewVariantExactlyWhenTheFrameDrawsADebugView) {
    auto set_debug_bit = [&](bool on) {
        for (auto& d : ctx->plan.draws) {
            d.features = on ? d.features | grass::kFeatureDebugView : d.features & ~grass::kFeatureDebugView;
            d.uniforms.tiling[3] = d.features;
        }
    };
    ASSERT_EQ(ctx->plan.flags & grass::kDebugViewFlags, 0u);
    set_debug_bit(true);
    expect_plan_refused("the debug view variant in a frame without a debug view");
    EXPECT_NE(last_message().find("feature mask"), std::string::npos) << last_message();
    for (const uint32_t flags : {uint32_t(GRASS_VIEW_FLAG_DEBUG_THRESHOLDS), uint32_t(GRASS_VIEW_FLAG_DEBUG_TIERS)}) {
        ctx->plan.flags = flags;
        set_debug_bit(true);
        EXPECT_EQ(grass::check_plan(ctx, "test", ctx->plan), GRASS_SUCCESS) << last_message();
        set_debug_bit(false);
        expect_plan_refused("a debug view drawn by the variant without its code");
    }
}

TEST_F(InvariantsTest, TheFrameGivesItsDrawsTheDebugViewVariantOnlyWhenItDrawsOne) {
    for (const uint32_t flags : {0u, uint32_t(GRASS_VIEW_FLAG_DEBUG_CELLS), uint32_t(GRASS_VIEW_FLAG_ENCODE_SRGB),
                                 uint32_t(GRASS_VIEW_FLAG_DEBUG_TIERS), uint32_t(GRASS_VIEW_FLAG_DEBUG_THRESHOLDS)}) {
        grass_view_desc v = view;
        v.flags = flags;
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        ASSERT_FALSE(ctx->plan.draws.empty());
        for (const auto& d : ctx->plan.draws) {
            EXPECT_EQ((d.features & grass::kFeatureDebugView) != 0, (flags & grass::kDebugViewFlags) != 0)
                << "view flags 0x" << std::hex << flags;
        }
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    }
}

TEST_F(InvariantsTest, ResponsiveBitsOnlyAsTheInteractionPlanAllows) {
    std::vector<uint32_t> base;
    for (const auto& d : ctx->plan.draws) base.push_back(d.features);
    auto set_bits = [&](uint32_t bits) {
        for (size_t i = 0; i < ctx->plan.draws.size(); ++i) {
            auto& d = ctx->plan.draws[i];
            d.features = base[i] | bits;
            d.uniforms.tiling[3] = d.features;
        }
    };
    set_bits(grass::kFeatureWind);
    EXPECT_EQ(grass::check_plan(ctx, "test", ctx->plan), GRASS_SUCCESS) << last_message();
    set_bits(grass::kFeatureInteraction); // no map this frame
    expect_plan_refused("the interaction variant without the map");
    set_bits(grass::kFeatureMaskCount);
    expect_plan_refused("an unknown feature bit");
    set_bits(grass::kFeatureWindMap); // the field has no wind map
    expect_plan_refused("the wind map variant without a wind map");
    // Per-blade culling: on geometry draws only.
    ASSERT_EQ(ctx->plan.draws[0].kind, GRASS_TIER_GEOMETRY);
    set_bits(grass::kFeatureBladeCulling);
    EXPECT_EQ(grass::check_plan(ctx, "test", ctx->plan), GRASS_SUCCESS) << last_message();
    ctx->plan.draws[0].kind = GRASS_TIER_VOLUME;
    expect_plan_refused("the culling variant on a volume draw");
    EXPECT_NE(last_message().find("feature mask"), std::string::npos) << last_message();
    ctx->plan.draws[0].kind = GRASS_TIER_GEOMETRY;
    set_bits(0);
    // Tile lists: an entry past the colliders, offsets that do not cover the entries.
    const grass_collider c{GRASS_COLLIDER_SPHERE, 0.5f, {4.0, 0.0, 4.0}, {}, {}};
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    ASSERT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    ASSERT_EQ(ctx->plan.interaction.levels, 2u);
    ASSERT_FALSE(ctx->plan.interaction.tile_colliders[0].empty());
    ctx->plan.interaction.tile_colliders[0][0] = 1;
    expect_plan_refused("a tile entry past the colliders");
    ctx->plan.interaction.tile_offsets[1].back() += 1;
    expect_plan_refused("tile offsets past the entries");
    ctx->plan.interaction.tile_offsets[0].pop_back();
    expect_plan_refused("too few tile offsets");
}

TEST_F(InvariantsTest, ADrawOfAnObjectTheContextDoesNotHoldIsAnInternalError) {
    ctx->plan.draws[0].field_slot = 7;
    expect_plan_refused("an unknown field");
    ctx->plan.draws[0].patch_slot = 3;
    expect_plan_refused("a patch that is not the field's");
    ctx->plan.draws[0].instance_count = static_cast<uint32_t>(ctx->plan.instances.size()) + 1;
    expect_plan_refused("instances past the plan's");
    const std::underlying_type_t<grass_tier_kind> nine = 9; // no grass_tier_kind: written as raw bytes
    std::memcpy(&ctx->plan.draws[0].kind, &nine, sizeof(nine));
    expect_plan_refused("an unknown tier kind");
}

TEST_F(InvariantsTest, FieldMapsThatDisagreeWithTheMaskAreAnInternalError) {
    grass::FieldMaps maps = ctx->fields.get(field.index - 1)->maps;
    EXPECT_EQ(grass::check_field_maps(ctx, "test", 0, maps), GRASS_SUCCESS);
    maps.features |= 1u << grass::kMapHeight; // no height map
    EXPECT_EQ(grass::check_field_maps(ctx, "test", 0, maps), GRASS_ERROR_INVALID_STATE);
    EXPECT_EQ(last_id(), GRASS_MSG_INTERNAL_ERROR) << last_message();
    maps.features = 1u << grass::kMapRoleCount;
    EXPECT_EQ(grass::check_field_maps(ctx, "test", 0, maps), GRASS_ERROR_INVALID_STATE);
    maps.features = 1u << grass::kMapDensity;
    maps.map_slot[grass::kMapDensity] = 5; // no such map
    EXPECT_EQ(grass::check_field_maps(ctx, "test", 0, maps), GRASS_ERROR_INVALID_STATE);
    EXPECT_EQ(last_id(), GRASS_MSG_INTERNAL_ERROR) << last_message();
}

TEST_F(InvariantsTest, AMalformedSliceSetIsAnInternalError) {
    grass::SliceSet set(&ctx->host);
    set.slices_per_axis = 2;
    set.layers = 5;
    set.width = set.height = 4;
    set.mip_levels = 3;
    const size_t values = set.offset(set.layers, 0) * 4;
    set.color.assign(values, 0);
    set.normal.assign(values, 0);
    set.threshold.assign(values, 0);
    EXPECT_EQ(grass::check_slice_set(ctx, "test", patch.index - 1, set), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass::check_slice_set(ctx, "test", 9, set), GRASS_ERROR_INVALID_STATE) << "no patch in slot 9";
    set.layers = 4; // N = 2 needs 5
    EXPECT_EQ(grass::check_slice_set(ctx, "test", patch.index - 1, set), GRASS_ERROR_INVALID_STATE);
    set.layers = 5;
    set.threshold.pop_back();
    EXPECT_EQ(grass::check_slice_set(ctx, "test", patch.index - 1, set), GRASS_ERROR_INVALID_STATE);
    EXPECT_EQ(last_id(), GRASS_MSG_INTERNAL_ERROR) << last_message();
}

} // namespace
