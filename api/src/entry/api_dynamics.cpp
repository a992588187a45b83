// C entry points of responsive grass (grass.h "Responsive grass"): blade mechanics, wind,
// colliders, the interaction map. Each validates everything before it changes anything, so
// a refusal leaves the earlier state intact; the state is read by the next grass_begin_frame.
#include "context/context.hpp"
#include "context/id_checks.hpp"
#include "dynamics/blade_mechanics.hpp"
#include "dynamics/colliders.hpp"
#include "dynamics/interaction_map.hpp"
#include "dynamics/wind.hpp"
#include "dynamics/wind_map.hpp"
#include "foundation/validate.hpp"

#include <cstring>

using grass::guarded;

extern "C" {

GRASS_API grass_blade_mechanics grass_default_blade_mechanics(void) { return grass::default_blade_mechanics(); }

GRASS_API grass_result grass_set_blade_mechanics(grass_context* context, grass_patch_id patch,
                                                 const grass_blade_mechanics* mechanics) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_set_blade_mechanics", [&] {
        const char* fn = "grass_set_blade_mechanics";
        GRASS_TRY(grass::check_patch_id(context, fn, "patch", patch));
        GRASS_TRY(GRASS_CHECK_DESC(context, fn, mechanics, GRASS_STRUCT_TYPE_BLADE_MECHANICS));
        GRASS_TRY(grass::validate_blade_mechanics(context, fn, "mechanics", *mechanics));
        grass::Patch* p = context->patches.get(patch.index - 1);
        p->mechanics = *mechanics;
        p->mechanics.next = nullptr;
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_wind_desc grass_default_wind_desc(void) { return grass::default_wind_desc(); }

GRASS_API grass_result grass_set_wind(grass_context* context, const grass_wind_desc* wind) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_set_wind", [&] {
        const char* fn = "grass_set_wind";
        grass::DynamicsState& state = context->dynamics;
        if (!wind) {
            state.wind = grass::default_wind_desc();
            return GRASS_SUCCESS;
        }
        GRASS_TRY(GRASS_CHECK_DESC(context, fn, wind, GRASS_STRUCT_TYPE_WIND_DESC));
        GRASS_TRY(grass::validate_wind(context, fn, *wind));
        // wind->sources may alias state.sources (a host passing back what it read): move.
        std::memmove(state.sources, wind->sources ? wind->sources : state.sources,
                     sizeof(grass_wind_source) * wind->source_count);
        state.wind = *wind;
        state.wind.sources = wind->source_count > 0 ? state.sources : nullptr;
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_result grass_set_colliders(grass_context* context, const grass_collider* colliders, uint32_t count) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_set_colliders", [&] {
        GRASS_TRY(grass::validate_colliders(context, "grass_set_colliders", colliders, count));
        // Copied into a new array first: if the host's allocator fails, the old colliders stay.
        grass::Vector<grass_collider> copy(grass::StlAllocator<grass_collider>(&context->host));
        if (count > 0) copy.assign(colliders, colliders + count);
        context->dynamics.colliders.swap(copy);
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_interaction_desc grass_default_interaction_desc(void) { return grass::default_interaction_desc(); }

GRASS_API grass_result grass_set_interaction(grass_context* context, const grass_interaction_desc* desc) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_set_interaction", [&] {
        const char* fn = "grass_set_interaction";
        grass_interaction_desc d = grass::default_interaction_desc();
        if (desc) {
            GRASS_TRY(GRASS_CHECK_DESC(context, fn, desc, GRASS_STRUCT_TYPE_INTERACTION_DESC));
            GRASS_TRY(grass::validate_interaction(context, fn, *desc));
            d = *desc;
        }
        grass::DynamicsState& state = context->dynamics;
        state.interaction = d;
        // Every trail is gone: the map is made anew (and cleared) at the next frame with
        // colliders; until then no frame binds it, and the backend may release it.
        state.map = grass::InteractionMapState{};
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_wind_map_desc grass_default_wind_map_desc(void) { return grass::default_wind_map_desc(); }

GRASS_API grass_result grass_set_field_wind_map(grass_context* context, grass_field_id field,
                                                const grass_wind_map_desc* desc) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_set_field_wind_map", [&] {
        const char* fn = "grass_set_field_wind_map";
        GRASS_TRY(grass::check_grid_field_id(context, fn, "field", field));
        if (context->in_frame) {
            return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                                 "%s: cannot set a wind map between grass_begin_frame and grass_end_frame", fn);
        }
        grass::Field* host_field = context->fields.get(field.index - 1);
        grass::FieldWindMap wind; // none
        if (desc) {
            GRASS_TRY(GRASS_CHECK_DESC(context, fn, desc, GRASS_STRUCT_TYPE_WIND_MAP_DESC));
            if (!grass_map_id_is_null(desc->map)) {
                GRASS_TRY(grass::check_map_id(context, fn, "desc->map", desc->map));
                GRASS_TRY(grass::validate_wind_map(context, fn, *desc, *context->maps.get(desc->map.index - 1),
                                                   host_field->desc.cells_x, host_field->desc.cells_z, &wind));
            }
        }
        // The field and its grass types (hidden fields of the same cells) share the wind.
        uint32_t slots[GRASS_MAX_GRASS_TYPES];
        uint32_t count = 0;
        slots[count++] = field.index - 1;
        for (uint32_t k = 0; k < host_field->child_count; ++k) slots[count++] = host_field->children[k];
        for (uint32_t k = 0; k < count; ++k) {
            grass::Field* f = context->fields.get(slots[k]);
            if (f->wind_map.active()) context->maps.get(f->wind_map.map_slot)->field_users -= 1;
            f->wind_map = wind;
            if (wind.active()) context->maps.get(wind.map_slot)->field_users += 1;
            context->backend->set_field_wind_map(slots[k], wind.map_slot);
        }
        return GRASS_SUCCESS;
    });
}

} // extern "C"
