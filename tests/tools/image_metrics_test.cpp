// grass-measure bench's image metrics (tools/measure/image_metrics.*): SSIM after Wang et al.
// 2004 (Gaussian window 11, sigma 1.5, K1 0.01, K2 0.03, L 255) and PSNR; the linear-light
// downsampling, RMS and row bands, and the accuracy measure normalised by the seed-to-seed
// error (tools/measure/accuracy.*).
#include "accuracy.hpp"
#include "image_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using grass_bench::psnr_rgba;
using grass_bench::ssim;
using grass_bench::ssim_rgba;

constexpr uint32_t kW = 64, kH = 48;

// A textured grey test image: gradients and a checkerboard, 0..255.
std::vector<double> pattern() {
    std::vector<double> v(kW * kH);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x)
            v[y * kW + x] = 40.0 + 2.0 * x + 1.5 * y + (((x / 4) + (y / 4)) % 2 ? 50.0 : 0.0);
    return v;
}

std::vector<double> with_noise(const std::vector<double>& v, double sigma, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> n(0.0, sigma);
    std::vector<double> out(v);
    for (double& x : out) x += n(rng);
    return out;
}

std::vector<uint8_t> rgba_from(const std::vector<double>& grey) {
    std::vector<uint8_t> out(grey.size() * 4);
    for (size_t i = 0; i < grey.size(); ++i) {
        const uint8_t g = uint8_t(std::lround(std::min(255.0, std::max(0.0, grey[i]))));
        out[4 * i] = out[4 * i + 1] = out[4 * i + 2] = g;
        out[4 * i + 3] = 255;
    }
    return out;
}

TEST(Ssim, IdenticalImagesScoreOne) {
    const auto a = pattern();
    EXPECT_NEAR(ssim(a.data(), a.data(), kW, kH), 1.0, 1e-12);
    const auto rgba = rgba_from(a);
    EXPECT_NEAR(ssim_rgba(rgba.data(), rgba.data(), kW, kH), 1.0, 1e-12);
}

TEST(Ssim, MoreNoiseScoresLower) {
    const auto a = pattern();
    const auto b1 = with_noise(a, 2.0, 1), b2 = with_noise(a, 8.0, 1), b3 = with_noise(a, 32.0, 1);
    const double s1 = ssim(a.data(), b1.data(), kW, kH), s2 = ssim(a.data(), b2.data(), kW, kH),
                 s3 = ssim(a.data(), b3.data(), kW, kH);
    EXPECT_LT(s1, 1.0);
    EXPECT_LT(s2, s1);
    EXPECT_LT(s3, s2);
    EXPECT_GT(s3, -1.0);
}

TEST(Ssim, BlurAndShiftScoreBelowOne) {
    const auto a = pattern();
    std::vector<double> blurred(a), shifted(a);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 1; x + 1 < kW; ++x) {
            blurred[y * kW + x] = (a[y * kW + x - 1] + a[y * kW + x] + a[y * kW + x + 1]) / 3.0;
            shifted[y * kW + x] = a[y * kW + x - 1];
        }
    EXPECT_LT(ssim(a.data(), blurred.data(), kW, kH), 0.99);
    EXPECT_LT(ssim(a.data(), shifted.data(), kW, kH), 0.9);
}

TEST(Ssim, IsSymmetric) {
    const auto a = pattern(), b = with_noise(a, 10.0, 7);
    EXPECT_DOUBLE_EQ(ssim(a.data(), b.data(), kW, kH), ssim(b.data(), a.data(), kW, kH));
}

// Flat images: no structure, so SSIM is the luminance term alone,
// (2 a b + C1) / (a^2 + b^2 + C1) with C1 = (0.01 x 255)^2, in every window.
TEST(Ssim, FlatImagesGiveTheLuminanceTerm) {
    const double va = 100.0, vb = 140.0, c1 = 2.55 * 2.55;
    const std::vector<double> a(kW * kH, va), b(kW * kH, vb);
    EXPECT_NEAR(ssim(a.data(), b.data(), kW, kH), (2 * va * vb + c1) / (va * va + vb * vb + c1), 1e-9);
}

// An inverted pattern has negative structure correlation.
TEST(Ssim, InvertedPatternScoresNegative) {
    const auto a = pattern();
    std::vector<double> inv(a);
    for (double& x : inv) x = 255.0 - x;
    EXPECT_LT(ssim(a.data(), inv.data(), kW, kH), 0.0);
}

TEST(Ssim, ImagesSmallerThanTheWindowUseOneWindow) {
    const std::vector<double> a = {10, 20, 30, 40}, b = {10, 20, 30, 40}, c = {40, 30, 20, 10};
    EXPECT_NEAR(ssim(a.data(), b.data(), 2, 2), 1.0, 1e-12);
    EXPECT_LT(ssim(a.data(), c.data(), 2, 2), 0.0);
}

TEST(Psnr, KnownValues) {
    const auto a = rgba_from(pattern());
    EXPECT_TRUE(std::isinf(psnr_rgba(a.data(), a.data(), kW, kH)));
    // Every channel of every pixel off by 4: MSE 16, PSNR = 10 log10(255^2 / 16).
    auto b = a;
    for (size_t i = 0; i < b.size(); ++i)
        if (i % 4 != 3) b[i] = uint8_t(b[i] >= 128 ? b[i] - 4 : b[i] + 4);
    EXPECT_NEAR(psnr_rgba(a.data(), b.data(), kW, kH), 10.0 * std::log10(255.0 * 255.0 / 16.0), 1e-9);
    EXPECT_DOUBLE_EQ(psnr_rgba(a.data(), b.data(), kW, kH), psnr_rgba(b.data(), a.data(), kW, kH));
}

TEST(DifferenceImage, AmplifiesAndClamps) {
    const std::vector<uint8_t> a = {10, 20, 30, 255, 0, 0, 0, 255}, b = {12, 20, 25, 0, 200, 0, 0, 255};
    const auto d = grass_bench::difference_rgba(a.data(), b.data(), 2, 1, 4.0);
    const std::vector<uint8_t> want = {8, 0, 20, 255, 255, 0, 0, 255};
    EXPECT_EQ(d, want);
}

// A 2 x 2 block of black and white is, in linear light, half white: sRGB 188, not 128.
TEST(Downsample, AveragesInLinearLight) {
    // 3 x 2 pixels: a 2 x 2 checker of black and white, and a third column (a partial block, left out).
    std::vector<uint8_t> img(4 * 3 * 2, 0);
    const uint8_t px[2][3] = {{0, 255, 9}, {255, 0, 9}};
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            for (int c = 0; c < 4; ++c) img[4 * (y * 3 + x) + c] = c == 3 ? 255 : px[y][x];
    uint32_t w = 0, h = 0;
    const auto d = grass_bench::downsample_rgba(img.data(), 3, 2, 2, &w, &h);
    ASSERT_EQ(w, 1u);
    ASSERT_EQ(h, 1u);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[0], grass_bench::linear_to_srgb8(0.5));
    EXPECT_EQ(d[0], 188);
    EXPECT_EQ(d[3], 255);
    const auto same = grass_bench::downsample_rgba(img.data(), 3, 2, 1, &w, &h);
    EXPECT_EQ(w, 3u);
    EXPECT_EQ(same, img);
}

TEST(Rms, KnownValue) {
    const auto a = rgba_from(pattern());
    auto b = a;
    for (size_t i = 0; i < b.size(); i += 4) b[i] = uint8_t(b[i] >= 128 ? b[i] - 6 : b[i] + 6); // red off by 6
    EXPECT_NEAR(grass_bench::rms_rgba(a.data(), b.data(), kW, kH), std::sqrt(36.0 / 3.0), 1e-12);
    EXPECT_EQ(grass_bench::rms_rgba(a.data(), a.data(), kW, kH), 0.0);
}

// An image: sky over the top half, and below it rows of grass green or host soil.
std::vector<uint8_t> field_image(uint32_t w, uint32_t h, double grass_share, int darken) {
    std::vector<uint8_t> img(size_t(w) * h * 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            uint8_t* p = &img[4 * (size_t(y) * w + x)];
            const bool sky = y < h / 2, grass = !sky && double(x) < grass_share * w;
            const uint8_t c[3] = {uint8_t(sky     ? 196
                                          : grass ? 60 - darken
                                                  : 62),
                                  uint8_t(sky     ? 218
                                          : grass ? 90 - darken
                                                  : 63),
                                  uint8_t(sky     ? 243
                                          : grass ? 40 - darken
                                                  : 38)};
            p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
        }
    return img;
}

TEST(RowBands, MeanColourAndGrassCoverage) {
    const uint32_t w = 40, h = 24;
    const auto img = field_image(w, h, 0.25, 0);
    const auto bands = grass_bench::row_bands(img.data(), w, h, 12);
    ASSERT_EQ(bands.size(), 12u);
    EXPECT_EQ(bands[0].coverage, 0.0); // sky
    EXPECT_DOUBLE_EQ(bands[0].mean[2], 243.0);
    EXPECT_DOUBLE_EQ(bands[11].coverage, 0.25); // a quarter of the soil is grass
    EXPECT_DOUBLE_EQ(bands[11].mean[1], 0.25 * 90 + 0.75 * 63);
    EXPECT_EQ(bands[11].y1, h);
}

// The error of a darker, thinner image against the truth, divided by a "seed" image's.
TEST(Accuracy, NormalisedBySeedToSeedError) {
    const uint32_t w = 64, h = 48;
    const auto truth = field_image(w, h, 0.5, 0);
    const auto seed = field_image(w, h, 0.4375, 0);  // another sample: a little less grass
    const auto darker = field_image(w, h, 0.5, 5);   // the same coverage, 5 levels darker
    const auto thinner = field_image(w, h, 0.25, 0); // much less grass
    const auto e_seed = grass_bench::image_error(truth.data(), seed.data(), w, h);
    const auto e_dark = grass_bench::image_error(truth.data(), darker.data(), w, h);
    const auto e_thin = grass_bench::image_error(truth.data(), thinner.data(), w, h);
    const auto e_same = grass_bench::image_error(truth.data(), truth.data(), w, h);
    for (int s = 0; s < grass_bench::kScaleCount; ++s) {
        EXPECT_EQ(e_same.rms[s], 0.0);
        EXPECT_NEAR(e_same.ssim_error[s], 0.0, 1e-12);
        EXPECT_GT(e_seed.rms[s], 0.0);
    }
    EXPECT_NEAR(e_dark.band_colour, -2.5, 1e-9); // half of the band's pixels, 5 levels darker
    EXPECT_EQ(e_dark.band_coverage, 0.0);
    EXPECT_NEAR(e_thin.band_coverage, -0.25, 1e-9);
    EXPECT_GE(e_thin.coverage_band, grass_bench::kBands / 2);
    const auto n_thin = grass_bench::normalised(e_thin, e_seed);
    EXPECT_NEAR(n_thin.band_coverage, 4.0, 1e-9); // 0.25 against the seed's 0.0625
    EXPECT_GT(n_thin.rms[0], 1.5);
    const auto n_seed = grass_bench::normalised(e_seed, e_seed);
    for (int s = 0; s < grass_bench::kScaleCount; ++s) {
        EXPECT_DOUBLE_EQ(n_seed.rms[s], 1.0);
        EXPECT_DOUBLE_EQ(n_seed.ssim_error[s], 1.0);
    }
    const auto n_same = grass_bench::normalised(e_same, e_same);
    EXPECT_EQ(n_same.rms[0], 1.0); // 0 / 0: as close as the seeds
    EXPECT_TRUE(std::isinf(grass_bench::normalised(e_seed, e_same).rms[0]));
}

} // namespace
