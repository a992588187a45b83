// Image error metrics of grass-measure bench: SSIM (Wang, Bovik, Sheikh, Simoncelli 2004, "Image
// quality assessment: from error visibility to structural similarity", with its reference
// parameters) on luma, PSNR on the 8-bit sRGB channels, and an amplified difference image.
// Images are RGBA8, sRGB-encoded, top row first (grass_host::Image's layout); alpha is
// ignored (the hosts' pictures are opaque).
#pragma once

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

// |a - b| per channel times `gain`, clamped to 255, alpha 255: black where equal.
std::vector<uint8_t> difference_rgba(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, double gain);

} // namespace grass_bench
