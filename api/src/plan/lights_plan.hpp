// The host's lights (grass_view_lights_desc; docs/engine-frames.md "The host's lights"): what a
// view lit by them adds to its plan.
#pragma once

#include "foundation/frame_plan.hpp"
#include "plan/frame_planner.hpp"

#include <grass/grass.h>

namespace grass {

// A colour view with a grass_view_lights_desc (a depth pass ignores it): every draw gets
// kFeatureHostLights, and the plan the GrassLights block: each light's position made
// relative to `camera` in double, directions unit, a spot's cone as cosines, the specular
// and the harmonics.
void plan_lights(const ViewExtensions& ext, const double camera[3], FramePlan* plan);

} // namespace grass
