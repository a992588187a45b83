// The context's design-map objects, made and released by the map entry points and by a
// field's private density map (api_field.cpp).
#pragma once

#include "context/context.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// Makes a map object in the context's pool and uploads it; `field_private` maps come from
// grass_field_desc.density_map and have no public id. On failure nothing is left.
grass_result make_map(grass_context* ctx, const char* function, const char* name, const grass_map_desc* desc,
                      bool field_private, uint32_t* out_slot);
// Releases the map in `slot` (no field may use it).
void release_map(grass_context* ctx, uint32_t slot);

} // namespace grass
