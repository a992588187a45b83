// The backend's programs, compiled by the driver from the embedded shader sources.
#pragma once

#include "gl_functions.hpp"

#include <context.hpp>

namespace grass {

// Texture units of the programs' samplers. Unit 0 holds the density map (the shaders'
// binding 2 is the Vulkan descriptor binding); units 3-5 the baked slices, as bound in
// blade_interface.glsl. All of them are saved and restored around drawing.
constexpr GLint kDensityMapUnit = 0;
constexpr GLint kSliceColorUnit = 3;
constexpr GLint kSliceNormalUnit = 4;
constexpr GLint kSliceThresholdUnit = 5;

// Compiles and links blade.vert + blade.frag. On failure the driver's log is in the
// context's error message (named after `function`) and nothing is left behind.
grass_result create_blade_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                  GLuint* out_program);

// Compiles and links debug_tiers.vert + debug_tiers.frag (GRASS_VIEW_FLAG_DEBUG_CELLS),
// with the same failure behaviour.
grass_result create_debug_tiers_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                        GLuint* out_program);

// Compiles and links image.vert + image.frag (the image tier), same failure behaviour.
grass_result create_image_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                  GLuint* out_program);

// Compiles and links volume.vert + volume.frag (the volume tier), same failure behaviour.
grass_result create_volume_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                   GLuint* out_program);

} // namespace grass
