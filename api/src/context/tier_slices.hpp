// The baked slices a field's tiers need (lemme2012 4.2): each volume tier the vertical
// slices of its slice count, the image tier the horizontal slice. Baked once per patch and
// slice count (or loaded from the context's disk cache) and uploaded to the backend.
#pragma once

#include "context/context.hpp"
#include "plan/lod_setup_types.hpp"

namespace grass {

grass_result prepare_tier_slices(grass_context* ctx, const char* function, uint32_t patch_slot, const LodSetup& lod);

} // namespace grass
