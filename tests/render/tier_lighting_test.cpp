// Consistent lighting across tiers (lemme2012 6.4.3): the same distant cells drawn by each
// tier alone have about the same mean colour and coverage, so a cell does not jump in
// colour when it changes tier. The test prints what it measures.
#include "render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grass_test {
namespace {

// Measured (GL; Vulkan within 0.3 levels and 0.001 coverage), as limits against
// regressions. Coverage and the coverage-weighted mean sRGB of the grass alone (the test
// separates it from the background):
//   geometry coverage 0.196, (74.5, 99.6, 46.0)
//   volume   coverage 0.196, (76.5, 101.9, 47.0): 2.3 levels lighter (7.0 darker before
//            partly covered texels kept their own colour, slice_mips.cpp bleed_colours;
//            SliceColourTest compares it band by band)
//   image    coverage 0.134, (78.4, 105.1, 49.5): 3.2 levels lighter than the volume tier
//            it follows in the lod setups (8.9 darker while the horizontal slice's colour
//            was the view from above, with its darker lower blades and bases; now baked as
//            a grazing ray sees it, slice_baker.cpp apply_grazing_colour). The rest: a flat
//            slice has no near field edge (the front blades' dark bases seen from the side)
//            and no blades standing above the far edge, hence also less coverage
// The slices' normals keep their spread and the magnitudes of their components across the
// slice (lighting.glsl, grass_lighting_lobes); lit with one averaged normal, a sun from
// the side left the volume 19 levels darker than the blades, then 2. The rest was albedo:
// unlit (ambient 1, no sun, no AO) the volume was 7.5 levels darker, from the colour bled
// into partly covered texels (fixed).
struct Tolerance {
    double colour;   // largest channel difference of the mean colour to geometry's, levels
    double coverage; // relative difference of the coverage to geometry's
};
constexpr Tolerance kVolume{10.0, 0.05};
constexpr Tolerance kImage{7.0, 0.35};
constexpr double kVolumeToImage = 3.5; // levels (9.5 while the image tier was darker; see above)

class TierLightingTest : public RenderTest {
protected:
    grass_host::Image render_with(grass_tier_kind kind, uint32_t slices) {
        const grass_field_desc d = solo_tier_field(8, kind, slices, 1); // 2 m x 2 m
        const grass_field_id f = make_field(d);
        // About 9 m away, 1.6 m up: "distant" cells seen at a walking-height angle.
        const double eye[3] = {1.0, 1.6, -8.0}, target[3] = {1.0, 0.0, 1.0};
        const auto image = render(view(eye, target, 14.0f));
        save(image, std::to_string(int(kind)) + "_" + std::to_string(slices));
        EXPECT_EQ(grass_destroy_field(ctx, f), GRASS_SUCCESS);
        return image;
    }
};

TEST_P(TierLightingTest, TheSameCellsLookAlikeInEveryTier) {
    // Each tier is rendered over a black and over a white background. The resolve mixes a
    // pixel's samples in linear RGB, so a pixel that the grass covers by c with colour g
    // reads c g over black and c g + (1 - c) over white: c = 1 - (white - black), and the
    // grass's own colour follows without the background mixed in. Its mean, weighted by
    // coverage, is the colour of the cells as a viewer sees them, whatever each tier's
    // sample coverage.
    const char* names[3] = {"geometry", "volume", "image"};
    const grass_tier_kind kinds[3] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_IMAGE};
    const uint32_t slices[3] = {0, 8, 0};
    grass_host::Image images[2][3];
    for (int b = 0; b < 2; ++b) {
        start(black_or_white_target(b == 1));
        for (int k = 0; k < 3; ++k) images[b][k] = render_with(kinds[k], slices[k]);
    }
    auto linear = [](uint8_t byte) {
        const double c = byte / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    auto srgb = [](double l) { return 255.0 * (l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055); };
    double coverage[3] = {0, 0, 0}, mean[3][3] = {};
    for (int k = 0; k < 3; ++k) {
        const grass_host::Image& black = images[0][k];
        const grass_host::Image& white = images[1][k];
        double sum[3] = {0, 0, 0}, covered = 0.0;
        for (uint32_t y = 0; y < black.height; ++y) {
            for (uint32_t x = 0; x < black.width; ++x) {
                double c = 0.0;
                for (int ch = 0; ch < 3; ++ch)
                    c += 1.0 - (linear(white.pixel(x, y)[ch]) - linear(black.pixel(x, y)[ch]));
                c = std::clamp(c / 3.0, 0.0, 1.0);
                covered += c;
                for (int ch = 0; ch < 3; ++ch) sum[ch] += linear(black.pixel(x, y)[ch]);
            }
        }
        ASSERT_GT(covered, 500.0) << names[k];
        coverage[k] = covered / double(black.width * black.height);
        for (int ch = 0; ch < 3; ++ch) mean[k][ch] = srgb(sum[ch] / covered);
        std::printf("[ measured ] %s %-8s coverage %.3f, mean sRGB of the grass (%.1f, %.1f, %.1f)\n",
                    backend_name(GetParam()).c_str(), names[k], coverage[k], mean[k][0], mean[k][1], mean[k][2]);
    }
    const Tolerance* tolerance[3] = {nullptr, &kVolume, &kImage};
    for (int k = 1; k < 3; ++k) {
        double diff = 0.0;
        for (int c = 0; c < 3; ++c) diff = std::max(diff, std::fabs(mean[k][c] - mean[0][c]));
        EXPECT_LT(diff, tolerance[k]->colour) << names[k] << ": largest channel difference of the mean colour";
        EXPECT_NEAR(coverage[k], coverage[0], tolerance[k]->coverage * coverage[0]) << names[k];
    }
    // The image tier follows the volume tier: where they meet, their colours agree closely.
    double step = 0.0;
    for (int c = 0; c < 3; ++c) step = std::max(step, std::fabs(mean[2][c] - mean[1][c]));
    EXPECT_LT(step, kVolumeToImage) << "largest channel difference of the image tier's mean colour to the volume's";
}

INSTANTIATE_TEST_SUITE_P(Backends, TierLightingTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
