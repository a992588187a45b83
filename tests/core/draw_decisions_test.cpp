// The decisions about a draw that the core makes once for every backend (issue 30): the
// vertices per instance of each tier kind, with and without a height map and in the debug
// view; the responsive variants' vertices per blade in the Field block; the target's samples
// and clip convention as the backend reports them, never guessed from its kind.
#include "core_fixture.hpp"
#include "test_backend.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "foundation/shader_interface.hpp"

#include <vector>

namespace {

class DrawDecisionsTest : public CoreTest {
protected:
    void SetUp() override {
        CoreTest::SetUp();
        patch = make_patch();
        ASSERT_EQ(grass_get_patch_info(ctx, patch, &info), GRASS_SUCCESS);
        const uint16_t ramp[4] = {0, 20000, 40000, 65535};
        grass_map_desc m = grass_default_map_desc();
        m.pixels = ramp;
        m.width = m.height = 2;
        m.format = GRASS_MAP_FORMAT_R16_UNORM;
        ASSERT_EQ(grass_create_map(ctx, &m, &height_map), GRASS_SUCCESS) << last_message();
    }

    // A field of one tier of `kind` seen from everywhere, on a height map or flat.
    void make_field(grass_tier_kind kind, bool on_height_map) {
        tier = grass_tier_desc{kind, kind == GRASS_TIER_VOLUME ? 4u : 0u};
        band = grass_lod_test{};
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.tier = 0;
        band.begin = 0.0f;
        band.end = 1e4f;
        grass_field_desc d = one_tier_field(patch, 8, &tier, &band);
        if (on_height_map) {
            d.maps.height = height_map;
            d.maps.height_scale = 0.5f;
        }
        grass_field_id f{};
        ASSERT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
        fields.push_back(f);
    }

    // The draws of one frame seen from above the fields.
    std::vector<grass::TierDraw> draws(uint32_t view_flags = 0) {
        const double eye[3] = {1.0, 3.0, -1.0}, target[3] = {1.0, 0.0, 1.0};
        grass_view_desc v = test_view(eye, target);
        v.flags = view_flags;
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        EXPECT_FALSE(ctx->plan.draws.empty());
        return std::vector<grass::TierDraw>(ctx->plan.draws.begin(), ctx->plan.draws.end());
    }

    grass_patch_id patch{};
    grass_patch_info info{};
    grass_map_id height_map{};
    grass_tier_desc tier{};
    grass_lod_test band{};
    std::vector<grass_field_id> fields;
};

TEST_F(DrawDecisionsTest, EachTierKindDrawsItsVerticesAndTheImageTierOnAHeightMapItsSkirts) {
    for (const bool on_height_map : {false, true}) {
        for (const grass_tier_kind kind : {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_IMAGE}) {
            make_field(kind, on_height_map);
            const std::vector<grass::TierDraw> d = draws();
            ASSERT_EQ(d.size(), 1u);
            EXPECT_EQ(d[0].kind, kind);
            const uint32_t expected = kind == GRASS_TIER_GEOMETRY ? info.triangle_count * 3 // the patch's indices
                                      : kind == GRASS_TIER_VOLUME ? grass::kVolumeVertices
                                      : on_height_map             ? grass::kImageVerticesWithSkirts
                                                                  : grass::kImageVertices;
            EXPECT_EQ(d[0].vertex_count, expected)
                << "tier kind " << kind << (on_height_map ? " on" : " off") << " a height map";
            ASSERT_EQ(grass_destroy_field(ctx, fields.back()), GRASS_SUCCESS);
            fields.pop_back();
        }
    }
    EXPECT_NE(grass::kImageVerticesWithSkirts, grass::kImageVertices);
}

TEST_F(DrawDecisionsTest, TheDebugViewDrawsEveryDrawAsABox) {
    make_field(GRASS_TIER_GEOMETRY, true);
    make_field(GRASS_TIER_VOLUME, true);
    make_field(GRASS_TIER_IMAGE, true);
    const std::vector<grass::TierDraw> d = draws(GRASS_VIEW_FLAG_DEBUG_CELLS);
    ASSERT_EQ(d.size(), 3u);
    for (const grass::TierDraw& draw : d) EXPECT_EQ(draw.vertex_count, grass::kDebugBoxVertices) << draw.kind;
    // The same fields outside the debug view draw their tiers' vertices.
    for (const grass::TierDraw& draw : draws()) {
        if (draw.kind != GRASS_TIER_GEOMETRY) {
            EXPECT_NE(draw.vertex_count, grass::kDebugBoxVertices) << draw.kind;
        }
    }
}

TEST_F(DrawDecisionsTest, ResponsiveDrawsCarryThePatchsVerticesPerBladeAndStillOnesNone) {
    make_field(GRASS_TIER_GEOMETRY, false);
    make_field(GRASS_TIER_IMAGE, false);
    for (const grass::TierDraw& draw : draws()) EXPECT_EQ(draw.uniforms.trample[3], 0.0f) << draw.kind;
    grass_wind_desc w = grass_default_wind_desc();
    w.speed = 3.0f;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS);
    ASSERT_GT(info.blade_count, 0u);
    const float per_blade = float(info.vertex_count / info.blade_count);
    for (const grass::TierDraw& draw : draws()) {
        ASSERT_NE(draw.features & grass::kBladeCurveFeatures, 0u);
        EXPECT_EQ(draw.uniforms.trample[3], per_blade) << draw.kind;
        EXPECT_EQ(draw.uniforms.tiling[3], draw.features);
    }
}

// Reports a render target; its kind says the other API, so a core that guessed the clip
// convention from the kind would write the opposite.
template <grass_backend Kind, uint32_t Samples, bool ZeroToOne>
class TargetBackend final : public HollowBackend {
public:
    grass_backend kind() const override { return Kind; }
    grass::RenderTarget render_target() const override {
        grass::RenderTarget t;
        t.samples = Samples;
        t.clip_zero_to_one = ZeroToOne;
        return t;
    }
};

TEST_F(DrawDecisionsTest, TheFrameBlockHoldsTheTargetTheBackendReportsWhateverItsKind) {
    const double eye[3] = {1.0, 3.0, -1.0}, target[3] = {1.0, 0.0, 1.0};
    const grass_view_desc v = test_view(eye, target);

    remake_with<TargetBackend<GRASS_BACKEND_GL, 4, true>>(&ctx);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(ctx->plan.frame.target[0], 1.0f); // clip z 0..1
    EXPECT_EQ(ctx->plan.frame.params[3], 4.0f); // samples per pixel
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);

    remake_with<TargetBackend<GRASS_BACKEND_VULKAN, 1, false>>(&ctx);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(ctx->plan.frame.target[0], 0.0f); // clip z -1..1
    EXPECT_EQ(ctx->plan.frame.params[3], 1.0f);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

} // namespace
