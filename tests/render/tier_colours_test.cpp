// The debug view shows each tier where its lod tests put it: red geometry near, yellow
// volume, blue image far, in both backends.
#include "render_fixture.hpp"

#include <cmath>

namespace grass_test {
namespace {

class TierColoursTest : public RenderTest {};

enum class Hue { red, yellow, blue, other };

Hue hue(const uint8_t* p) {
    const int r = p[0], g = p[1], b = p[2];
    if (r > 2 * g && r > 2 * b) return Hue::red;
    if (r > 2 * b && g > 2 * b && g * 2 > r) return Hue::yellow;
    if (b > 2 * r && b > g) return Hue::blue;
    return Hue::other;
}

TEST_P(TierColoursTest, TierColoursAppearAtTheDistancesTheLodTestsGive) {
    // 16 m x 64 m; geometry to 3 m, volume 3..10 m in macro-cells of up to 8 cells, image
    // beyond in macro-cells of up to 64. Exact edges, no transitions: one tier per cell.
    grass_tier_desc tiers[3] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 4}, {GRASS_TIER_IMAGE, 0}};
    grass_lod_test tests[5] = {};
    tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[0].tier = 0;
    tests[0].end = 3.0f;
    tests[1].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[1].tier = 1;
    tests[1].begin = 3.0f;
    tests[1].end = 10.0f;
    tests[2].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[2].tier = 1;
    tests[2].max_macro_cells = 8;
    tests[3].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[3].tier = 2;
    tests[3].begin = 10.0f;
    tests[3].end = INFINITY;
    tests[4].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[4].tier = 2;
    tests[4].max_macro_cells = 64;
    grass_field_desc d = grass_default_field_desc();
    d.patch = patch;
    d.cells_x = 64;
    d.cells_z = 256;
    d.tiers = tiers;
    d.tier_count = 3;
    d.lod_tests = tests;
    d.lod_test_count = 5;
    make_field(d);

    const double eye[3] = {8.0, 1.5, 0.5}, target[3] = {8.0, 0.0, 6.0};
    const float fov = 60.0f;
    grass_view_desc v = view(eye, target, fov);
    v.flags = GRASS_VIEW_FLAG_DEBUG_CELLS;
    const auto image = render(v);
    save(image, backend_name(GetParam()));

    // Down the middle column: the distance to the ground point each pixel sees.
    double f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& x : f) x /= fl;
    const double u[3] = {0.0, f[2], -f[1]}; // up in the image: r = (-1, 0, 0) x f
    const double t = std::tan(fov * 3.141592653589793 / 360.0);
    int checked[3] = {0, 0, 0}, gaps[3] = {0, 0, 0};
    for (uint32_t y = 0; y < image.height; ++y) {
        const double sy = (1.0 - 2.0 * (y + 0.5) / image.height) * t;
        const double dir[3] = {f[0] + sy * u[0], f[1] + sy * u[1], f[2] + sy * u[2]};
        if (dir[1] >= 0.0) continue;
        const double s = -eye[1] / dir[1];
        const double dist = s * std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        if (eye[2] + s * dir[2] > 64.0) continue; // past the field
        // The majority hue of the row's middle (the debug boxes are inset: gaps show the sky).
        int votes[4] = {0, 0, 0, 0};
        for (uint32_t x = image.width / 2 - 24; x < image.width / 2 + 24; ++x) votes[int(hue(image.pixel(x, y)))]++;
        Hue h = Hue::other;
        for (int k = 0; k < 3; ++k) {
            if (votes[k] > 24) h = Hue(k);
        }
        // Margins around the band edges: a cell's box spans about a cell and its blades.
        // A row on an inset gap between boxes shows no tier (counted, and limited below).
        const int zone = dist < 2.4 ? 0 : (dist > 3.8 && dist < 9.0) ? 1 : dist > 11.5 ? 2 : -1;
        if (zone < 0) continue;
        if (h == Hue::other) {
            gaps[zone]++;
            continue;
        }
        EXPECT_EQ(int(h), zone) << "row " << y << " at " << dist << " m";
        checked[zone]++;
    }
    for (int zone = 0; zone < 3; ++zone) {
        EXPECT_GT(checked[zone], 5) << "zone " << zone;
        EXPECT_LE(gaps[zone] * 5, checked[zone] + gaps[zone]) << "zone " << zone << ": at most 20% gap rows";
    }

    // Without the debug view every tier draws its own representation: blades near, the
    // ray-cast volume, then the horizontal slice, with grass in every zone (no gap between
    // tiers) and none beyond the field's far edge.
    v.flags = 0;
    const auto tiers_image = render(v);
    save(tiers_image, std::string(backend_name(GetParam())) + ".tiers");
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    int rows_per_zone[3] = {0, 0, 0};
    for (uint32_t y = 0; y < tiers_image.height; ++y) {
        const double sy = (1.0 - 2.0 * (y + 0.5) / tiers_image.height) * t;
        const double dir[3] = {f[0] + sy * u[0], f[1] + sy * u[1], f[2] + sy * u[2]};
        if (dir[1] >= 0.0) continue;
        const double s = -eye[1] / dir[1];
        const double dist = s * std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        const int zone = dist < 2.4 ? 0 : (dist > 3.8 && dist < 9.0) ? 1 : (dist > 11.5 && dist < 14.0) ? 2 : -1;
        if (zone < 0) continue;
        // The middle half of the row lies inside the 16 m wide field up to 14 m away.
        const double share = grass_share(tiers_image, sky, tiers_image.width / 4, y, 3 * tiers_image.width / 4, y + 1);
        EXPECT_GT(share, 0.5) << "row " << y << " at " << dist << " m (tier " << zone << ")";
        rows_per_zone[zone]++;
    }
    for (int zone = 0; zone < 3; ++zone) EXPECT_GE(rows_per_zone[zone], 2) << "zone " << zone;
}

INSTANTIATE_TEST_SUITE_P(Backends, TierColoursTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
