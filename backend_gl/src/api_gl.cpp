// The C entry points of grass_gl.h.
#include "gl_backend.hpp"

#include "context/context.hpp"
#include "foundation/names.hpp"
#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"

#include <grass/grass_gl.h>

namespace {

constexpr const char* kCreate = "grass_gl_create_context";

// Runs inside grass::create_context once the context (and so its log) exists, so that
// gl_desc errors are reported with message ids like every other argument error.
grass_result gl_backend_factory(grass_context* ctx, void* user_data, grass::Backend** out_backend) {
    const auto* gl_desc = static_cast<const grass_gl_desc*>(user_data);
    if (gl_desc == nullptr) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: gl_desc is NULL", kCreate);
    }
    if (grass::raw_enum(gl_desc->type) != GRASS_STRUCT_TYPE_GL_DESC) {
        return ctx->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                         "%s: gl_desc->type is 0x%08X, expected GRASS_STRUCT_TYPE_GL_DESC (0x%08X); fill it with "
                         "grass_default_gl_desc()",
                         kCreate, static_cast<unsigned>(grass::raw_enum(gl_desc->type)),
                         static_cast<unsigned>(GRASS_STRUCT_TYPE_GL_DESC));
    }
    if (gl_desc->next != nullptr) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL,
                         "%s: gl_desc->next is %p; it is reserved and must be NULL", kCreate, gl_desc->next);
    }
    if (gl_desc->get_proc_address == nullptr) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                         "%s: gl_desc->get_proc_address is NULL; pass the GL loader (e.g. eglGetProcAddress)", kCreate);
    }
    return grass::GlBackend::create(ctx, *gl_desc, out_backend);
}

grass_result render_view(grass_context* context, const char* function, uint32_t view) {
    const grass_backend kind = context->backend ? context->backend->kind() : GRASS_BACKEND_NONE;
    if (kind != GRASS_BACKEND_GL) {
        return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_WRONG_BACKEND,
                             "%s: the context was made by %s, not grass_gl_create_context", function,
                             grass::backend_creator(kind));
    }
    GRASS_TRY(grass::check_gpu_current(context, function));
    if (!context->in_frame) {
        return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_NOT_BEGUN,
                             "%s: no frame has begun; call grass_begin_frame first", function);
    }
    GRASS_TRY(grass::check_view_planned(context, function, view));
    return static_cast<grass::GlBackend*>(context->backend)->render_checked(function, view);
}

} // namespace

extern "C" {

GRASS_API grass_gl_desc grass_default_gl_desc(void) {
    grass_gl_desc desc{};
    desc.type = GRASS_STRUCT_TYPE_GL_DESC;
    return desc;
}

GRASS_API grass_result grass_gl_create_context(uint32_t header_version, const grass_context_desc* desc,
                                               const grass_gl_desc* gl_desc, grass_context** out_context) {
    return grass::create_context(kCreate, header_version, desc, gl_backend_factory, const_cast<grass_gl_desc*>(gl_desc),
                                 out_context);
}

GRASS_API grass_result grass_gl_render(grass_context* context) {
    if (context == nullptr) return GRASS_ERROR_INVALID_ARGUMENT;
    return grass::guarded(context, "grass_gl_render", [&] { return render_view(context, "grass_gl_render", 0); });
}

GRASS_API grass_result grass_gl_render_view(grass_context* context, uint32_t view) {
    if (context == nullptr) return GRASS_ERROR_INVALID_ARGUMENT;
    return grass::guarded(context, "grass_gl_render_view",
                          [&] { return render_view(context, "grass_gl_render_view", view); });
}

} // extern "C"
