// Colliders (jahrmann2017 5.3: spheres; capsules for legs, bodies, logs): validated and
// copied by grass_set_colliders, then at each frame converted into the interaction map's
// frame and binned into its tiles by their swept footprint, so that the pass tests each
// texel only against the colliders that can reach it: the work grows with the area the
// colliders touch, not with the field or the number of colliders elsewhere.
#pragma once

#include "dynamics/dynamics_state.hpp"
#include "foundation/frame_plan.hpp"
#include "foundation/log.hpp"

#include <grass/grass.h>

namespace grass {

// Tile side of the interaction map, texels (InteractionLevelUniforms::counts.y).
constexpr uint32_t kInteractionTileSize = 16;
// The most colliders a tile's texels test (docs/responsive.md "Colliders per tile"): a texel
// of the pass tests at most this many, whatever stacks over it. Of more, the tile keeps the
// ones whose lowest point over the step is lowest (ties: the lower index), in index order;
// the frame reports it (DynamicsState::full_tiles, GRASS_MSG_COLLIDER_TILE_CAP once).
constexpr uint32_t kMaxCollidersPerTile = GRASS_MAX_COLLIDERS_PER_TILE;

// Every collider: a known shape, a radius in 0 .. 1e6, finite positions within +-1e12 m,
// velocity components within +-1e5 m/s.
grass_result validate_colliders(Log* log, const char* fn, const grass_collider* colliders, uint32_t count);

// The longest sweep of a collider in one time step, metres (|velocity| x step). The pass
// sweeps in float around the camera: longer sweeps lost their path (they collapsed to their
// end point near 1e7 m), so a frame that would sweep further is refused.
constexpr double kMaxColliderSweep = 1e6;

// Refuses a frame at `time` whose time step would sweep a collider further than
// kMaxColliderSweep, naming the collider, its velocity, the step and the sweep.
grass_result check_collider_sweeps(Log* log, const char* fn, const DynamicsState& state, double time);

// The map's frame at this frame: unit axes (world), the camera's height above the anchor.
struct MapFrame {
    double up[3], u[3], v[3];
    double camera[3];     // world metres
    double camera_height; // along up, above the height anchor (m)
};

// Converts the colliders that reach a level's window into plan->colliders (GpuCollider) and
// fills plan->tile_offsets / tile_colliders of each of plan->levels levels (whose uniforms
// are already set). Returns the number of colliders in the map.
// A collider continues its passage (GpuCollider::velocity[3] = 1) when `previous` (the last
// frame's colliders) has one of its shape at its index, each of whose ends lies within its
// radius of where this frame's sweep starts (end - velocity x dt). Otherwise it is new: its
// first frame, or moved without a velocity; its contacts replace what earlier passages left.
// A tile lists at most kMaxCollidersPerTile colliders (scratch->full_tiles counts those cut).
uint64_t bin_colliders(const Vector<grass_collider>& colliders, const Vector<grass_collider>& previous,
                       const MapFrame& frame, double dt, DynamicsState* scratch, InteractionPlan* plan);

} // namespace grass
