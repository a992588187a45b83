// grass-measure bench's accuracy measure (docs/quality.md, "How accurate"): an image's error
// against the ground truth, at three scales, and that error divided by what another sample
// of the ground truth scores (the seed-to-seed error): 1.0 = as close as the reference
// rendered with other seeds.
//
// At each scale (full resolution, x2 and x4 box-downsampled in linear light) two errors:
// 1 - SSIM on luma (image_metrics.hpp) and the RMS difference over R, G, B in sRGB levels. Per
// row band (kBands bands of equal height): the mean-colour difference (mean over R, G, B of
// the image's band mean minus the truth's, sRGB levels; negative = darker) and the coverage
// difference (share of grass pixels, image minus truth); the error reports the band where
// each is largest in size.
#pragma once

#include <cstdint>

namespace grass_bench {

constexpr int kScaleCount = 3;
constexpr uint32_t kScales[kScaleCount] = {1, 2, 4};
constexpr uint32_t kBands = 12;

struct ImageError {
    double ssim_error[kScaleCount] = {0, 0, 0};  // 1 - SSIM
    double rms[kScaleCount] = {0, 0, 0};         // sRGB levels
    double band_colour = 0;                      // signed, sRGB levels, the largest in size
    double band_coverage = 0;                    // signed share, the largest in size
    uint32_t colour_band = 0, coverage_band = 0; // which band (0 = top)
};

// The error of `image` against `truth` (RGBA8 sRGB, the same size, top row first).
ImageError image_error(const uint8_t* truth, const uint8_t* image, uint32_t width, uint32_t height);

// e's errors divided by the seed-to-seed error `seed` (the band figures by their sizes);
// +infinity where the seed-to-seed error is 0 and e's is not, 1 where both are 0.
ImageError normalised(const ImageError& e, const ImageError& seed);

} // namespace grass_bench
