// C entry points of the blades' dynamic tessellation (grass.h "Dynamic tessellation of the
// blades", jahrmann2017 6.3). Checked before any change, so a refusal leaves the earlier
// setting intact; the next grass_begin_frame plans with the new one.
#include "context/context.hpp"
#include "context/id_checks.hpp"
#include "foundation/validate.hpp"
#include "plan/blade_tessellation.hpp"

using grass::guarded;

extern "C" {

GRASS_API grass_blade_tessellation_desc grass_default_blade_tessellation_desc(void) {
    return grass::default_blade_tessellation_desc();
}

GRASS_API grass_blade_tessellation_desc grass_quality_blade_tessellation(grass_quality_level level) {
    return grass::quality_blade_tessellation(level);
}

GRASS_API grass_result grass_set_blade_tessellation(grass_context* context, grass_field_id field,
                                                    const grass_blade_tessellation_desc* tessellation) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_set_blade_tessellation", [&] {
        const char* fn = "grass_set_blade_tessellation";
        GRASS_TRY(grass::check_grid_field_id(context, fn, "field", field));
        if (tessellation)
            GRASS_TRY(GRASS_CHECK_DESC(context, fn, tessellation, GRASS_STRUCT_TYPE_BLADE_TESSELLATION_DESC));
        grass::BladeTessellation resolved;
        if (tessellation) GRASS_TRY(grass::resolve_blade_tessellation(context, fn, *tessellation, &resolved));
        // The host's field, then its hidden grass types.
        grass::Field* host_field = context->fields.get(field.index - 1);
        host_field->tessellation = resolved;
        for (uint32_t c = 0; c < host_field->child_count; ++c)
            context->fields.get(host_field->children[c])->tessellation = resolved;
        return GRASS_SUCCESS;
    });
}

} // extern "C"
