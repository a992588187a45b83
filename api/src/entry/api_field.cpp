// C entry points for fields: a grid of cells covered by one patch.
#include "context/context.hpp"
#include "context/id_checks.hpp"
#include "context/invariants.hpp"
#include "context/tier_slices.hpp"
#include "entry/api_map.hpp"
#include "foundation/validate.hpp"
#include "maps/design_map.hpp"
#include "plan/lod_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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
    // The translation within +-1e12 m, the camera's bound (api_frame.cpp): beyond it a
    // double's spacing passes 0.1 mm and camera-relative cells lose their precision.
    for (int c = 12; c < 15; ++c) {
        if (std::fabs(m[c]) > 1e12) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->base_transform[%d] (translation) is %g; it must be within +-1e12 m", fn, c,
                             m[c]);
        }
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
    const double det =
        m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) + m[8] * (m[1] * m[6] - m[5] * m[2]);
    if (det < 0.0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: desc->base_transform mirrors space (determinant %g); it must be a proper rotation", fn,
                         det);
    }
    return GRASS_SUCCESS;
}

// The map stack: valid ids, formats that fit their roles, a finite height scale and an
// invertible cell-to-map transform.
grass_result validate_map_stack(grass_context* ctx, const char* fn, const grass_field_desc& d) {
    const grass_map_stack& m = d.maps;
    const grass_map_id ids[kMapRoleCount] = {m.density, m.color, m.ambient, m.diffuse, m.height};
    static const char* const names[kMapRoleCount] = {"desc->maps.density", "desc->maps.color", "desc->maps.ambient",
                                                     "desc->maps.diffuse", "desc->maps.height"};
    for (uint32_t r = 0; r < kMapRoleCount; ++r) {
        const grass_map_id id = ids[r];
        if (id.index == 0 && id.generation == 0 && id.owner == 0) continue; // none
        GRASS_TRY(check_map_id(ctx, fn, names[r], id));
        const uint32_t channels = ctx->maps.get(id.index - 1)->channels;
        const uint32_t wanted = r == kMapColor ? 4 : 1;
        if (channels != wanted) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                             "%s: %s has %u channel(s); a %s map needs %s", fn, names[r], channels,
                             r == kMapColor ? "colour" : "density, ambient, diffuse or height",
                             wanted == 4 ? "an RGBA format" : "a single-channel (R) format");
        }
    }
    if (d.density_map && m.density.index != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                         "%s: desc->density_map and desc->maps.density are both set; give one density map", fn);
    }
    GRASS_TRY(check_range(ctx, fn, "desc->maps.height_scale", m.height_scale, 0.0, 1e5));
    GRASS_TRY(check_finite_array(ctx, fn, "desc->maps.cell_to_map", m.cell_to_map, 6));
    bool all_zero = true;
    for (double v : m.cell_to_map) all_zero = all_zero && v == 0.0;
    const double det = m.cell_to_map[0] * m.cell_to_map[3] - m.cell_to_map[1] * m.cell_to_map[2];
    if (!all_zero && !(std::fabs(det) > 0.0)) {
        return ctx->fail(
            GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
            "%s: desc->maps.cell_to_map maps the field onto a line (determinant %g); it must be invertible, "
            "or all zero for maps that span the field",
            fn, det);
    }
    return GRASS_SUCCESS;
}

// The desc of one grass type, validated as a field (its next is NULL: checked by the caller).
grass_result validate_field_desc(grass_context* ctx, const char* fn, const grass_field_desc* desc) {
    GRASS_TRY(check_not_null(ctx, fn, "desc", desc));
    GRASS_TRY(check_desc_header(ctx, fn, "desc", desc, raw_enum(desc->type), nullptr, GRASS_STRUCT_TYPE_FIELD_DESC,
                                "GRASS_STRUCT_TYPE_FIELD_DESC"));
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
    return validate_map_stack(ctx, fn, d);
}

// Makes one field (one grass type) from a validated desc; `parent` is the slot of the
// host's field for a hidden grass type, or none.
grass_result create_one_field(grass_context* ctx, const char* fn, const grass_field_desc* desc, uint32_t parent,
                              uint32_t* out_slot) {
    LodSetup lod;
    GRASS_TRY(make_lod_setup(ctx, fn, *desc, &lod));
    // The slices the tiers draw from: baked (or read from the cache) and uploaded once per
    // patch and slice count; a later failure of this call leaves them for the next field.
    GRASS_TRY(prepare_tier_slices(ctx, fn, desc->patch.index - 1, lod));

    Field* field = ctx->host.create<Field>();
    field->lod = lod;
    field->parent = parent;
    if (desc->density_map) {
        grass_result r = GRASS_SUCCESS;
        try {
            r = make_map(ctx, fn, "desc->density_map", desc->density_map, true, &field->maps.map_slot[kMapDensity]);
        } catch (...) { // out of memory: nothing of this call is left
            ctx->host.destroy(field);
            throw;
        }
        if (r != GRASS_SUCCESS) {
            ctx->host.destroy(field);
            return r;
        }
        if (ctx->maps.get(field->maps.map_slot[kMapDensity])->channels != 1) {
            release_map(ctx, field->maps.map_slot[kMapDensity]);
            ctx->host.destroy(field);
            return ctx->fail(
                GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                "%s: desc->density_map has an RGBA format; a density map needs a single-channel (R) format", fn);
        }
        field->owns_density_map = true;
    }
    {
        const grass_map_stack& m = desc->maps;
        const grass_map_id ids[kMapRoleCount] = {m.density, m.color, m.ambient, m.diffuse, m.height};
        for (uint32_t r = 0; r < kMapRoleCount; ++r) {
            if (ids[r].index != 0) field->maps.map_slot[r] = ids[r].index - 1;
        }
        for (uint32_t r = 0; r < kMapRoleCount; ++r) {
            if (field->maps.map_slot[r] != kNoMap) field->maps.features |= 1u << r;
        }
        bool all_zero = true;
        for (double v : m.cell_to_map) all_zero = all_zero && v == 0.0;
        if (all_zero) {
            field->cell_to_map[0] = 1.0 / desc->cells_x;
            field->cell_to_map[3] = 1.0 / desc->cells_z;
        } else {
            for (int k = 0; k < 6; ++k) field->cell_to_map[k] = m.cell_to_map[k];
        }
        field->height_scale = field->maps.map_slot[kMapHeight] != kNoMap ? m.height_scale : 0.0;
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
        if (lod.overlay_tiers & (1u << t)) { // hilltop tiers take no share: weight 0 at every distance
            band[0] = band[1] = -1.0f;
            continue;
        }
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

    // On any failure from here on, nothing of this call is left (nor on std::bad_alloc).
    const bool owned = field->owns_density_map;
    const uint32_t density_slot = field->maps.map_slot[kMapDensity];
    uint32_t slot = 0;
    try {
        slot = ctx->fields.insert(field); // destroys the field if the pool cannot grow
    } catch (...) {
        if (owned) release_map(ctx, density_slot);
        throw;
    }
    auto undo = [&] {
        ctx->backend->release_field(slot);
        ctx->fields.erase(slot);
        if (owned) release_map(ctx, density_slot);
    };
    grass_result r = GRASS_SUCCESS;
    try {
        r = check_field_maps(ctx, fn, slot, field->maps);
        if (r == GRASS_SUCCESS) r = ctx->backend->upload_field(slot, field->maps);
        if (r == GRASS_SUCCESS) r = prepare_field_variants(ctx, fn, slot);
    } catch (...) {
        undo();
        throw;
    }
    if (r != GRASS_SUCCESS) {
        undo();
        return r;
    }
    ctx->patches.get(field->patch_slot)->field_users += 1;
    for (uint32_t map_slot : field->maps.map_slot) {
        if (map_slot != kNoMap) ctx->maps.get(map_slot)->field_users += 1;
    }
    *out_slot = slot;
    return GRASS_SUCCESS;
}

void destroy_one_field(grass_context* ctx, uint32_t slot) {
    const Field* f = ctx->fields.get(slot);
    ctx->patches.get(f->patch_slot)->field_users -= 1;
    const FieldMaps maps = f->maps;
    const bool owned = f->owns_density_map;
    if (f->wind_map.active()) ctx->maps.get(f->wind_map.map_slot)->field_users -= 1;
    ctx->backend->release_field(slot);
    ctx->fields.erase(slot);
    for (uint32_t m : maps.map_slot) {
        if (m != kNoMap) ctx->maps.get(m)->field_users -= 1;
    }
    if (owned) release_map(ctx, maps.map_slot[kMapDensity]);
}

void destroy_field_and_types(grass_context* ctx, uint32_t slot) {
    Field* f = ctx->fields.get(slot);
    for (uint32_t k = 0; k < f->child_count; ++k) destroy_one_field(ctx, f->children[k]);
    destroy_one_field(ctx, slot);
}

// The field desc of grass type `t`: the field's desc with the type's patch, density and lod setup.
grass_field_desc type_field_desc(const grass_field_desc& field, const grass_grass_type_desc& t) {
    grass_field_desc d = field;
    d.next = nullptr;
    d.patch = t.patch;
    d.density = t.density;
    d.density_map = nullptr;
    d.maps.density = t.density_map;
    d.tiers = t.tiers;
    d.tier_count = t.tier_count;
    d.lod_tests = t.lod_tests;
    d.lod_test_count = t.lod_test_count;
    return d;
}

grass_result create_field(grass_context* ctx, const grass_field_desc* desc, grass_field_id* out) {
    const char* fn = "grass_create_field";
    GRASS_TRY(check_not_null(ctx, fn, "out_field", out));
    GRASS_TRY(check_not_null(ctx, fn, "desc", desc));
    // The chain of further grass types (lemme 6.4.5).
    const grass_grass_type_desc* types[GRASS_MAX_GRASS_TYPES - 1];
    uint32_t type_count = 0;
    for (const void* p = desc->next; p; p = types[type_count++]->next) {
        if (type_count == GRASS_MAX_GRASS_TYPES - 1) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->next chains more than %d grass types (or loops); a field has at most %d", fn,
                             GRASS_MAX_GRASS_TYPES - 1, GRASS_MAX_GRASS_TYPES);
        }
        const auto* t = static_cast<const grass_grass_type_desc*>(p);
        char name[48];
        std::snprintf(name, sizeof(name), "grass type %u", type_count + 1);
        GRASS_TRY(check_desc_header(ctx, fn, name, t, raw_enum(t->type), nullptr, GRASS_STRUCT_TYPE_GRASS_TYPE_DESC,
                                    "GRASS_STRUCT_TYPE_GRASS_TYPE_DESC"));
        types[type_count] = t;
    }
    grass_field_desc first = *desc;
    first.next = nullptr;
    GRASS_TRY(validate_field_desc(ctx, fn, &first));
    for (uint32_t k = 0; k < type_count; ++k) {
        const grass_field_desc d = type_field_desc(first, *types[k]);
        const grass_result r = validate_field_desc(ctx, fn, &d);
        if (r != GRASS_SUCCESS) {
            ctx->warn(GRASS_MSG_IN_GRASS_TYPE, "%s: the error above is in grass type %u (desc->next chain)", fn, k + 1);
            return r;
        }
    }
    uint32_t slot = 0;
    GRASS_TRY(create_one_field(ctx, fn, &first, 0xffffffffu, &slot));
    for (uint32_t k = 0; k < type_count; ++k) {
        const grass_field_desc d = type_field_desc(first, *types[k]);
        uint32_t child = 0;
        grass_result r = GRASS_SUCCESS;
        try {
            r = create_one_field(ctx, fn, &d, slot, &child);
        } catch (...) { // out of memory: nothing of this call is left either
            destroy_field_and_types(ctx, slot);
            throw;
        }
        if (r != GRASS_SUCCESS) {
            destroy_field_and_types(ctx, slot); // nothing of this call is left
            return r;
        }
        Field* f = ctx->fields.get(slot);
        f->children[f->child_count++] = child;
    }
    out->index = slot + 1;
    out->generation = ctx->fields.generation(slot);
    out->owner = ctx->owner;
    return GRASS_SUCCESS;
}

} // namespace
} // namespace grass

using grass::guarded;

extern "C" {

GRASS_API grass_field_desc grass_default_field_desc(void) {
    grass_field_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_FIELD_DESC;
    d.cell_size = 0.25;
    d.base_transform[0] = d.base_transform[5] = d.base_transform[10] = d.base_transform[15] = 1.0;
    d.density = 1.0f;
    d.mirror_tiling = 1;
    d.transition_window = 0.05f;
    d.maps.height_scale = 1.0f;
    return d;
}

GRASS_API grass_grass_type_desc grass_default_grass_type_desc(void) {
    grass_grass_type_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_GRASS_TYPE_DESC;
    d.density = 1.0f;
    return d;
}

GRASS_API grass_result grass_create_field(grass_context* context, const grass_field_desc* desc,
                                          grass_field_id* out_field) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_create_field", [&] {
        GRASS_TRY(grass::check_gpu_current(context, "grass_create_field"));
        return grass::create_field(context, desc, out_field);
    });
}

GRASS_API grass_result grass_destroy_field(grass_context* context, grass_field_id field) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_destroy_field", [&] {
        const char* fn = "grass_destroy_field";
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(grass::check_field_id(context, fn, "field", field));
        if (context->in_frame) {
            return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                                 "%s: cannot destroy a field between grass_begin_frame and grass_end_frame", fn);
        }
        grass::destroy_field_and_types(context, field.index - 1);
        return GRASS_SUCCESS;
    });
}

} // extern "C"
