// Quality presets: each one makes a valid patch and field; the presets order the cost (the
// geometry they plan) from reference to fastest; bad knobs are refused, naming them.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include <cmath>
#include <limits>

namespace {

class QualityTest : public CoreTest {
protected:
    // Plans a 200 x 200 field of 0.25 m cells at `level` from player height; returns the stats.
    grass_frame_stats plan_at(grass_quality_level level, uint32_t* tier_count = nullptr) {
        grass_quality_desc q = grass_quality_preset(level);
        grass_patch_desc pd = grass_default_patch_desc();
        grass_tier_desc tiers[GRASS_MAX_TIERS];
        grass_lod_test tests[GRASS_MAX_LOD_TESTS];
        uint32_t nt = 0, nk = 0;
        EXPECT_EQ(grass_apply_quality(ctx, &q, 0.25, &pd, tiers, &nt, tests, &nk), GRASS_SUCCESS) << last_message();
        if (tier_count) *tier_count = nt;
        const grass_patch_id p = make_patch(pd);
        grass_field_desc fd = grass_default_field_desc();
        fd.patch = p;
        fd.cells_x = fd.cells_z = 200;
        fd.tiers = tiers;
        fd.tier_count = nt;
        fd.lod_tests = tests;
        fd.lod_test_count = nk;
        grass_field_id f{};
        EXPECT_EQ(grass_create_field(ctx, &fd, &f), GRASS_SUCCESS) << last_message();
        const double eye[3] = {25.0, 1.7, 2.0}, at[3] = {25.0, 0.0, 40.0};
        grass_view_desc v = test_view(eye, at, 60.0f, 1.7f, 0.05f, 2000.0f);
        grass_frame_stats s{};
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        EXPECT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        EXPECT_EQ(grass_destroy_patch(ctx, p), GRASS_SUCCESS);
        return s;
    }
};

TEST_F(QualityTest, PresetsOrderTheCostFromReferenceToFastest) {
    uint32_t tiers = 0;
    const grass_frame_stats ref = plan_at(GRASS_QUALITY_REFERENCE, &tiers);
    EXPECT_EQ(tiers, 1u);
    EXPECT_EQ(ref.instances[GRASS_TIER_VOLUME] + ref.instances[GRASS_TIER_IMAGE], 0u) << "blades everywhere";
    uint64_t previous = ref.triangles;
    for (int level = GRASS_QUALITY_HIGH; level <= GRASS_QUALITY_FASTEST; ++level) {
        const grass_frame_stats s = plan_at(static_cast<grass_quality_level>(level), &tiers);
        EXPECT_EQ(tiers, uint32_t(GRASS_DEFAULT_TIER_COUNT));
        EXPECT_LT(s.triangles, previous) << "level " << level << " draws no fewer triangles than the one above";
        EXPECT_GT(s.cells[GRASS_TIER_VOLUME] + s.cells[GRASS_TIER_IMAGE], 0u) << "level " << level;
        previous = s.triangles;
    }
}

TEST_F(QualityTest, KnobsShapeThePatchAndTheLodSetup) {
    grass_quality_desc q = grass_quality_preset(GRASS_QUALITY_DEFAULT);
    q.distance_scale = 2.0f;
    q.transition_scale = 0.5f;
    q.slice_scale = 0.5f;
    q.macro_cell_scale = 0.1f;
    q.blade_subdivisions = 3;
    q.blade_fraction = 0.25f;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 1000;
    grass_tier_desc tiers[GRASS_MAX_TIERS];
    grass_lod_test tests[GRASS_MAX_LOD_TESTS], defaults[GRASS_MAX_LOD_TESTS];
    grass_tier_desc default_tiers[GRASS_MAX_TIERS];
    uint32_t nt = 0, nk = 0;
    ASSERT_EQ(grass_apply_quality(ctx, &q, 0.5, &pd, tiers, &nt, tests, &nk), GRASS_SUCCESS) << last_message();
    grass_default_lod_setup(0.5, default_tiers, defaults);
    EXPECT_EQ(pd.blade_count, 250u);
    EXPECT_EQ(pd.subdivisions, 3u);
    EXPECT_EQ(tiers[1].slices, 4u);
    EXPECT_EQ(tiers[2].slices, 1u);
    EXPECT_EQ(tiers[3].slices, 1u) << "at least one slice";
    for (uint32_t k = 0; k < nk; ++k) {
        if (tests[k].kind == GRASS_LOD_TEST_DISTANCE_BAND) {
            EXPECT_FLOAT_EQ(tests[k].begin, 2.0f * defaults[k].begin);
            if (std::isfinite(defaults[k].end)) {
                EXPECT_FLOAT_EQ(tests[k].end, 2.0f * defaults[k].end);
            }
            EXPECT_FLOAT_EQ(tests[k].transition_out, 1.0f * defaults[k].transition_out);
        } else {
            EXPECT_EQ(tests[k].max_macro_cells,
                      std::max<uint32_t>(1, uint32_t(std::lround(0.1 * defaults[k].max_macro_cells))));
        }
    }
}

TEST_F(QualityTest, BadKnobsAreRefusedNamingThemAndNothingIsWritten) {
    grass_patch_desc pd = grass_default_patch_desc();
    const uint32_t blades = pd.blade_count;
    grass_tier_desc tiers[GRASS_MAX_TIERS];
    grass_lod_test tests[GRASS_MAX_LOD_TESTS];
    uint32_t nt = 77, nk = 77;
    struct Case {
        void (*spoil)(grass_quality_desc*);
        const char* name;
    } cases[] = {
        {[](grass_quality_desc* q) { q->distance_scale = std::numeric_limits<float>::quiet_NaN(); }, "distance_scale"},
        {[](grass_quality_desc* q) { q->transition_scale = 2.0f; }, "transition_scale"},
        {[](grass_quality_desc* q) { q->slice_scale = 0.0f; }, "slice_scale"},
        {[](grass_quality_desc* q) { q->macro_cell_scale = std::numeric_limits<float>::infinity(); },
         "macro_cell_scale"},
        {[](grass_quality_desc* q) { q->blade_subdivisions = 0; }, "blade_subdivisions"},
        {[](grass_quality_desc* q) { q->blade_fraction = 0.0f; }, "blade_fraction"},
        {[](grass_quality_desc* q) { q->msaa_samples = 3; }, "msaa_samples"},
    };
    for (const Case& c : cases) {
        grass_quality_desc q = grass_quality_preset(GRASS_QUALITY_LOW);
        c.spoil(&q);
        EXPECT_EQ(grass_apply_quality(ctx, &q, 0.25, &pd, tiers, &nt, tests, &nk), GRASS_ERROR_INVALID_ARGUMENT)
            << c.name;
        EXPECT_NE(last_message().find(c.name), std::string::npos) << last_message();
    }
    // The documented ends of every range are accepted, as floats (1.2f lies above 1.2).
    grass_quality_desc ends = grass_quality_preset(GRASS_QUALITY_LOW);
    ends.distance_scale = 16.0f;
    ends.transition_scale = 1.2f;
    ends.slice_scale = 8.0f;
    ends.macro_cell_scale = 4.0f;
    ends.blade_subdivisions = 32;
    ends.blade_fraction = 1.0f;
    EXPECT_EQ(grass_apply_quality(ctx, &ends, 0.25, &pd, tiers, &nt, tests, &nk), GRASS_SUCCESS) << last_message();
    ends.distance_scale = 0.1f;
    ends.transition_scale = 0.0f;
    ends.slice_scale = 0.125f;
    ends.macro_cell_scale = 0.025f;
    ends.blade_subdivisions = 1;
    EXPECT_EQ(grass_apply_quality(ctx, &ends, 0.25, &pd, tiers, &nt, tests, &nk), GRASS_SUCCESS) << last_message();
    pd = grass_default_patch_desc();
    nt = nk = 77;
    const grass_quality_desc unknown = grass_quality_preset(static_cast<grass_quality_level>(42));
    EXPECT_EQ(grass_apply_quality(ctx, &unknown, 0.25, &pd, tiers, &nt, tests, &nk), GRASS_ERROR_WRONG_STRUCT_TYPE);
    const grass_quality_desc ok = grass_quality_preset(GRASS_QUALITY_LOW);
    EXPECT_EQ(grass_apply_quality(ctx, &ok, std::numeric_limits<double>::quiet_NaN(), &pd, tiers, &nt, tests, &nk),
              GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("cell_size"), std::string::npos) << last_message();
    EXPECT_EQ(pd.blade_count, blades);
    EXPECT_EQ(nt, 77u);
    EXPECT_EQ(nk, 77u);
}

} // namespace
