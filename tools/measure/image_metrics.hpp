// Image error metrics of grass-measure bench: SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, "Image
// quality assessment: from error visibility to structural similarity", with its reference
// parameters) on luma, PSNR on the 8-bit sRGB channels, and an amplified difference image.
// Images are RGBA8, sRGB-encoded, top row first (grass_host::Image's layout); alpha is
// ignored (the hosts' pictures are opaque).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace grass_bench {

struct SsimParams {
    int window = 11;    // Gaussian window side (odd)
    double sigma = 1.5; // its standard deviation, pixels
    double k1 = 0.01, k2 = 0.03;
    double range = 255.0; // L: the dynamic range of the values
};

// Luma of each pixel from the sRGB-encoded values (ITU-R BT.601 weights, as rgb2gray in
// Wang's MATLAB code), 0..255.
std::vector<double> luma(const uint8_t* rgba, uint32_t width, uint32_t height);

// Mean SSIM of two single-channel images of the same size: the SSIM map over every window
// that lies wholly inside the image ("valid" filtering, as Wang's ssim.m), averaged. An
// image smaller than the window is one window with uniform weights. 1 for identical images.
double ssim(const double* a, const double* b, uint32_t width, uint32_t height, const SsimParams& p = SsimParams());

// SSIM of two RGBA8 images on their luma.
double ssim_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height);

// PSNR in dB over the R, G and B channels of two RGBA8 images (peak 255); +infinity when
// they are identical.
double psnr_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height);

// sRGB-encoded 0..255 to linear 0..1, and linear 0..1 (clamped) to sRGB-encoded 0..255 (rounded).
double srgb_to_linear(double encoded);
uint8_t linear_to_srgb8(double linear);

// An RGBA8 image box-downsampled by `factor` (1 = a copy) in linear light: each output pixel
// the mean of a factor x factor block, decoded from sRGB, averaged, encoded again (what a
// multisample resolve of an sRGB target does). A partial block at the right or bottom edge is
// left out. *out_width, *out_height: the output's size.
std::vector<uint8_t> downsample_rgba(const uint8_t* rgba, uint32_t width, uint32_t height, uint32_t factor,
                                     uint32_t* out_width, uint32_t* out_height);

// Root mean square of the difference of two RGBA8 images over R, G and B, in sRGB levels.
double rms_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height);

// A grass pixel, for coverage: green exceeds both red and blue by kGrassGreenExcess sRGB
// levels or more. The hosts' soil (about 62, 63, 38) and sky (196, 218, 243) are not; lit and
// shadowed blades are (their green exceeds their red by 10 to 30 levels).
constexpr int kGrassGreenExcess = 6;
inline bool is_grass(const uint8_t* rgba_pixel) {
    return int(rgba_pixel[1]) - std::max(int(rgba_pixel[0]), int(rgba_pixel[2])) >= kGrassGreenExcess;
}

// The image cut into `count` horizontal bands of equal height (the last takes the rest):
// per band its rows, the mean sRGB colour and the share of grass pixels.
struct RowBand {
    uint32_t y0 = 0, y1 = 0; // rows y0 .. y1 - 1
    double mean[3] = {0, 0, 0};
    double coverage = 0;
};
std::vector<RowBand> row_bands(const uint8_t* rgba, uint32_t width, uint32_t height, uint32_t count);

// |a - b| per channel times `gain`, clamped to 255, alpha 255: black where equal.
std::vector<uint8_t> difference_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, double gain);

} // namespace grass_bench
