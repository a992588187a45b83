// Baking of the volume tier's vertical slices and the image tier's horizontal slice from
// the geometry patch (lemme2012 4.2, boulanger2006 3.3-3.4): the patch and its 8 neighbours
// are rasterised between clipping planes with an orthographic view, then mip-mapped with
// the coverage-preserving filters and colour bleeding of slice_mips.hpp.
#pragma once

#include "bake/baked_slices.hpp"
#include "bake/slice_image.hpp"
#include "foundation/allocator.hpp"
#include "patch/patch_data.hpp"

#include <cstdint>

namespace grass {

// Default sizes when width / height are 0: vertical slices 256 x 64 (lemme chapter 7),
// the horizontal slice 128 x 128.
constexpr uint32_t kDefaultVerticalSliceWidth = 256;
constexpr uint32_t kDefaultVerticalSliceHeight = 64;
constexpr uint32_t kDefaultHorizontalSliceSize = 128;

// Bakes the slice set laid out as baked_slices.hpp says, with a full mip chain, and sets its
// content_hash. slices_per_axis N >= 1: 2N vertical layers; layer i < N holds the blade
// geometry with x in [i/N, (i+1)/N] seen along +x (viewer at -x), s = z; layer N + i the
// slab z in [i/N, (i+1)/N] seen along +z (viewer at -z), s = x; t = y / bounds_max[1].
// N = 0: the single horizontal slice seen from above, s = x, t = z. Deterministic: the same
// patch and parameters give identical bytes. `out` is overwritten.
void bake_slices(const PatchData& patch, uint32_t slices_per_axis, uint32_t width, uint32_t height, HostAllocator* host,
                 SliceSet* out);

// Level 0 of one layer in floating point, before mip-mapping and encoding (layer numbering
// and sizes as bake_slices, 0 sizes meaning the defaults). For tests and tools.
void rasterize_slice_layer(const PatchData& patch, uint32_t slices_per_axis, uint32_t layer, uint32_t width,
                           uint32_t height, HostAllocator* host, SliceImage* out);

} // namespace grass
