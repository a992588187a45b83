// Grass's own colour and coverage, measured from two renders of the same frame: one over a
// black and one over a white background. A pixel that grass covers by c with colour g reads
// c g over black and c g + (1 - c) over white (the multisample resolve mixes in linear RGB),
// so c = 1 - (white - black), and the black render divided by c is grass's colour. Used by the
// tests that compare the tiers' colour with the blades' (SliceColourTest) and by
// grass-measure tier-sweep.
#pragma once

#include "headless_host.hpp"

#include <cstdint>
#include <vector>

namespace grass_host {

// An 8-bit sRGB value as linear light, 0..1, and back (0..255, unclamped).
double srgb_to_linear(uint8_t byte);
double linear_to_srgb_levels(double linear);

// The same frame over black and over white (equal sizes).
struct CoveragePair {
    Image black, white;
    // Grass's coverage of pixel (x, y), 0..1 (the mean over R, G, B).
    double coverage(uint32_t x, uint32_t y) const;
};

// The coverage-weighted mean sRGB colour of grass in a band of rows, and the coverage summed
// over it (in pixels).
struct BandColour {
    double colour[3] = {0.0, 0.0, 0.0};
    double coverage = 0.0;
};

// The rows [first, last) of `p` split into `bands` bands of equal height, far (top) first.
std::vector<BandColour> band_colours(const CoveragePair& p, uint32_t first, uint32_t last, int bands);

// Per row of [first, last), the columns [begin, end) between the first and the last pixel that
// `p` covers by more than `threshold` (the field's outline in that row; empty where none).
struct RowSpan {
    uint32_t begin = 0, end = 0;
};
std::vector<RowSpan> row_spans(const CoveragePair& p, uint32_t first, uint32_t last, double threshold);

// The mean sRGB colour of `p` composited over a ground of linear colour `ground` (what the frame
// shows over a host's ground: the black render plus (1 - coverage) x ground), over the spans
// (rows first.. first + spans.size()) split into `bands` bands; coverage is the pixels counted.
std::vector<BandColour> composite_band_colours(const CoveragePair& p, uint32_t first, const std::vector<RowSpan>& spans,
                                               const double ground[3], int bands);

// The rows where grass covers more than `min_pixels` pixels' worth: [*first, *last); *last <=
// *first when none does.
void covered_rows(const CoveragePair& p, double min_pixels, uint32_t* first, uint32_t* last);

// The largest of the three channels' absolute differences, sRGB levels.
double largest_channel_difference(const double a[3], const double b[3]);

} // namespace grass_host
