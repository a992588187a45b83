// Seamless transitions (boulanger2006 3.4, lemme2012 5.4) on the GPU: in a transition zone
// where the geometry and volume tiers weigh one half each, blades are counted through the
// density-threshold channel (GRASS_VIEW_FLAG_DEBUG_THRESHOLDS). A blade is drawn by one tier
// only -- the coarse tier takes the low thresholds (r <= 0.5), the blades the high ones --
// and none is lost: together the two tiers show the whole range of thresholds.
#include "render_fixture.hpp"

#include <cmath>
#include <cstdio>
#include <set>

namespace grass_test {
namespace {

class TransitionTest : public RenderTest {};

// On a single-sampled target the partition is exact with or without the crossover window
// (a blade is drawn by the tier where its opacity is at least one half): the test runs with
// no window and with a wide one.
TEST_P(TransitionTest, EachBladeIsDrawnByOneTierAndNoneIsLost) {
    for (const float window : {0.0f, 0.1f}) {
        SCOPED_TRACE("transition_window " + std::to_string(window));
        grass_host::TargetDesc t;
        t.width = t.height = 256;
        t.samples = 1; // one fragment per pixel: its code is read back exactly
        start(t);
        // Geometry to 100 m fading out from 60 m; volume from 60 m fading in to 100 m: at 80 m
        // each weighs one half.
        grass_tier_desc tiers[2] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 8}};
        grass_lod_test tests[3] = {};
        tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[0].tier = 0;
        tests[0].end = 100.0f;
        tests[0].transition_out = 40.0f;
        tests[1].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[1].tier = 1;
        tests[1].begin = 60.0f;
        tests[1].end = INFINITY;
        tests[1].transition_in = 40.0f;
        tests[2].kind = GRASS_LOD_TEST_MACRO_CELL;
        tests[2].tier = 1;
        tests[2].max_macro_cells = 1;
        grass_field_desc d = field_desc(4); // 1 m x 1 m
        d.tiers = tiers;
        d.tier_count = 2;
        d.lod_tests = tests;
        d.lod_test_count = 3;
        d.transition_window = window;
        make_field(d);
        // 80 m away, looking down at 15 degrees; a narrow lens frames the cells.
        const double elevation = 15.0 * 3.141592653589793 / 180.0;
        const double eye[3] = {0.5, 80.0 * std::sin(elevation), 0.5 - 80.0 * std::cos(elevation)};
        const double target[3] = {0.5, 0.0, 0.5};
        grass_view_desc v = view(eye, target, 0.9f);
        v.flags = GRASS_VIEW_FLAG_DEBUG_THRESHOLDS;
        const auto image = render(v);
        save(image, backend_name(GetParam()) + "_" + std::to_string(window));

        uint8_t sky[3];
        expected_sky(host->target(), sky);
        std::set<int> by_blades, by_volume;
        int pixels[2] = {0, 0};
        for (uint32_t y = 0; y < image.height; ++y) {
            for (uint32_t x = 0; x < image.width; ++x) {
                const uint8_t* p = image.pixel(x, y);
                if (p[0] == sky[0] && p[1] == sky[1] && p[2] == sky[2]) continue;
                ASSERT_TRUE(p[2] == 0 || p[2] == 128) << "pixel (" << x << ", " << y << ") blue " << int(p[2]);
                const int code = p[0] * 256 + p[1];
                ASSERT_GT(code, 0);
                (p[2] == 0 ? by_blades : by_volume).insert(code);
                pixels[p[2] == 0 ? 0 : 1]++;
            }
        }
        // The cells span 80 m +- 0.75 m: the weights there are 0.5 +- 0.02.
        const double cut = 0.5, slack = 0.025;
        int twice = 0;
        for (int code : by_blades) {
            EXPECT_GT(code / 65535.0, cut - slack) << "a blade of the low half drawn as geometry";
            twice += by_volume.count(code) != 0 && std::fabs(code / 65535.0 - cut) > slack;
        }
        for (int code : by_volume)
            EXPECT_LE(code / 65535.0, cut + slack) << "a blade of the high half drawn in the volume";
        EXPECT_EQ(twice, 0) << "blades drawn by both tiers";
        // None lost: both halves of the range appear, in bins of 0.05.
        for (int bin = 0; bin < 20; ++bin) {
            const double lo = bin * 0.05, hi = lo + 0.05;
            const std::set<int>& tier = hi <= cut ? by_volume : by_blades;
            if (std::fabs(lo - cut) < 1e-9 || std::fabs(hi - cut) < 1e-9) continue; // the bins at the cut
            bool seen = false;
            for (int code : tier) seen = seen || (code / 65535.0 > lo && code / 65535.0 <= hi);
            EXPECT_TRUE(seen) << "no blade with a threshold in (" << lo << ", " << hi << "]";
        }
        std::printf("[ measured ] %s, window %.2f: %zu thresholds drawn as blades (%d px), %zu in the volume (%d px)\n",
                    backend_name(GetParam()).c_str(), window, by_blades.size(), pixels[0], by_volume.size(), pixels[1]);
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, TransitionTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
