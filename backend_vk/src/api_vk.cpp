// The public entry points of grass_vk.h: argument checks, then the Vulkan backend.
#include "context/context.hpp"
#include "foundation/names.hpp"
#include "vk_backend.hpp"
#include "vk_desc_check.hpp"
#include "vk_device.hpp"

#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"

#include <grass/grass_vk.h>

#include <cstddef>
#include <cstring>

using grass::vk::VkBackend;

namespace {

grass_result make_backend(grass_context* ctx, void* user_data, grass::Backend** out_backend) {
    const char* function = "grass_vk_create_context";
    const auto* vk_desc = static_cast<const grass_vk_desc*>(user_data);
    grass::vk::VkDescExtensions extensions;
    grass_result r = grass::vk::check_vk_desc(ctx, function, vk_desc, &extensions);
    if (r != GRASS_SUCCESS) return r;
    grass_vk_desc copy = *vk_desc;
    copy.next = nullptr; // its extensions are read (extensions); the host's chain is not kept
    grass::vk::Device device;
    r = grass::vk::load_device(ctx, function, copy, extensions, &device);
    if (r != GRASS_SUCCESS) return r;

    VkBackend* backend = ctx->host.create<VkBackend>(ctx, copy, device);
    try {
        r = backend->init(function);
    } catch (...) {
        ctx->host.destroy(backend);
        throw;
    }
    if (r != GRASS_SUCCESS) {
        ctx->host.destroy(backend);
        return r;
    }
    *out_backend = backend;
    return GRASS_SUCCESS;
}

// The checks every recording call makes; on success *out is the context's backend.
grass_result check_frame_call(grass_context* ctx, const char* function, VkBackend** out) {
    if (ctx->backend == nullptr || ctx->backend->kind() != GRASS_BACKEND_VULKAN) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_WRONG_BACKEND,
                         "%s: the context was made by %s; only a context made by grass_vk_create_context records "
                         "Vulkan commands",
                         function, grass::backend_creator(ctx->backend ? ctx->backend->kind() : GRASS_BACKEND_NONE));
    }
    if (!ctx->in_frame) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_NOT_BEGUN,
                         "%s: no frame is begun; call grass_begin_frame() first", function);
    }
    *out = static_cast<VkBackend*>(ctx->backend);
    return GRASS_SUCCESS;
}

// grass_vk_record and grass_vk_record_view (view 0 for the first).
grass_result record_view(grass_context* ctx, const char* function, uint32_t view, const grass_vk_record_desc* record) {
    VkBackend* backend = nullptr;
    GRASS_TRY(check_frame_call(ctx, function, &backend));
    if (!record)
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: record is NULL", function);
    if (grass::raw_enum(record->type) != GRASS_STRUCT_TYPE_VK_RECORD_DESC) {
        return ctx->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                         "%s: record->type is 0x%08x; expected GRASS_STRUCT_TYPE_VK_RECORD_DESC (0x%08x)", function,
                         static_cast<unsigned>(grass::raw_enum(record->type)),
                         static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_RECORD_DESC));
    }
    if (record->next) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL, "%s: record->next must be NULL",
                         function);
    }
    if (!record->command_buffer) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: record->command_buffer is NULL",
                         function);
    }
    GRASS_TRY(grass::check_view_planned(ctx, function, view));
    return backend->record(function, static_cast<VkCommandBuffer>(record->command_buffer), view);
}

} // namespace

grass_vk_desc grass_default_vk_desc(void) {
    grass_vk_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_DESC;
    d.sample_count = 1;
    d.frames_in_flight = 2;
    return d;
}

grass_vk_host_objects_desc grass_default_vk_host_objects_desc(void) {
    grass_vk_host_objects_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC;
    return d;
}

grass_vk_multiview_desc grass_default_vk_multiview_desc(void) {
    grass_vk_multiview_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC;
    return d;
}

grass_vk_depth_pass_desc grass_default_vk_depth_pass_desc(void) {
    grass_vk_depth_pass_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC;
    d.sample_count = 1;
    return d;
}

grass_vk_velocity_target_desc grass_default_vk_velocity_target_desc(void) {
    grass_vk_velocity_target_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC;
    d.color_attachment_count = 2;
    d.velocity_attachment = 1;
    return d;
}

grass_vk_gbuffer_target_desc grass_default_vk_gbuffer_target_desc(void) {
    grass_vk_gbuffer_target_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC;
    d.color_attachment_count = 4;
    return d;
}

grass_vk_record_desc grass_default_vk_record_desc(void) {
    grass_vk_record_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_RECORD_DESC;
    return d;
}

grass_vk_prepare_desc grass_default_vk_prepare_desc(void) {
    grass_vk_prepare_desc d{};
    d.type = GRASS_STRUCT_TYPE_VK_PREPARE_DESC;
    return d;
}

grass_result grass_vk_create_context(uint32_t header_version, const grass_context_desc* desc,
                                     const grass_vk_desc* vk_desc, grass_context** out_context) {
    // vk_desc is checked by the factory, once the context can log.
    return grass::create_context("grass_vk_create_context", header_version, desc, make_backend,
                                 const_cast<grass_vk_desc*>(vk_desc), out_context);
}

grass_result grass_vk_prepare(grass_context* ctx, const grass_vk_prepare_desc* prepare) {
    const char* function = "grass_vk_prepare";
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    return grass::guarded(ctx, function, [&] {
        VkBackend* backend = nullptr;
        grass_result r = check_frame_call(ctx, function, &backend);
        if (r != GRASS_SUCCESS) return r;
        if (!prepare)
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: prepare is NULL", function);
        if (grass::raw_enum(prepare->type) != GRASS_STRUCT_TYPE_VK_PREPARE_DESC) {
            return ctx->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                             "%s: prepare->type is 0x%08x; expected GRASS_STRUCT_TYPE_VK_PREPARE_DESC (0x%08x)",
                             function, static_cast<unsigned>(grass::raw_enum(prepare->type)),
                             static_cast<unsigned>(GRASS_STRUCT_TYPE_VK_PREPARE_DESC));
        }
        if (prepare->next) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL, "%s: prepare->next must be NULL",
                             function);
        }
        if (!prepare->command_buffer) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                             "%s: prepare->command_buffer is NULL", function);
        }
        return backend->prepare_frame(static_cast<VkCommandBuffer>(prepare->command_buffer));
    });
}

grass_result grass_vk_record(grass_context* ctx, const grass_vk_record_desc* record) {
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    return grass::guarded(ctx, "grass_vk_record", [&] { return record_view(ctx, "grass_vk_record", 0, record); });
}

grass_result grass_vk_record_view(grass_context* ctx, uint32_t view, const grass_vk_record_desc* record) {
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    return grass::guarded(ctx, "grass_vk_record_view",
                          [&] { return record_view(ctx, "grass_vk_record_view", view, record); });
}
