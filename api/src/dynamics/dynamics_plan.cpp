#include "dynamics/dynamics_plan.hpp"

#include "dynamics/colliders.hpp"
#include "dynamics/interaction_map.hpp"
#include "dynamics/wind.hpp"

#include <cstddef>
#include <cstring>

namespace grass {

namespace {

// The responsive part of the Frame block, from `wind` to the end: zero unless used.
void clear_responsive_uniforms(FrameUniforms* f) {
    const size_t begin = offsetof(FrameUniforms, wind);
    std::memset(reinterpret_cast<char*>(f) + begin, 0, sizeof(FrameUniforms) - begin);
}

} // namespace

DynamicsFrame plan_dynamics(DynamicsState* state_out, FramePlan* plan_out, Log* log, const grass_view_desc& view) {
    DynamicsState& state = *state_out;
    FramePlan& plan = *plan_out;
    // The step: the time since the previous frame; 0 at the first frame and when the host's
    // clock went backwards (said once per occurrence).
    double dt = state.has_time ? view.time - state.previous_time : 0.0;
    if (dt < 0.0) {
        log->warn(GRASS_MSG_TIME_BACKWARDS,
                  "grass_begin_frame: view->time is %.9g s, earlier than the previous frame's %.9g s; the responsive "
                  "grass steps 0 this frame",
                  view.time, state.previous_time);
        dt = 0.0;
    }
    plan.stats.time_step = dt;
    state.pending_time = view.time;

    clear_responsive_uniforms(&plan.frame);
    DynamicsFrame out;
    out.wind = wind_is_active(state.wind);
    const MapFrame axes = map_frame(state.interaction, view.camera_position, 0.0);
    for (int c = 0; c < 3; ++c) out.map_up[c] = axes.up[c];
    if (out.wind) pack_wind(state.wind, view.camera_position, view.time, axes.up, &plan.frame);
    plan_interaction(state, view.camera_position, dt, &state, &plan, &state.pending_map);
    if (state.full_tiles > 0 && !state.tile_cap_said) {
        state.tile_cap_said = true;
        log->warn(GRASS_MSG_COLLIDER_TILE_CAP,
                  "grass_begin_frame: %u colliders reach one tile of the interaction map's level %u (%u tiles over the "
                  "cap this frame); a tile tests at most GRASS_MAX_COLLIDERS_PER_TILE (%u): it keeps those reaching "
                  "lowest, the others press nothing there (said once per context)",
                  state.most_in_tile, state.most_level, state.full_tiles, kMaxCollidersPerTile);
    }
    out.map = plan.interaction.levels > 0;
    if (out.wind || out.map) plan.frame.wind_shape[3] = static_cast<float>(dt);
    return out;
}

DynamicsFrame plan_view_dynamics(const DynamicsState& state, const FramePlan& first, FramePlan* plan_out,
                                 const grass_view_desc& view) {
    FramePlan& plan = *plan_out;
    FrameUniforms& f = plan.frame;
    const double dt = first.stats.time_step;
    plan.stats.time_step = dt;
    clear_responsive_uniforms(&f);
    DynamicsFrame out;
    out.wind = wind_is_active(state.wind);
    const MapFrame axes = map_frame(state.interaction, view.camera_position, 0.0);
    for (int c = 0; c < 3; ++c) out.map_up[c] = axes.up[c];
    if (out.wind) pack_wind(state.wind, view.camera_position, view.time, axes.up, &f);
    const InteractionPlan& map = first.interaction;
    if (map.levels > 0) { // view 0's map, window and uniforms; this camera's offset from view 0's
        std::memcpy(f.map_up, first.frame.map_up, sizeof(f.map_up));
        std::memcpy(f.map_axis_u, first.frame.map_axis_u, sizeof(f.map_axis_u));
        std::memcpy(f.map_axis_v, first.frame.map_axis_v, sizeof(f.map_axis_v));
        std::memcpy(f.map_levels, first.frame.map_levels, sizeof(f.map_levels));
        for (int c = 0; c < 3; ++c) {
            f.map_offset[c] = static_cast<float>(view.camera_position[c] - first.origin[c]);
            out.map_up[c] = first.frame.map_up[c];
        }
        plan.interaction.levels = map.levels;
        plan.interaction.resolution = map.resolution;
        for (int l = 0; l < 2; ++l) plan.interaction.level[l] = map.level[l];
    }
    out.map = map.levels > 0;
    if (out.wind || out.map) f.wind_shape[3] = static_cast<float>(dt);
    return out;
}

void commit_dynamics(DynamicsState* state_out) {
    DynamicsState& state = *state_out;
    state.has_time = true;
    state.previous_time = state.pending_time;
    state.map = state.pending_map;
    state.previous_colliders.swap(state.pending_colliders); // no allocation: the copy was made while planning
}

} // namespace grass
