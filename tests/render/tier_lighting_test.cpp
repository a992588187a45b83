// Consistent lighting across tiers (lemme2012 6.4.3): the same distant cells drawn by each
// tier alone have about the same mean colour and coverage, so a cell does not jump in
// colour when it changes tier. The test prints what it measures.
#include "render_fixture.hpp"

#include <cmath>
#include <cstdio>

namespace grass_test {
namespace {

// Measured (docs/three-tiers.md, both backends alike), as limits against regressions; the
// goal of the three-tier issue is tighter and not reached yet:
//   geometry coverage 0.211, mean sRGB (82.6, 107.0, 64.0)
//   volume   coverage 0.214, mean sRGB (66.2, 89.4, 52.6): 17.6 levels darker
//   image    coverage 0.142, mean sRGB (118.8, 149.3, 76.8): 42.3 levels lighter; a flat
//            slice has no blades standing above the field's far edge, hence less coverage
struct Tolerance {
    double colour;   // largest channel difference of the mean colour to geometry's, levels
    double coverage; // relative difference of the coverage to geometry's
};
constexpr Tolerance kVolume{20.0, 0.10};
constexpr Tolerance kImage{48.0, 0.35};

class TierLightingTest : public RenderTest {
protected:
    struct Look {
        double coverage = 0.0; // share of the cells' screen area covered by grass
        double mean[3] = {0, 0, 0}; // mean sRGB colour of the grass pixels
    };

    Look look_with(grass_tier_kind kind, uint32_t slices) {
        grass_tier_desc tier{kind, slices};
        grass_lod_test band{};
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.end = INFINITY;
        grass_lod_test macro{};
        macro.kind = GRASS_LOD_TEST_MACRO_CELL;
        macro.max_macro_cells = 1;
        grass_lod_test tests[2] = {band, macro};
        grass_field_desc d = field_desc(8); // 2 m x 2 m
        d.tiers = &tier;
        d.tier_count = 1;
        d.lod_tests = tests;
        d.lod_test_count = kind == GRASS_TIER_GEOMETRY ? 1 : 2;
        const grass_field_id f = make_field(d);
        // About 9 m away, 1.6 m up: "distant" cells seen at a walking-height angle.
        const double eye[3] = {1.0, 1.6, -8.0}, target[3] = {1.0, 0.0, 1.0};
        const auto image = render(view(eye, target, 14.0f));
        save(image, std::to_string(int(kind)) + "_" + std::to_string(slices));
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        Look l;
        uint8_t sky[3];
        expected_sky(host->target(), sky);
        uint64_t covered = 0;
        for (uint32_t y = 0; y < image.height; ++y) {
            for (uint32_t x = 0; x < image.width; ++x) {
                const uint8_t* p = image.pixel(x, y);
                if (!is_grass(p, sky)) continue;
                ++covered;
                for (int c = 0; c < 3; ++c) l.mean[c] += p[c];
            }
        }
        for (double& m : l.mean) m /= covered ? double(covered) : 1.0;
        l.coverage = double(covered) / (image.width * image.height);
        return l;
    }
};

TEST_P(TierLightingTest, TheSameCellsLookAlikeInEveryTier) {
    grass_host::TargetDesc t;
    t.width = t.height = 128;
    t.samples = 4;
    start(t);
    const Look geometry = look_with(GRASS_TIER_GEOMETRY, 0);
    const Look volume = look_with(GRASS_TIER_VOLUME, 8);
    const Look image = look_with(GRASS_TIER_IMAGE, 0);
    const Look* looks[3] = {&geometry, &volume, &image};
    const char* names[3] = {"geometry", "volume", "image"};
    for (int k = 0; k < 3; ++k) {
        std::printf("[ measured ] %s %-8s coverage %.3f mean sRGB (%.1f, %.1f, %.1f)\n", backend_name(GetParam()).c_str(),
                    names[k], looks[k]->coverage, looks[k]->mean[0], looks[k]->mean[1], looks[k]->mean[2]);
    }
    const Tolerance* tolerance[3] = {nullptr, &kVolume, &kImage};
    for (int k = 1; k < 3; ++k) {
        double diff = 0.0;
        for (int c = 0; c < 3; ++c) diff = std::max(diff, std::fabs(looks[k]->mean[c] - geometry.mean[c]));
        EXPECT_LT(diff, tolerance[k]->colour) << names[k] << ": largest channel difference of the mean colour";
        EXPECT_NEAR(looks[k]->coverage, geometry.coverage, tolerance[k]->coverage * geometry.coverage) << names[k];
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, TierLightingTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
