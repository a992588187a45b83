// What the context keeps for responsive grass (jahrmann2017 5, bakay2003 3.3): the wind and
// its sources, the colliders of the next frames, the interaction map's configuration and its
// scrolling state, and the clock. Per blade, only the blade window's slots (the state itself is the backend's).
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/frame_plan.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// The interaction map's scrolling state: where each level's window was at the last frame
// that ran the pass, and the height anchor. Committed only when a frame begins successfully.
struct InteractionMapState {
    bool exists = false;       // the backend holds the map (made at the first frame with colliders)
    bool clear_pending = true; // the next pass clears every texel (new map, grass_set_interaction)
    double anchor = 0.0;       // height anchor A along up (world metres): map heights are above it
    int64_t window[2][2] = {}; // W of each level at the last pass (world texel indices)
};

// A collider's rectangle of tiles at one level (inclusive; empty when x0 > x1).
struct TileRect {
    int32_t x0, z0, x1, z1;
};

struct DynamicsState {
    // The defaults: no wind, standard gravity, no colliders, the default interaction map.
    explicit DynamicsState(HostAllocator* host);
    grass_wind_desc wind{};                              // sources points at `sources` below
    grass_wind_source sources[GRASS_MAX_WIND_SOURCES]{}; // the copied wind sources
    Vector<grass_collider> colliders;                    // copied by grass_set_colliders
    // The colliders of the last frame that began (index i there is index i now): a collider
    // continues its passage only where it was then (GpuCollider::velocity[3]).
    Vector<grass_collider> previous_colliders;
    grass_interaction_desc interaction{};
    InteractionMapState map;
    bool has_time = false; // a frame has begun: previous_time holds its time
    double previous_time = 0.0;
    // What the frame being planned commits once it has begun (commit_dynamics).
    double pending_time = 0.0;
    InteractionMapState pending_map;
    Vector<grass_collider> pending_colliders; // this frame's colliders, previous_colliders once committed
    // Scratch of the binning (kept so that a frame allocates nothing once grown): the tile
    // rectangles of the colliders in the map, two per collider, and per-tile write cursors.
    Vector<TileRect> tile_rects;
    Vector<uint32_t> tile_fill;
    // Per collider in the map: its lowest point over the step (the cap's key, colliders.hpp).
    Vector<float> collider_low;
    // The binning's overflow at this frame (kMaxCollidersPerTile): tiles over the cap, the
    // most colliders that reached one tile and its level; and whether it was said.
    uint32_t full_tiles = 0;
    uint32_t most_in_tile = 0;
    uint32_t most_level = 0;
    bool tile_cap_said = false; // GRASS_MSG_COLLIDER_TILE_CAP: once per context
    // The blade window of the last frame that began (view 0's, plan/blade_window.hpp): which
    // cell holds which slot, so that a cell that stays keeps its slot and its blades' state.
    // Empty: no window then (the backend holds no state). window_used: the planner's scratch.
    BladeWindowPlan window;
    Vector<uint32_t> window_used;
};

} // namespace grass
