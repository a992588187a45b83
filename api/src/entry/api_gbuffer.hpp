// G-buffer views (GRASS_PASS_GBUFFER, grass_view_gbuffer_desc, grass.h): the struct's
// validation and defaults. The plan is api/src/plan/gbuffer_plan.cpp.
#pragma once

#include "context/context.hpp"
#include "plan/frame_planner.hpp"

#include <grass/grass.h>

namespace grass {

// 1 to GRASS_MAX_GBUFFER_ATTACHMENTS attachments, each of a known semantic and format, a
// write mask of 0 to 15, every semantic but NONE at most once. Names the field and its value.
grass_result check_view_gbuffer(grass_context* ctx, const char* fn, const grass_view_gbuffer_desc& d);

// The chain as a whole: a G-buffer pass has a grass_view_gbuffer_desc, and one whose layout
// has a VELOCITY attachment a grass_view_motion_desc.
grass_result check_gbuffer_chain(grass_context* ctx, const char* fn, const ViewExtensions& ext);

} // namespace grass
