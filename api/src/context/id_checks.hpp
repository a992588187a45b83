// The id checks of the C entry points: each logs a sentence that names the function, the
// argument and why the id is refused (null, another context's, stale, or not of the public
// kind asked), and returns GRASS_ERROR_INVALID_HANDLE (GRASS_SUCCESS if fine).
#pragma once

#include "context/context.hpp"
#include "foundation/validate.hpp"

#include <grass/grass.h>

namespace grass {

grass_result check_patch_id(grass_context* ctx, const char* function, const char* name, grass_patch_id id);
grass_result check_field_id(grass_context* ctx, const char* function, const char* name, grass_field_id id);
// check_field_id, and the field is a grid field (grass_create_field): the calls that apply
// to grids only refuse a mesh field (GRASS_MSG_MESH_FIELD).
grass_result check_grid_field_id(grass_context* ctx, const char* function, const char* name, grass_field_id id);
// A map id made by grass_create_map (a field's private density map has no valid id).
grass_result check_map_id(grass_context* ctx, const char* function, const char* name, grass_map_id id);

} // namespace grass
