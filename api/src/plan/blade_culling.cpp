#include "plan/blade_culling.hpp"

#include "foundation/validate.hpp"
#include "plan/field.hpp"

namespace grass {

grass_blade_culling_desc default_blade_culling_desc() {
    grass_blade_culling_desc d{};
    d.type = GRASS_STRUCT_TYPE_BLADE_CULLING_DESC;
    d.next = nullptr;
    d.orientation = 0;
    d.orientation_limit = 0.9f; // jahrmann eq. 17
    d.view_frustum = 0;
    d.frustum_tolerance = 0.1f;
    d.distance = GRASS_DISTANCE_CULLING_OFF;
    d.distance_levels = 4;
    d.distance_max = 0.0f;
    return d;
}

namespace {

// The largest finite end of the field's geometry tiers' distance bands (metres); 0 if none.
// Field::bands holds an infinite end (or a tier without a band) as 3e38.
float geometry_end(const Field& field) {
    float end = 0.0f;
    for (uint32_t t = 0; t < field.lod.tier_count; ++t) {
        if (field.lod.tiers[t].kind != GRASS_TIER_GEOMETRY) continue;
        const float e = field.bands[t][1];
        if (e < 1.0e38f && e > end) end = e;
    }
    return end;
}

} // namespace

grass_result resolve_blade_culling(Log* log, const char* fn, const Field& field, const grass_blade_culling_desc& d,
                                   BladeCulling* out) {
    GRASS_TRY(check_bool(log, fn, "culling->orientation", d.orientation));
    GRASS_TRY(check_range(log, fn, "culling->orientation_limit", d.orientation_limit, 0.5, 1.0));
    GRASS_TRY(check_bool(log, fn, "culling->view_frustum", d.view_frustum));
    GRASS_TRY(check_range(log, fn, "culling->frustum_tolerance", d.frustum_tolerance, 0.0, 1.0));
    const int64_t mode = raw_enum(d.distance);
    if (mode != GRASS_DISTANCE_CULLING_OFF && mode != GRASS_DISTANCE_CULLING_BLADE_INDEX &&
        mode != GRASS_DISTANCE_CULLING_THRESHOLD) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: culling->distance is %lld; it must be GRASS_DISTANCE_CULLING_OFF, _BLADE_INDEX or "
                         "_THRESHOLD",
                         fn, static_cast<long long>(mode));
    }
    GRASS_TRY(check_range(log, fn, "culling->distance_levels", d.distance_levels, 1.0, 64.0));
    GRASS_TRY(check_range(log, fn, "culling->distance_max", d.distance_max, 0.0, 3.0e38));
    BladeCulling c;
    if (mode != GRASS_DISTANCE_CULLING_OFF) {
        c.distance_max = d.distance_max > 0.0f ? d.distance_max : geometry_end(field);
        if (c.distance_max <= 0.0f) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: culling->distance_max is 0, which means the far end of the field's geometry "
                             "tiers, but none of its geometry tiers has a finite distance band; give metres",
                             fn);
        }
        c.distance_levels = mode == GRASS_DISTANCE_CULLING_BLADE_INDEX ? static_cast<float>(d.distance_levels) : 0.0f;
    }
    if (d.orientation) c.orientation_limit = d.orientation_limit;
    if (d.view_frustum) c.frustum_tolerance = d.frustum_tolerance;
    c.enabled = d.orientation || d.view_frustum || mode != GRASS_DISTANCE_CULLING_OFF;
    *out = c;
    return GRASS_SUCCESS;
}

} // namespace grass
