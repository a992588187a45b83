// Motion vectors (grass_view_motion_desc; docs/engine-frames.md "Motion vectors"): what a
// view that writes them adds to its plan.
#pragma once

#include "foundation/frame_plan.hpp"
#include "plan/frame_planner.hpp"

#include <grass/grass.h>

namespace grass {

// A colour view with a grass_view_motion_desc (a depth pass ignores it): every draw gets
// kFeatureMotion, and the plan the velocity attachment and the GrassMotion block: this
// view's and the previous frame's view-projections without their jitter, both taking this
// view's camera-relative positions (the previous one made so in double), and the wind's gust
// phases at the previous time (`wind`: the context's wind, nullptr when none blows; `up`: the
// interaction map's up, as pack_wind takes it) and how long before the frame's `time` that
// was (the trails' age then).
void plan_motion(const grass_view_desc& view, const ViewExtensions& ext, const double camera[3], double time,
                 const grass_wind_desc* wind, const double up[3], FramePlan* plan);

} // namespace grass
