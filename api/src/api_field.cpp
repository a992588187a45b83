// C entry points for fields: a grid of cells covered by one patch.
#include "context.hpp"
#include "design_map.hpp"
#include "lod_setup.hpp"
#include "tier_slices.hpp"
#include "validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace grass {
namespace {

// base_transform must be finite, rigid (orthonormal rotation, no scale or shear: the cell
// size scales) and affine (last row 0 0 0 1).
grass_result validate_base_transform(grass_context* ctx, const char* fn, const double* m) {
    GRASS_TRY(check_finite_array(ctx, fn, "desc->base_transform", m, 16));
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: desc->base_transform's last row is (%g, %g, %g, %g); it must be (0, 0, 0, 1)", fn, m[3],
                         m[7], m[11], m[15]);
    }
    constexpr double kTolerance = 1e-5;
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
            const double dot = m[4 * a] * m[4 * b] + m[4 * a + 1] * m[4 * b + 1] + m[4 * a + 2] * m[4 * b + 2];
            if (std::fabs(dot - (a == b ? 1.0 : 0.0)) > kTolerance) {
                return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                                 "%s: desc->base_transform is not a rotation plus translation (columns %d and %d have "
                                 "dot product %g); scale the field with cell_size instead",
                                 fn, a, b, dot);
            }
        }
    }
    const double det = m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
                       m[8] * (m[1] * m[6] - m[5] * m[2]);
    if (det < 0.0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: desc->base_transform mirrors space (determinant %g); it must be a proper rotation", fn, det);
    }
    return GRASS_SUCCESS;
}

grass_result validate_field_desc(grass_context* ctx, const char* fn, const grass_field_desc* desc) {
    GRASS_TRY(GRASS_CHECK_DESC(ctx, fn, desc, GRASS_STRUCT_TYPE_FIELD_DESC));
    const grass_field_desc& d = *desc;
    GRASS_TRY(check_patch_id(ctx, fn, "desc->patch", d.patch));
    if (d.cells_x == 0 || d.cells_z == 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_ZERO_CELLS,
                         "%s: desc->cells_x x desc->cells_z is %u x %u; a field needs at least one cell each way", fn,
                         d.cells_x, d.cells_z);
    }
    GRASS_TRY(check_range(ctx, fn, "desc->cells_x", d.cells_x, 1, 1u << 30));
    GRASS_TRY(check_range(ctx, fn, "desc->cells_z", d.cells_z, 1, 1u << 30));
    GRASS_TRY(check_range(ctx, fn, "desc->cell_size", d.cell_size, 1e-4, 1e4));
    GRASS_TRY(validate_base_transform(ctx, fn, d.base_transform));
    GRASS_TRY(check_range(ctx, fn, "desc->density", d.density, 0.0, 1.0));
    GRASS_TRY(check_range(ctx, fn, "desc->transition_window", d.transition_window, 0.0, 0.25));
    return GRASS_SUCCESS;
}

grass_result create_field(grass_context* ctx, const grass_field_desc* desc, grass_field_id* out) {
    const char* fn = "grass_create_field";
    GRASS_TRY(check_not_null(ctx, fn, "out_field", out));
    GRASS_TRY(validate_field_desc(ctx, fn, desc));

    LodSetup lod;
    GRASS_TRY(make_lod_setup(ctx, fn, *desc, &lod));
    // The slices the tiers draw from: baked (or read from the cache) and uploaded once per
    // patch and slice count; a later failure of this call leaves them for the next field.
    GRASS_TRY(prepare_tier_slices(ctx, fn, desc->patch.index - 1, lod));

    Field* field = ctx->host.create<Field>(&ctx->host);
    field->lod = lod;
    if (desc->density_map) {
        const grass_result r = convert_map(ctx, fn, "desc->density_map", desc->density_map, &field->density_texels);
        if (r != GRASS_SUCCESS) {
            ctx->host.destroy(field);
            return r;
        }
        field->density_width = desc->density_map->width;
        field->density_height = desc->density_map->height;
    }
    field->desc = *desc;
    field->desc.density_map = nullptr; // never keep host pointers
    field->desc.tiers = nullptr;
    field->desc.lod_tests = nullptr;
    field->tree = QuadtreeShape(desc->cells_x, desc->cells_z);
    // The band of each tier for the transition weights: its first distance-band test; a
    // tier chosen by other tests only counts at every distance.
    for (uint32_t t = 0; t < lod.tier_count; ++t) {
        float* band = field->bands[t];
        band[0] = 0.0f;
        band[1] = 3.0e38f;
        band[2] = band[3] = 0.0f;
        for (uint32_t k = 0; k < lod.test_count; ++k) {
            const grass_lod_test& test = lod.tests[k];
            if (test.tier != t || test.kind != GRASS_LOD_TEST_DISTANCE_BAND) continue;
            band[0] = test.begin;
            band[1] = std::min(test.end, 3.0e38f);
            band[2] = test.transition_in;
            band[3] = test.transition_out;
            break;
        }
    }
    // Flat field: every level spans the patch's blades vertically. Tips may lean out of
    // their cell; mirroring makes the overhang the same on both sides.
    const PatchData& pd = ctx->patches.get(desc->patch.index - 1)->data;
    field->overhang = std::max({0.0, -static_cast<double>(pd.bounds_min[0]), pd.bounds_max[0] - 1.0,
                                -static_cast<double>(pd.bounds_min[2]), pd.bounds_max[2] - 1.0});
    for (uint32_t level = 0; level < field->tree.levels(); ++level) {
        field->extents[level].min_y = std::min(0.0f, pd.bounds_min[1]);
        field->extents[level].max_y = std::max(0.0f, pd.bounds_max[1]);
    }
    field->patch_slot = desc->patch.index - 1;
    const double* m = desc->base_transform;
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) field->rotation[3 * c + r] = m[4 * c + r];
        field->translation[c] = m[12 + c];
    }

    const uint32_t slot = ctx->fields.insert(field);
    MapTexels density;
    if (!field->density_texels.empty()) {
        density.texels = field->density_texels.data();
        density.width = field->density_width;
        density.height = field->density_height;
    }
    const grass_result r = ctx->backend->upload_field(slot, density);
    if (r != GRASS_SUCCESS) {
        ctx->backend->release_field(slot);
        ctx->fields.erase(slot);
        return r;
    }
    ctx->patches.get(field->patch_slot)->field_users += 1;
    out->index = slot + 1;
    out->generation = ctx->fields.generation(slot);
    out->owner = ctx->owner;
    return GRASS_SUCCESS;
}

} // namespace
} // namespace grass

using grass::guarded;

extern "C" {

GRASS_API grass_map_desc grass_default_map_desc(void) {
    grass_map_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_MAP_DESC;
    d.format = GRASS_MAP_FORMAT_R8_UNORM;
    return d;
}

GRASS_API grass_field_desc grass_default_field_desc(void) {
    grass_field_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_FIELD_DESC;
    d.cell_size = 0.25;
    d.base_transform[0] = d.base_transform[5] = d.base_transform[10] = d.base_transform[15] = 1.0;
    d.density = 1.0f;
    d.mirror_tiling = 1;
    d.transition_window = 0.05f;
    return d;
}

GRASS_API grass_result grass_create_field(grass_context* context, const grass_field_desc* desc, grass_field_id* out_field) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_create_field", [&] { return grass::create_field(context, desc, out_field); });
}

GRASS_API grass_result grass_destroy_field(grass_context* context, grass_field_id field) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_destroy_field", [&] {
        const char* fn = "grass_destroy_field";
        GRASS_TRY(grass::check_field_id(context, fn, "field", field));
        if (context->in_frame) {
            return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                                 "%s: cannot destroy a field between grass_begin_frame and grass_end_frame", fn);
        }
        const uint32_t slot = field.index - 1;
        context->patches.get(context->fields.get(slot)->patch_slot)->field_users -= 1;
        context->backend->release_field(slot);
        context->fields.erase(slot);
        return GRASS_SUCCESS;
    });
}

} // extern "C"
