// The interaction map (docs/responsive.md): where what colliders leave behind lives, around
// the camera. One or two square RGBA32F levels of N x N texels lying across the map's up,
// toroidally addressed: world texel k (64-bit, k = floor(position / texel size) along the
// map's axes u, v) lives at texel k mod N, so the map scrolls with the camera without
// copies; the interaction pass clears the texels that left the window. Heights are metres
// along up above a height anchor the core keeps (and moves, clearing the map, when the
// camera is more than kReanchorDistance from it).
#pragma once

#include "dynamics/colliders.hpp"
#include "dynamics/dynamics_state.hpp"
#include "foundation/frame_plan.hpp"
#include "foundation/log.hpp"

#include <grass/grass.h>

namespace grass {

constexpr double kReanchorDistance = 1e4; // metres along up
// The coarse level (1) widens a collider's footprint narrower than this many texels (half a
// texel's diagonal, rounded up) to that radius R: a texel centre d from the axis of a collider
// of radius r < R is pressed as the collider presses at d r / R. Every point lies within R of
// a texel centre, so a collider narrower than a coarse texel (a leg, a 1 m ball on 1 m
// texels) cannot slip between the centres and its trail reads from afar; a wider collider is
// pressed exactly. The fine level (0) presses exactly under every footprint.
constexpr double kCoarseLeastRadius = 0.7072;

grass_interaction_desc default_interaction_desc();

grass_result validate_interaction(Log* log, const char* fn, const grass_interaction_desc& desc);

// The map's unit axes for desc.up: u (world x made orthogonal to up; world z when up is near
// x) and v = u x up, across it; and the camera's height above `anchor`. For up = +y: u = +x,
// v = +z.
MapFrame map_frame(const grass_interaction_desc& desc, const double camera[3], double anchor);

// Plans the interaction pass of a frame into plan->interaction and the frame's map_*
// uniforms, from the map state and colliders in `state`. Writes the state to commit once
// the frame has begun into *next. No map (no colliders yet): levels = 0, uniforms zero.
void plan_interaction(const DynamicsState& state, const double camera[3], double dt, DynamicsState* scratch,
                      FramePlan* plan, InteractionMapState* next);

} // namespace grass
