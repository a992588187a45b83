// The frame plan for flat fields: cells, camera-relative origins, mirror bits, stats.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "patch/mirror_tiling.hpp"

#include <cmath>
#include <set>
#include <vector>

namespace {

class PlanTest : public CoreTest {
protected:
    grass_field_id make_field(grass_field_desc d) {
        grass_field_id f{};
        EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
        return f;
    }
    grass_field_desc field_desc(uint32_t cells) {
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = cells;
        return d;
    }
    void plan(const grass_view_desc& v) {
        ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    }
    const grass::FramePlan& the_plan() const { return ctx->plan; }
    // The geometry tier's instances, in plan order (front to back).
    std::vector<grass::TierInstance> geometry() const {
        std::vector<grass::TierInstance> out;
        for (const auto& d : ctx->plan.draws) {
            if (d.kind != GRASS_TIER_GEOMETRY) continue;
            out.insert(out.end(), ctx->plan.instances.begin() + d.first_instance,
                       ctx->plan.instances.begin() + d.first_instance + d.instance_count);
        }
        return out;
    }
    // One geometry tier drawn up to `distance` metres.
    void geometry_only(grass_field_desc* d, float distance) {
        tier = grass_tier_desc{GRASS_TIER_GEOMETRY, 0};
        band = grass_lod_test{};
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.tier = 0;
        band.begin = 0.0f;
        band.end = distance;
        d->tiers = &tier;
        d->tier_count = 1;
        d->lod_tests = &band;
        d->lod_test_count = 1;
    }
    grass_tier_desc tier{};
    grass_lod_test band{};
    // The mirror bits the shaders give each planned geometry cell (same hash as the GPU).
    std::vector<uint32_t> mirror_states() const {
        std::vector<uint32_t> out;
        for (const auto& d : ctx->plan.draws) {
            if (d.kind != GRASS_TIER_GEOMETRY) continue;
            for (uint32_t k = 0; k < d.instance_count; ++k) {
                const auto& inst = ctx->plan.instances[d.first_instance + k];
                out.push_back(
                    d.uniforms.tiling[1] ? grass::mirror_bits(inst.cell[0], inst.cell[1], d.uniforms.tiling[0]) : 0u);
            }
        }
        return out;
    }
    void SetUp() override {
        CoreTest::SetUp();
        patch = make_patch();
    }
    grass_patch_id patch{};
};

TEST_F(PlanTest, AllFourMirrorStatesOccurOnAnEightByEightField) {
    make_field(field_desc(8)); // 2 m x 2 m
    const double eye[3] = {1.0, 3.5, 1.0}, target[3] = {1.0, 0.0, 1.0};
    plan(test_view(eye, target));
    ASSERT_EQ(geometry().size(), 64u);
    std::set<uint32_t> states;
    for (uint32_t m : mirror_states()) states.insert(m);
    EXPECT_EQ(states, (std::set<uint32_t>{0, 1, 2, 3}));
}

TEST_F(PlanTest, MirrorTilingOffDrawsEveryCellUnmirroredAndTheSeedChangesThePattern) {
    grass_field_desc d = field_desc(8);
    d.mirror_tiling = 0;
    const grass_field_id f = make_field(d);
    const double eye[3] = {1.0, 3.5, 1.0}, target[3] = {1.0, 0.0, 1.0};
    plan(test_view(eye, target));
    for (uint32_t m : mirror_states()) EXPECT_EQ(m, 0u);
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);

    std::vector<uint32_t> a, b;
    d.mirror_tiling = 1;
    const grass_field_id f1 = make_field(d);
    plan(test_view(eye, target));
    a = mirror_states();
    ASSERT_EQ(grass_destroy_field(ctx, f1), GRASS_SUCCESS);
    d.mirror_seed = 7;
    make_field(d);
    plan(test_view(eye, target));
    b = mirror_states();
    EXPECT_NE(a, b);
}

TEST_F(PlanTest, OnlyCellsInFrontOfTheCameraWithinTheDrawDistanceAreDrawnFrontToBack) {
    grass_field_desc d = field_desc(200); // 50 m x 50 m
    geometry_only(&d, 6.0f);
    make_field(d);
    const double eye[3] = {25.0, 1.5, 25.0}, target[3] = {30.0, 1.0, 25.0}; // looking along +x
    plan(test_view(eye, target));
    const auto& p = the_plan();
    const auto instances = geometry();
    ASSERT_GT(instances.size(), 50u);
    const double overhang = 0.5; // generous bound on blade tips leaving the cell, in cells
    double last = 0.0;
    for (const auto& inst : instances) {
        // Behind the camera (x relative < 0) only cells whose box still reaches forward.
        EXPECT_GT(inst.origin[0] + (1.0 + overhang) * 0.25, 0.0);
        // Within the draw distance: the cell's nearest point.
        const double nx = std::max(0.0, std::max(double(inst.origin[0]), -(inst.origin[0] + 0.25)));
        const double nz = std::max(0.0, std::max(double(inst.origin[2]), -(inst.origin[2] + 0.25)));
        EXPECT_LE(std::sqrt(nx * nx + nz * nz), 6.0 + 1e-3);
        const double cx = inst.origin[0] + 0.125, cz = inst.origin[2] + 0.125, cy = inst.origin[1];
        const double dist = std::sqrt(cx * cx + cy * cy + cz * cz);
        EXPECT_GE(dist, last - 1e-4) << "front to back";
        last = dist;
    }
    EXPECT_EQ(p.stats.cells_drawn, instances.size());
    EXPECT_EQ(p.stats.instances[GRASS_TIER_GEOMETRY], instances.size());
    EXPECT_EQ(p.stats.macro_cells[GRASS_TIER_GEOMETRY], 0u);

    // Turned around, the camera sees other cells.
    const double back[3] = {20.0, 1.0, 25.0};
    plan(test_view(eye, back));
    for (const auto& inst : geometry()) EXPECT_LT(inst.origin[0] - overhang * 0.25, 0.0);
}

TEST_F(PlanTest, AFieldTenThousandKilometresOutPlansTheSameCameraRelativeOrigins) {
    grass_field_desc d = field_desc(16);
    const grass_field_id near_field = make_field(d);
    const double eye[3] = {2.0, 1.2, -1.0}, target[3] = {2.0, 0.0, 2.0};
    plan(test_view(eye, target));
    const auto near_instances = geometry();
    ASSERT_GT(near_instances.size(), 10u);
    ASSERT_EQ(grass_destroy_field(ctx, near_field), GRASS_SUCCESS);

    const double far = 1e7; // 10,000 km
    d.base_transform[12] = far;
    d.base_transform[14] = -far;
    make_field(d);
    const double eye_far[3] = {far + 2.0, 1.2, -far - 1.0}, target_far[3] = {far + 2.0, 0.0, -far + 2.0};
    plan(test_view(eye_far, target_far));
    const auto& far_instances = geometry();
    ASSERT_EQ(far_instances.size(), near_instances.size());
    for (size_t k = 0; k < far_instances.size(); ++k) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(far_instances[k].origin[c], near_instances[k].origin[c], 1e-6f);
        EXPECT_EQ(far_instances[k].cell[0], near_instances[k].cell[0]);
        EXPECT_EQ(far_instances[k].cell[1], near_instances[k].cell[1]);
    }
}

TEST_F(PlanTest, StatsCountBladesThroughTheDensityThresholds) {
    grass_field_desc d = field_desc(8);
    geometry_only(&d, 50.0f); // no transition zone: every visible blade is a blade
    d.density = 0.5f;
    make_field(d);
    const double eye[3] = {1.0, 3.5, 1.0}, target[3] = {1.0, 0.0, 1.0};
    plan(test_view(eye, target));
    grass_frame_stats s{};
    ASSERT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
    EXPECT_EQ(s.cells_drawn, 64u);
    EXPECT_EQ(s.blades_submitted, 64u * 384u);
    EXPECT_EQ(s.blades_drawn, 64u * 192u);
    EXPECT_EQ(s.triangles, s.blades_drawn * 8u);
    EXPECT_EQ(s.fields_drawn, 1u);
}

TEST_F(PlanTest, StatsCountOnlyTheGeometryTiersShareInATransitionZone) {
    grass_field_desc d = field_desc(8); // default setup: geometry fades out over 1.25..5 m
    make_field(d);
    const double eye[3] = {1.0, 3.5, 1.0}, target[3] = {1.0, 0.0, 1.0};
    plan(test_view(eye, target));
    grass_frame_stats s{};
    ASSERT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
    EXPECT_EQ(s.blades_submitted, 64u * 384u);
    // About 3.5 m away the geometry tier holds (5 - 3.5) / 3.75 = 40% of the blades.
    EXPECT_GT(s.blades_drawn, 64u * 384u * 30 / 100);
    EXPECT_LT(s.blades_drawn, 64u * 384u * 45 / 100);
}

TEST_F(PlanTest, ZeroDensityDrawsNoBlades) {
    const double eye[3] = {1.0, 3.5, 1.0}, target[3] = {1.0, 0.0, 1.0};
    grass_field_desc d = field_desc(8);
    grass_frame_stats s{};
    // Positive control: the same field and view at full density draw blades.
    const grass_field_id full = make_field(d);
    plan(test_view(eye, target));
    ASSERT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
    EXPECT_GT(s.blades_drawn, 1000u) << "density 1 draws the view's blades";
    EXPECT_GT(s.triangles, 0u);
    ASSERT_EQ(grass_destroy_field(ctx, full), GRASS_SUCCESS);

    d.density = 0.0f;
    make_field(d);
    plan(test_view(eye, target));
    ASSERT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
    EXPECT_EQ(s.blades_drawn, 0u);
    EXPECT_EQ(s.triangles, 0u);
}

TEST_F(PlanTest, RotatedBaseTransformPlacesCellsInWorldSpace) {
    grass_field_desc d = field_desc(4);
    // 90 degrees about y: field x -> world -z, field z -> world x.
    double* m = d.base_transform;
    for (int k = 0; k < 16; ++k) m[k] = 0.0;
    m[2] = -1.0; // column 0 = (0, 0, -1)
    m[5] = 1.0;  // column 1 = (0, 1, 0)
    m[8] = 1.0;  // column 2 = (1, 0, 0)
    m[15] = 1.0;
    make_field(d);
    const double eye[3] = {0.5, 5.0, -0.5}, target[3] = {0.5, 0.0, -0.5};
    plan(test_view(eye, target));
    ASSERT_EQ(geometry().size(), 16u);
    for (const auto& inst : geometry()) {
        // Field cells lie in world x in [0, 1], z in [-1, 0].
        EXPECT_GE(inst.origin[0] + 0.5, -1e-6);
        EXPECT_LE(inst.origin[0] + 0.5, 1.0 + 1e-6);
        EXPECT_LE(inst.origin[2] - 0.5, 1e-6);
        EXPECT_GE(inst.origin[2] - 0.5, -1.0 - 1e-6);
    }
}

} // namespace

namespace {

TEST(MirrorBits, TheFourStatesAreEquallyLikelyAnywhereInTheField) {
    for (uint32_t base : {0u, 1u << 20, (1u << 30) - 200u}) {
        int count[4] = {0, 0, 0, 0};
        for (uint32_t z = 0; z < 100; ++z) {
            for (uint32_t x = 0; x < 100; ++x) count[grass::mirror_bits(base + x, base + z, 0)]++;
        }
        for (int c : count) EXPECT_NEAR(c, 2500, 200) << "cells from " << base;
    }
    // Neighbouring cells are independent: a state repeats on its right neighbour 1/4 of the time.
    int same = 0;
    for (uint32_t x = 0; x < 10000; ++x) same += grass::mirror_bits(x, 7, 3) == grass::mirror_bits(x + 1, 7, 3);
    EXPECT_NEAR(same, 2500, 200);
}

} // namespace
