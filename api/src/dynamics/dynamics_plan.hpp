// Responsive grass in the frame plan: the time step, the wind's and the interaction map's
// frame uniforms, the interaction pass, and which draws need the responsive shader variants.
// A context without wind, colliders or a gravity change plans exactly what still grass
// plans: no feature bit, no pass, zero uniforms.
#pragma once

#include "dynamics/dynamics_state.hpp"
#include "foundation/frame_plan.hpp"
#include "foundation/log.hpp"

#include <grass/grass.h>

namespace grass {

struct DynamicsFrame {
    bool wind = false; // every draw gets kFeatureWind
    bool map = false;  // the interaction map exists: draws of fields that read it get kFeatureInteraction
    double map_up[3] = {0, 1, 0};
    // A field reads the map when its up is within 60 degrees of the map's.
    bool field_reads_map(const double field_up[3]) const {
        return map && field_up[0] * map_up[0] + field_up[1] * map_up[1] + field_up[2] * map_up[2] >= 0.5;
    }
};

// Fills plan's responsive parts (frame uniforms, interaction plan, stats.colliders*,
// interaction_texels, time_step) for `view` and keeps what to commit in *state.
DynamicsFrame plan_dynamics(DynamicsState* state, FramePlan* plan, Log* log, const grass_view_desc& view);

// A later view of the frame whose view 0 is `first` (planned by plan_dynamics): the same
// step and wind, from this view's camera, and view 0's interaction map read from here
// (FrameUniforms::map_offset); no pass of its own (plan's interaction keeps no colliders).
DynamicsFrame plan_view_dynamics(const DynamicsState& state, const FramePlan& first, FramePlan* plan,
                                 const grass_view_desc& view);

// After the frame has begun: the time and the map's state become the previous frame's.
void commit_dynamics(DynamicsState* state);

} // namespace grass
