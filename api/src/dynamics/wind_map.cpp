#include "dynamics/wind_map.hpp"

#include "foundation/validate.hpp"

#include <cmath>
#include <cstring>

namespace grass {

grass_wind_map_desc default_wind_map_desc() {
    grass_wind_map_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_WIND_MAP_DESC;
    d.speed = 5.0f;
    return d;
}

grass_result validate_wind_map(Log* log, const char* fn, const grass_wind_map_desc& d, const DesignMap& map,
                               uint32_t cells_x, uint32_t cells_z, FieldWindMap* out) {
    if (map.channels != 4) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_ROLE,
                         "%s: desc->map has %u channel(s); a wind map needs an RGBA format (r, g: the wind along "
                         "the field's x and z)",
                         fn, map.channels);
    }
    GRASS_TRY(check_range(log, fn, "desc->speed", d.speed, 0.0, 1e3));
    GRASS_TRY(check_finite_array(log, fn, "desc->cell_to_map", d.cell_to_map, 6));
    bool all_zero = true;
    for (double v : d.cell_to_map) all_zero = all_zero && v == 0.0;
    const double det = d.cell_to_map[0] * d.cell_to_map[3] - d.cell_to_map[1] * d.cell_to_map[2];
    if (!all_zero && !(std::fabs(det) > 0.0)) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: desc->cell_to_map maps the field onto a line (determinant %g); it must be invertible, "
                         "or all zero for a map that spans the field",
                         fn, det);
    }
    FieldWindMap w;
    w.map_slot = d.map.index - 1;
    w.speed = d.speed;
    if (all_zero) {
        w.cell_to_map[0] = 1.0 / cells_x;
        w.cell_to_map[3] = 1.0 / cells_z;
    } else {
        for (int k = 0; k < 6; ++k) w.cell_to_map[k] = d.cell_to_map[k];
    }
    *out = w;
    return GRASS_SUCCESS;
}

void pack_wind_map(const FieldWindMap& wind, FieldUniforms* u) {
    for (int k = 0; k < 4; ++k) u->wind_map_u[k] = u->wind_map_v[k] = 0.0f;
    if (!wind.active()) return;
    const double* m = wind.cell_to_map;
    u->wind_map_u[0] = static_cast<float>(m[0]);
    u->wind_map_u[1] = static_cast<float>(m[2]);
    u->wind_map_u[2] = static_cast<float>(m[4]);
    u->wind_map_u[3] = wind.speed;
    u->wind_map_v[0] = static_cast<float>(m[1]);
    u->wind_map_v[1] = static_cast<float>(m[3]);
    u->wind_map_v[2] = static_cast<float>(m[5]);
}

} // namespace grass
