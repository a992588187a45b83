#include "accuracy.hpp"

#include "image_metrics.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace grass_bench {

ImageError image_error(const uint8_t* truth, const uint8_t* image, uint32_t width, uint32_t height) {
    ImageError e;
    for (int s = 0; s < kScaleCount; ++s) {
        uint32_t w = width, h = height;
        const std::vector<uint8_t> t = downsample_rgba(truth, width, height, kScales[s], &w, &h);
        const std::vector<uint8_t> i = downsample_rgba(image, width, height, kScales[s], &w, &h);
        e.ssim_error[s] = 1.0 - ssim_rgba(t.data(), i.data(), w, h);
        e.rms[s] = rms_rgba(t.data(), i.data(), w, h);
    }
    const std::vector<RowBand> bt = row_bands(truth, width, height, kBands),
                               bi = row_bands(image, width, height, kBands);
    for (uint32_t k = 0; k < bt.size(); ++k) {
        const double colour =
            (bi[k].mean[0] + bi[k].mean[1] + bi[k].mean[2] - bt[k].mean[0] - bt[k].mean[1] - bt[k].mean[2]) / 3.0;
        const double coverage = bi[k].coverage - bt[k].coverage;
        if (std::fabs(colour) > std::fabs(e.band_colour)) e.band_colour = colour, e.colour_band = k;
        if (std::fabs(coverage) > std::fabs(e.band_coverage)) e.band_coverage = coverage, e.coverage_band = k;
    }
    return e;
}

namespace {
double ratio(double e, double seed) {
    if (seed > 0) return e / seed;
    return e == 0 ? 1.0 : std::numeric_limits<double>::infinity();
}
} // namespace

ImageError normalised(const ImageError& e, const ImageError& seed) {
    ImageError n = e;
    for (int s = 0; s < kScaleCount; ++s) {
        n.ssim_error[s] = ratio(e.ssim_error[s], seed.ssim_error[s]);
        n.rms[s] = ratio(e.rms[s], seed.rms[s]);
    }
    n.band_colour = ratio(std::fabs(e.band_colour), std::fabs(seed.band_colour));
    n.band_coverage = ratio(std::fabs(e.band_coverage), std::fabs(seed.band_coverage));
    return n;
}

} // namespace grass_bench
