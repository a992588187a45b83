// The host's lights (grass_view_lights_desc, grass.h): the struct's validation and defaults.
#pragma once

#include "context/context.hpp"

#include <grass/grass.h>

namespace grass {

// 0 to GRASS_MAX_VIEW_LIGHTS lights, each of a known kind with finite numbers in their
// ranges (positions within +-1e12 m, directions not zero where used, colours and
// intensities 0 or more, range > 0, 0 <= inner < outer <= pi/2 for a spot), the specular
// strength 0..1 and exponent 1..1024, finite harmonics. Names the field and its value.
grass_result check_view_lights(grass_context* ctx, const char* fn, const grass_view_lights_desc& d);

} // namespace grass
