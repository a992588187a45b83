// Entry points of backends left out of this build: they exist and say so.
#include "context/context.hpp"

#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

#include <cstring>

extern "C" {

#ifndef GRASS_HAS_GL
GRASS_API grass_gl_desc grass_default_gl_desc(void) {
    grass_gl_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_GL_DESC;
    return d;
}
GRASS_API grass_result grass_gl_create_context(uint32_t, const grass_context_desc* desc, const grass_gl_desc*,
                                               grass_context**) {
    if (desc && desc->log_fn) {
        desc->log_fn(desc->log_user_data, GRASS_LOG_ERROR, GRASS_MSG_DEVICE_UNSUPPORTED,
                     "grass_gl_create_context: this build of grass has no GL backend (GRASS_BUILD_GL=OFF)");
    }
    return GRASS_ERROR_UNSUPPORTED;
}
GRASS_API grass_result grass_gl_render(grass_context* context) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_WRONG_BACKEND,
                         "grass_gl_render: the context is not a GL context (this build has no GL backend)");
}
GRASS_API grass_result grass_gl_render_view(grass_context* context, uint32_t) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_WRONG_BACKEND,
                         "grass_gl_render_view: the context is not a GL context (this build has no GL backend)");
}
#endif

#ifndef GRASS_HAS_VULKAN
GRASS_API grass_vk_desc grass_default_vk_desc(void) {
    grass_vk_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_DESC;
    d.sample_count = 1;
    d.frames_in_flight = 2;
    return d;
}
GRASS_API grass_vk_host_objects_desc grass_default_vk_host_objects_desc(void) {
    grass_vk_host_objects_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC;
    return d;
}
GRASS_API grass_vk_multiview_desc grass_default_vk_multiview_desc(void) {
    grass_vk_multiview_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC;
    return d;
}
GRASS_API grass_vk_depth_pass_desc grass_default_vk_depth_pass_desc(void) {
    grass_vk_depth_pass_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC;
    d.sample_count = 1;
    return d;
}
GRASS_API grass_vk_velocity_target_desc grass_default_vk_velocity_target_desc(void) {
    grass_vk_velocity_target_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC;
    d.color_attachment_count = 2;
    d.velocity_attachment = 1;
    return d;
}
GRASS_API grass_vk_gbuffer_target_desc grass_default_vk_gbuffer_target_desc(void) {
    grass_vk_gbuffer_target_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC;
    d.color_attachment_count = 4;
    return d;
}
GRASS_API grass_vk_record_desc grass_default_vk_record_desc(void) {
    grass_vk_record_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_RECORD_DESC;
    return d;
}
GRASS_API grass_vk_prepare_desc grass_default_vk_prepare_desc(void) {
    grass_vk_prepare_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VK_PREPARE_DESC;
    return d;
}
GRASS_API grass_result grass_vk_create_context(uint32_t, const grass_context_desc* desc, const grass_vk_desc*,
                                               grass_context**) {
    if (desc && desc->log_fn) {
        desc->log_fn(desc->log_user_data, GRASS_LOG_ERROR, GRASS_MSG_DEVICE_UNSUPPORTED,
                     "grass_vk_create_context: this build of grass has no Vulkan backend (GRASS_BUILD_VULKAN=OFF)");
    }
    return GRASS_ERROR_UNSUPPORTED;
}
GRASS_API grass_result grass_vk_prepare(grass_context* context, const grass_vk_prepare_desc*) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_WRONG_BACKEND,
                         "grass_vk_prepare: the context is not a Vulkan context (this build has no Vulkan backend)");
}
GRASS_API grass_result grass_vk_record(grass_context* context, const grass_vk_record_desc*) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_WRONG_BACKEND,
                         "grass_vk_record: the context is not a Vulkan context (this build has no Vulkan backend)");
}
GRASS_API grass_result grass_vk_record_view(grass_context* context, uint32_t, const grass_vk_record_desc*) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_WRONG_BACKEND,
                         "grass_vk_record_view: the context is not a Vulkan context (this build has no Vulkan "
                         "backend)");
}
#endif

} // extern "C"
