// Motion vectors (grass_view_motion_desc, grass.h; docs/engine-frames.md "Motion vectors"):
// the struct's validation and defaults. The plan is api/src/plan/motion_plan.cpp.
#include "entry/api_motion.hpp"

#include "foundation/validate.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace grass {

grass_result check_view_motion(grass_context* ctx, const char* fn, const grass_view_motion_desc& d) {
    GRASS_TRY(
        check_world_position(ctx, fn, "grass_view_motion_desc->previous_camera_position", d.previous_camera_position));
    GRASS_TRY(check_finite_array(ctx, fn, "grass_view_motion_desc->previous_view", d.previous_view, 16));
    GRASS_TRY(check_finite_array(ctx, fn, "grass_view_motion_desc->previous_projection", d.previous_projection, 16));
    const float* m = d.previous_view;
    const double det = m[0] * (static_cast<double>(m[5]) * m[10] - static_cast<double>(m[9]) * m[6]) -
                       m[4] * (static_cast<double>(m[1]) * m[10] - static_cast<double>(m[9]) * m[2]) +
                       m[8] * (static_cast<double>(m[1]) * m[6] - static_cast<double>(m[5]) * m[2]);
    if (!(std::fabs(det) > 1e-12)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: grass_view_motion_desc->previous_view has a singular rotation (determinant %g)", fn, det);
    }
    bool any = false;
    for (int k = 0; k < 16; ++k) any = any || d.previous_projection[k] != 0.0f;
    if (!any) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: grass_view_motion_desc->previous_projection is all zero", fn);
    }
    static const char* const jitter_names[4] = {
        "grass_view_motion_desc->jitter[0]", "grass_view_motion_desc->jitter[1]",
        "grass_view_motion_desc->previous_jitter[0]", "grass_view_motion_desc->previous_jitter[1]"};
    for (int c = 0; c < 2; ++c) {
        GRASS_TRY(check_range(ctx, fn, jitter_names[c], d.jitter[c], -2.0, 2.0));
        GRASS_TRY(check_range(ctx, fn, jitter_names[2 + c], d.previous_jitter[c], -2.0, 2.0));
    }
    GRASS_TRY(check_finite(ctx, fn, "grass_view_motion_desc->previous_time", d.previous_time));
    if (d.velocity_attachment < 1 || d.velocity_attachment > 7) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_view_motion_desc->velocity_attachment is %u; expected 1 to 7 (GL: a draw buffer "
                         "index; 0 is the lit colour)",
                         fn, d.velocity_attachment);
    }
    return GRASS_SUCCESS;
}

} // namespace grass

GRASS_API grass_view_motion_desc grass_default_view_motion_desc(void) {
    grass_view_motion_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VIEW_MOTION_DESC;
    for (int k = 0; k < 4; ++k) {
        d.previous_view[k * 5] = 1.0f;
        d.previous_projection[k * 5] = 1.0f;
    }
    d.velocity_attachment = 1;
    return d;
}
