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
// separates it from the background), over all its rows and over the far two thirds of them:
//   geometry coverage 0.196, (74.5, 99.6, 46.0), far (81.7, 108.3, 50.8)
//   volume   coverage 0.196, (75.3, 100.5, 46.4), far (81.6, 108.2, 50.8): 0.9 levels lighter,
//            0.1 over the far rows (7.0 darker before partly covered texels kept their own
//            colour, slice_mips.cpp bleed_colours; 2.3 lighter, 1.3 over the far rows, before
//            the colour was looked up at the level of the ray's descent, volume.frag;
//            SliceColourTest compares it band by band)
//   image    coverage 0.134, (82.8, 109.9, 51.5) in every row: 1.6 levels from the blades'
//            far rows and 1.7 from the volume's (0.2 while the volume's far rows were 1.3
//            lighter than the blades: the volume moved to the blades). Before: 8.9 darker
//            than the volume while the horizontal slice's colour was the view from above,
//            with its darker lower blades and bases; 3.2 lighter (over all rows) once baked as a grazing ray sees it; 4.6
//            darker than the volume's far rows while its normals were those seen from above
//            (slice_baker.cpp apply_grazing: now those seen grazing, per heading). The image
//            tier is compared over the far rows only: the nearest third holds the field's near
//            edge (the front blades' dark bases seen from the side), which a flat slice does not
//            have, as it has no blades standing above the far edge (less coverage).
// The slices' normals keep their spread and the magnitudes of their components across the
// slice (lighting.glsl, grass_lighting_lobes); lit with one averaged normal, a sun from
// the side left the volume 19 levels darker than the blades, then 2. The rest was albedo:
// unlit (ambient 1, no sun, no AO) the volume was 7.5 levels darker, from the colour bled
// into partly covered texels (fixed).
struct Tolerance {
    double colour;   // largest channel difference of the mean colour to geometry's, levels
    double coverage; // relative difference of the coverage to geometry's
};
constexpr Tolerance kVolume{2.0, 0.05};
constexpr Tolerance kImage{3.0, 0.35}; // its colour over the far rows
constexpr double kVolumeToImage = 2.0; // levels, over the far rows (see above)

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
    auto cover = [&](int k, uint32_t x, uint32_t y) {
        double c = 0.0;
        for (int ch = 0; ch < 3; ++ch)
            c += 1.0 - (linear(images[1][k].pixel(x, y)[ch]) - linear(images[0][k].pixel(x, y)[ch]));
        return std::clamp(c / 3.0, 0.0, 1.0);
    };
    // The grass's rows in the blades' picture; the far two thirds of them are what the image
    // tier stands for (the nearest third holds the field's near edge, the front blades seen
    // from the side down to their dark bases, which a flat slice does not have).
    uint32_t first = images[0][0].height, last = 0;
    for (uint32_t y = 0; y < images[0][0].height; ++y) {
        double row = 0.0;
        for (uint32_t x = 0; x < images[0][0].width; ++x) row += cover(0, x, y);
        if (row > 1.0) first = std::min(first, y), last = std::max(last, y);
    }
    ASSERT_LT(first, last);
    const uint32_t far_end = first + (last - first) * 2 / 3;
    double coverage[3] = {0, 0, 0}, mean[3][3] = {}, far_mean[3][3] = {};
    for (int k = 0; k < 3; ++k) {
        const grass_host::Image& black = images[0][k];
        double sum[3] = {0, 0, 0}, covered = 0.0, far_sum[3] = {0, 0, 0}, far_covered = 0.0;
        for (uint32_t y = 0; y < black.height; ++y) {
            for (uint32_t x = 0; x < black.width; ++x) {
                const double c = cover(k, x, y);
                covered += c;
                for (int ch = 0; ch < 3; ++ch) sum[ch] += linear(black.pixel(x, y)[ch]);
                if (y > far_end) continue;
                far_covered += c;
                for (int ch = 0; ch < 3; ++ch) far_sum[ch] += linear(black.pixel(x, y)[ch]);
            }
        }
        ASSERT_GT(covered, 500.0) << names[k];
        ASSERT_GT(far_covered, 200.0) << names[k];
        coverage[k] = covered / double(black.width * black.height);
        for (int ch = 0; ch < 3; ++ch) mean[k][ch] = srgb(sum[ch] / covered);
        for (int ch = 0; ch < 3; ++ch) far_mean[k][ch] = srgb(far_sum[ch] / far_covered);
        std::printf("[ measured ] %s %-8s coverage %.3f, mean sRGB of the grass (%.1f, %.1f, %.1f), of its far two "
                    "thirds (%.1f, %.1f, %.1f)\n",
                    backend_name(GetParam()).c_str(), names[k], coverage[k], mean[k][0], mean[k][1], mean[k][2],
                    far_mean[k][0], far_mean[k][1], far_mean[k][2]);
    }
    const Tolerance* tolerance[3] = {nullptr, &kVolume, &kImage};
    for (int k = 1; k < 3; ++k) {
        // The image tier against the far two thirds (above), the volume against the whole.
        const double(&m)[3][3] = k == 2 ? far_mean : mean;
        double diff = 0.0;
        for (int c = 0; c < 3; ++c) diff = std::max(diff, std::fabs(m[k][c] - m[0][c]));
        EXPECT_LT(diff, tolerance[k]->colour) << names[k] << ": largest channel difference of the mean colour";
        EXPECT_NEAR(coverage[k], coverage[0], tolerance[k]->coverage * coverage[0]) << names[k];
    }
    // The image tier follows the volume tier: where they meet, their colours agree closely.
    double step = 0.0;
    for (int c = 0; c < 3; ++c) step = std::max(step, std::fabs(far_mean[2][c] - far_mean[1][c]));
    EXPECT_LT(step, kVolumeToImage) << "largest channel difference of the image tier's mean colour to the volume's";
}

INSTANTIATE_TEST_SUITE_P(Backends, TierLightingTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
