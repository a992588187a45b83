// Motion vectors (grass_view_motion_desc): the GrassMotion block of a view that writes them.
#include "plan/motion_plan.hpp"

#include "dynamics/wind.hpp"
#include "foundation/shader_interface.hpp"

namespace grass {
namespace {

// projection x the view's rotation x translation by `offset`, less the projection's jitter
// (an NDC offset j is clip.xy += j clip.w: rows 0 and 1 lose j times row 3), column-major.
void unjittered_view_projection(const float view[16], const float projection[16], const double offset[3],
                                const float jitter[2], float out[16]) {
    double p[16];
    for (int k = 0; k < 16; ++k) p[k] = projection[k];
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 2; ++r) p[4 * c + r] -= double(jitter[r]) * p[4 * c + 3];
    }
    double m[16];
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            double s = 0.0;
            if (c < 3) {
                for (int k = 0; k < 3; ++k) s += p[4 * k + r] * view[4 * c + k];
            } else {
                s = p[12 + r];
            }
            m[4 * c + r] = s;
        }
    }
    for (int r = 0; r < 4; ++r) m[12 + r] += m[r] * offset[0] + m[4 + r] * offset[1] + m[8 + r] * offset[2];
    for (int k = 0; k < 16; ++k) out[k] = static_cast<float>(m[k]);
}

} // namespace

void plan_motion(const grass_view_desc& view, const ViewExtensions& ext, const double camera[3], double time,
                 const grass_wind_desc* wind, const double up[3], FramePlan* plan) {
    // A G-buffer view writes velocity where its layout has a VELOCITY attachment alone.
    plan->motion =
        ext.motion != nullptr && !plan->depth_pass &&
        (!plan->gbuffer || plan->gbuffer_attachment[kGBufferOutput[GRASS_GBUFFER_VELOCITY]] != kNoGBufferOutput);
    plan->velocity_attachment = plan->motion ? ext.motion->velocity_attachment : 0u;
    plan->motion_uniforms = MotionUniforms{};
    if (!plan->motion) return;
    const grass_view_motion_desc& d = *ext.motion;
    MotionUniforms& u = plan->motion_uniforms;
    const double none[3] = {0.0, 0.0, 0.0};
    unjittered_view_projection(view.view, view.projection, none, d.jitter, u.view_projection);
    double offset[3];
    for (int c = 0; c < 3; ++c) offset[c] = camera[c] - d.previous_camera_position[c];
    unjittered_view_projection(d.previous_view, d.previous_projection, offset, d.previous_jitter,
                               u.previous_view_projection);
    if (wind) {
        FrameUniforms previous{};
        pack_wind(*wind, camera, d.previous_time, up, &previous);
        for (int k = 0; k < 4; ++k) u.previous_wind_phase[k] = previous.wind_phase[k];
    }
    u.times[0] = static_cast<float>(time - d.previous_time);
    for (TierDraw& draw : plan->draws) {
        draw.features |= kFeatureMotion;
        draw.uniforms.tiling[3] = draw.features;
    }
}

} // namespace grass
