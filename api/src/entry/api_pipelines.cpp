// C entry points of "Pipelines before the first frame" (grass.h): grass_prepare_pipelines
// declares the features the host will use and has the backend compile every variant they
// need (foundation/shader_variants.hpp decides which); grass_get_pipeline_cache_data hands
// the backend's own cache out as a blob (context/pipeline_blob.hpp).
#include "context/context.hpp"
#include "foundation/shader_variants.hpp"
#include "foundation/validate.hpp"

using grass::guarded;

namespace {

grass_result refuse_in_frame(grass_context* ctx, const char* fn) {
    if (!ctx->in_frame) return GRASS_SUCCESS;
    return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                     "%s: cannot be called between grass_begin_frame and grass_end_frame; compiling is what it "
                     "keeps out of frames",
                     fn);
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
        GRASS_TRY(GRASS_CHECK_DESC(context, fn, desc, GRASS_STRUCT_TYPE_PIPELINE_DESC));
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(refuse_in_frame(context, fn));
        if ((desc->features & ~static_cast<uint32_t>(GRASS_PIPELINE_FEATURE_ALL)) != 0) {
            return context->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                                 "%s: desc->features is 0x%x; only GRASS_PIPELINE_FEATURE_* bits (0x%x) are allowed",
                                 fn, desc->features, static_cast<unsigned>(GRASS_PIPELINE_FEATURE_ALL));
        }
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
        if (interaction) GRASS_TRY(context->backend->prepare_variants(fn, nullptr, 0, true, false));
        context->prepared_features = before | grass::declared_feature_bits(desc->features);
        for (uint32_t slot = 0; slot < context->fields.capacity(); ++slot) {
            const grass_result r = grass::prepare_field_variants(context, fn, slot);
            if (r != GRASS_SUCCESS) { // what was compiled stays; the declaration is the earlier one
                context->prepared_features = before;
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
