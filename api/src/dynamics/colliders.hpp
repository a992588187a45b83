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

// Every collider: a known shape, a radius in 0 .. 1e6, finite positions within +-1e12 m,
// velocity components within +-1e5 m/s.
grass_result validate_colliders(Log* log, const char* fn, const grass_collider* colliders, uint32_t count);

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
uint64_t bin_colliders(const Vector<grass_collider>& colliders, const Vector<grass_collider>& previous,
                       const MapFrame& frame, double dt, DynamicsState* scratch, InteractionPlan* plan);

} // namespace grass
