// The frame plan: for each field, one traversal of its implicit quadtree with all of its
// lod tests (lemme2012 6.1.3) and view-frustum culling (6.1.4); for each tier, the
// instances to draw, relative to the camera. No GPU involved.
#pragma once

#include "dynamics/dynamics_state.hpp"
#include "foundation/frame_plan.hpp"
#include "foundation/handle_pool.hpp"
#include "foundation/log.hpp"
#include "maps/design_map.hpp"
#include "plan/field.hpp"
#include "plan/plan_scratch.hpp"

#include <grass/grass.h>

namespace grass {

// What a frame is planned from and into (the context's, context.hpp): its fields, patches
// and maps; its responsive state (dynamics_plan.hpp); the plan and the planner's scratch.
// Errors go to `log`; `lod_callbacks_running` counts a host lod-test callback in flight
// (calls on the context are refused meanwhile).
struct FramePlanning {
    const HandlePool<Field>& fields;
    const HandlePool<Patch>& patches;
    const HandlePool<DesignMap>& maps;
    DynamicsState& dynamics;
    FramePlan& plan;
    PlanScratch& scratch;
    Log& log;
    uint32_t& lod_callbacks_running;
    grass_depth_mode depth_mode;
    RenderTarget target; // the target's samples and clip convention, as the backend reports them
    double time;         // the frame's (grass_frame_desc.time; grass_begin_frame: the view's)
    // The frame's view 0, when this plan is a later view of it: the responsive grass stepped
    // there, and this view reads its interaction map (plan_view_dynamics). nullptr: view 0.
    const FramePlan* first_view;
    // The backend runs the blade window pass (Backend::runs_blade_window): view 0 plans the
    // window (blade_window.hpp) and the draws whose cells it holds get its variant.
    bool blade_window = false;
    // ... and compacts the culled blades of the window draws (Backend::compacts_blade_window).
    bool compact_blade_window = false;
};

// The validated extensions chained on grass_view_desc.next (each may be absent).
struct ViewExtensions {
    const grass_stereo_view_desc* stereo = nullptr;    // the second eye: a stereo frame
    const grass_lod_origin_desc* lod_origin = nullptr; // where the lod distances are measured from
    const grass_view_pass_desc* pass = nullptr;        // the pass (none: GRASS_PASS_COLOR)
    const grass_shadow_receive_desc* shadow = nullptr; // the host's shadow map, received (colour views)
    const grass_view_motion_desc* motion = nullptr;    // motion vectors: the previous camera and time
    const grass_view_lights_desc* lights = nullptr;    // the host's lights (colour views)
    const grass_view_gbuffer_desc* gbuffer = nullptr;  // the host's G-buffer layout (G-buffer views)
};

// Rebuilds in.plan from a validated view. Fails only when a host lod-test callback
// answers something that is not a grass_lod_answer (the plan is then empty).
// A stereo frame plans once for both eyes: instances relative to the plan's origin (the lod
// origin: the eyes' midpoint by default), culled against the union of the eyes' frusta, and
// plan.eyes holds each eye's view-projection and position relative to that origin.
grass_result build_frame_plan(const FramePlanning& in, const grass_view_desc& view,
                              const ViewExtensions& extensions = ViewExtensions{});

} // namespace grass
