// Design maps through the C API without a GPU: validation, the map stack, and what the
// planner does with them (empty nodes discarded, terrain extents, unplanarity, hilltops).
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace {

class DesignMapTest : public CoreTest {
protected:
    void SetUp() override {
        CoreTest::SetUp();
        patch = make_patch();
    }
    grass_map_id make_map(const void* pixels, uint32_t w, uint32_t h, grass_map_format f) {
        grass_map_desc d = grass_default_map_desc();
        d.pixels = pixels;
        d.width = w;
        d.height = h;
        d.format = f;
        grass_map_id m{};
        EXPECT_EQ(grass_create_map(ctx, &d, &m), GRASS_SUCCESS) << last_message();
        return m;
    }
    grass_field_desc field_desc(uint32_t cells) const {
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cells_x = d.cells_z = cells;
        d.cell_size = 1.0;
        return d;
    }
    grass_field_id make_field(const grass_field_desc& d) {
        grass_field_id f{};
        EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_SUCCESS) << last_message();
        return f;
    }
    grass_frame_stats plan(const grass_view_desc& v) {
        grass_frame_stats s{};
        EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
        EXPECT_EQ(grass_get_frame_stats(ctx, &s), GRASS_SUCCESS);
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        return s;
    }
    // A camera high above the middle of a `cells` field, seeing all of it.
    grass_view_desc overhead(uint32_t cells) const {
        const double eye[3] = {cells * 0.5, cells * 1.5, cells * 0.5 + 0.01}, at[3] = {cells * 0.5, 0.0, cells * 0.5};
        return test_view(eye, at, 60.0f, 1.0f, 0.1f, 10000.0f);
    }
    std::vector<grass::TierInstance> instances() const {
        return std::vector<grass::TierInstance>(ctx->plan.instances.begin(), ctx->plan.instances.end());
    }
    grass_patch_id patch{};
};

TEST_F(DesignMapTest, BadMapsAreRefusedWithTheArgumentNamed) {
    uint8_t px[16] = {0};
    grass_map_desc d = grass_default_map_desc();
    d.pixels = px;
    d.width = 4;
    d.height = 4;
    grass_map_id m{};
    d.width = 0;
    EXPECT_EQ(grass_create_map(ctx, &d, &m), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_BAD_MAP);
    EXPECT_NE(last_message().find("0 x 4"), std::string::npos) << last_message();
    d.width = 16385;
    EXPECT_EQ(grass_create_map(ctx, &d, &m), GRASS_ERROR_INVALID_ARGUMENT);
    d.width = 4;
    d.row_pitch = 3;
    EXPECT_EQ(grass_create_map(ctx, &d, &m), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("row_pitch is 3"), std::string::npos) << last_message();
    d.row_pitch = 0;
    d.format = static_cast<grass_map_format>(77);
    EXPECT_EQ(grass_create_map(ctx, &d, &m), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("77"), std::string::npos) << last_message();
    float f[4] = {0.5f, std::numeric_limits<float>::quiet_NaN(), 0.0f, 1.0f};
    d.pixels = f;
    d.width = 2;
    d.height = 2;
    d.format = GRASS_MAP_FORMAT_R32_FLOAT;
    EXPECT_EQ(grass_create_map(ctx, &d, &m), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("texel (1, 0)"), std::string::npos) << last_message();
    EXPECT_EQ(m.index, 0u) << "nothing made on failure";
    EXPECT_EQ(ctx->maps.capacity(), 0u);
}

TEST_F(DesignMapTest, TheMapStackRefusesWrongRolesScalesAndTransforms) {
    const uint8_t grey[4] = {128, 128, 128, 128}, rgba[16] = {0};
    const grass_map_id r = make_map(grey, 2, 2, GRASS_MAP_FORMAT_R8_UNORM);
    const grass_map_id c = make_map(rgba, 2, 2, GRASS_MAP_FORMAT_RGBA8_UNORM);
    grass_field_id f{};
    grass_field_desc d = field_desc(8);
    d.maps.color = r;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_MAP_ROLE);
    EXPECT_NE(last_message().find("desc->maps.color"), std::string::npos) << last_message();
    d.maps.color = c;
    d.maps.height = c;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("desc->maps.height"), std::string::npos) << last_message();
    d.maps.height = r;
    d.maps.height_scale = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("desc->maps.height_scale"), std::string::npos) << last_message();
    d.maps.height_scale = 2.0f;
    const double line[6] = {1, 2, 2, 4, 0, 0};
    std::memcpy(d.maps.cell_to_map, line, sizeof(line));
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_BAD_TRANSFORM);
    d.maps.cell_to_map[0] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    std::memset(d.maps.cell_to_map, 0, sizeof(d.maps.cell_to_map));
    grass_map_desc dm = grass_default_map_desc();
    dm.pixels = grey;
    dm.width = dm.height = 2;
    d.density_map = &dm;
    d.maps.density = r;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("both set"), std::string::npos) << last_message();
    d.density_map = nullptr;
    grass_map_id stale = r;
    stale.generation += 1;
    d.maps.ambient = stale;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_HANDLE);
    d.maps.ambient = r;
    d.maps.diffuse = r;
    EXPECT_EQ(ctx->fields.capacity(), 0u) << "no field made by the refused calls";
    f = make_field(d);
    EXPECT_EQ(ctx->fields.get(f.index - 1)->maps.features, 0x1fu);
    // Maps in use cannot go; after the field, they can.
    EXPECT_EQ(grass_destroy_map(ctx, r), GRASS_ERROR_IN_USE);
    EXPECT_EQ(last_id(), GRASS_MSG_MAP_IN_USE) << "a map's own id, not the patch's";
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    EXPECT_EQ(grass_destroy_map(ctx, r), GRASS_SUCCESS);
    EXPECT_EQ(grass_destroy_map(ctx, r), GRASS_ERROR_INVALID_HANDLE) << "stale";
    EXPECT_EQ(grass_destroy_map(ctx, c), GRASS_SUCCESS);
}

TEST_F(DesignMapTest, UpdatesOutsideTheMapOrOfAnotherFormatAreRefusedAndChangeNothing) {
    std::vector<uint8_t> px(8 * 8, 255);
    const grass_map_id m = make_map(px.data(), 8, 8, GRASS_MAP_FORMAT_R8_UNORM);
    const std::vector<uint16_t> before(ctx->maps.get(m.index - 1)->texels.begin(),
                                       ctx->maps.get(m.index - 1)->texels.end());
    uint8_t zeros[16] = {0};
    grass_map_desc r = grass_default_map_desc();
    r.pixels = zeros;
    r.width = r.height = 4;
    EXPECT_EQ(grass_update_map(ctx, m, 5, 0, &r), GRASS_ERROR_INVALID_ARGUMENT)
        << "4 wide from x = 5 leaves an 8-wide map";
    EXPECT_EQ(last_id(), GRASS_MSG_BAD_MAP);
    EXPECT_EQ(grass_update_map(ctx, m, 8, 0, &r), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_MAP_REGION);
    r.format = GRASS_MAP_FORMAT_R16_UNORM;
    EXPECT_EQ(grass_update_map(ctx, m, 0, 0, &r), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_MAP_REGION);
    const std::vector<uint16_t> after(ctx->maps.get(m.index - 1)->texels.begin(),
                                      ctx->maps.get(m.index - 1)->texels.end());
    EXPECT_EQ(before, after);
    r.format = GRASS_MAP_FORMAT_R8_UNORM;
    EXPECT_EQ(grass_update_map(ctx, m, 4, 4, &r), GRASS_SUCCESS) << last_message();
    const auto& t = ctx->maps.get(m.index - 1)->texels;
    for (uint32_t y = 0; y < 8; ++y) {
        for (uint32_t x = 0; x < 8; ++x) EXPECT_EQ(t[y * 8 + x], (x >= 4 && y >= 4) ? 0 : 65535) << x << "," << y;
    }
}

TEST_F(DesignMapTest, NodesWithZeroDensityAreDiscardedWithoutVisitingTheirChildren) {
    const uint32_t cells = 64;
    std::vector<uint8_t> px(64 * 64, 255);
    for (uint32_t z = 0; z < 64; ++z) {
        for (uint32_t x = 0; x < 32; ++x) px[z * 64 + x] = 0; // the west half is bare
    }
    grass_field_desc d = field_desc(cells);
    grass_tier_desc tier{GRASS_TIER_GEOMETRY, 0}; // blades everywhere: the traversal reaches every cell
    grass_lod_test band{};
    band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    band.end = 1e6f;
    d.tiers = &tier;
    d.tier_count = 1;
    d.lod_tests = &band;
    d.lod_test_count = 1;
    const grass_field_id full = make_field(d);
    const grass_frame_stats s_full = plan(overhead(cells));
    EXPECT_EQ(grass_destroy_field(ctx, full), GRASS_SUCCESS);
    const grass_map_id m = make_map(px.data(), 64, 64, GRASS_MAP_FORMAT_R8_UNORM);
    d.maps.density = m;
    make_field(d);
    const grass_frame_stats s_half = plan(overhead(cells));
    EXPECT_GT(s_half.nodes_empty, 0u);
    EXPECT_EQ(s_full.nodes_empty, 0u);
    EXPECT_LT(s_half.nodes_visited, s_full.nodes_visited * 3 / 4)
        << "half the field is bare: its subtrees must not be visited (" << s_half.nodes_visited << " vs "
        << s_full.nodes_visited << ")";
    for (const grass::TierInstance& i : instances()) {
        EXPECT_GE(i.cell[0] + i.count[0], 31u) << "an instance entirely in the bare half, at cell " << i.cell[0];
    }
    // Mowing the other half too (grass_update_map) leaves nothing to plan.
    std::vector<uint8_t> zeros(32 * 64, 0);
    grass_map_desc r = grass_default_map_desc();
    r.pixels = zeros.data();
    r.width = 32;
    r.height = 64;
    ASSERT_EQ(grass_update_map(ctx, m, 32, 0, &r), GRASS_SUCCESS) << last_message();
    const grass_frame_stats s_none = plan(overhead(cells));
    EXPECT_EQ(s_none.nodes_visited, 1u);
    EXPECT_EQ(s_none.nodes_empty, 1u);
    EXPECT_TRUE(instances().empty());
}

TEST_F(DesignMapTest, ADensityOfZeroPlansNothing) {
    grass_field_desc d = field_desc(16);
    d.density = 0.0f;
    make_field(d);
    const grass_frame_stats s = plan(overhead(16));
    EXPECT_EQ(s.nodes_visited, 1u);
    EXPECT_TRUE(instances().empty());
}

// A ramp along x over a field of n cells: texel i (at the centre of cell i) holds
// (i + 0.5) / n, so with a height scale of n / 2 metres the terrain rises 0.5 m per cell.
std::vector<uint16_t> ramp(uint32_t n) {
    std::vector<uint16_t> px(size_t(n) * n);
    for (uint32_t z = 0; z < n; ++z) {
        for (uint32_t x = 0; x < n; ++x)
            px[size_t(z) * n + x] = static_cast<uint16_t>(std::lround(65535.0 * (x + 0.5) / n));
    }
    return px;
}

TEST_F(DesignMapTest, InstancesAndLodNodesCarryTheTerrainUnderThem) {
    const uint32_t cells = 32;
    const std::vector<uint16_t> px = ramp(cells);
    grass_field_desc d = field_desc(cells);
    d.maps.height = make_map(px.data(), cells, cells, GRASS_MAP_FORMAT_R16_UNORM);
    d.maps.height_scale = 16.0f; // 0.5 m per cell of x
    struct Seen {
        double lo = 1e9, hi = -1e9;
        bool ok = true;
    } seen;
    grass_tier_desc tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test tests[2] = {};
    tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[0].end = 1e6f;
    tests[1].kind = GRASS_LOD_TEST_CALLBACK;
    tests[1].callback = [](void* user, const grass_lod_node* n) {
        auto* s = static_cast<Seen*>(user);
        // The terrain under the node (0.5 m per cell, clamped to the outer texel centres)
        // lies within the range, and the range is at most half the node's side wider each way
        // (the pyramid reads whole entries of a coarser level).
        const double lo = 0.5 * std::max(n->cell_x + 0.0, 0.5), hi = 0.5 * std::min(n->cell_x + n->cells_x + 0.0, 31.5);
        const double slack = 0.5 * (0.5 * n->cells_x + 1.0);
        if (n->height_min > lo + 1e-3 || n->height_max < hi - 1e-3 || n->height_min < lo - slack - 1e-3 ||
            n->height_max > hi + slack + 1e-3) {
            s->ok = false;
        }
        s->lo = std::min(s->lo, n->height_min);
        s->hi = std::max(s->hi, n->height_max);
        return GRASS_LOD_SPLIT;
    };
    tests[1].user_data = &seen;
    d.tiers = &tier;
    d.tier_count = 1;
    d.lod_tests = tests;
    d.lod_test_count = 2;
    make_field(d);
    plan(overhead(cells));
    EXPECT_TRUE(seen.ok);
    EXPECT_NEAR(seen.lo, 0.25, 1e-3);
    EXPECT_NEAR(seen.hi, 15.75, 1e-3);
    ASSERT_FALSE(instances().empty());
    for (const grass::TierInstance& i : instances()) {
        // terrain is in patch units = cells (cell_size 1): 0.5 per cell of x, within a texel.
        EXPECT_NEAR(i.terrain[0], std::max(0.25, 0.5 * i.cell[0]), 0.51);
        EXPECT_NEAR(i.terrain[1], std::min(15.75, 0.5 * (i.cell[0] + 1)), 0.51);
        EXPECT_LE(i.terrain[0], i.terrain[1]);
    }
}

TEST_F(DesignMapTest, RaisedTerrainIsNotCulledAsIfItWereFlat) {
    // A plateau 30 m up; the camera above it looks level across it: flat bounds would put
    // every node below the view and cull it.
    const uint32_t cells = 32;
    std::vector<uint8_t> px(4, 255);
    grass_field_desc d = field_desc(cells);
    d.maps.height = make_map(px.data(), 2, 2, GRASS_MAP_FORMAT_R8_UNORM);
    d.maps.height_scale = 30.0f;
    make_field(d);
    const double eye[3] = {16.0, 30.5, -2.0}, at[3] = {16.0, 30.5, 30.0};
    const grass_frame_stats s = plan(test_view(eye, at, 30.0f));
    EXPECT_GT(s.instances[GRASS_TIER_GEOMETRY] + s.instances[GRASS_TIER_VOLUME], 0u);
}

TEST_F(DesignMapTest, UnplanarityTestsSplitMacroCellsOnSlopesOnly) {
    const uint32_t cells = 64;
    grass_tier_desc tier{GRASS_TIER_IMAGE, 0};
    grass_lod_test tests[2] = {};
    tests[0].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[0].max_macro_cells = 64;
    tests[1].kind = GRASS_LOD_TEST_UNPLANARITY;
    tests[1].max_unplanarity = 1.2f;
    const std::vector<uint16_t> px = ramp(cells);
    grass_field_desc d = field_desc(cells);
    d.tiers = &tier;
    d.tier_count = 1;
    d.lod_tests = tests;
    d.lod_test_count = 2;
    const grass_field_id flat = make_field(d);
    const grass_frame_stats s_flat = plan(overhead(cells));
    EXPECT_EQ(s_flat.instances[GRASS_TIER_IMAGE], 1u) << "flat: one macro-cell";
    grass_destroy_field(ctx, flat);
    d.maps.height = make_map(px.data(), cells, cells, GRASS_MAP_FORMAT_R16_UNORM);
    d.maps.height_scale = 32.0f; // 0.5 m per cell: a cell spans 1 m with its bilinear neighbours, 2 cells 1.5 m
    make_field(d);
    const grass_frame_stats s = plan(overhead(cells));
    EXPECT_GT(s.instances[GRASS_TIER_IMAGE], uint64_t(cells) * cells * 9 / 10)
        << "split down to cells on the slope (2-cell nodes pass only at the clamped ends)";
    for (const grass::TierInstance& i : instances()) {
        EXPECT_LE(i.terrain[1] - i.terrain[0], 1.2f + 1e-4f) << "cells " << i.count[0];
    }
    EXPECT_EQ(s.cells[GRASS_TIER_IMAGE], uint64_t(cells) * cells) << "every cell still drawn once";
}

TEST_F(DesignMapTest, AHilltopTierDrawsOnlyWhatReachesAboveTheCamera) {
    // A ramp rising to 16 m in +x; the camera 8 m up at the low end. The overlay volume tier
    // draws the nodes whose box reaches above 8 m; the image tier draws everything.
    const uint32_t cells = 32;
    const std::vector<uint16_t> px = ramp(cells);
    grass_tier_desc tiers[2] = {{GRASS_TIER_IMAGE, 0}, {GRASS_TIER_VOLUME, 2}};
    grass_lod_test tests[3] = {};
    tests[0].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[0].max_macro_cells = 4;
    tests[1].kind = GRASS_LOD_TEST_HILLTOP;
    tests[1].tier = 1;
    tests[2].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[2].tier = 1;
    tests[2].max_macro_cells = 4;
    grass_field_desc d = field_desc(cells);
    d.tiers = tiers;
    d.tier_count = 2;
    d.lod_tests = tests;
    d.lod_test_count = 3;
    d.maps.height = make_map(px.data(), cells, cells, GRASS_MAP_FORMAT_R16_UNORM);
    d.maps.height_scale = 16.0f;
    const grass_field_id f = make_field(d);
    const double eye[3] = {-5.0, 8.0, 16.0}, at[3] = {16.0, 8.0, 16.0};
    plan(test_view(eye, at, 90.0f, 1.0f, 0.1f, 1000.0f));
    const grass::Field& field = *ctx->fields.get(f.index - 1);
    EXPECT_EQ(field.lod.overlay_tiers, 2u);
    uint32_t overlay = 0;
    for (const auto& draw : ctx->plan.draws) {
        if (draw.tier != 1) continue;
        EXPECT_EQ(draw.uniforms.tiers[2], 1u) << "the shaders see an overlay tier";
        for (uint32_t k = 0; k < draw.instance_count; ++k) {
            const grass::TierInstance& i = ctx->plan.instances[draw.first_instance + k];
            // Its box top (terrain + blades, under 1 m) reaches above 8 m: x beyond ~14 cells.
            EXPECT_GE(i.cell[0] + i.count[0], 14u);
            overlay += 1;
        }
    }
    EXPECT_GT(overlay, 0u);
    // The overlay takes no share of the transitions: its band weighs nothing.
    EXPECT_LT(field.bands[1][1], 0.0f);
}

TEST_F(DesignMapTest, ADefaultSetupOnAHeightMapGetsUnplanarityTests) {
    uint8_t px[4] = {0, 255, 0, 255};
    grass_field_desc d = field_desc(8);
    const grass_field_id flat = make_field(d);
    EXPECT_EQ(ctx->fields.get(flat.index - 1)->lod.test_count, uint32_t(GRASS_DEFAULT_LOD_TEST_COUNT));
    d.maps.height = make_map(px, 2, 2, GRASS_MAP_FORMAT_R8_UNORM);
    const grass_field_id hilly = make_field(d);
    const grass::LodSetup& lod = ctx->fields.get(hilly.index - 1)->lod;
    EXPECT_EQ(lod.test_count, uint32_t(GRASS_DEFAULT_LOD_TEST_COUNT) + 4u);
    EXPECT_EQ(lod.tests[lod.test_count - 1].kind, GRASS_LOD_TEST_UNPLANARITY);
}

} // namespace

namespace {

// Several grass types on one field (lemme 6.4.5): each has its own patch, density map and
// lod tests, and shares the field's other maps.
TEST_F(DesignMapTest, GrassTypesShareTheFieldAndKeepTheirOwnPatchDensityAndTiers) {
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 64;
    pd.seed = 9;
    const grass_patch_id flowers = make_patch(pd);
    std::vector<uint8_t> bed(16 * 16, 0);
    for (uint32_t z = 4; z < 8; ++z) {
        for (uint32_t x = 4; x < 8; ++x) bed[z * 16 + x] = 255; // flowers grow in one bed only
    }
    const uint8_t shade[4] = {100, 100, 100, 100};
    grass_tier_desc blades{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test near_band{};
    near_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    near_band.end = 1e6f;
    grass_grass_type_desc t = grass_default_grass_type_desc();
    t.patch = flowers;
    t.density_map = make_map(bed.data(), 16, 16, GRASS_MAP_FORMAT_R8_UNORM);
    t.tiers = &blades;
    t.tier_count = 1;
    t.lod_tests = &near_band;
    t.lod_test_count = 1;
    grass_field_desc d = field_desc(16);
    d.maps.ambient = make_map(shade, 2, 2, GRASS_MAP_FORMAT_R8_UNORM);
    d.tiers = &blades;
    d.tier_count = 1;
    d.lod_tests = &near_band;
    d.lod_test_count = 1;
    d.next = &t;
    const grass_field_id f = make_field(d);
    EXPECT_EQ(ctx->fields.capacity(), 2u) << "one field per grass type";
    plan(overhead(16));
    uint32_t grass_cells = 0, flower_cells = 0;
    for (const auto& draw : ctx->plan.draws) {
        const bool is_flowers = draw.patch_slot == flowers.index - 1;
        EXPECT_EQ(draw.features & (1u << grass::kMapAmbient), 1u << grass::kMapAmbient) << "the shared ambient map";
        EXPECT_EQ((draw.features >> grass::kMapDensity) & 1u, is_flowers ? 1u : 0u);
        for (uint32_t k = 0; k < draw.instance_count; ++k) {
            const grass::TierInstance& i = ctx->plan.instances[draw.first_instance + k];
            if (is_flowers) {
                EXPECT_TRUE(i.cell[0] >= 3 && i.cell[0] <= 8 && i.cell[1] >= 3 && i.cell[1] <= 8)
                    << "flowers planned outside their bed, at " << i.cell[0] << ", " << i.cell[1];
                flower_cells += 1;
            } else {
                grass_cells += 1;
            }
        }
    }
    EXPECT_EQ(grass_cells, 256u);
    EXPECT_GE(flower_cells, 16u);
    EXPECT_EQ(grass_destroy_patch(ctx, flowers), GRASS_ERROR_IN_USE) << "the second type uses it";
    // The hidden type has no id of its own.
    grass_field_id hidden = f;
    hidden.index = 2;
    hidden.generation = ctx->fields.generation(1);
    EXPECT_EQ(grass_destroy_field(ctx, hidden), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
    EXPECT_EQ(grass_destroy_patch(ctx, flowers), GRASS_SUCCESS) << "destroyed with its field";
}

TEST_F(DesignMapTest, ABadGrassTypeRefusesTheWholeFieldAndLeavesNothing) {
    grass_grass_type_desc t = grass_default_grass_type_desc();
    t.patch = patch;
    t.density = 2.0f;
    grass_field_desc d = field_desc(8);
    d.next = &t;
    grass_field_id f{};
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("grass type 1"), std::string::npos) << last_message();
    EXPECT_EQ(last_id(), GRASS_MSG_IN_GRASS_TYPE);
    ASSERT_GE(log.size(), 2u);
    EXPECT_EQ(log[log.size() - 2].level, GRASS_LOG_ERROR);
    EXPECT_EQ(log[log.size() - 2].id, GRASS_MSG_OUT_OF_RANGE) << "the error the warning points at";
    t.density = 1.0f;
    t.type = GRASS_STRUCT_TYPE_FIELD_DESC;
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_WRONG_STRUCT_TYPE);
    t.type = GRASS_STRUCT_TYPE_GRASS_TYPE_DESC;
    t.next = &t; // a loop
    EXPECT_EQ(grass_create_field(ctx, &d, &f), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ctx->fields.capacity(), 0u);
    EXPECT_EQ(f.index, 0u);
}

} // namespace
