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

// Walks the extensions chained to vk_desc->next: each a known type, each once.
grass_result read_chain(grass_context* ctx, const char* function, const void* next,
                        grass_vk_host_objects_desc* host_objects) {
    *host_objects = grass_default_vk_host_objects_desc();
    bool has_host_objects = false;
    for (int depth = 0; next; ++depth) {
        struct Header {
            grass_struct_type type;
            const void* next;
        };
        const auto* header = static_cast<const Header*>(next);
        const uint32_t type = grass::raw_enum(header->type);
        if (type != GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC || has_host_objects || depth > 0) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL,
                             "%s: vk_desc->next chain holds a struct of type 0x%08x; it may hold "
                             "GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC (0x%08x), once",
                             function, static_cast<unsigned>(type),
                             static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC));
        }
        *host_objects = *static_cast<const grass_vk_host_objects_desc*>(next);
        has_host_objects = true;
        next = host_objects->next;
        host_objects->next = nullptr;
        const grass_result r = check_host_objects(ctx, function, *host_objects);
        if (r != GRASS_SUCCESS) return r;
    }
    return GRASS_SUCCESS;
}

} // namespace

grass_result check_vk_desc(grass_context* ctx, const char* function, const grass_vk_desc* d,
                           grass_vk_host_objects_desc* host_objects) {
    if (!d) return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: vk_desc is NULL", function);
    if (grass::raw_enum(d->type) != GRASS_STRUCT_TYPE_VK_DESC) {
        return ctx->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                         "%s: vk_desc->type is 0x%08x; expected GRASS_STRUCT_TYPE_VK_DESC (0x%08x)", function,
                         static_cast<unsigned>(grass::raw_enum(d->type)),
                         static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_DESC));
    }
    const grass_result chain = read_chain(ctx, function, d->next, host_objects);
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
