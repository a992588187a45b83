// Baked slices of a patch (lemme2012 4.2, boulanger2006 3.3): the volume tier's vertical
// slices and the image tier's horizontal slice, rasterised on the CPU from the geometry
// patch, with full mip chains. Deterministic for a given patch and bake parameters, so both
// backends sample identical textures and tests can hash them. Layout contract between the
// core (slice_baker.cpp) and the backends (texture arrays).
#pragma once

#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

// One set of slices: the vertical slices of a volume tier with N slices per axis
// (layers 0..N-1 are orthogonal to x at x = (i + 0.5) / N, layers N..2N-1 orthogonal to z at
// z = (i + 0.5) / N, each holding the blades inside its slab [i/N, (i+1)/N], and layer 2N the
// horizontal slice at the set's size, which the volume shows near the ground for views from
// above, after boulanger2006 3.3), or the image tier's horizontal slice (N = 0, the whole
// patch seen from above) in three layers of the same coverage and thresholds: layer 0 the
// colour, heights and normals seen from above, layers 1 and 2 the colour and heights a
// grazing ray sees and its normals heading along x and along z (slice_baker.cpp; image.frag
// lights with the pair the view's heading picks, and turns to layer 0 as the view steepens).
//
// Texel (s, t) of a vertical slice orthogonal to x: s = z in [0, 1) across the patch, t = y
// from 0 (ground, row 0) to `height_patch_units` (top row); orthogonal to z: s = x. Texel
// (s, t) of the horizontal slice: s = x, t = z. Mip level k has max(1, w >> k) x max(1, h >> k)
// texels; levels are stored one after another for each layer, layer after layer.
// The layers of a set of N slices per axis: 2N + 1, or 3 for the image tier's (N = 0).
inline uint32_t slice_layer_count(uint32_t slices_per_axis) { return slices_per_axis ? 2 * slices_per_axis + 1 : 3; }

struct SliceSet {
    explicit SliceSet(HostAllocator* host)
        : color(StlAllocator<uint8_t>(host)), normal(StlAllocator<uint8_t>(host)),
          threshold(StlAllocator<uint16_t>(host)) {}
    uint32_t slices_per_axis = 0; // N; 0 = the horizontal slice
    uint32_t layers = 0;          // slice_layer_count(N)
    uint32_t width = 0;           // texels of mip 0 along s
    uint32_t height = 0;          // texels of mip 0 along t
    uint32_t mip_levels = 0;
    float height_patch_units = 0; // the patch height a vertical slice spans (t = 1)
    // RGBA8: rgb = albedo, sRGB-encoded (sample as an sRGB texture); a = coverage, with the
    // coverage-preserving mips of lemme eq. 4.11-4.15 and colour bled into transparent
    // texels (eq. 4.16).
    Vector<uint8_t> color;
    // RGBA8 unorm: xyz = patch-space normal * 0.5 + 0.5, facing the slice's viewer side (vertical
    // slices: horizontally, with |y|: the blades' up and down lobes, see volume.frag);
    // a = height of the texel above the ground / height_patch_units (vertical slices), or
    // the blade height there (horizontal slice), for the blade ambient occlusion.
    Vector<uint8_t> normal;
    // RGBA16 unorm: r = density threshold of the blade covering the texel (0 = none); gba =
    // its coverage curve: the share of the texel's coverage whose blades' thresholds are at
    // most 1/4, 1/2 and 3/4 (the rest of the curve: 0 at 0, 1 at 1), so that a tier draws
    // alpha x (curve(high) - curve(low)) for the thresholds its density and transitions select.
    Vector<uint16_t> threshold;
    uint64_t content_hash = 0; // FNV-1a 64 over color, normal, threshold
    // The horizontal slice (layer 2N; the image tier's layers alike) keeps its mean opacity
    // through the mips, which a multisampled target draws as a share of its samples. A
    // single-sampled one alpha-tests at 1/2, which needs the coverage-preserving scale of
    // eq. 4.13-4.15 instead: alpha_test_scale[k] is that scale for mip k (1 at level 0 and
    // past the last level), applied by the shaders (sample_coverage.glsl). Derived from the
    // stored alphas (set_alpha_test_scales, slice_mips.hpp), not stored in the cache.
    static constexpr uint32_t kAlphaTestLevels = 16;
    float alpha_test_scale[kAlphaTestLevels] = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};

    // Offset (in texels) of mip `level` of `layer` in the arrays.
    uint64_t offset(uint32_t layer, uint32_t level) const;
    uint32_t level_width(uint32_t level) const { return width >> level ? width >> level : 1; }
    uint32_t level_height(uint32_t level) const { return height >> level ? height >> level : 1; }
};

} // namespace grass
