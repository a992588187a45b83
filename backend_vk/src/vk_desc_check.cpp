#include "vk_desc_check.hpp"

#include "foundation/raw_enum.hpp"

#include <vulkan/vulkan.h>

#include "context/context.hpp"

namespace grass::vk {

namespace {

// The checks of a chained grass_vk_host_objects_desc.
grass_result check_host_objects(grass_context* ctx, const char* function, const grass_vk_host_objects_desc& h) {
    if (h.allocation_callbacks) {
        const auto* c = static_cast<const VkAllocationCallbacks*>(h.allocation_callbacks);
        const struct {
            bool missing;
            const char* name;
        } callbacks[] = {
            {c->pfnAllocation == nullptr, "pfnAllocation"},
            {c->pfnReallocation == nullptr, "pfnReallocation"},
            {c->pfnFree == nullptr, "pfnFree"},
        };
        for (const auto& f : callbacks) {
            if (f.missing) {
                return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                                 "%s: grass_vk_host_objects_desc.allocation_callbacks->%s is NULL; Vulkan requires it",
                                 function, f.name);
            }
        }
        if ((c->pfnInternalAllocation == nullptr) != (c->pfnInternalFree == nullptr)) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                             "%s: grass_vk_host_objects_desc.allocation_callbacks has pfnInternal%s but not "
                             "pfnInternal%s; set both or neither",
                             function, c->pfnInternalFree ? "Free" : "Allocation",
                             c->pfnInternalFree ? "Allocation" : "Free");
        }
    }
    return GRASS_SUCCESS;
}

// The checks of a chained grass_vk_multiview_desc.
grass_result check_multiview(grass_context* ctx, const char* function, const grass_vk_multiview_desc& m) {
    if (m.view_mask != 0 && m.view_mask != 0x3u) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_vk_multiview_desc.view_mask is 0x%x; it must be 0 (mono) or 0x3 (stereo: views 0 "
                         "and 1, the two eyes of grass_stereo_view_desc)",
                         function, m.view_mask);
    }
    return GRASS_SUCCESS;
}

// The checks of a chained grass_vk_depth_pass_desc (what the device supports: load_device).
grass_result check_depth_pass(grass_context* ctx, const char* function, const grass_vk_depth_pass_desc& d) {
    if (d.depth_format == 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: grass_vk_depth_pass_desc.depth_format is 0 (VK_FORMAT_UNDEFINED); the depth-only "
                         "target's depth attachment needs its VkFormat",
                         function);
    }
    const uint32_t s = d.sample_count;
    if (s == 0 || s > 64 || (s & (s - 1)) != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_vk_depth_pass_desc.sample_count is %u; it must be a VkSampleCountFlagBits value "
                         "(1, 2, 4, 8, 16, 32 or 64)",
                         function, s);
    }
    if (d.render_pass == 0 && d.subpass != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_vk_depth_pass_desc.subpass is %u with render_pass 0 (dynamic rendering, which has "
                         "no subpasses); give 0",
                         function, d.subpass);
    }
    return GRASS_SUCCESS;
}

// The checks of a chained grass_vk_velocity_target_desc (`dynamic`: grass_vk_desc.render_pass 0).
grass_result check_velocity_target(grass_context* ctx, const char* function, const grass_vk_velocity_target_desc& v,
                                   bool dynamic) {
    if (v.color_attachment_count < 2 || v.color_attachment_count > 8) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_vk_velocity_target_desc.color_attachment_count is %u; it must be 2 to 8 (the lit "
                         "colour at attachment 0 and the velocity target among the others)",
                         function, v.color_attachment_count);
    }
    if (v.velocity_attachment < 1 || v.velocity_attachment >= v.color_attachment_count) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_vk_velocity_target_desc.velocity_attachment is %u; it must be 1 to %u "
                         "(color_attachment_count - 1; attachment 0 is the lit colour)",
                         function, v.velocity_attachment, v.color_attachment_count - 1);
    }
    for (uint32_t i = 1; dynamic && i < v.color_attachment_count; ++i) {
        if (v.color_formats[i - 1] == 0) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: grass_vk_velocity_target_desc.color_formats[%u] is 0 (VK_FORMAT_UNDEFINED); dynamic "
                             "rendering (render_pass 0) needs the VkFormat of colour attachment %u",
                             function, i - 1, i);
        }
    }
    return GRASS_SUCCESS;
}

// The checks of a chained grass_vk_gbuffer_target_desc (`dynamic`: grass_vk_desc.render_pass 0).
grass_result check_gbuffer_target(grass_context* ctx, const char* function, const grass_vk_gbuffer_target_desc& g,
                                  bool dynamic) {
    if (g.color_attachment_count < 1 || g.color_attachment_count > 8) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_vk_gbuffer_target_desc.color_attachment_count is %u; it must be 1 to 8", function,
                         g.color_attachment_count);
    }
    for (uint32_t i = 1; dynamic && i < g.color_attachment_count; ++i) {
        if (g.color_formats[i] == 0) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: grass_vk_gbuffer_target_desc.color_formats[%u] is 0 (VK_FORMAT_UNDEFINED); dynamic "
                             "rendering (render_pass 0) needs the VkFormat of colour attachment %u",
                             function, i, i);
        }
    }
    return GRASS_SUCCESS;
}

// Walks the extensions chained to vk_desc->next: each a known type, each once.
grass_result read_chain(grass_context* ctx, const char* function, const void* next, bool dynamic,
                        VkDescExtensions* out) {
    *out = VkDescExtensions{};
    bool has_host_objects = false, has_multiview = false;
    const auto known = [](uint32_t type) {
        return type == GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC || type == GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC ||
               type == GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC || type == GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC ||
               type == GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC;
    };
    while (next) {
        struct Header {
            grass_struct_type type;
            const void* next;
        };
        const uint32_t type = grass::raw_enum(static_cast<const Header*>(next)->type);
        grass_result r = GRASS_SUCCESS;
        if (type == GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC && !has_host_objects) {
            out->host_objects = *static_cast<const grass_vk_host_objects_desc*>(next);
            has_host_objects = true;
            next = out->host_objects.next;
            out->host_objects.next = nullptr;
            r = check_host_objects(ctx, function, out->host_objects);
        } else if (type == GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC && !has_multiview) {
            out->multiview = *static_cast<const grass_vk_multiview_desc*>(next);
            has_multiview = true;
            next = out->multiview.next;
            out->multiview.next = nullptr;
            r = check_multiview(ctx, function, out->multiview);
        } else if (type == GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC && !out->has_depth_pass) {
            out->depth_pass = *static_cast<const grass_vk_depth_pass_desc*>(next);
            out->has_depth_pass = true;
            next = out->depth_pass.next;
            out->depth_pass.next = nullptr;
            r = check_depth_pass(ctx, function, out->depth_pass);
        } else if (type == GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC && !out->has_velocity) {
            out->velocity = *static_cast<const grass_vk_velocity_target_desc*>(next);
            out->has_velocity = true;
            next = out->velocity.next;
            out->velocity.next = nullptr;
            r = check_velocity_target(ctx, function, out->velocity, dynamic);
        } else if (type == GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC && !out->has_gbuffer) {
            out->gbuffer = *static_cast<const grass_vk_gbuffer_target_desc*>(next);
            out->has_gbuffer = true;
            next = out->gbuffer.next;
            out->gbuffer.next = nullptr;
            r = check_gbuffer_target(ctx, function, out->gbuffer, dynamic);
        } else {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL,
                             "%s: vk_desc->next chain holds a struct of type 0x%08x%s; it may hold "
                             "GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC (0x%08x), GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC "
                             "(0x%08x), GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC (0x%08x), "
                             "GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC (0x%08x) and "
                             "GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC (0x%08x), each once",
                             function, static_cast<unsigned>(type), known(type) ? " a second time" : "",
                             static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC),
                             static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC),
                             static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC),
                             static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC),
                             static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC));
        }
        if (r != GRASS_SUCCESS) return r;
    }
    if (out->has_depth_pass && out->multiview.view_mask != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: vk_desc->next chains a grass_vk_depth_pass_desc and a grass_vk_multiview_desc with "
                         "view_mask 0x%x; depth passes are drawn by mono contexts only",
                         function, out->multiview.view_mask);
    }
    if (out->has_velocity && out->multiview.view_mask != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: vk_desc->next chains a grass_vk_velocity_target_desc and a grass_vk_multiview_desc with "
                         "view_mask 0x%x; motion vectors are drawn by mono contexts only",
                         function, out->multiview.view_mask);
    }
    if (out->has_gbuffer && out->multiview.view_mask != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: vk_desc->next chains a grass_vk_gbuffer_target_desc and a grass_vk_multiview_desc with "
                         "view_mask 0x%x; G-buffer views are drawn by mono contexts only",
                         function, out->multiview.view_mask);
    }
    if (out->has_gbuffer && out->has_velocity &&
        out->gbuffer.color_attachment_count != out->velocity.color_attachment_count) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_vk_gbuffer_target_desc.color_attachment_count is %u, but "
                         "grass_vk_velocity_target_desc.color_attachment_count is %u; both describe the one pass grass "
                         "draws in",
                         function, out->gbuffer.color_attachment_count, out->velocity.color_attachment_count);
    }
    return GRASS_SUCCESS;
}

} // namespace

grass_result check_vk_desc(grass_context* ctx, const char* function, const grass_vk_desc* d,
                           VkDescExtensions* extensions) {
    if (!d) return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: vk_desc is NULL", function);
    if (grass::raw_enum(d->type) != GRASS_STRUCT_TYPE_VK_DESC) {
        return ctx->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                         "%s: vk_desc->type is 0x%08x; expected GRASS_STRUCT_TYPE_VK_DESC (0x%08x)", function,
                         static_cast<unsigned>(grass::raw_enum(d->type)),
                         static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_DESC));
    }
    const grass_result chain = read_chain(ctx, function, d->next, d->render_pass == 0, extensions);
    if (chain != GRASS_SUCCESS) return chain;
    const struct {
        bool missing;
        const char* name;
    } required[] = {
        {d->get_instance_proc_addr == nullptr, "get_instance_proc_addr"},
        {d->instance == nullptr, "instance"},
        {d->physical_device == nullptr, "physical_device"},
        {d->device == nullptr, "device"},
    };
    for (const auto& r : required) {
        if (r.missing) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                             "%s: vk_desc->%s is NULL; it is required", function, r.name);
        }
    }
    const uint32_t s = d->sample_count;
    if (s == 0 || s > 64 || (s & (s - 1)) != 0) {
        return ctx->fail(
            GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
            "%s: vk_desc->sample_count is %u; it must be a VkSampleCountFlagBits value (1, 2, 4, 8, 16, 32 "
            "or 64)",
            function, s);
    }
    if (d->frames_in_flight < 1 || d->frames_in_flight > kMaxFramesInFlight) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: vk_desc->frames_in_flight is %u; it must be 1..%u", function, d->frames_in_flight,
                         kMaxFramesInFlight);
    }
    if (d->depth_format == 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: vk_desc->depth_format is 0 (VK_FORMAT_UNDEFINED); grass depth-tests against the host's "
                         "depth attachment, so its VkFormat is required",
                         function);
    }
    if (d->render_pass == 0 && d->color_format == 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: vk_desc->color_format is 0 (VK_FORMAT_UNDEFINED) with render_pass 0; dynamic rendering "
                         "needs the VkFormat of the colour attachment",
                         function);
    }
    return GRASS_SUCCESS;
}

} // namespace grass::vk
