// The frame plan: for each field, one traversal of its implicit quadtree with all of its
// lod tests (lemme2012 6.1.3) and view-frustum culling (6.1.4); for each tier, the
// instances to draw, relative to the camera. No GPU involved.
#pragma once

#include "context/context.hpp"

#include <grass/grass.h>

namespace grass {

// Rebuilds ctx->plan from a validated view. Fails only when a host lod-test callback
// answers something that is not a grass_lod_answer (the plan is then empty).
grass_result build_frame_plan(grass_context* ctx, const grass_view_desc& view);

} // namespace grass
