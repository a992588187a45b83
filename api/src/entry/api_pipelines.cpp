// C entry points of "Pipelines before the first frame" (grass.h): grass_prepare_pipelines
// declares the features the host will use and has the backend compile every variant they
// need (foundation/shader_variants.hpp decides which); grass_get_pipeline_cache_data hands
// the backend's own cache out as a blob (context/pipeline_blob.hpp).
#include "context/context.hpp"
#include "entry/api_gbuffer.hpp"
#include "foundation/raw_enum.hpp"
#include "foundation/shader_variants.hpp"
#include "foundation/validate.hpp"
#include "plan/gbuffer_plan.hpp"

using grass::guarded;

namespace {

grass_result refuse_in_frame(grass_context* ctx, const char* fn) {
    if (!ctx->in_frame) return GRASS_SUCCESS;
    return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                     "%s: cannot be called between grass_begin_frame and grass_end_frame; compiling is what it "
                     "keeps out of frames",
                     fn);
}

// desc->next: NULL, or the G-buffer layout GRASS_PIPELINE_FEATURE_GBUFFER prepares (required
// with that bit, refused without it; on Vulkan of the context's G-buffer target's count).
grass_result read_gbuffer_layout(grass_context* ctx, const char* fn, const grass_pipeline_desc& desc,
                                 const grass_view_gbuffer_desc** out) {
    *out = nullptr;
    const bool gbuffer = (desc.features & GRASS_PIPELINE_FEATURE_GBUFFER) != 0;
    if (desc.next == nullptr) {
        if (!gbuffer) return GRASS_SUCCESS;
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                         "%s: desc->features 0x%x has GRASS_PIPELINE_FEATURE_GBUFFER (0x%x), but desc->next is NULL; "
                         "chain the grass_view_gbuffer_desc of the G-buffer views to prepare (Vulkan makes their "
                         "pipelines per layout)",
                         fn, desc.features, static_cast<unsigned>(GRASS_PIPELINE_FEATURE_GBUFFER));
    }
    const auto* layout = static_cast<const grass_view_gbuffer_desc*>(desc.next);
    GRASS_TRY(grass::check_desc_header(ctx, fn, "desc->next", layout, grass::raw_enum(layout->type), layout->next,
                                       GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC, "GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC"));
    if (!gbuffer) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL,
                         "%s: desc->next chains a grass_view_gbuffer_desc, but desc->features 0x%x lacks "
                         "GRASS_PIPELINE_FEATURE_GBUFFER (0x%x), the only feature that reads it",
                         fn, desc.features, static_cast<unsigned>(GRASS_PIPELINE_FEATURE_GBUFFER));
    }
    GRASS_TRY(grass::check_view_gbuffer(ctx, fn, *layout));
    const grass::RenderTarget target = ctx->backend->render_target();
    if (ctx->backend->kind() == GRASS_BACKEND_VULKAN && target.gbuffer_attachments != 0 &&
        layout->attachment_count != target.gbuffer_attachments) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_GBUFFER_TARGET,
                         "%s: grass_view_gbuffer_desc->attachment_count is %u, but the context's "
                         "grass_vk_gbuffer_target_desc.color_attachment_count is %u (attachment i of the layout is "
                         "colour attachment i of the pass)",
                         fn, layout->attachment_count, target.gbuffer_attachments);
    }
    *out = layout;
    return GRASS_SUCCESS;
}

// Adds `layout` to the context's declared G-buffer layouts unless it is there; true if added.
bool remember_gbuffer_layout(grass_context* ctx, const grass::GBufferLayout& layout) {
    for (const grass::GBufferLayout& l : ctx->prepared_gbuffer_layouts) {
        if (l == layout) return false;
    }
    ctx->prepared_gbuffer_layouts.push_back(layout);
    return true;
}

} // namespace

extern "C" {

GRASS_API grass_pipeline_desc grass_default_pipeline_desc(void) {
    grass_pipeline_desc d{};
    d.type = GRASS_STRUCT_TYPE_PIPELINE_DESC;
    d.features = GRASS_PIPELINE_FEATURE_ALL & ~static_cast<uint32_t>(GRASS_PIPELINE_FEATURE_DEBUG_VIEWS);
    return d;
}

GRASS_API grass_result grass_prepare_pipelines(grass_context* context, const grass_pipeline_desc* desc) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_prepare_pipelines", [&] {
        const char* fn = "grass_prepare_pipelines";
        // desc->next may chain a G-buffer layout (read_gbuffer_layout): the header alone here.
        GRASS_TRY(grass::check_desc_header(
            context, fn, "desc", desc, desc ? grass::raw_enum(desc->type) : int64_t{GRASS_STRUCT_TYPE_PIPELINE_DESC},
            nullptr, GRASS_STRUCT_TYPE_PIPELINE_DESC, "GRASS_STRUCT_TYPE_PIPELINE_DESC"));
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(refuse_in_frame(context, fn));
        const uint32_t known = GRASS_PIPELINE_FEATURE_ALL | GRASS_PIPELINE_FEATURE_ALL_VIEWS;
        if ((desc->features & ~known) != 0) {
            return context->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                                 "%s: desc->features is 0x%x; only GRASS_PIPELINE_FEATURE_* bits (0x%x) are allowed",
                                 fn, desc->features, known);
        }
        const grass_view_gbuffer_desc* layout = nullptr;
        GRASS_TRY(read_gbuffer_layout(context, fn, *desc, &layout));
        if ((desc->cache_data == nullptr) != (desc->cache_data_size == 0)) {
            return context->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                                 "%s: desc->cache_data is %s with desc->cache_data_size %llu; give both or neither", fn,
                                 desc->cache_data ? "set" : "NULL",
                                 static_cast<unsigned long long>(desc->cache_data_size));
        }
        if (desc->cache_data)
            GRASS_TRY(context->backend->seed_pipeline_cache(fn, desc->cache_data, desc->cache_data_size));
        // The union with what was declared before: nothing made is released, and a field
        // created later gets every variant declared so far.
        const uint32_t before = context->prepared_features;
        const bool interaction = (desc->features & GRASS_PIPELINE_FEATURE_INTERACTION) != 0;
        if (interaction) GRASS_TRY(context->backend->prepare_variants(fn, nullptr, 0, true, false, nullptr));
        const bool added = layout && remember_gbuffer_layout(context, grass::gbuffer_layout(*layout));
        context->prepared_features = before | grass::declared_feature_bits(desc->features);
        for (uint32_t slot = 0; slot < context->fields.capacity(); ++slot) {
            const grass_result r = grass::prepare_field_variants(context, fn, slot);
            if (r != GRASS_SUCCESS) { // what was compiled stays; the declaration is the earlier one
                context->prepared_features = before;
                if (added) context->prepared_gbuffer_layouts.pop_back();
                return r;
            }
        }
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_result grass_get_pipeline_cache_data(grass_context* context, void* data, uint64_t* size) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_get_pipeline_cache_data", [&] {
        const char* fn = "grass_get_pipeline_cache_data";
        GRASS_TRY(grass::check_not_null(context, fn, "size", size));
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(refuse_in_frame(context, fn));
        if (data != nullptr && *size == 0) {
            return context->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                                 "%s: *size is 0 with data given; call with data NULL first to learn the size", fn);
        }
        return context->backend->pipeline_cache_data(fn, data, size);
    });
}

} // extern "C"
