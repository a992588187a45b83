// The implicit quadtree and the lod tests (lemme2012 6.1-6.2).
#include "core_fixture.hpp"
#include "plan_helpers.hpp"
#include "view_helpers.hpp"

#include "plan/quadtree.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <vector>

namespace {

TEST(Quadtree, LevelsFollowLemmesDepthFormula) {
    EXPECT_EQ(grass::QuadtreeShape(1, 1).levels(), 1u);
    EXPECT_EQ(grass::QuadtreeShape(2, 1).levels(), 2u);
    EXPECT_EQ(grass::QuadtreeShape(5, 3).levels(), 4u);      // ceil(log2 5) + 1
    EXPECT_EQ(grass::QuadtreeShape(380, 532).levels(), 11u); // ceil(log2 532) + 1
    EXPECT_EQ(grass::QuadtreeShape(100000, 100000).levels(), 18u);
}

TEST(Quadtree, EveryLevelTilesTheFieldExactlyWithNodesThatStayCloseToSquare) {
    for (auto dims : {std::pair<uint32_t, uint32_t>{5, 3}, {380, 532}, {1, 7}, {64, 64}, {33, 17}}) {
        const grass::QuadtreeShape tree(dims.first, dims.second);
        for (uint32_t level = 0; level < tree.levels(); ++level) {
            std::vector<int> covered(size_t(dims.first) * dims.second, 0);
            for (uint64_t z = 0; z < tree.nodes_z(level); ++z) {
                for (uint64_t x = 0; x < tree.nodes_x(level); ++x) {
                    const grass::NodeCells c = tree.cells_of(level, x, z);
                    ASSERT_GE(c.count_x, 1u);
                    ASSERT_GE(c.count_z, 1u);
                    // 2^level a side, except where the field ends.
                    if (c.x0 + (1ull << level) <= dims.first) {
                        EXPECT_EQ(c.count_x, 1ull << level);
                    }
                    if (c.z0 + (1ull << level) <= dims.second) {
                        EXPECT_EQ(c.count_z, 1ull << level);
                    }
                    for (uint64_t j = c.z0; j < c.z0 + c.count_z; ++j) {
                        for (uint64_t i = c.x0; i < c.x0 + c.count_x; ++i) covered[j * dims.first + i] += 1;
                    }
                }
            }
            for (int n : covered) ASSERT_EQ(n, 1) << dims.first << "x" << dims.second << " level " << level;
        }
        EXPECT_EQ(tree.nodes_x(tree.root_level()), 1u);
        EXPECT_EQ(tree.nodes_z(tree.root_level()), 1u);
    }
}

class LodTest : public CoreTest {
protected:
    void SetUp() override {
        CoreTest::SetUp();
        patch = make_patch();
    }
    grass_field_id make_field(grass_field_desc d) {
        grass_field_id f{};
        EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
        return f;
    }
    grass_patch_id patch{};
};

TEST_F(LodTest, AFieldOfTenBillionCellsCostsTheHostMemoryOfATinyOne) {
    grass_memory_stats before{}, small{}, huge{};
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cells_x = d.cells_z = 10;
    // A first field makes the context's slot table and free list: later fields reuse them.
    ASSERT_EQ(grass_destroy_field(ctx, make_field(d)), GRASS_SUCCESS);
    ASSERT_EQ(grass_get_memory_stats(ctx, &before), GRASS_SUCCESS);
    const grass_field_id f = make_field(d);
    ASSERT_EQ(grass_get_memory_stats(ctx, &small), GRASS_SUCCESS);
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    d.cells_x = d.cells_z = 100000; // 1e10 cells
    const auto t0 = std::chrono::steady_clock::now();
    make_field(d);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(grass_get_memory_stats(ctx, &huge), GRASS_SUCCESS);
    std::printf("[ measured ] 1e10-cell field created in %.3f ms; field memory %llu bytes (10x10: %llu)\n", ms,
                static_cast<unsigned long long>(huge.host_bytes - before.host_bytes),
                static_cast<unsigned long long>(small.host_bytes - before.host_bytes));
    EXPECT_EQ(huge.host_bytes - before.host_bytes, small.host_bytes - before.host_bytes);
    // And it plans a frame from the middle of it.
    const double eye[3] = {12500.0, 1.7, 12500.0}, target[3] = {12500.0, 0.0, 12520.0};
    const grass_view_desc v = test_view(eye, target, 60.0f, 1.6f, 0.05f, 3000.0f);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    grass_frame_stats s{};
    grass_get_frame_stats(ctx, &s);
    EXPECT_GT(s.instances[GRASS_TIER_GEOMETRY], 50u);
    EXPECT_GT(s.instances[GRASS_TIER_IMAGE], 10u);
    EXPECT_LT(s.nodes_visited, 20000u) << "the traversal does not grow with the field";
}

// Default setup (Lemme's table in cells), 1 m cells: each tier's instances lie within its
// band (or cross an edge only as edge_ratio allows), respect the macro-cell limits, never
// overlap within a tier, and geometry draws single cells only.
TEST_F(LodTest, EveryTierDrawsWhereItsTestsSayAndNowhereElse) {
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cell_size = 1.0;
    d.cells_x = 700;
    d.cells_z = 900;
    make_field(d);
    grass_tier_desc tiers[GRASS_DEFAULT_TIER_COUNT];
    grass_lod_test tests[GRASS_DEFAULT_LOD_TEST_COUNT];
    grass_default_lod_setup(1.0, tiers, tests);
    const double eye[3] = {350.0, 2.0, 10.0}, target[3] = {350.0, 0.0, 200.0};
    const grass_view_desc v = test_view(eye, target, 70.0f, 1.6f, 0.05f, 5000.0f);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);

    const auto instances = planned_instances(ctx, d.cells_x, d.cells_z);
    std::set<std::pair<uint32_t, uint64_t>> seen; // (tier, cell index)
    int per_kind[3] = {0, 0, 0};
    const uint32_t image_tier = GRASS_DEFAULT_TIER_COUNT - 1;
    ASSERT_EQ(tiers[image_tier].kind, GRASS_TIER_IMAGE);
    size_t edge_instances = 0;
    for (const auto& p : instances) {
        const bool border = p.x0 == 0 || p.z0 == 0 || p.x0 + p.count_x == d.cells_x || p.z0 + p.count_z == d.cells_z;
        if (p.field_edge) {
            // Field edges (frame_planner.cpp): the last volume tier draws the image tier's border
            // cells, in strips at most 16 cells deep and long, where the image tier's band is.
            ++edge_instances;
            EXPECT_EQ(p.tier, image_tier - 1u);
            EXPECT_TRUE(border) << "a field-edge instance at cell " << p.x0 << ", " << p.z0;
            EXPECT_LE(std::max(p.count_x, p.count_z), 16u);
            const double nx = std::max({0.0, p.x0 - eye[0], eye[0] - double(p.x0 + p.count_x)});
            const double nz = std::max({0.0, p.z0 - eye[2], eye[2] - double(p.z0 + p.count_z)});
            EXPECT_GE(std::sqrt(nx * nx + nz * nz) + 24.0, tests[2 * image_tier - 1].begin);
            for (uint64_t j = p.z0; j < p.z0 + p.count_z; ++j) {
                for (uint64_t i = p.x0; i < p.x0 + p.count_x; ++i) {
                    ASSERT_TRUE(seen.insert({image_tier + 1, j * d.cells_x + i}).second)
                        << "two field-edge instances draw a cell";
                }
            }
            continue;
        }
        // The image tier leaves the field's border to the field-edge instances.
        if (p.kind == GRASS_TIER_IMAGE) {
            EXPECT_FALSE(border) << "the image tier at cell " << p.x0 << ", " << p.z0;
        }
        per_kind[p.kind] += 1;
        // Distances of the instance's ground rectangle (blades add < 1 cell of height/overhang).
        const double nx = std::max({0.0, p.x0 - eye[0], eye[0] - double(p.x0 + p.count_x)});
        const double nz = std::max({0.0, p.z0 - eye[2], eye[2] - double(p.z0 + p.count_z)});
        const double dmin = std::sqrt(nx * nx + nz * nz + eye[1] * eye[1]);
        const double fx = std::max(std::fabs(p.x0 - eye[0]), std::fabs(double(p.x0 + p.count_x) - eye[0]));
        const double fz = std::max(std::fabs(p.z0 - eye[2]), std::fabs(double(p.z0 + p.count_z) - eye[2]));
        const double dmax = std::sqrt(fx * fx + fz * fz + eye[1] * eye[1]);
        const grass_lod_test& band = tests[p.tier == 0 ? 0 : 2 * p.tier - 1];
        ASSERT_EQ(band.tier, p.tier);
        const double slack = 2.0; // blade height and overhang, in cells
        EXPECT_LE(dmin, band.end + slack) << "tier " << p.tier;
        EXPECT_GE(dmax, band.begin - slack) << "tier " << p.tier;
        const bool crosses = dmin < band.begin - slack || dmax > band.end + slack;
        if (crosses) {
            EXPECT_LE(double(std::max(p.count_x, p.count_z)), band.edge_ratio * (dmin + slack) + 1.0);
        }
        if (p.kind == GRASS_TIER_GEOMETRY) {
            EXPECT_EQ(p.count_x * p.count_z, 1u);
        } else {
            const uint32_t limit = tests[2 * p.tier].max_macro_cells;
            EXPECT_LE(std::max(p.count_x, p.count_z), limit) << "tier " << p.tier;
        }
        for (uint64_t j = p.z0; j < p.z0 + p.count_z; ++j) {
            for (uint64_t i = p.x0; i < p.x0 + p.count_x; ++i) {
                ASSERT_TRUE(seen.insert({p.tier, j * d.cells_x + i}).second)
                    << "tier " << p.tier << " draws a cell twice";
            }
        }
    }
    EXPECT_GT(per_kind[GRASS_TIER_GEOMETRY], 0);
    EXPECT_GT(per_kind[GRASS_TIER_VOLUME], 0);
    EXPECT_GT(per_kind[GRASS_TIER_IMAGE], 0);
    EXPECT_GT(edge_instances, 0u);
    // Every border cell the image tier would draw is drawn by a field-edge instance: the far
    // edge (z = 899) in view across the image tier's band.
    for (uint64_t i = 200; i < 500; ++i) {
        EXPECT_TRUE(seen.count({image_tier + 1, 899 * uint64_t(d.cells_x) + i})) << "far edge, cell " << i;
    }
    grass_frame_stats s{};
    grass_get_frame_stats(ctx, &s);
    EXPECT_GT(s.macro_cells[GRASS_TIER_IMAGE], 0u);
    EXPECT_EQ(s.macro_cells[GRASS_TIER_GEOMETRY], 0u);
}

// A host test through the callback: never asked again below a node it drew or discarded
// (the inherited skip flags of lemme figure 6.3), and its answers are obeyed.
struct CallbackLog {
    std::vector<grass_lod_node> asked;
    std::vector<grass_lod_answer> answers;
};

grass_lod_answer split_half(void* user, const grass_lod_node* n) {
    auto* log = static_cast<CallbackLog*>(user);
    // Draw nodes of 4 cells or less in the x < 32 half, discard the x >= 32 half.
    grass_lod_answer a = GRASS_LOD_SPLIT;
    if (n->cell_x >= 32)
        a = GRASS_LOD_DISCARD;
    else if (n->cells_x <= 4 && n->cell_x + n->cells_x <= 32)
        a = GRASS_LOD_DRAW;
    log->asked.push_back(*n);
    log->answers.push_back(a);
    return a;
}

bool contains(const grass_lod_node& outer, const grass_lod_node& inner) {
    return inner.level < outer.level && inner.cell_x >= outer.cell_x && inner.cell_z >= outer.cell_z &&
           inner.cell_x + inner.cells_x <= outer.cell_x + outer.cells_x &&
           inner.cell_z + inner.cells_z <= outer.cell_z + outer.cells_z;
}

TEST_F(LodTest, ACallbackTestIsNotAskedBelowANodeItDecidedAndIsObeyed) {
    CallbackLog log_;
    grass_tier_desc tier{GRASS_TIER_VOLUME, 4};
    grass_lod_test test{};
    test.kind = GRASS_LOD_TEST_CALLBACK;
    test.tier = 0;
    test.callback = split_half;
    test.user_data = &log_;
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cell_size = 1.0;
    d.cells_x = d.cells_z = 64;
    d.tiers = &tier;
    d.tier_count = 1;
    d.lod_tests = &test;
    d.lod_test_count = 1;
    make_field(d);
    const double eye[3] = {32.0, 120.0, 32.0}, target[3] = {32.0, 0.0, 32.001};
    const grass_view_desc v = test_view(eye, target, 60.0f);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    for (size_t a = 0; a < log_.asked.size(); ++a) {
        if (log_.answers[a] == GRASS_LOD_SPLIT) continue;
        for (size_t b = 0; b < log_.asked.size(); ++b) {
            ASSERT_FALSE(contains(log_.asked[a], log_.asked[b])) << "asked below a decided node";
        }
    }
    const auto instances = planned_instances(ctx, 64, 64);
    uint64_t cells = 0;
    for (const auto& p : instances) {
        EXPECT_LE(p.x0 + p.count_x, 32u);
        EXPECT_EQ(p.count_x, 4u);
        cells += p.count_x * p.count_z;
    }
    EXPECT_EQ(cells, 32u * 64u) << "the whole x < 32 half, in 4x4 macro-cells";
    grass_frame_stats s{};
    grass_get_frame_stats(ctx, &s);
    EXPECT_EQ(s.lod_test_calls, log_.asked.size());
}

grass_lod_answer bad_answer(void*, const grass_lod_node*) { return static_cast<grass_lod_answer>(7); }

TEST_F(LodTest, ACallbackAnsweringNonsenseFailsTheFrameCleanly) {
    grass_tier_desc tier{GRASS_TIER_IMAGE, 0};
    grass_lod_test test{};
    test.kind = GRASS_LOD_TEST_CALLBACK;
    test.callback = bad_answer;
    grass_field_desc d = one_tier_field(patch, 8, &tier, &test);
    const grass_field_id f = make_field(d);
    const double eye[3] = {1.0, 4.0, 1.0}, target[3] = {1.0, 0.0, 1.001};
    const grass_view_desc v = test_view(eye, target);
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_BAD_ENUM);
    EXPECT_EQ(grass_end_frame(ctx), GRASS_ERROR_INVALID_STATE) << "no frame was begun";
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    d.tiers = nullptr;
    d.tier_count = 0;
    d.lod_tests = nullptr;
    d.lod_test_count = 0;
    make_field(d);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << "usable afterwards";
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

TEST_F(LodTest, BadTiersAndTestsAreRefusedWithTheTestNamed) {
    grass_tier_desc tiers[2] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 8}};
    grass_lod_test tests[2] = {};
    tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[0].tier = 0;
    tests[0].end = 10.0f;
    tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[1].tier = 1;
    tests[1].max_macro_cells = 16;
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cells_x = d.cells_z = 8;
    d.tiers = tiers;
    d.tier_count = 2;
    d.lod_tests = tests;
    d.lod_test_count = 2;
    grass_field_id f{};
    ASSERT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);

    tests[0].end = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("lod_tests[0]"), std::string::npos) << last_message();
    tests[0].end = 10.0f;
    tests[1].tier = 5;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("lod_tests[1].tier"), std::string::npos) << last_message();
    tests[1].tier = 0; // a macro-cell test on the geometry tier, and tier 1 left without a test
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("geometry"), std::string::npos) << last_message();
    tests[1].max_macro_cells = 1;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("tiers[1] has no lod test"), std::string::npos) << last_message();
    tiers[1].slices = 0;
    tests[1].tier = 1;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("slices"), std::string::npos) << last_message();
    tiers[1].slices = 8;
    tests[0].edge_ratio = 2.0f;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("edge_ratio"), std::string::npos) << last_message();
}

TEST(DefaultLodSetup, IsLemmesFootballTableInCells) {
    grass_tier_desc tiers[GRASS_DEFAULT_TIER_COUNT];
    grass_lod_test tests[GRASS_DEFAULT_LOD_TEST_COUNT];
    grass_default_lod_setup(0.5, tiers, tests);
    EXPECT_EQ(tiers[0].kind, GRASS_TIER_GEOMETRY);
    EXPECT_EQ(tiers[1].slices, 8u);
    EXPECT_EQ(tiers[2].slices, 2u);
    EXPECT_EQ(tiers[3].slices, 1u);
    EXPECT_EQ(tiers[4].kind, GRASS_TIER_IMAGE);
    EXPECT_FLOAT_EQ(tests[0].end, 10.0f);  // 20 cells of 0.5 m
    EXPECT_FLOAT_EQ(tests[1].begin, 2.5f); // 5 cells
    EXPECT_FLOAT_EQ(tests[1].end, 40.0f);  // 80 cells
    EXPECT_EQ(tests[2].max_macro_cells, 40u);
    EXPECT_FLOAT_EQ(tests[7].begin, 100.0f); // image from 200 cells
    EXPECT_TRUE(std::isinf(tests[7].end));
    EXPECT_EQ(tests[8].max_macro_cells, 500u);
}

} // namespace
