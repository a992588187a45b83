// The content hash of a SliceSet (declared here because baked_slices.hpp is the contract
// header; the function could move there).
#pragma once

#include "bake/baked_slices.hpp"

#include <cstdint>

namespace grass {

// FNV-1a 64 over the bytes of color, then normal, then threshold (uint16 in memory order).
uint64_t slice_content_hash(const SliceSet& set);

// Texels of all mip levels of one layer.
uint64_t slice_layer_texels(uint32_t width, uint32_t height, uint32_t mip_levels);

} // namespace grass
