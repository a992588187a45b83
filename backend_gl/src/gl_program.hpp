// The backend's programs, compiled by the driver from the embedded shader sources.
#pragma once

#include "gl_functions.hpp"

#include <context.hpp>

namespace grass {

// Compiles and links blade.vert + blade.frag. On failure the driver's log is in the
// context's error message (named after `function`) and nothing is left behind.
grass_result create_blade_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                  GLuint* out_program);

// Compiles and links debug_tiers.vert + debug_tiers.frag (GRASS_VIEW_FLAG_DEBUG_TIERS),
// with the same failure behaviour.
grass_result create_debug_tiers_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                        GLuint* out_program);

} // namespace grass
