// Mip chains of baked slices (lemme2012 4.2.2-4.2.3): alpha-weighted colour (eq. 4.9-4.10),
// coverage-preserving alpha (eq. 4.11, 4.13-4.15, Castano 2010) and colour bleeding into the
// transparent texels (eq. 4.16). The plain box filter (eq. 4.7-4.8) is here only to show,
// in the tests, the coverage it loses.
#pragma once

#include "bake/slice_image.hpp"
#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

// Levels of a full chain down to 1 x 1: level k has max(1, w >> k) x max(1, h >> k) texels.
uint32_t full_mip_count(uint32_t width, uint32_t height);

// eq. 4.11: the fraction of texels with alpha > reference.
double alpha_coverage(const float* alpha, size_t count, float reference);

// The alpha-test reference a_r of eq. 4.11.
constexpr float kCoverageReference = 0.5f;

// What the coverage scale of eq. 4.15 multiplies.
enum class MipAlphaBase {
    // The footprint's mean alpha (Castano 2010, the alpha-to-coverage mips lemme cites).
    // The default: its values spread, so a single scale meets the coverage.
    kMean,
    // max(A_0..A_3), lemme eq. 4.12 as written. Kept for comparison: on thin blades the
    // max dilates the coverage and saturates at 1 in every footprint that holds an opaque
    // texel, and equal values pass the alpha test together, so no scale can bring the
    // coverage back (default patch, N = 8, mean over layers: +45% at 64 x 16; at 32 x 8
    // each layer ends +100% or 0, and every level below is 0).
    kMax,
    // The footprint's mean, not rescaled: the mean opacity. For the horizontal slice, which
    // a ray meets once and whose alpha the tiers draw as an opacity (the share of a pixel's
    // samples, sample_coverage.glsl): a rescale that keeps the alpha-tested coverage (the
    // share of texels above a_r) moves the mean instead. Seen from above through a coarse
    // level, the default patch's horizontal slice covered 0.57-0.66 of the view where the
    // blades cover 0.82 (docs/records/tier-sweep.md).
    kMeanOpacity,
};

// `levels` holds level 0; appends levels 1 .. level_count - 1. Each texel of level k
// filters its footprint in level k - 1 (2 x 2 for even sizes):
//   colour  = alpha-weighted average (eq. 4.9-4.10; 0 where all alphas are 0);
//   alpha   = scale_k * base (eq. 4.15, base: MipAlphaBase), clamped to 1, scale_k chosen
//             from the sorted values so that the coverage at a_r (eq. 4.11) is the closest
//             achievable to level 0's (eq. 4.13-4.14); kMeanOpacity: the mean, scale 1;
//   normal  = alpha-weighted average, renormalised (plain average where all alphas are 0);
//             w (height) alpha-weighted;
//   threshold = that of the footprint texel with the largest alpha (ties: smaller); 0 where
//             the stored alpha is 0, so that threshold 0 <=> alpha 0 on every level.
// All alphas, level 0's included, are rounded to the unorm8 grid they are stored on, so the
// coverage measured on the stored bytes is the one the scale was chosen for.
void build_coverage_mips(Vector<SliceImage>* levels, uint32_t level_count, HostAllocator* host,
                         MipAlphaBase base = MipAlphaBase::kMean);

// SliceSet::alpha_test_scale from the stored alphas of `set`'s horizontal slice: per mip,
// the scale of eq. 4.13-4.14 that gives the share of level 0's texels above a_r.
struct SliceSet;
void set_alpha_test_scales(SliceSet* set, HostAllocator* host);

// eq. 4.7-4.8: every channel is the plain average of its footprint (alpha included).
void build_box_mips(Vector<SliceImage>* levels, uint32_t level_count, HostAllocator* host);

// eq. 4.16 from the coarsest level to the finest, for the empty texels only (A_i = 0):
// C'_i = C'_{i+1}, level i + 1 (already bled) sampled nearest at the texel centre. Applied
// to the colour and to the normal (xyz and w), so that bilinear filtering at blade edges
// mixes in plausible values on both. A partly covered texel keeps its own values: the tiers
// blend it by its alpha (eq. 4.16's A_i C_i + (1 - A_i) C'_{i+1} is for an alpha test, and
// darkened the blended slices). Thresholds are left alone (0 stays "no blade").
void bleed_colours(Vector<SliceImage>* levels);

} // namespace grass
