// Grass displacement by a height map (lemme2012 6.4.4) in every tier, and the hilltop
// overlay tier (lemme 6.4.6), in both backends.
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace grass_test {
namespace {

// A 16 x 4 cell field (4 m along x, 1 m deep) on a ramp: flat at 0 for x < 1 m, rising
// to 0.5 m at x = 3 m, flat beyond. Seen from the front and above, the lowest grass pixel
// of each column is the field's near edge (z = 0) on the terrain.
constexpr uint32_t kRampTexels = 64;
constexpr double kRampScale = 0.5; // metres
const double kEye[3] = {2.0, 3.0, -10.0};
const double kTarget[3] = {2.0, 0.25, 0.5};
constexpr float kFov = 20.0f;

double ramp_texel(uint32_t i) { return std::clamp(((i + 0.5) / kRampTexels - 0.25) / 0.5, 0.0, 1.0); }

// The map as the GPU samples it: bilinear between texel centres, clamped at the edges.
double ramp_height(double x_metres) {
    const double s = x_metres / 4.0 * kRampTexels - 0.5;
    const double i = std::floor(s);
    const double f = s - i;
    const auto at = [](double k) { return ramp_texel(uint32_t(std::clamp(k, 0.0, double(kRampTexels - 1)))); };
    return kRampScale * ((1.0 - f) * at(i) + f * at(i + 1.0));
}

class TerrainDisplacementTest : public RenderTest {
protected:
    void SetUp() override {
        // RenderTest::SetUp's band, on a smaller 4:3 target (one host, not two).
        blade_band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        blade_band.end = 60.0f;
        grass_host::TargetDesc t;
        t.width = 160;
        t.height = 120;
        start(t);
    }

    grass_map_id ramp_map() {
        std::vector<uint16_t> texels(kRampTexels * 2);
        for (uint32_t y = 0; y < 2; ++y) {
            for (uint32_t x = 0; x < kRampTexels; ++x) {
                texels[y * kRampTexels + x] = uint16_t(std::lround(ramp_texel(x) * 65535.0));
            }
        }
        grass_map_desc m = grass_default_map_desc();
        m.pixels = texels.data();
        m.width = kRampTexels;
        m.height = 2;
        m.format = GRASS_MAP_FORMAT_R16_UNORM;
        grass_map_id id{};
        EXPECT_EQ(grass_create_map(ctx, &m, &id), GRASS_SUCCESS) << log;
        return id;
    }

    static constexpr double kSkirtPx =
        3.0; // a cell's skirt on the ramp: its terrain range with the bilinear neighbours

    // The lowest grass pixel row of every column (-1: none).
    std::vector<int> bottom_rows(const grass_host::Image& image) const {
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        std::vector<int> rows(image.width, -1);
        for (uint32_t x = 0; x < image.width; ++x) {
            for (int y = int(image.height) - 1; y >= 0; --y) {
                if (is_grass(image.pixel(x, uint32_t(y)), sky)) {
                    rows[x] = y;
                    break;
                }
            }
        }
        return rows;
    }

    // Renders the field drawn by `kind` alone, flat and then on the ramp, and checks that
    // every column's lowest grass pixel moves up by the projected terrain height there.
    // `base` is the height above the ground of the tier's lowest visible grass (metres).
    // With `debug_view`, the debug view's boxes instead (on the near edge of the field).
    void check_follows_the_ramp(grass_tier_kind kind, double base, bool debug_view = false) {
        // Image instances on a height map hang skirts from their edges (down by their terrain
        // range, to close T-junction cracks; a host's terrain hides them below ground, and
        // none is drawn here): single cells keep them short, and the lowest grass may then
        // lie below the terrain by up to a skirt (kSkirtPx), never above it.
        const bool skirts = kind == GRASS_TIER_IMAGE && !debug_view;
        grass_field_desc d = solo_tier_field(16, kind, kind == GRASS_TIER_VOLUME ? 4u : 0u, skirts ? 1u : 4u);
        d.cells_z = 4;
        grass_view_desc v = view(kEye, kTarget, kFov);
        if (debug_view) v.flags = GRASS_VIEW_FLAG_DEBUG_CELLS;
        const grass_field_id flat = make_field(d);
        const auto image_flat = render(v);
        ASSERT_EQ(grass_destroy_field(ctx, flat), GRASS_SUCCESS);
        d.maps.height = ramp_map();
        d.maps.height_scale = float(kRampScale);
        make_field(d);
        const auto image_ramp = render(v);
        const std::string tag =
            backend_name(GetParam()) + "." + std::to_string(int(kind)) + (debug_view ? ".debug" : "");
        save(image_flat, tag + ".flat");
        save(image_ramp, tag + ".ramp");
        const std::vector<int> flat_rows = bottom_rows(image_flat), ramp_rows = bottom_rows(image_ramp);

        // Which world x each column sees on the near edge (0.15 m in from the field's sides).
        const uint32_t w = image_ramp.width, h = image_ramp.height;
        std::vector<double> column_x(w, -1.0);
        for (double x = 0.15; x <= 3.85; x += 0.001) {
            const double p[3] = {x, 0.0, 0.0};
            double px = 0.0, py = 0.0;
            ASSERT_TRUE(project_point(kEye, kTarget, kFov, w, h, p, &px, &py));
            if (px >= 1.0 && px < w - 1.0) column_x[uint32_t(px)] = x;
        }
        int columns = 0, close = 0, exact = 0, flat_on_ground = 0;
        double worst = 0.0, raised = 0.0;
        for (uint32_t c = 0; c < w; ++c) {
            const double x = column_x[c];
            if (x < 0.0 || flat_rows[c] < 0) continue;
            ++columns;
            const double flat_p[3] = {x, base, 0.0}, ramp_p[3] = {x, base + ramp_height(x), 0.0};
            double px = 0.0, flat_y = 0.0, ramp_y = 0.0;
            project_point(kEye, kTarget, kFov, w, h, flat_p, &px, &flat_y);
            project_point(kEye, kTarget, kFov, w, h, ramp_p, &px, &ramp_y);
            // The flat field's lowest grass sits on the ground line (a pixel whose centre is
            // just above it), give or take a thin root missing a pixel centre.
            const double flat_error = flat_y - (flat_rows[c] + 0.5);
            flat_on_ground += flat_error > -1.0 && flat_error < 2.5;
            // On the ramp it moves up by the projected height.
            const double expected = flat_rows[c] + (ramp_y - flat_y);
            const double error = ramp_rows[c] < 0 ? 1e9 : ramp_rows[c] - expected;
            // Skirts only lower the lowest grass (rows grow downwards: a positive error).
            const double e = skirts && error > 0.0 ? std::max(0.0, error - kSkirtPx) : error;
            close += std::abs(e) <= 1.5;
            exact += std::abs(e) <= 0.75;
            worst = std::max(worst, std::abs(e));
            raised = std::max(raised, flat_y - ramp_y);
        }
        std::printf(
            "[ measured ] %s tier %d%s: %d columns, %d within 1.5 px of the ramp, %d within 0.75 px, worst %.1f px, "
            "%d flat rows on the ground line; the ramp rises %.1f px\n",
            backend_name(GetParam()).c_str(), int(kind), debug_view ? " (debug view)" : "", columns, close, exact,
            worst, flat_on_ground, raised);
        ASSERT_GT(columns, int(w) / (debug_view ? 3 : 2)); // the debug boxes leave gaps
        ASSERT_GT(raised, 10.0) << "the ramp must show";
        EXPECT_GE(close, columns * 9 / 10) << "the grass follows the terrain";
        EXPECT_GE(exact, columns * 2 / 3);
        EXPECT_GE(flat_on_ground, columns * 9 / 10) << "(the flat field itself stands on the ground line)";
    }
};

TEST_P(TerrainDisplacementTest, BladeRootsSitOnTheTerrain) { check_follows_the_ramp(GRASS_TIER_GEOMETRY, 0.0); }

TEST_P(TerrainDisplacementTest, TheVolumeTierStandsOnTheTerrain) { check_follows_the_ramp(GRASS_TIER_VOLUME, 0.0); }

TEST_P(TerrainDisplacementTest, TheImageTierLiesOnTheTerrain) {
    // The quad floats half the slice height (about 0.1 m) above the ground.
    check_follows_the_ramp(GRASS_TIER_IMAGE, 0.1);
}

// The debug view's boxes lie on the terrain too (here those of the image tier's macro-cells,
// 2 cm above the ground, inset from the field's near edge by 2 cm).
TEST_P(TerrainDisplacementTest, TheDebugViewsBoxesLieOnTheTerrain) {
    check_follows_the_ramp(GRASS_TIER_IMAGE, 0.02, true);
}

// A ridge seen from afar and from below its crest: 32 x 8 cells of 1 m; the terrain rises
// along z to a 4 m crest at z = 4 m and falls. The image tier flattens the grass on the
// crest into its quads; the hilltop overlay tier (a volume tier with a HILLTOP test) adds the
// blades' silhouette above them.
class RidgeTest : public TerrainDisplacementTest {
protected:
    grass_tier_desc tiers_[2] = {{GRASS_TIER_IMAGE, 0}, {GRASS_TIER_VOLUME, 2}};
    grass_lod_test tests_[4] = {};
    grass_view_desc view_{};

    // The ridge's field: the image tier alone, and with `overlay` the hilltop overlay tier.
    grass_field_desc ridge_field(grass_map_id hill, bool overlay) {
        tests_[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests_[0].tier = 0;
        tests_[0].end = INFINITY;
        tests_[1].kind = GRASS_LOD_TEST_MACRO_CELL;
        tests_[1].tier = 0;
        tests_[1].max_macro_cells = 1;
        tests_[2].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests_[2].tier = 1;
        tests_[2].end = INFINITY;
        tests_[3].kind = GRASS_LOD_TEST_HILLTOP;
        tests_[3].tier = 1;
        grass_field_desc d = grass_default_field_desc();
        d.patch = patch;
        d.cell_size = 1.0;
        d.cells_x = 32;
        d.cells_z = 8;
        d.tiers = tiers_;
        d.lod_tests = tests_;
        d.tier_count = overlay ? 2 : 1;
        d.lod_test_count = overlay ? 4 : 2;
        d.maps.height = hill;
        d.maps.height_scale = 4.0f;
        return d;
    }

    grass_map_id ridge_map() {
        constexpr uint32_t kRows = 64;
        std::vector<uint16_t> texels(2 * kRows);
        for (uint32_t y = 0; y < kRows; ++y) {
            const double v = (y + 0.5) / kRows;
            texels[2 * y] = texels[2 * y + 1] = uint16_t(std::lround(std::sin(3.141592653589793 * v) * 65535.0));
        }
        grass_map_desc m = grass_default_map_desc();
        m.pixels = texels.data();
        m.width = 2;
        m.height = kRows;
        m.format = GRASS_MAP_FORMAT_R16_UNORM;
        grass_map_id hill{};
        EXPECT_EQ(grass_create_map(ctx, &m, &hill), GRASS_SUCCESS) << log;
        const double eye[3] = {16.0, 2.0, -40.0}, target[3] = {16.0, 3.5, 4.0};
        view_ = view(eye, target, 10.0f);
        return hill;
    }

    // The silhouette: the highest grass pixel row of a column (the image's height: none).
    int top_row(const grass_host::Image& image, uint32_t x) const {
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        for (uint32_t y = 0; y < image.height; ++y) {
            if (is_grass(image.pixel(x, y), sky)) return int(y);
        }
        return int(image.height);
    }
};

TEST_P(RidgeTest, TheHilltopOverlayRaisesTheSilhouette) {
    const grass_map_id hill = ridge_map();
    const grass_field_id image_only = make_field(ridge_field(hill, false));
    const auto without = render(view_);
    ASSERT_EQ(grass_destroy_field(ctx, image_only), GRASS_SUCCESS);
    make_field(ridge_field(hill, true));
    const auto with = render(view_);
    grass_frame_stats stats{};
    ASSERT_EQ(grass_get_frame_stats(ctx, &stats), GRASS_SUCCESS);
    save(without, backend_name(GetParam()) + ".image_only");
    save(with, backend_name(GetParam()) + ".overlay");
    EXPECT_GT(stats.instances[GRASS_TIER_VOLUME], 0u) << "the overlay draws the cells on the crest";

    int columns = 0, higher = 0, lower = 0;
    double rise = 0.0;
    for (uint32_t x = 0; x < with.width; ++x) {
        const int a = top_row(without, x), b = top_row(with, x);
        if (a >= int(without.height)) continue;
        ++columns;
        rise += a - b;
        higher += b <= a - 1;
        lower += b > a + 1;
    }
    rise /= std::max(columns, 1);
    std::printf("[ measured ] %s: the overlay raises the silhouette by %.1f px on average; %d of %d columns higher\n",
                backend_name(GetParam()).c_str(), rise, higher, columns);
    ASSERT_GT(columns, int(with.width) * 9 / 10) << "the crest spans the view";
    EXPECT_GE(rise, 1.5); // the tips of the slices' tallest blades: about half the blade height
    EXPECT_GE(higher, columns * 3 / 4);
    EXPECT_EQ(lower, 0) << "the overlay only adds grass";
}

// Hill silhouettes keep the grass's height (issue 12): the crest with the overlay stands as
// high as blades everywhere, column by column, within a row of what another patch and
// mirror seed of the blades differ by; the image tier alone (the control) stands lower.
TEST_P(RidgeTest, TheHilltopOverlaysSilhouetteStandsAsHighAsTheBlades) {
    const grass_map_id hill = ridge_map();
    grass_patch_desc pd = grass_default_patch_desc();
    pd.seed = 2;
    grass_patch_id other{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &other), GRASS_SUCCESS) << log;
    const auto draw = [&](grass_field_desc d) {
        const grass_field_id f = make_field(d);
        grass_host::Image image = render(view_);
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        return image;
    };
    grass_field_desc blades = ridge_field(hill, false);
    blades.tiers = &blade_tier; // one geometry tier over every distance (RenderTest's band)
    blades.tier_count = 1;
    blades.lod_tests = &blade_band;
    blades.lod_test_count = 1;
    blade_band.end = INFINITY;
    const grass_host::Image truth = draw(blades);
    blades.patch = other;
    blades.mirror_seed = 1;
    const grass_host::Image seed2 = draw(blades);
    const grass_host::Image overlay = draw(ridge_field(hill, true));
    const grass_host::Image image_only = draw(ridge_field(hill, false));
    save(truth, backend_name(GetParam()) + ".blades");
    save(seed2, backend_name(GetParam()) + ".blades_seed2");
    save(overlay, backend_name(GetParam()) + ".overlay");
    double seed_offset = 0.0, overlay_offset = 0.0, image_offset = 0.0;
    int columns = 0;
    for (uint32_t x = 0; x < truth.width; ++x) {
        const int a = top_row(truth, x);
        if (a >= int(truth.height)) continue;
        ++columns;
        seed_offset += top_row(seed2, x) - a; // rows: positive = lower than the truth's
        overlay_offset += top_row(overlay, x) - a;
        image_offset += top_row(image_only, x) - a;
    }
    ASSERT_GT(columns, int(truth.width) * 9 / 10) << "the crest spans the view";
    seed_offset /= columns;
    overlay_offset /= columns;
    image_offset /= columns;
    std::printf("[ measured ] %s: the crest's top row, mean over %d columns: another seed %+.2f rows, the overlay "
                "%+.2f, the image tier alone %+.2f from the blades' (positive: lower)\n",
                backend_name(GetParam()).c_str(), columns, seed_offset, overlay_offset, image_offset);
    EXPECT_LE(std::fabs(overlay_offset), std::fabs(seed_offset) + 1.0);
    EXPECT_GT(image_offset, std::fabs(seed_offset) + 1.0) << "the control: a flat crest stands lower";
}

INSTANTIATE_TEST_SUITE_P(Backends, TerrainDisplacementTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });
INSTANTIATE_TEST_SUITE_P(Backends, RidgeTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
