#include "vk_desc_check.hpp"

#include "foundation/raw_enum.hpp"

#include "context/context.hpp"

namespace grass::vk {

grass_result check_vk_desc(grass_context* ctx, const char* function, const grass_vk_desc* d) {
    if (!d) return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: vk_desc is NULL", function);
    if (grass::raw_enum(d->type) != GRASS_STRUCT_TYPE_VK_DESC) {
        return ctx->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                         "%s: vk_desc->type is 0x%08x; expected GRASS_STRUCT_TYPE_VK_DESC (0x%08x)", function,
                         static_cast<unsigned>(grass::raw_enum(d->type)),
                         static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_DESC));
    }
    if (d->next) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL, "%s: vk_desc->next must be NULL",
                         function);
    }
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
    if (d->view_mask != 0 && d->view_mask != 0x3u) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: vk_desc->view_mask is 0x%x; it must be 0 (mono) or 0x3 (stereo: views 0 and 1, the two "
                         "eyes of grass_stereo_view_desc)",
                         function, d->view_mask);
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
