// C entry points for patches (grass types).
#include "context/context.hpp"
#include "context/id_checks.hpp"
#include "foundation/abi_sizes.hpp"
#include "foundation/validate.hpp"
#include "patch/patch_generator.hpp"

#include <cstring>

namespace grass {
namespace {

grass_result validate_patch_desc(grass_context* ctx, const char* fn, const grass_patch_desc* desc) {
    GRASS_TRY(GRASS_CHECK_DESC(ctx, fn, desc, GRASS_STRUCT_TYPE_PATCH_DESC));
    const grass_patch_desc& d = *desc;
    GRASS_TRY(check_range(ctx, fn, "desc->blade_count", d.blade_count, 1, 65536));
    GRASS_TRY(check_range(ctx, fn, "desc->subdivisions", d.subdivisions, 1, 32));
    GRASS_TRY(check_min_max(ctx, fn, "desc->length_min", "desc->length_max", d.length_min, d.length_max, 1e3));
    if (d.length_max <= 0.0f) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: desc->length_max is %g; it must be > 0", fn, static_cast<double>(d.length_max));
    }
    if (d.length_min <= 0.0f) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: desc->length_min is %g; it must be > 0", fn, static_cast<double>(d.length_min));
    }
    GRASS_TRY(check_min_max(ctx, fn, "desc->width_min", "desc->width_max", d.width_min, d.width_max, 1e3));
    GRASS_TRY(check_min_max(ctx, fn, "desc->tilt_min", "desc->tilt_max", d.tilt_min, d.tilt_max, 1.5));
    GRASS_TRY(check_min_max(ctx, fn, "desc->bend_min", "desc->bend_max", d.bend_min, d.bend_max, 2.0));
    GRASS_TRY(check_finite_array(ctx, fn, "desc->root_color", d.root_color, 3));
    GRASS_TRY(check_finite_array(ctx, fn, "desc->tip_color", d.tip_color, 3));
    static const char* const root_names[3] = {"desc->root_color[0]", "desc->root_color[1]", "desc->root_color[2]"};
    static const char* const tip_names[3] = {"desc->tip_color[0]", "desc->tip_color[1]", "desc->tip_color[2]"};
    for (int c = 0; c < 3; ++c) {
        GRASS_TRY(check_range(ctx, fn, root_names[c], d.root_color[c], 0.0, 1.0));
        GRASS_TRY(check_range(ctx, fn, tip_names[c], d.tip_color[c], 0.0, 1.0));
    }
    GRASS_TRY(check_range(ctx, fn, "desc->blade_color_variation", d.blade_color_variation, 0.0, 1.0));
    GRASS_TRY(check_range(ctx, fn, "desc->vertex_color_variation", d.vertex_color_variation, 0.0, 1.0));
    const int64_t mode = raw_enum(d.threshold_mode);
    if (mode != GRASS_THRESHOLD_UNIFORM && mode != GRASS_THRESHOLD_CLUSTERED) {
        return ctx->fail(
            GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
            "%s: desc->threshold_mode is %lld; it must be GRASS_THRESHOLD_UNIFORM or GRASS_THRESHOLD_CLUSTERED", fn,
            static_cast<long long>(mode));
    }
    GRASS_TRY(check_range(ctx, fn, "desc->cluster_sigma", d.cluster_sigma, 0.0, 1.0));
    GRASS_TRY(check_range(ctx, fn, "desc->cluster_frequency", d.cluster_frequency, 1, 64));
    GRASS_TRY(check_range(ctx, fn, "desc->ao_impact", d.ao_impact, 0.0, 1.0));
    GRASS_TRY(check_range(ctx, fn, "desc->ao_height", d.ao_height, 1e-6, 1e3));
    return GRASS_SUCCESS;
}

grass_result create_patch(grass_context* ctx, const grass_patch_desc* desc, grass_patch_id* out) {
    const char* fn = "grass_create_patch";
    GRASS_TRY(check_not_null(ctx, fn, "out_patch", out));
    GRASS_TRY(validate_patch_desc(ctx, fn, desc));

    Patch* patch = ctx->host.create<Patch>(&ctx->host);
    patch->desc = *desc;
    try {
        generate_patch(*desc, &ctx->host, &patch->data);
    } catch (...) {
        ctx->host.destroy(patch);
        throw;
    }
    const uint32_t slot = ctx->patches.insert(patch);
    const grass_result r = ctx->backend->upload_patch(slot, patch->data);
    if (r != GRASS_SUCCESS) {
        ctx->backend->release_patch(slot);
        ctx->patches.erase(slot);
        return r;
    }
    out->index = slot + 1;
    out->generation = ctx->patches.generation(slot);
    out->owner = ctx->owner;
    ctx->info(GRASS_MSG_PATCH_GENERATED, "%s: %u blades, %u triangles, hash %016llx", fn, patch->data.blade_count,
              static_cast<unsigned>(patch->data.full_index_count() / 3),
              static_cast<unsigned long long>(patch->data.content_hash));
    return GRASS_SUCCESS;
}

} // namespace
} // namespace grass

using grass::guarded;

extern "C" {

GRASS_API grass_patch_desc grass_default_patch_desc(void) {
    grass_patch_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_PATCH_DESC;
    d.blade_count = 384;
    d.subdivisions = 4;
    d.length_min = 0.45f;
    d.length_max = 0.85f;
    d.width_min = 0.018f;
    d.width_max = 0.032f;
    d.tilt_min = 0.05f;
    d.tilt_max = 0.55f;
    d.bend_min = 0.2f;
    d.bend_max = 0.7f;
    const float root[3] = {0.05f, 0.12f, 0.02f}, tip[3] = {0.28f, 0.45f, 0.09f};
    std::memcpy(d.root_color, root, sizeof(root));
    std::memcpy(d.tip_color, tip, sizeof(tip));
    d.blade_color_variation = 0.35f;
    d.vertex_color_variation = 0.08f;
    d.threshold_mode = GRASS_THRESHOLD_CLUSTERED;
    d.cluster_sigma = 0.12f;
    d.cluster_frequency = 3;
    d.ao_impact = 0.65f;
    d.ao_height = 0.55f;
    d.seed = 1;
    return d;
}

GRASS_API grass_result grass_create_patch(grass_context* context, const grass_patch_desc* desc,
                                          grass_patch_id* out_patch) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_create_patch", [&] {
        GRASS_TRY(grass::check_gpu_current(context, "grass_create_patch"));
        return grass::create_patch(context, desc, out_patch);
    });
}

GRASS_API grass_result grass_destroy_patch(grass_context* context, grass_patch_id patch) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_destroy_patch", [&] {
        const char* fn = "grass_destroy_patch";
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(grass::check_patch_id(context, fn, "patch", patch));
        const uint32_t slot = patch.index - 1;
        const grass::Patch* p = context->patches.get(slot);
        if (p->field_users > 0) {
            return context->fail(GRASS_ERROR_IN_USE, GRASS_MSG_PATCH_IN_USE,
                                 "%s: patch (index %u) is used by %u field(s); destroy them first", fn, patch.index,
                                 p->field_users);
        }
        if (context->in_frame) {
            return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                                 "%s: cannot destroy a patch between grass_begin_frame and grass_end_frame", fn);
        }
        context->backend->release_patch(slot);
        context->patches.erase(slot);
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_result grass_get_patch_info(const grass_context* context, grass_patch_id patch,
                                            grass_patch_info* out_info) {
    auto* ctx = const_cast<grass_context*>(context); // logging only
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    const char* fn = "grass_get_patch_info";
    GRASS_TRY(grass::check_entry(ctx, fn));
    GRASS_TRY(grass::check_not_null(ctx, fn, "out_info", out_info));
    GRASS_TRY(grass::check_patch_id(ctx, fn, "patch", patch));
    const grass::PatchData& d = ctx->patches.get(patch.index - 1)->data;
    grass_patch_info info{};
    info.blade_count = d.blade_count;
    info.vertex_count = static_cast<uint32_t>(d.vertices.size());
    info.triangle_count = d.full_index_count() / 3;
    for (int c = 0; c < 3; ++c) {
        info.bounds_min[c] = d.bounds_min[c];
        info.bounds_max[c] = d.bounds_max[c];
    }
    info.content_hash = d.content_hash;
    grass::write_out_struct(ctx->header_minor, info, out_info);
    return GRASS_SUCCESS;
}

GRASS_API grass_result grass_get_patch_thresholds(const grass_context* context, grass_patch_id patch,
                                                  float* out_thresholds, uint32_t capacity) {
    auto* ctx = const_cast<grass_context*>(context);
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    const char* fn = "grass_get_patch_thresholds";
    GRASS_TRY(grass::check_entry(ctx, fn));
    GRASS_TRY(grass::check_not_null(ctx, fn, "out_thresholds", out_thresholds));
    GRASS_TRY(grass::check_patch_id(ctx, fn, "patch", patch));
    const grass::PatchData& d = ctx->patches.get(patch.index - 1)->data;
    if (capacity < d.blade_count) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: capacity is %u; the patch has %u blades", fn, capacity, d.blade_count);
    }
    std::memcpy(out_thresholds, d.thresholds.data(), d.blade_count * sizeof(float));
    return GRASS_SUCCESS;
}

} // extern "C"
