// The id checks of the C entry points: an id of this context's pools, live, of the kind asked.
#include "context/id_checks.hpp"

namespace grass {

namespace {
template <class Pool>
grass_result check_id(grass_context* ctx, const char* function, const char* name, const Pool& pool, uint32_t index,
                      uint16_t generation, uint16_t owner) {
    switch (pool.check(index, generation, owner, ctx->owner)) {
    case HandleCheck::ok:
        return GRASS_SUCCESS;
    case HandleCheck::null_id:
        return ctx->fail(GRASS_ERROR_INVALID_HANDLE, GRASS_MSG_NULL_HANDLE, "%s: %s is the null id", function, name);
    case HandleCheck::foreign:
        return ctx->fail(GRASS_ERROR_INVALID_HANDLE, GRASS_MSG_FOREIGN_HANDLE,
                         "%s: %s (index %u) was made by another context", function, name, index);
    case HandleCheck::stale:
        break;
    }
    return ctx->fail(GRASS_ERROR_INVALID_HANDLE, GRASS_MSG_STALE_HANDLE,
                     "%s: %s (index %u, generation %u) is stale: its object was destroyed", function, name, index,
                     static_cast<unsigned>(generation));
}
} // namespace

grass_result check_patch_id(grass_context* ctx, const char* function, const char* name, grass_patch_id id) {
    return check_id(ctx, function, name, ctx->patches, id.index, id.generation, id.owner);
}

grass_result check_field_id(grass_context* ctx, const char* function, const char* name, grass_field_id id) {
    GRASS_TRY(check_id(ctx, function, name, ctx->fields, id.index, id.generation, id.owner));
    if (ctx->fields.get(id.index - 1)->parent != 0xffffffffu) {
        return ctx->fail(GRASS_ERROR_INVALID_HANDLE, GRASS_MSG_STALE_HANDLE,
                         "%s: %s (index %u) is not a field made by grass_create_field", function, name, id.index);
    }
    return GRASS_SUCCESS;
}

grass_result check_grid_field_id(grass_context* ctx, const char* function, const char* name, grass_field_id id) {
    GRASS_TRY(check_field_id(ctx, function, name, id));
    if (ctx->fields.get(id.index - 1)->mesh) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MESH_FIELD,
                         "%s: %s (index %u) is a mesh field (grass_create_mesh_field); this call applies to fields "
                         "made by grass_create_field",
                         function, name, id.index);
    }
    return GRASS_SUCCESS;
}

grass_result check_map_id(grass_context* ctx, const char* function, const char* name, grass_map_id id) {
    GRASS_TRY(check_id(ctx, function, name, ctx->maps, id.index, id.generation, id.owner));
    if (ctx->maps.get(id.index - 1)->field_private) {
        return ctx->fail(GRASS_ERROR_INVALID_HANDLE, GRASS_MSG_STALE_HANDLE,
                         "%s: %s (index %u) is not a map made by grass_create_map", function, name, id.index);
    }
    return GRASS_SUCCESS;
}

} // namespace grass
