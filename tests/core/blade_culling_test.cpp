// Per-blade culling (grass.h "Per-blade culling", jahrmann2017 6.2) through the core: the
// documented defaults, what the plan asks of the backends (the variant bit on geometry draws
// only, the Field block's culling vector, the blade curves), and every refusal, which names
// the argument and the value and leaves the earlier culling in place.
#include "dynamics_fixture.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace {

class BladeCullingTest : public DynamicsTest {
protected:
    // The geometry draw of the last frame (the fixture's field has one geometry tier).
    const grass::TierDraw& geometry_draw() {
        EXPECT_EQ(frame(0.0), GRASS_SUCCESS) << last_message();
        for (const grass::TierDraw& d : ctx->plan.draws)
            if (d.kind == GRASS_TIER_GEOMETRY) return d;
        ADD_FAILURE() << "no geometry draw";
        return ctx->plan.draws.front();
    }
};

TEST_F(BladeCullingTest, DefaultsAreOffAtJahrmannsValues) {
    const grass_blade_culling_desc d = grass_default_blade_culling_desc();
    EXPECT_EQ(d.type, GRASS_STRUCT_TYPE_BLADE_CULLING_DESC);
    EXPECT_EQ(d.next, nullptr);
    EXPECT_EQ(d.orientation, 0u);
    EXPECT_FLOAT_EQ(d.orientation_limit, 0.9f);
    EXPECT_EQ(d.view_frustum, 0u);
    EXPECT_FLOAT_EQ(d.frustum_tolerance, 0.1f);
    EXPECT_EQ(d.distance, GRASS_DISTANCE_CULLING_OFF);
    EXPECT_EQ(d.distance_levels, 4u);
    EXPECT_EQ(d.distance_max, 0.0f);
}

TEST_F(BladeCullingTest, OffCostsNothingAndRunsTheStillShaders) {
    // Never set, and set to the defaults (every test off): the still variant, no curves.
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            const grass_blade_culling_desc d = grass_default_blade_culling_desc();
            ASSERT_EQ(grass_set_blade_culling(ctx, field, &d), GRASS_SUCCESS) << last_message();
        }
        const grass::TierDraw& g = geometry_draw();
        EXPECT_EQ(g.features & grass::kBladeCurveFeatures, 0u);
        EXPECT_EQ(backend->curve_uploads, 0u);
    }
}

TEST_F(BladeCullingTest, EachTestSetsTheVariantAndTheFieldBlock) {
    grass_blade_culling_desc d = grass_default_blade_culling_desc();
    d.orientation = 1;
    d.orientation_limit = 0.8f;
    ASSERT_EQ(grass_set_blade_culling(ctx, field, &d), GRASS_SUCCESS) << last_message();
    const grass::TierDraw& a = geometry_draw();
    EXPECT_NE(a.features & grass::kFeatureBladeCulling, 0u);
    EXPECT_EQ(a.uniforms.tiling[3], a.features);
    EXPECT_FLOAT_EQ(a.uniforms.culling[0], 0.8f);
    EXPECT_LT(a.uniforms.culling[1], 0.0f); // frustum off
    EXPECT_EQ(a.uniforms.culling[2], 0.0f); // distance off
    EXPECT_EQ(backend->curve_uploads, 1u);  // the blades' width directions and control points

    d = grass_default_blade_culling_desc();
    d.view_frustum = 1;
    d.frustum_tolerance = 0.25f;
    d.distance = GRASS_DISTANCE_CULLING_BLADE_INDEX;
    d.distance_levels = 8;
    d.distance_max = 30.0f;
    ASSERT_EQ(grass_set_blade_culling(ctx, field, &d), GRASS_SUCCESS) << last_message();
    const grass::TierDraw& b = geometry_draw();
    EXPECT_GT(b.uniforms.culling[0], 1.0f); // orientation off
    EXPECT_FLOAT_EQ(b.uniforms.culling[1], 0.25f);
    EXPECT_FLOAT_EQ(b.uniforms.culling[2], 30.0f);
    EXPECT_FLOAT_EQ(b.uniforms.culling[3], 8.0f);

    // By threshold, and distance_max 0: the far end of the geometry tier's band (1e4 m).
    d = grass_default_blade_culling_desc();
    d.distance = GRASS_DISTANCE_CULLING_THRESHOLD;
    ASSERT_EQ(grass_set_blade_culling(ctx, field, &d), GRASS_SUCCESS) << last_message();
    const grass::TierDraw& c = geometry_draw();
    EXPECT_FLOAT_EQ(c.uniforms.culling[2], 1e4f);
    EXPECT_EQ(c.uniforms.culling[3], 0.0f);

    // NULL: off again, the still variant.
    ASSERT_EQ(grass_set_blade_culling(ctx, field, nullptr), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(geometry_draw().features & grass::kFeatureBladeCulling, 0u);
}

TEST_F(BladeCullingTest, OnlyGeometryDrawsGetTheBit) {
    // A geometry tier near and a volume tier far: the volume draw keeps its variant.
    const grass_tier_desc tiers[2] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 2}};
    grass_lod_test tests[2] = {band, band};
    tests[0].end = 3.0f;
    tests[1].tier = 1;
    tests[1].begin = 3.0f;
    grass_field_desc fd = one_tier_field(patch, 16, tiers, tests);
    fd.tier_count = fd.lod_test_count = 2;
    grass_field_id two{};
    ASSERT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
    ASSERT_EQ(grass_create_field(ctx, &fd, &two), GRASS_SUCCESS) << last_message();
    grass_blade_culling_desc d = grass_default_blade_culling_desc();
    d.distance = GRASS_DISTANCE_CULLING_BLADE_INDEX;
    ASSERT_EQ(grass_set_blade_culling(ctx, two, &d), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(frame(0.0), GRASS_SUCCESS) << last_message();
    int kinds_seen = 0;
    for (const grass::TierDraw& g : ctx->plan.draws) {
        kinds_seen |= 1 << g.kind;
        EXPECT_EQ((g.features & grass::kFeatureBladeCulling) != 0, g.kind == GRASS_TIER_GEOMETRY);
        if (g.kind == GRASS_TIER_GEOMETRY) {
            EXPECT_FLOAT_EQ(g.uniforms.culling[2], 3.0f); // the band's end
        }
    }
    EXPECT_EQ(kinds_seen, 3) << "both tiers drawn";
}

TEST_F(BladeCullingTest, RefusalsNameTheArgumentAndKeepTheEarlierCulling) {
    grass_blade_culling_desc good = grass_default_blade_culling_desc();
    good.orientation = 1;
    ASSERT_EQ(grass_set_blade_culling(ctx, field, &good), GRASS_SUCCESS) << last_message();
    const float before = geometry_draw().uniforms.culling[0];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Bad {
        const char* text; // in the message
        std::function<void(grass_blade_culling_desc*)> spoil;
    };
    const Bad bad[] = {
        {"culling->orientation is 2", [](grass_blade_culling_desc* d) { d->orientation = 2; }},
        {"culling->orientation_limit", [](grass_blade_culling_desc* d) { d->orientation_limit = 0.2f; }},
        {"culling->orientation_limit", [&](grass_blade_culling_desc* d) { d->orientation_limit = float(nan); }},
        {"culling->view_frustum is 7", [](grass_blade_culling_desc* d) { d->view_frustum = 7; }},
        {"culling->frustum_tolerance", [](grass_blade_culling_desc* d) { d->frustum_tolerance = -0.1f; }},
        {"culling->frustum_tolerance", [](grass_blade_culling_desc* d) { d->frustum_tolerance = INFINITY; }},
        {"culling->distance is 9", [](grass_blade_culling_desc* d) { d->distance = grass_distance_culling(9); }},
        {"culling->distance_levels", [](grass_blade_culling_desc* d) { d->distance_levels = 0; }},
        {"culling->distance_levels", [](grass_blade_culling_desc* d) { d->distance_levels = 65; }},
        {"culling->distance_max", [](grass_blade_culling_desc* d) { d->distance_max = -1.0f; }},
        {"culling->distance_max", [&](grass_blade_culling_desc* d) { d->distance_max = float(nan); }},
    };
    for (const Bad& b : bad) {
        grass_blade_culling_desc d = grass_default_blade_culling_desc();
        d.distance = GRASS_DISTANCE_CULLING_THRESHOLD;
        b.spoil(&d);
        EXPECT_EQ(grass_set_blade_culling(ctx, field, &d), GRASS_ERROR_INVALID_ARGUMENT) << b.text;
        EXPECT_NE(last_message().find(b.text), std::string::npos) << last_message();
        EXPECT_NE(last_message().find("grass_set_blade_culling"), std::string::npos) << last_message();
        EXPECT_FLOAT_EQ(geometry_draw().uniforms.culling[0], before) << b.text << ": the earlier culling is kept";
    }
    grass_blade_culling_desc d = grass_default_blade_culling_desc();
    d.type = GRASS_STRUCT_TYPE_WIND_DESC;
    EXPECT_EQ(grass_set_blade_culling(ctx, field, &d), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_EQ(grass_set_blade_culling(ctx, grass_field_id{}, &good), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(grass_set_blade_culling(nullptr, field, &good), GRASS_ERROR_INVALID_ARGUMENT);
}

TEST_F(BladeCullingTest, DistanceMaxZeroNeedsAFiniteGeometryBand) {
    // Blades everywhere: the geometry band has no end, so distance_max 0 means nothing.
    grass_lod_test everywhere = band;
    everywhere.end = INFINITY;
    grass_field_desc fd = one_tier_field(patch, 16, &tier, &everywhere);
    grass_field_id f{};
    ASSERT_EQ(grass_create_field(ctx, &fd, &f), GRASS_SUCCESS) << last_message();
    grass_blade_culling_desc d = grass_default_blade_culling_desc();
    d.distance = GRASS_DISTANCE_CULLING_BLADE_INDEX;
    EXPECT_EQ(grass_set_blade_culling(ctx, f, &d), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("distance_max is 0"), std::string::npos) << last_message();
    d.distance_max = 12.0f;
    EXPECT_EQ(grass_set_blade_culling(ctx, f, &d), GRASS_SUCCESS) << last_message();
}

} // namespace
