// C entry points for frames and their views (grass.h "Frames and views"): begin the host's
// frame, validate and plan each view, end; stats.
#include "context/context.hpp"
#include "context/invariants.hpp"
#include "dynamics/colliders.hpp"
#include "dynamics/dynamics_plan.hpp"
#include "entry/api_gbuffer.hpp"
#include "entry/api_lights.hpp"
#include "entry/api_motion.hpp"
#include "foundation/abi_sizes.hpp"
#include "foundation/validate.hpp"
#include "plan/blade_window.hpp"
#include "plan/frame_planner.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace grass {
namespace {

// An eye: a position, a view with an invertible rotation and a projection (`who` names it).
grass_result check_eye(grass_context* ctx, const char* fn, const char* who, const double position[3],
                       const float view[16], const float projection[16]) {
    char name[64];
    std::snprintf(name, sizeof(name), "%s->camera_position", who);
    GRASS_TRY(check_world_position(ctx, fn, name, position));
    std::snprintf(name, sizeof(name), "%s->view", who);
    GRASS_TRY(check_finite_array(ctx, fn, name, view, 16));
    std::snprintf(name, sizeof(name), "%s->projection", who);
    GRASS_TRY(check_finite_array(ctx, fn, name, projection, 16));
    const float* m = view;
    double det = m[0] * (static_cast<double>(m[5]) * m[10] - static_cast<double>(m[9]) * m[6]) -
                 m[4] * (static_cast<double>(m[1]) * m[10] - static_cast<double>(m[9]) * m[2]) +
                 m[8] * (static_cast<double>(m[1]) * m[6] - static_cast<double>(m[5]) * m[2]);
    if (!(std::fabs(det) > 1e-6)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: %s->view has a singular rotation (determinant %g)", fn, who, det);
    }
    bool projection_zero = true;
    for (int k = 0; k < 16; ++k) projection_zero = projection_zero && projection[k] == 0.0f;
    if (projection_zero) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM, "%s: %s->projection is all zeros", fn,
                         who);
    }
    return GRASS_SUCCESS;
}

// A grass_view_pass_desc: a known pass, finite biases within range; a depth pass draws no
// debug view and keeps the depth test (it is all it writes).
grass_result check_pass(grass_context* ctx, const char* fn, const grass_view_pass_desc& pass, uint32_t view_flags) {
    const int64_t kind = raw_enum(pass.pass);
    if (kind != GRASS_PASS_COLOR && kind != GRASS_PASS_DEPTH && kind != GRASS_PASS_GBUFFER) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: grass_view_pass_desc->pass is %lld; expected GRASS_PASS_COLOR (0), GRASS_PASS_DEPTH (1) "
                         "or GRASS_PASS_GBUFFER (2)",
                         fn, static_cast<long long>(kind));
    }
    GRASS_TRY(
        check_range(ctx, fn, "grass_view_pass_desc->depth_bias_constant", pass.depth_bias_constant, -65536.0, 65536.0));
    GRASS_TRY(check_range(ctx, fn, "grass_view_pass_desc->depth_bias_slope", pass.depth_bias_slope, -64.0, 64.0));
    const uint32_t refused = kDebugViewFlags | GRASS_VIEW_FLAG_DEBUG_CELLS | GRASS_VIEW_FLAG_NO_DEPTH_TEST;
    if (kind != GRASS_PASS_COLOR && (view_flags & refused) != 0) {
        const bool depth = kind == GRASS_PASS_DEPTH;
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: view->flags is 0x%x with grass_view_pass_desc->pass %s; a %s pass takes no debug view "
                         "flag and no GRASS_VIEW_FLAG_NO_DEPTH_TEST",
                         fn, view_flags, depth ? "GRASS_PASS_DEPTH" : "GRASS_PASS_GBUFFER",
                         depth ? "depth" : "G-buffer");
    }
    return GRASS_SUCCESS;
}

// A grass_shadow_receive_desc: a map, 1-4 cascades with finite matrices and ascending
// positive ends, a known comparison, bias and radius in range.
grass_result check_shadow(grass_context* ctx, const char* fn, const grass_shadow_receive_desc& d) {
    if (d.shadow_map == 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_HANDLE,
                         "%s: grass_shadow_receive_desc->shadow_map is 0; expected the host's shadow map "
                         "(GL: a GL_TEXTURE_2D_ARRAY depth texture's name)",
                         fn);
    }
    if (d.cascade_count < 1 || d.cascade_count > GRASS_MAX_SHADOW_CASCADES) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_shadow_receive_desc->cascade_count is %u; expected 1 to %d", fn, d.cascade_count,
                         GRASS_MAX_SHADOW_CASCADES);
    }
    char name[80];
    for (uint32_t i = 0; i < d.cascade_count; ++i) {
        std::snprintf(name, sizeof(name), "grass_shadow_receive_desc->world_to_shadow[%u]", i);
        GRASS_TRY(check_finite_array(ctx, fn, name, d.world_to_shadow[i], 16));
        std::snprintf(name, sizeof(name), "grass_shadow_receive_desc->cascade_end[%u]", i);
        GRASS_TRY(check_finite_array(ctx, fn, name, &d.cascade_end[i], 1));
        const float before = i == 0 ? 0.0f : d.cascade_end[i - 1];
        if (!(d.cascade_end[i] > before)) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_RANGE_INVERTED,
                             "%s: grass_shadow_receive_desc->cascade_end[%u] is %g; it must be greater than %g (%s)",
                             fn, i, static_cast<double>(d.cascade_end[i]), static_cast<double>(before),
                             i == 0 ? "positive" : "the ends ascend");
        }
    }
    const int64_t compare = raw_enum(d.compare);
    if (compare != GRASS_SHADOW_COMPARE_LESS_EQUAL && compare != GRASS_SHADOW_COMPARE_GREATER_EQUAL) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: grass_shadow_receive_desc->compare is %lld; expected GRASS_SHADOW_COMPARE_LESS_EQUAL (0) "
                         "or GRASS_SHADOW_COMPARE_GREATER_EQUAL (1)",
                         fn, static_cast<long long>(compare));
    }
    GRASS_TRY(check_range(ctx, fn, "grass_shadow_receive_desc->depth_bias", d.depth_bias, 0.0, 1.0));
    GRASS_TRY(check_range(ctx, fn, "grass_shadow_receive_desc->filter_radius", d.filter_radius, 0.0, 16.0));
    return GRASS_SUCCESS;
}

// The view's extension chain (grass_view_desc.next): each known struct at most once.
grass_result parse_view_chain(grass_context* ctx, const char* fn, const grass_view_desc& v, ViewExtensions* out) {
    *out = ViewExtensions{};
    uint32_t position = 0;
    for (const void* p = v.next; p; ++position) {
        const auto* header = static_cast<const grass_view_desc*>(p); // every desc begins with type, next
        const int64_t type = raw_enum(header->type);
        if (type == GRASS_STRUCT_TYPE_STEREO_VIEW_DESC && !out->stereo) {
            out->stereo = static_cast<const grass_stereo_view_desc*>(p);
            GRASS_TRY(check_eye(ctx, fn, "grass_stereo_view_desc", out->stereo->camera_position, out->stereo->view,
                                out->stereo->projection));
            p = out->stereo->next;
        } else if (type == GRASS_STRUCT_TYPE_LOD_ORIGIN_DESC && !out->lod_origin) {
            out->lod_origin = static_cast<const grass_lod_origin_desc*>(p);
            GRASS_TRY(check_world_position(ctx, fn, "grass_lod_origin_desc->position", out->lod_origin->position));
            p = out->lod_origin->next;
        } else if (type == GRASS_STRUCT_TYPE_VIEW_PASS_DESC && !out->pass) {
            out->pass = static_cast<const grass_view_pass_desc*>(p);
            GRASS_TRY(check_pass(ctx, fn, *out->pass, v.flags));
            p = out->pass->next;
        } else if (type == GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC && !out->shadow) {
            out->shadow = static_cast<const grass_shadow_receive_desc*>(p);
            GRASS_TRY(check_shadow(ctx, fn, *out->shadow));
            p = out->shadow->next;
        } else if (type == GRASS_STRUCT_TYPE_VIEW_MOTION_DESC && !out->motion) {
            out->motion = static_cast<const grass_view_motion_desc*>(p);
            GRASS_TRY(check_view_motion(ctx, fn, *out->motion));
            p = out->motion->next;
        } else if (type == GRASS_STRUCT_TYPE_VIEW_LIGHTS_DESC && !out->lights) {
            out->lights = static_cast<const grass_view_lights_desc*>(p);
            GRASS_TRY(check_view_lights(ctx, fn, *out->lights));
            p = out->lights->next;
        } else if (type == GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC && !out->gbuffer) {
            out->gbuffer = static_cast<const grass_view_gbuffer_desc*>(p);
            GRASS_TRY(check_view_gbuffer(ctx, fn, *out->gbuffer));
            p = out->gbuffer->next;
        } else {
            return ctx->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                             "%s: view->next chain element %u has type 0x%08x; expected "
                             "GRASS_STRUCT_TYPE_STEREO_VIEW_DESC, GRASS_STRUCT_TYPE_LOD_ORIGIN_DESC, "
                             "GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC, GRASS_STRUCT_TYPE_VIEW_MOTION_DESC, "
                             "GRASS_STRUCT_TYPE_VIEW_LIGHTS_DESC, GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC or "
                             "GRASS_STRUCT_TYPE_VIEW_PASS_DESC, each at most once",
                             fn, position, static_cast<unsigned>(type));
        }
    }
    return check_gbuffer_chain(ctx, fn, *out);
}

// Vulkan: the layout the host's map is in while grass's pass runs is one grass samples a
// depth image in (VkImageLayout values: the core includes no Vulkan header); a multiview
// (stereo) pass receives no shadows.
grass_result check_vk_shadow(grass_context* ctx, const char* fn, const grass_shadow_receive_desc& d,
                             const RenderTarget& target) {
    static const struct {
        uint32_t value;
        const char* name;
    } kLayouts[] = {{4, "VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL"},
                    {1000241001, "VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL"},
                    {5, "VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL"},
                    {1000314000, "VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL"},
                    {1, "VK_IMAGE_LAYOUT_GENERAL"}};
    bool known = false;
    for (const auto& l : kLayouts) known = known || l.value == d.vk_image_layout;
    if (!known) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: grass_shadow_receive_desc->vk_image_layout is %u; expected the VkImageLayout the map is "
                         "in while grass's pass runs: %s (%u), %s (%u), %s (%u), %s (%u) or %s (%u)",
                         fn, d.vk_image_layout, kLayouts[0].name, kLayouts[0].value, kLayouts[1].name,
                         kLayouts[1].value, kLayouts[2].name, kLayouts[2].value, kLayouts[3].name, kLayouts[3].value,
                         kLayouts[4].name, kLayouts[4].value);
    }
    if (target.views != 1) {
        return ctx->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                         "%s: view->next chains a grass_shadow_receive_desc, but the context draws into a multiview "
                         "pass (grass_vk_multiview_desc.view_mask 0x3), whose views do not receive the host's shadow "
                         "maps; draw the eyes as two mono frames to receive them",
                         fn);
    }
    return GRASS_SUCCESS;
}

// A stereo frame needs a target of two views, and a target of two views a stereo frame.
// A depth pass needs a target to draw in (Vulkan: grass_vk_depth_pass_desc). A multiview pass
// (Vulkan stereo) receives no shadows and is not lit by the host's lights.
grass_result check_views(grass_context* ctx, const char* fn, const ViewExtensions& ext) {
    if (!ctx->backend || ctx->backend->kind() == GRASS_BACKEND_NONE) return GRASS_SUCCESS; // plans only
    const RenderTarget target = ctx->backend->render_target();
    if (ext.pass && ext.pass->pass == GRASS_PASS_DEPTH && !target.depth_pass) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_DEVICE_UNSUPPORTED,
                         "%s: view->next chains a grass_view_pass_desc with GRASS_PASS_DEPTH, but the context was "
                         "created without a grass_vk_depth_pass_desc (chained on grass_vk_desc.next): the depth-only "
                         "target grass makes its depth pipelines for",
                         fn);
    }
    if (ext.pass && ext.pass->pass == GRASS_PASS_GBUFFER && ctx->backend->kind() == GRASS_BACKEND_VULKAN) {
        if (target.gbuffer_attachments == 0) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_GBUFFER_TARGET,
                             "%s: view->next chains a grass_view_pass_desc with GRASS_PASS_GBUFFER, but the context "
                             "was made without a grass_vk_gbuffer_target_desc on grass_vk_desc.next, which names the "
                             "pass's colour attachments that grass makes its G-buffer pipelines for",
                             fn);
        }
        if (ext.gbuffer && ext.gbuffer->attachment_count != target.gbuffer_attachments) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_GBUFFER_TARGET,
                             "%s: grass_view_gbuffer_desc->attachment_count is %u, but the context's "
                             "grass_vk_gbuffer_target_desc.color_attachment_count is %u (attachment i of the layout "
                             "is colour attachment i of the pass)",
                             fn, ext.gbuffer->attachment_count, target.gbuffer_attachments);
        }
    }
    if (ext.shadow && ctx->backend->kind() == GRASS_BACKEND_VULKAN)
        GRASS_TRY(check_vk_shadow(ctx, fn, *ext.shadow, target));
    if (ext.motion && ctx->backend->kind() == GRASS_BACKEND_VULKAN &&
        !(ext.pass && ext.pass->pass == GRASS_PASS_DEPTH)) {
        if (target.velocity_attachment == 0) {
            return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_VELOCITY_TARGET,
                             "%s: view->next chains a grass_view_motion_desc, but the context was made without a "
                             "grass_vk_velocity_target_desc on grass_vk_desc.next, which names the pass's colour "
                             "attachments that grass makes its motion pipelines for",
                             fn);
        }
        if (ext.motion->velocity_attachment != target.velocity_attachment) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_VELOCITY_TARGET,
                             "%s: grass_view_motion_desc->velocity_attachment is %u, but the context's "
                             "grass_vk_velocity_target_desc.velocity_attachment is %u (its motion pipelines write "
                             "that colour attachment)",
                             fn, ext.motion->velocity_attachment, target.velocity_attachment);
        }
    }
    if (ext.lights && !(ext.pass && ext.pass->pass == GRASS_PASS_DEPTH) && target.views != 1) {
        return ctx->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                         "%s: view->next chains a grass_view_lights_desc, but the context draws into a multiview "
                         "pass (grass_vk_multiview_desc.view_mask 0x3), whose views are not lit by the host's "
                         "lights; draw the eyes as two mono frames to light them",
                         fn);
    }
    const uint32_t views = target.views;
    if (ext.stereo && views == 2) return GRASS_SUCCESS;
    if (!ext.stereo && views == 1) return GRASS_SUCCESS;
    if (ctx->backend->kind() == GRASS_BACKEND_GL) {
        return ctx->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                         "%s: view->next chains a grass_stereo_view_desc, but the GL backend has no multiview path "
                         "(GL_OVR_multiview, which Mesa's llvmpipe does not expose): draw the eyes "
                         "as two mono frames",
                         fn);
    }
    if (ext.stereo) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_DEVICE_UNSUPPORTED,
                         "%s: view->next chains a grass_stereo_view_desc, but the context was created with "
                         "grass_vk_multiview_desc.view_mask 0 (a mono pass); create it with view_mask 0x3",
                         fn);
    }
    return ctx->fail(
        GRASS_ERROR_INVALID_STATE, GRASS_MSG_DEVICE_UNSUPPORTED,
        "%s: the context draws into a multiview pass (grass_vk_multiview_desc.view_mask 0x3) but view->next "
        "chains no grass_stereo_view_desc (the second eye)",
        fn);
}

grass_result validate_view(grass_context* ctx, const char* fn, const grass_view_desc* view, ViewExtensions* ext) {
    if (!view) return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: view is NULL", fn);
    GRASS_TRY(check_desc_header(ctx, fn, "view", view, raw_enum(view->type), nullptr, GRASS_STRUCT_TYPE_VIEW_DESC,
                                "GRASS_STRUCT_TYPE_VIEW_DESC"));
    const grass_view_desc& v = *view;
    GRASS_TRY(check_eye(ctx, fn, "view", v.camera_position, v.view, v.projection));
    GRASS_TRY(parse_view_chain(ctx, fn, v, ext));
    GRASS_TRY(check_views(ctx, fn, *ext));
    if (v.viewport[2] <= 0 || v.viewport[3] <= 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: view->viewport is %d x %d pixels; width and height must be > 0", fn, v.viewport[2],
                         v.viewport[3]);
    }
    GRASS_TRY(check_finite_array(ctx, fn, "view->sun_direction", v.sun_direction, 3));
    const double sun2 = static_cast<double>(v.sun_direction[0]) * v.sun_direction[0] +
                        static_cast<double>(v.sun_direction[1]) * v.sun_direction[1] +
                        static_cast<double>(v.sun_direction[2]) * v.sun_direction[2];
    if (!(sun2 > 1e-12)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_ZERO_VECTOR,
                         "%s: view->sun_direction is (%g, %g, %g); it must point towards the sun (length > 1e-6)", fn,
                         static_cast<double>(v.sun_direction[0]), static_cast<double>(v.sun_direction[1]),
                         static_cast<double>(v.sun_direction[2]));
    }
    static const char* const sun_names[3] = {"view->sun_color[0]", "view->sun_color[1]", "view->sun_color[2]"};
    static const char* const amb_names[3] = {"view->ambient_color[0]", "view->ambient_color[1]",
                                             "view->ambient_color[2]"};
    for (int c = 0; c < 3; ++c) {
        GRASS_TRY(check_range(ctx, fn, sun_names[c], v.sun_color[c], 0.0, 1e6));
        GRASS_TRY(check_range(ctx, fn, amb_names[c], v.ambient_color[c], 0.0, 1e6));
    }
    GRASS_TRY(check_range(ctx, fn, "view->time", v.time, -1e9, 1e9));
    if (v.flags & ~static_cast<uint32_t>(GRASS_VIEW_FLAG_NO_DEPTH_TEST | GRASS_VIEW_FLAG_DEBUG_TIERS |
                                         GRASS_VIEW_FLAG_DEBUG_CELLS | GRASS_VIEW_FLAG_DEBUG_THRESHOLDS |
                                         GRASS_VIEW_FLAG_ENCODE_SRGB)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: view->flags is 0x%x; unknown bits are set", fn, v.flags);
    }
    return GRASS_SUCCESS;
}

// Before the backend's begin_frame: the blade curves of each patch a responsive draw uses,
// once per patch.
grass_result upload_blade_curves(grass_context* ctx, const FramePlan& plan) {
    for (const TierDraw& draw : plan.draws) {
        if ((draw.features & kBladeCurveFeatures) == 0) continue;
        Patch* patch = ctx->patches.get(draw.patch_slot);
        if (patch->blade_curves_uploaded) continue;
        const grass_result r = ctx->backend->upload_blade_curves(draw.patch_slot, patch->data);
        if (r != GRASS_SUCCESS) return r;
        patch->blade_curves_uploaded = true;
    }
    return GRASS_SUCCESS;
}

grass_result refuse_in_frame(grass_context* ctx, const char* fn) {
    if (!ctx->in_frame) return GRASS_SUCCESS;
    return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                     "%s: a frame has already begun; call grass_end_frame first", fn);
}

grass_result validate_frame(grass_context* ctx, const char* fn, const grass_frame_desc* frame) {
    GRASS_TRY(GRASS_CHECK_DESC(ctx, fn, frame, GRASS_STRUCT_TYPE_FRAME_DESC));
    const HostFrame& last = ctx->host_frame;
    if (frame->frame_index == 0 || frame->frame_index <= last.index) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: frame->frame_index is %llu; it must be at least 1 and greater than the previous "
                         "frame's %llu",
                         fn, static_cast<unsigned long long>(frame->frame_index),
                         static_cast<unsigned long long>(last.index));
    }
    if (frame->completed_frame_index >= frame->frame_index || frame->completed_frame_index < last.completed) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: frame->completed_frame_index is %llu; it must be less than frame_index %llu and not "
                         "less than the previous frame's %llu",
                         fn, static_cast<unsigned long long>(frame->completed_frame_index),
                         static_cast<unsigned long long>(frame->frame_index),
                         static_cast<unsigned long long>(last.completed));
    }
    return check_range(ctx, fn, "frame->time", frame->time, -1e9, 1e9);
}

// Begins a validated host frame; `implied`: grass_begin_frame's, whose host promises that the
// frame frames_in_flight before has finished. The backend may refuse it: nothing changes then.
grass_result begin_host_frame(grass_context* ctx, const char* fn, const grass_frame_desc& frame, bool implied) {
    HostFrame next;
    next.index = frame.frame_index;
    next.completed = frame.completed_frame_index;
    next.time = frame.time;
    GRASS_TRY(ctx->backend->begin_host_frame(fn, next, implied));
    ctx->host_frame = next;
    ctx->views.begin();
    ctx->in_frame = true;
    ctx->frame_number += 1;
    return GRASS_SUCCESS;
}

// Plans the next view of the begun frame from a validated view.
grass_result plan_view(grass_context* ctx, const char* fn, const grass_view_desc& view,
                       const ViewExtensions& extensions) {
    const uint32_t index = ctx->views.count();
    FramePlan& plan = ctx->views.next();
    const FramePlanning planning{ctx->fields,
                                 ctx->patches,
                                 ctx->maps,
                                 ctx->dynamics,
                                 plan,
                                 ctx->plan_scratch,
                                 *ctx,
                                 ctx->lod_callbacks_running,
                                 ctx->desc.depth_mode,
                                 ctx->backend ? ctx->backend->render_target() : RenderTarget{},
                                 ctx->host_frame.time,
                                 index > 0 ? &ctx->views.plan(0) : nullptr,
                                 ctx->backend && ctx->backend->runs_blade_window(),
                                 ctx->backend && ctx->backend->compacts_blade_window()};
    GRASS_TRY(build_frame_plan(planning, view, extensions));
    GRASS_TRY(check_plan(ctx, fn, plan));
    GRASS_TRY(upload_blade_curves(ctx, plan));
    GRASS_TRY(ctx->backend->begin_view(fn, index, plan));
    if (index == 0) { // one step per frame
        commit_dynamics(&ctx->dynamics);
        keep_blade_window(plan.blade_window, &ctx->dynamics.window);
    }
    ctx->views.commit();
    return GRASS_SUCCESS;
}

void end_frame(grass_context* ctx) {
    ctx->backend->end_frame();
    ctx->in_frame = false;
}
} // namespace
} // namespace grass

using grass::guarded;

extern "C" {

GRASS_API grass_view_desc grass_default_view_desc(void) {
    grass_view_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VIEW_DESC;
    d.view[0] = d.view[5] = d.view[10] = d.view[15] = 1.0f;
    d.projection[0] = d.projection[5] = d.projection[10] = d.projection[15] = 1.0f;
    d.viewport[2] = 1;
    d.viewport[3] = 1;
    const float sun[3] = {0.35f, 0.8f, 0.25f}, sun_color[3] = {1.0f, 0.95f, 0.85f}, ambient[3] = {0.30f, 0.36f, 0.45f};
    std::memcpy(d.sun_direction, sun, sizeof(sun));
    std::memcpy(d.sun_color, sun_color, sizeof(sun_color));
    std::memcpy(d.ambient_color, ambient, sizeof(ambient));
    return d;
}

GRASS_API grass_stereo_view_desc grass_default_stereo_view_desc(void) {
    grass_stereo_view_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_STEREO_VIEW_DESC;
    d.view[0] = d.view[5] = d.view[10] = d.view[15] = 1.0f;
    d.projection[0] = d.projection[5] = d.projection[10] = d.projection[15] = 1.0f;
    return d;
}

GRASS_API grass_lod_origin_desc grass_default_lod_origin_desc(void) {
    grass_lod_origin_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_LOD_ORIGIN_DESC;
    return d;
}

GRASS_API grass_view_pass_desc grass_default_view_pass_desc(void) {
    grass_view_pass_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VIEW_PASS_DESC;
    d.pass = GRASS_PASS_COLOR;
    return d;
}

GRASS_API grass_shadow_receive_desc grass_default_shadow_receive_desc(void) {
    grass_shadow_receive_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC;
    d.cascade_count = 1;
    for (int i = 0; i < GRASS_MAX_SHADOW_CASCADES; ++i) {
        for (int k = 0; k < 4; ++k) d.world_to_shadow[i][k * 5] = 1.0f;
        d.cascade_end[i] = 1e30f;
    }
    d.compare = GRASS_SHADOW_COMPARE_LESS_EQUAL;
    d.depth_bias = 0.0005f;
    d.filter_radius = 1.0f;
    return d;
}

GRASS_API grass_frame_desc grass_default_frame_desc(void) {
    grass_frame_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_FRAME_DESC;
    d.frame_index = 1;
    return d;
}

GRASS_API grass_result grass_begin_frame(grass_context* context, const grass_view_desc* view) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_begin_frame", [&] {
        const char* fn = "grass_begin_frame";
        GRASS_TRY(grass::check_gpu_current(context, fn)); // responsive grass uploads here
        GRASS_TRY(grass::refuse_in_frame(context, fn));
        // The view first: a refused view begins no frame.
        grass::ViewExtensions extensions;
        GRASS_TRY(grass::validate_view(context, fn, view, &extensions));
        grass_frame_desc frame = grass_default_frame_desc();
        frame.frame_index = context->host_frame.index + 1;
        frame.completed_frame_index = context->host_frame.completed;
        frame.time = view->time;
        GRASS_TRY(grass::check_collider_sweeps(context, fn, context->dynamics, frame.time));
        GRASS_TRY(grass::begin_host_frame(context, fn, frame, true));
        // A view that fails to plan (an error, or std::bad_alloc on its way to guarded) leaves
        // no frame begun, as before grass_begin_host_frame existed.
        struct EndUnlessPlanned {
            grass_context* ctx;
            bool planned = false;
            ~EndUnlessPlanned() {
                if (!planned) grass::end_frame(ctx);
            }
        } frame_guard{context};
        GRASS_TRY(grass::plan_view(context, fn, *view, extensions));
        frame_guard.planned = true;
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_result grass_begin_host_frame(grass_context* context, const grass_frame_desc* frame) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_begin_host_frame", [&] {
        const char* fn = "grass_begin_host_frame";
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(grass::refuse_in_frame(context, fn));
        GRASS_TRY(grass::validate_frame(context, fn, frame));
        GRASS_TRY(grass::check_collider_sweeps(context, fn, context->dynamics, frame->time));
        return grass::begin_host_frame(context, fn, *frame, false);
    });
}

GRASS_API grass_result grass_plan_view(grass_context* context, const grass_view_desc* view, uint32_t* out_view) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_plan_view", [&] {
        const char* fn = "grass_plan_view";
        GRASS_TRY(grass::check_gpu_current(context, fn)); // responsive grass uploads here
        GRASS_TRY(grass::check_not_null(context, fn, "out_view", out_view));
        if (!context->in_frame) {
            return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_NOT_BEGUN,
                                 "%s: no frame has begun; call grass_begin_host_frame first", fn);
        }
        if (context->views.count() >= GRASS_MAX_VIEWS_PER_FRAME) {
            return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_OUT_OF_RANGE,
                                 "%s: the frame has %u views already, GRASS_MAX_VIEWS_PER_FRAME", fn,
                                 context->views.count());
        }
        grass::ViewExtensions extensions;
        GRASS_TRY(grass::validate_view(context, fn, view, &extensions));
        const uint32_t index = context->views.count();
        GRASS_TRY(grass::plan_view(context, fn, *view, extensions));
        *out_view = index;
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_result grass_end_frame(grass_context* context) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    GRASS_TRY(grass::check_entry(context, "grass_end_frame"));
    if (!context->in_frame) {
        return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_NOT_BEGUN,
                             "grass_end_frame: no frame has begun; call grass_begin_frame first");
    }
    grass::end_frame(context);
    return GRASS_SUCCESS;
}

GRASS_API grass_result grass_get_frame_stats(const grass_context* context, grass_frame_stats* out_stats) {
    auto* ctx = const_cast<grass_context*>(context); // logging only
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    const char* fn = "grass_get_frame_stats";
    GRASS_TRY(grass::check_entry(ctx, fn));
    GRASS_TRY(grass::check_not_null(ctx, fn, "out_stats", out_stats));
    const uint32_t views = context->views.count(); // the last planned view's
    const grass::FramePlan& last = views > 0 ? context->views.plan(views - 1) : context->plan;
    grass::write_out_struct(context->header_minor, last.stats, out_stats);
    return GRASS_SUCCESS;
}

GRASS_API grass_result grass_get_tier_gpu_ms(const grass_context* context, double out_ms[GRASS_TIER_KIND_COUNT],
                                             grass_bool* out_available) {
    // The context is const for the host; polling the backend's queries is not a change
    // the host can see.
    grass_context* ctx = const_cast<grass_context*>(context);
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    const char* fn = "grass_get_tier_gpu_ms";
    GRASS_TRY(grass::check_entry(ctx, fn));
    GRASS_TRY(grass::check_not_null(ctx, fn, "out_ms", out_ms));
    GRASS_TRY(grass::check_not_null(ctx, fn, "out_available", out_available));
    for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = 0.0;
    *out_available = 0;
    if (!ctx->backend) return GRASS_SUCCESS;
    double ms[GRASS_TIER_KIND_COUNT] = {};
    return guarded(ctx, fn, [&] {
        GRASS_TRY(grass::check_gpu_current(ctx, fn)); // polls the timer queries
        if (ctx->backend->tier_gpu_ms(ms)) {
            for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) out_ms[k] = ms[k] > 0.0 ? ms[k] : 0.0;
            *out_available = 1;
        }
        return GRASS_SUCCESS;
    });
}

} // extern "C"
