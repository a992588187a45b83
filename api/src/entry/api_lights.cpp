// The host's lights (grass_view_lights_desc, grass.h; docs/integration.md "The host's
// lights"): the struct's validation and defaults. The plan is api/src/plan/lights_plan.cpp.
#include "entry/api_lights.hpp"

#include "foundation/validate.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace grass {
namespace {

// "grass_view_lights_desc->lights[i].field"
struct LightName {
    char text[96];
    LightName(uint32_t i, const char* field) {
        std::snprintf(text, sizeof(text), "grass_view_lights_desc->lights[%u].%s", i, field);
    }
};

grass_result check_light(grass_context* ctx, const char* fn, uint32_t i, const grass_light& l) {
    const int64_t kind = raw_enum(l.kind);
    if (kind != GRASS_LIGHT_DIRECTIONAL && kind != GRASS_LIGHT_POINT && kind != GRASS_LIGHT_SPOT) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: grass_view_lights_desc->lights[%u].kind is %lld; expected GRASS_LIGHT_DIRECTIONAL (0), "
                         "GRASS_LIGHT_POINT (1) or GRASS_LIGHT_SPOT (2)",
                         fn, i, static_cast<long long>(kind));
    }
    const bool positioned = kind != GRASS_LIGHT_DIRECTIONAL;
    if (positioned) {
        GRASS_TRY(check_world_position(ctx, fn, LightName(i, "position").text, l.position));
        GRASS_TRY(check_range_above(ctx, fn, LightName(i, "range").text, l.range, 0.0, 1e12));
    }
    if (kind != GRASS_LIGHT_POINT) GRASS_TRY(check_direction(ctx, fn, LightName(i, "direction").text, l.direction));
    for (int c = 0; c < 3; ++c) {
        char name[96];
        std::snprintf(name, sizeof(name), "grass_view_lights_desc->lights[%u].color[%d]", i, c);
        GRASS_TRY(check_range(ctx, fn, name, l.color[c], 0.0, 1e30));
    }
    GRASS_TRY(check_range(ctx, fn, LightName(i, "intensity").text, l.intensity, 0.0, 1e30));
    if (kind == GRASS_LIGHT_SPOT) {
        const double half_pi = 1.5707963267948966;
        GRASS_TRY(check_range(ctx, fn, LightName(i, "outer_cone_angle").text, l.outer_cone_angle, 0.0, half_pi + 1e-6));
        GRASS_TRY(check_range(ctx, fn, LightName(i, "inner_cone_angle").text, l.inner_cone_angle, 0.0, half_pi + 1e-6));
        if (!(l.inner_cone_angle < l.outer_cone_angle)) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_RANGE_INVERTED,
                             "%s: grass_view_lights_desc->lights[%u].inner_cone_angle is %g and outer_cone_angle %g; "
                             "the inner angle must be less than the outer",
                             fn, i, static_cast<double>(l.inner_cone_angle), static_cast<double>(l.outer_cone_angle));
        }
    }
    return GRASS_SUCCESS;
}

} // namespace

grass_result check_view_lights(grass_context* ctx, const char* fn, const grass_view_lights_desc& d) {
    if (d.light_count > GRASS_MAX_VIEW_LIGHTS) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_view_lights_desc->light_count is %u; expected 0 to %d (GRASS_MAX_VIEW_LIGHTS)", fn,
                         d.light_count, GRASS_MAX_VIEW_LIGHTS);
    }
    if (d.light_count > 0) GRASS_TRY(check_not_null(ctx, fn, "grass_view_lights_desc->lights", d.lights));
    for (uint32_t i = 0; i < d.light_count; ++i) GRASS_TRY(check_light(ctx, fn, i, d.lights[i]));
    GRASS_TRY(check_range(ctx, fn, "grass_view_lights_desc->specular_strength", d.specular_strength, 0.0, 1.0));
    GRASS_TRY(check_range(ctx, fn, "grass_view_lights_desc->specular_exponent", d.specular_exponent, 1.0, 1024.0));
    if (d.ambient_sh_enabled > 1) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: grass_view_lights_desc->ambient_sh_enabled is %u; expected 0 or 1", fn,
                         d.ambient_sh_enabled);
    }
    if (d.ambient_sh_enabled)
        GRASS_TRY(check_finite_array(ctx, fn, "grass_view_lights_desc->ambient_sh", &d.ambient_sh[0][0], 27));
    return GRASS_SUCCESS;
}

} // namespace grass

GRASS_API grass_light grass_default_light(void) {
    grass_light l;
    std::memset(&l, 0, sizeof(l));
    l.kind = GRASS_LIGHT_POINT;
    l.direction[1] = -1.0f;
    for (int c = 0; c < 3; ++c) l.color[c] = 1.0f;
    l.intensity = 1.0f;
    l.range = 10.0f;
    l.outer_cone_angle = 0.7853982f;
    return l;
}

GRASS_API grass_view_lights_desc grass_default_view_lights_desc(void) {
    grass_view_lights_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_VIEW_LIGHTS_DESC;
    d.specular_exponent = 32.0f;
    return d;
}
