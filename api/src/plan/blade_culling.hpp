// Per-blade culling in the geometry tier (jahrmann2017 6.2): the orientation, view-frustum
// and distance tests of grass_blade_culling_desc, validated here and evaluated by
// api/shaders/blade_culling.glsl as each blade's vertices are placed.
#pragma once

#include "foundation/log.hpp"

#include <grass/grass.h>

namespace grass {

struct Field;

// A field's culling as the shaders read it (FieldUniforms::culling). Off: enabled false.
struct BladeCulling {
    bool enabled = false;
    float orientation_limit = 2.0f;  // |cos| above which a blade is culled; 2: the test is off
    float frustum_tolerance = -1.0f; // widening of the frustum, relative to w; < 0: off
    float distance_max = 0.0f;       // metres; 0: the distance test is off
    float distance_levels = 0.0f;    // n of the blade-index test; 0: thinning by threshold
};

grass_blade_culling_desc default_blade_culling_desc();

// Checks `desc` (named "culling") for `field`'s tiers and writes what the shaders read. A
// distance_max of 0 takes the far end of the field's geometry bands; none finite is refused.
grass_result resolve_blade_culling(Log* log, const char* fn, const Field& field, const grass_blade_culling_desc& desc,
                                   BladeCulling* out);

} // namespace grass
