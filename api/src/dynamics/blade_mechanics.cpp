#include "dynamics/blade_mechanics.hpp"

#include "foundation/validate.hpp"

#include <cstdio>

namespace grass {

grass_blade_mechanics default_blade_mechanics() {
    grass_blade_mechanics m{};
    m.type = GRASS_STRUCT_TYPE_BLADE_MECHANICS;
    m.next = nullptr;
    m.stiffness = 40.0f;
    m.mass = 1.0f;
    m.wind_response = 2.0f;
    m.trample_depth = 0.5f;
    m.recovery_time = 4.0f;
    m.variation = 0.25f;
    return m;
}

grass_result validate_blade_mechanics(Log* log, const char* fn, const char* name, const grass_blade_mechanics& m) {
    struct Rule {
        const char* field;
        float value;
        double lo, hi;
    };
    const Rule rules[] = {{"stiffness", m.stiffness, 0.1, 1e5},           {"mass", m.mass, 0.0, 100.0},
                          {"wind_response", m.wind_response, 0.0, 100.0}, {"trample_depth", m.trample_depth, 0.0, 1.0},
                          {"recovery_time", m.recovery_time, 0.01, 1e5},  {"variation", m.variation, 0.0, 0.9}};
    for (const Rule& r : rules) {
        char arg[96];
        std::snprintf(arg, sizeof arg, "%s->%s", name, r.field);
        GRASS_TRY(check_float_range(log, fn, arg, r.value, r.lo, r.hi)); // 0.01f is in range
    }
    return GRASS_SUCCESS;
}

} // namespace grass
