// The blades' dynamic tessellation (grass.h "Dynamic tessellation of the blades",
// jahrmann2017 6.3) through the core: the patch's levels as index subsets of its quad strips,
// and the plan that splits each geometry draw's cells by level: near cells full, far cells
// coarser, off (the default, NULL, REFERENCE's preset) always full, every index range inside
// the patch's indices. Refusals name the argument and leave the earlier setting in place.
// Seen failing: with every coarser draw's first index one quad past its level's, the index
// ranges' check of FarCellsGetCoarserLevelsNearCellsTheFullBlades and
// OneQuadHasNothingCoarserAndThirtyTwoReachOne failed.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "patch/blade_levels.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <vector>

namespace {

class BladeTessellationTest : public CoreTest {
protected:
    static grass_lod_test everywhere() {
        grass_lod_test t{};
        t.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        t.end = INFINITY;
        return t;
    }
    // A strip of 8 x 160 cells (2 m x 40 m of 0.25 m cells) of a patch of `subdivisions`
    // quads a blade, drawn by one geometry tier at every distance.
    grass_field_id make_strip(uint32_t subdivisions) {
        grass_patch_desc pd = grass_default_patch_desc();
        pd.blade_count = 16;
        pd.subdivisions = subdivisions;
        EXPECT_EQ(grass_create_patch(ctx, &pd, &last_patch), GRASS_SUCCESS) << last_message();
        patch_data = &ctx->patches.get(last_patch.index - 1)->data;
        grass_field_desc d = grass_default_field_desc();
        d.patch = last_patch;
        d.cells_x = 8;
        d.cells_z = 160;
        d.tiers = &tier;
        d.tier_count = 1;
        d.lod_tests = &band;
        d.lod_test_count = 1;
        grass_field_id f{};
        EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
        return f;
    }
    // A camera 1.7 m above the strip's near end looking along it, 256 x 256 pixels, 60 degrees.
    void plan() {
        const double eye[3] = {1.0, 1.7, -0.5}, target[3] = {1.0, 0.0, 15.0};
        const grass_view_desc v = test_view(eye, target);
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    }
    std::vector<const grass::TierDraw*> geometry_draws() const {
        std::vector<const grass::TierDraw*> out;
        for (const grass::TierDraw& d : ctx->plan.draws)
            if (d.kind == GRASS_TIER_GEOMETRY) out.push_back(&d);
        return out;
    }
    // The distance of an instance's centre from the eye, metres.
    double distance(const grass::TierInstance& i) const {
        const double x = i.origin[0] + 0.125 * i.count[0], y = i.origin[1], z = i.origin[2] + 0.125 * i.count[1];
        return std::sqrt(x * x + y * y + z * z);
    }
    // Every geometry draw's index range lies in the patch's indices, at its level's first index.
    void expect_valid_ranges() const {
        for (const grass::TierDraw* d : geometry_draws()) {
            ASSERT_LT(d->blade_level, patch_data->level_count);
            EXPECT_EQ(d->first_index, patch_data->levels[d->blade_level].first_index);
            EXPECT_EQ(d->vertex_count, patch_data->blade_count * patch_data->levels[d->blade_level].indices_per_blade);
            EXPECT_LE(uint64_t(d->first_index) + d->vertex_count, patch_data->indices.size());
        }
    }
    uint64_t planned_instances() const {
        uint64_t n = 0;
        for (const grass::TierDraw* d : geometry_draws()) n += d->instance_count;
        return n;
    }

    grass_tier_desc tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test band = everywhere();
    grass_patch_id last_patch{};
    const grass::PatchData* patch_data = nullptr;
};

TEST_F(BladeTessellationTest, LevelsAreRowSubsetsEndingAtTheTip) {
    EXPECT_EQ(grass::blade_level_count(1), 1u);
    EXPECT_EQ(grass::blade_level_count(4), 3u);
    EXPECT_EQ(grass::blade_level_count(5), 4u); // 5, 3, 2, 1 quads
    EXPECT_EQ(grass::blade_level_count(32), 6u);
    for (uint32_t subdivisions : {1u, 3u, 4u, 7u, 32u}) {
        make_strip(subdivisions);
        const grass::PatchData& pd = *patch_data;
        ASSERT_EQ(pd.level_count, grass::blade_level_count(subdivisions));
        EXPECT_EQ(pd.levels[0].first_index, 0u);
        EXPECT_EQ(pd.full_index_count(), pd.blade_count * subdivisions * 6);
        EXPECT_EQ(pd.levels[pd.level_count - 1].indices_per_blade, 6u) << "the coarsest level: one quad a blade";
        grass_patch_info info{};
        ASSERT_EQ(grass_get_patch_info(ctx, last_patch, &info), GRASS_SUCCESS);
        EXPECT_EQ(info.triangle_count, pd.blade_count * subdivisions * 2) << "the full blades only";
        for (uint32_t k = 0; k < pd.level_count; ++k) {
            const uint32_t step = 1u << k, per_blade = pd.levels[k].indices_per_blade;
            for (uint32_t b = 0; b < pd.blade_count; ++b) {
                std::set<uint32_t> rows;
                for (uint32_t i = 0; i < per_blade; ++i) {
                    const uint32_t v = pd.indices[pd.levels[k].first_index + b * per_blade + i];
                    ASSERT_EQ(v / pd.vertices_per_blade, b) << "level " << k << ": a vertex of another blade";
                    rows.insert((v % pd.vertices_per_blade) / 2);
                }
                ASSERT_EQ(rows.size(), per_blade / 6 + 1) << "level " << k;
                for (uint32_t r : rows)
                    EXPECT_TRUE(r % step == 0 || r == subdivisions) << "level " << k << " row " << r;
                EXPECT_EQ(*rows.begin(), 0u);
                EXPECT_EQ(*rows.rbegin(), subdivisions) << "the tip row is always kept";
            }
        }
    }
}

TEST_F(BladeTessellationTest, OffByDefaultAndInReferenceAndAfterNull) {
    const grass_blade_tessellation_desc d = grass_default_blade_tessellation_desc();
    EXPECT_EQ(d.type, GRASS_STRUCT_TYPE_BLADE_TESSELLATION_DESC);
    EXPECT_EQ(d.enabled, 0u);
    EXPECT_FLOAT_EQ(d.error_pixels, 0.5f);
    EXPECT_EQ(grass_quality_blade_tessellation(GRASS_QUALITY_REFERENCE).enabled, 0u);
    const float pixels[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
    for (int level = GRASS_QUALITY_HIGH; level <= GRASS_QUALITY_FASTEST; ++level) {
        const grass_blade_tessellation_desc q = grass_quality_blade_tessellation(grass_quality_level(level));
        EXPECT_EQ(q.enabled, 1u) << level;
        EXPECT_FLOAT_EQ(q.error_pixels, pixels[level]);
    }
    const grass_field_id field = make_strip(4);
    const grass_blade_tessellation_desc reference = grass_quality_blade_tessellation(GRASS_QUALITY_REFERENCE);
    const grass_blade_tessellation_desc on = grass_quality_blade_tessellation(GRASS_QUALITY_DEFAULT);
    for (int pass = 0; pass < 3; ++pass) {
        if (pass == 1) {
            ASSERT_EQ(grass_set_blade_tessellation(ctx, field, &reference), GRASS_SUCCESS);
        }
        if (pass == 2) {
            ASSERT_EQ(grass_set_blade_tessellation(ctx, field, &on), GRASS_SUCCESS);
            ASSERT_EQ(grass_set_blade_tessellation(ctx, field, nullptr), GRASS_SUCCESS) << last_message();
        }
        plan();
        const auto draws = geometry_draws();
        ASSERT_EQ(draws.size(), 1u) << "pass " << pass << ": one draw of the full blades";
        EXPECT_EQ(draws[0]->blade_level, 0u);
        EXPECT_EQ(draws[0]->first_index, 0u);
        EXPECT_EQ(draws[0]->vertex_count, patch_data->full_index_count());
    }
}

// 256 pixels, 60 degrees: 221.7 pixels a metre at 1 m. A cell draws level k from where level
// k's error (patch units of 0.25 m) is DEFAULT's 0.5 pixels: from d_k = error_k x 0.25 x
// 221.7 / 0.5 metres, at the cell's nearest point (its centre less half its diagonal).
TEST_F(BladeTessellationTest, FarCellsGetCoarserLevelsNearCellsTheFullBlades) {
    const grass_field_id field = make_strip(4);
    plan();
    const uint64_t full_instances = planned_instances();
    const uint64_t full_triangles = ctx->plan.stats.triangles;
    ASSERT_GT(full_instances, 500u);
    const grass_blade_tessellation_desc on = grass_quality_blade_tessellation(GRASS_QUALITY_DEFAULT);
    ASSERT_EQ(grass_set_blade_tessellation(ctx, field, &on), GRASS_SUCCESS) << last_message();
    plan();
    const auto draws = geometry_draws();
    ASSERT_EQ(patch_data->level_count, 3u);
    ASSERT_EQ(draws.size(), 3u) << "one draw per level";
    EXPECT_EQ(planned_instances(), full_instances) << "the same cells, split";
    expect_valid_ranges();
    double from[4] = {0.0, 0.0, 0.0, 1e30};
    for (uint32_t k = 1; k < 3; ++k) {
        from[k] = patch_data->levels[k].error * 0.25 * 221.7 / 0.5;
        EXPECT_GT(patch_data->levels[k].error, patch_data->levels[k - 1].error) << "level " << k;
    }
    std::printf("[ measured ] level 1 from %.2f m, level 2 from %.2f m\n", from[1], from[2]);
    const double kSlack = 0.02; // float rounding
    for (uint32_t k = 0; k < draws.size(); ++k) {
        EXPECT_EQ(draws[k]->blade_level, k) << "finer levels first: front to back";
        for (uint32_t i = 0; i < draws[k]->instance_count; ++i) {
            const double nearest = distance(ctx->plan.instances[draws[k]->first_instance + i]) - 0.125 * std::sqrt(2.0);
            EXPECT_GT(nearest, from[k] - kSlack) << "level " << k;
            EXPECT_LT(nearest, from[k + 1] + kSlack) << "level " << k;
        }
    }
    EXPECT_LT(ctx->plan.stats.triangles, full_triangles) << "coarser levels draw fewer triangles";
    // A larger error allowed moves the levels nearer: more cells at the coarsest.
    grass_blade_tessellation_desc coarse = on;
    coarse.error_pixels = 2.0f;
    ASSERT_EQ(grass_set_blade_tessellation(ctx, field, &coarse), GRASS_SUCCESS);
    const uint32_t at_half = draws[2]->instance_count;
    plan();
    ASSERT_GE(geometry_draws().size(), 2u);
    EXPECT_GT(geometry_draws().back()->instance_count, at_half);
}

// An orthographic view has the same pixels per metre everywhere: one level for every cell.
TEST_F(BladeTessellationTest, AnOrthographicViewDrawsOneLevel) {
    const grass_field_id field = make_strip(4);
    const grass_blade_tessellation_desc on = grass_quality_blade_tessellation(GRASS_QUALITY_DEFAULT);
    ASSERT_EQ(grass_set_blade_tessellation(ctx, field, &on), GRASS_SUCCESS);
    const double eye[3] = {1.0, 30.0, 20.0}, target[3] = {1.0, 0.0, 20.0001};
    // 25 m half height over 256 pixels: 5.1 pixels a metre, every level's error far under a pixel.
    const grass_view_desc v = test_ortho_view(eye, target, 25.0f, 1.0f, 0.1f, 100.0f);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    const auto draws = geometry_draws();
    ASSERT_EQ(draws.size(), 1u);
    EXPECT_EQ(draws[0]->blade_level, 2u);
    expect_valid_ranges();
}

// The extremes of the subdivisions: one quad has nothing coarser; 32 quads have six levels,
// down to one quad, which a view that shows the blades a few pixels tall reaches.
TEST_F(BladeTessellationTest, OneQuadHasNothingCoarserAndThirtyTwoReachOne) {
    const grass_blade_tessellation_desc on = grass_quality_blade_tessellation(GRASS_QUALITY_FASTEST);
    const grass_field_id one = make_strip(1);
    ASSERT_EQ(grass_set_blade_tessellation(ctx, one, &on), GRASS_SUCCESS);
    plan();
    ASSERT_EQ(geometry_draws().size(), 1u);
    EXPECT_EQ(geometry_draws()[0]->blade_level, 0u);
    EXPECT_EQ(geometry_draws()[0]->vertex_count, patch_data->full_index_count());
    ASSERT_EQ(grass_destroy_field(ctx, one), GRASS_SUCCESS);
    const grass_field_id many = make_strip(32);
    ASSERT_EQ(grass_set_blade_tessellation(ctx, many, &on), GRASS_SUCCESS);
    plan();
    auto draws = geometry_draws();
    ASSERT_GE(draws.size(), 2u);
    // 32 quads are far finer than a pixel of error needs: even the nearest cells drop levels.
    EXPECT_LT(draws.front()->blade_level, draws.back()->blade_level) << "the near cells finer than the far";
    for (size_t k = 1; k < draws.size(); ++k) EXPECT_GT(draws[k]->blade_level, draws[k - 1]->blade_level);
    expect_valid_ranges();
    const double eye[3] = {1.0, 30.0, 20.0}, target[3] = {1.0, 0.0, 20.0001};
    const grass_view_desc v = test_ortho_view(eye, target, 25.0f, 1.0f, 0.1f, 100.0f);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    draws = geometry_draws();
    ASSERT_EQ(draws.size(), 1u);
    EXPECT_EQ(draws[0]->blade_level, 5u) << "one quad a blade";
    EXPECT_EQ(draws[0]->vertex_count, patch_data->blade_count * 6);
    expect_valid_ranges();
}

TEST_F(BladeTessellationTest, RefusalsNameTheArgumentAndKeepTheEarlierSetting) {
    const grass_field_id field = make_strip(4);
    const grass_blade_tessellation_desc on = grass_quality_blade_tessellation(GRASS_QUALITY_DEFAULT);
    ASSERT_EQ(grass_set_blade_tessellation(ctx, field, &on), GRASS_SUCCESS);
    struct Bad {
        float pixels;
        grass_bool enabled;
        const char* name;
    };
    const Bad bad[] = {{0.005f, 1, "tessellation->error_pixels"},
                       {17.0f, 1, "tessellation->error_pixels"},
                       {std::numeric_limits<float>::quiet_NaN(), 1, "tessellation->error_pixels"},
                       {0.5f, 2, "tessellation->enabled"}};
    for (const Bad& b : bad) {
        grass_blade_tessellation_desc d = on;
        d.error_pixels = b.pixels;
        d.enabled = b.enabled;
        EXPECT_EQ(grass_set_blade_tessellation(ctx, field, &d), GRASS_ERROR_INVALID_ARGUMENT);
        EXPECT_NE(last_message().find(b.name), std::string::npos) << last_message();
    }
    grass_blade_tessellation_desc wrong = on;
    wrong.type = GRASS_STRUCT_TYPE_BLADE_CULLING_DESC;
    EXPECT_EQ(grass_set_blade_tessellation(ctx, field, &wrong), GRASS_ERROR_WRONG_STRUCT_TYPE);
    grass_blade_tessellation_desc chained = on;
    chained.next = &on;
    EXPECT_EQ(grass_set_blade_tessellation(ctx, field, &chained), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NEXT_NOT_NULL);
    EXPECT_NE(grass_set_blade_tessellation(ctx, grass_field_id{}, &on), GRASS_SUCCESS);
    plan();
    EXPECT_EQ(geometry_draws().size(), 3u) << "the earlier setting still holds";
}

} // namespace
