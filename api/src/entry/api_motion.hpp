// Motion vectors (grass_view_motion_desc, grass.h): the struct's validation and defaults.
#pragma once

#include "context/context.hpp"

#include <grass/grass.h>

namespace grass {

// The previous camera within +-1e12 m, finite matrices with an invertible rotation and a
// projection that is not all zero, jitters within +-2, a finite previous time, a velocity
// attachment of 1 to 7. Names the field and its value.
grass_result check_view_motion(grass_context* ctx, const char* fn, const grass_view_motion_desc& d);

} // namespace grass
