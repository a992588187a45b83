#include "coverage_colour.hpp"

#include <algorithm>
#include <cmath>

namespace grass_host {

double srgb_to_linear(uint8_t byte) {
    const double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb_levels(double l) {
    return 255.0 * (l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055);
}

double CoveragePair::coverage(uint32_t x, uint32_t y) const {
    double c = 0.0;
    for (int ch = 0; ch < 3; ++ch) {
        c += 1.0 - (srgb_to_linear(white.pixel(x, y)[ch]) - srgb_to_linear(black.pixel(x, y)[ch]));
    }
    return std::clamp(c / 3.0, 0.0, 1.0);
}

std::vector<BandColour> band_colours(const CoveragePair& p, uint32_t first, uint32_t last, int bands) {
    std::vector<BandColour> out(size_t(std::max(bands, 1)));
    std::vector<double> sum(out.size() * 3, 0.0);
    if (last <= first) return out;
    for (uint32_t y = first; y < last; ++y) {
        const size_t band = std::min(out.size() - 1, size_t(y - first) * out.size() / (last - first));
        for (uint32_t x = 0; x < p.black.width; ++x) {
            out[band].coverage += p.coverage(x, y);
            for (int ch = 0; ch < 3; ++ch) sum[band * 3 + ch] += srgb_to_linear(p.black.pixel(x, y)[ch]);
        }
    }
    for (size_t k = 0; k < out.size(); ++k) {
        for (int ch = 0; ch < 3; ++ch) {
            out[k].colour[ch] = out[k].coverage > 0.0 ? linear_to_srgb_levels(sum[k * 3 + ch] / out[k].coverage) : 0.0;
        }
    }
    return out;
}

std::vector<RowSpan> row_spans(const CoveragePair& p, uint32_t first, uint32_t last, double threshold) {
    std::vector<RowSpan> spans(last > first ? last - first : 0);
    for (uint32_t y = first; y < last; ++y) {
        RowSpan& s = spans[y - first];
        for (uint32_t x = 0; x < p.black.width; ++x) {
            if (p.coverage(x, y) <= threshold) continue;
            if (s.end == 0) s.begin = x;
            s.end = x + 1;
        }
    }
    return spans;
}

std::vector<BandColour> composite_band_colours(const CoveragePair& p, uint32_t first, const std::vector<RowSpan>& spans,
                                               const double ground[3], int bands) {
    std::vector<BandColour> out(size_t(std::max(bands, 1)));
    std::vector<double> sum(out.size() * 3, 0.0);
    for (size_t r = 0; r < spans.size(); ++r) {
        const size_t band = std::min(out.size() - 1, r * out.size() / spans.size());
        const uint32_t y = first + uint32_t(r);
        for (uint32_t x = spans[r].begin; x < spans[r].end; ++x) {
            const double c = p.coverage(x, y);
            out[band].coverage += 1.0;
            for (int ch = 0; ch < 3; ++ch) {
                sum[band * 3 + ch] += srgb_to_linear(p.black.pixel(x, y)[ch]) + (1.0 - c) * ground[ch];
            }
        }
    }
    for (size_t k = 0; k < out.size(); ++k) {
        for (int ch = 0; ch < 3; ++ch) {
            out[k].colour[ch] = out[k].coverage > 0.0 ? linear_to_srgb_levels(sum[k * 3 + ch] / out[k].coverage) : 0.0;
        }
    }
    return out;
}

void covered_rows(const CoveragePair& p, double min_pixels, uint32_t* first, uint32_t* last) {
    *first = p.black.height;
    *last = 0;
    for (uint32_t y = 0; y < p.black.height; ++y) {
        double row = 0.0;
        for (uint32_t x = 0; x < p.black.width; ++x) row += p.coverage(x, y);
        if (row > min_pixels) {
            *first = std::min(*first, y);
            *last = y + 1;
        }
    }
}

double largest_channel_difference(const double a[3], const double b[3]) {
    double d = 0.0;
    for (int ch = 0; ch < 3; ++ch) d = std::max(d, std::fabs(a[ch] - b[ch]));
    return d;
}

} // namespace grass_host
