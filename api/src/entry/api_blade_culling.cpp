// C entry points of per-blade culling (grass.h "Per-blade culling", jahrmann2017 6.2). The
// field and every grass type of it are checked before any changes, so a refusal leaves the
// earlier culling intact; the next grass_begin_frame plans with the new one.
#include "context/context.hpp"
#include "context/id_checks.hpp"
#include "foundation/validate.hpp"
#include "plan/blade_culling.hpp"

using grass::guarded;

extern "C" {

GRASS_API grass_blade_culling_desc grass_default_blade_culling_desc(void) {
    return grass::default_blade_culling_desc();
}

GRASS_API grass_result grass_set_blade_culling(grass_context* context, grass_field_id field,
                                               const grass_blade_culling_desc* culling) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_set_blade_culling", [&] {
        const char* fn = "grass_set_blade_culling";
        GRASS_TRY(grass::check_grid_field_id(context, fn, "field", field));
        const grass_blade_culling_desc desc = culling ? *culling : grass::default_blade_culling_desc();
        if (culling) GRASS_TRY(GRASS_CHECK_DESC(context, fn, culling, GRASS_STRUCT_TYPE_BLADE_CULLING_DESC));
        grass::Field* host_field = context->fields.get(field.index - 1);
        // The host's field, then its hidden grass types (each with its own tiers).
        grass::Field* targets[GRASS_MAX_GRASS_TYPES] = {host_field};
        uint32_t count = 1;
        for (uint32_t c = 0; c < host_field->child_count; ++c)
            targets[count++] = context->fields.get(host_field->children[c]);
        grass::BladeCulling resolved[GRASS_MAX_GRASS_TYPES];
        for (uint32_t i = 0; i < count; ++i)
            GRASS_TRY(grass::resolve_blade_culling(context, fn, *targets[i], desc, &resolved[i]));
        for (uint32_t i = 0; i < count; ++i) targets[i]->culling = resolved[i];
        return GRASS_SUCCESS;
    });
}

} // extern "C"
