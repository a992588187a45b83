// Generates the geometry-based grass patch of lemme2012 4.1 from a validated desc.
#pragma once

#include "patch/patch_data.hpp"

#include <grass/grass.h>

namespace grass {

// Fills `out` (which must be empty). Deterministic: the same desc gives identical bytes.
void generate_patch(const grass_patch_desc& desc, HostAllocator* host, PatchData* out);

} // namespace grass
