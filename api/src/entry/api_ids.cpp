// C entry points for ids: equality and the null test (exported, so that bindings in other
// languages can call them).
#include <grass/grass.h>

namespace {

template <class Id>
grass_bool ids_equal(const Id& a, const Id& b) {
    return a.index == b.index && a.generation == b.generation && a.owner == b.owner ? 1u : 0u;
}

template <class Id>
grass_bool id_is_null(const Id& id) {
    return id.index == 0 && id.generation == 0 && id.owner == 0 ? 1u : 0u;
}

} // namespace

extern "C" {

GRASS_API grass_bool grass_patch_id_equal(grass_patch_id a, grass_patch_id b) { return ids_equal(a, b); }
GRASS_API grass_bool grass_field_id_equal(grass_field_id a, grass_field_id b) { return ids_equal(a, b); }
GRASS_API grass_bool grass_map_id_equal(grass_map_id a, grass_map_id b) { return ids_equal(a, b); }
GRASS_API grass_bool grass_patch_id_is_null(grass_patch_id id) { return id_is_null(id); }
GRASS_API grass_bool grass_field_id_is_null(grass_field_id id) { return id_is_null(id); }
GRASS_API grass_bool grass_map_id_is_null(grass_map_id id) { return id_is_null(id); }

} // extern "C"
