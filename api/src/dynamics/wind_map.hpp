// A host wind-vector map of a field (grass_set_field_wind_map): wind painted over the
// field in its map space, added to the context's wind and sources wherever the field's
// grass is drawn (api/shaders/wind.glsl, wind_of_map). Its draws get kFeatureWindMap (and
// kFeatureWind); a field without one plans and draws exactly what it did before.
#pragma once

#include "foundation/frame_plan.hpp"
#include "foundation/log.hpp"
#include "foundation/shader_interface.hpp" // kNoMap
#include "maps/design_map.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

struct FieldWindMap {
    uint32_t map_slot = kNoMap;                 // the RGBA map (kNoMap: the field has none)
    float speed = 0.0f;                         // m/s for an encoded 1
    double cell_to_map[6] = {0, 0, 0, 0, 0, 0}; // cell (x, z) -> map (u, v), never all zero once set
    bool active() const { return map_slot != kNoMap; }
};

grass_wind_map_desc default_wind_map_desc();

// Validates `desc` (its map's format: `map` is the design map desc->map names, whose id
// the caller checked; speed, transform) for a field of cells_x x cells_z cells and fills
// `out` (the all-zero transform made to span the field).
// On error logs naming the argument and returns the code; `out` is untouched.
grass_result validate_wind_map(Log* log, const char* fn, const grass_wind_map_desc& desc, const DesignMap& map,
                               uint32_t cells_x, uint32_t cells_z, FieldWindMap* out);

// FieldUniforms::wind_map_u / wind_map_v of a field with `wind` (zero without a wind map).
void pack_wind_map(const FieldWindMap& wind, FieldUniforms* uniforms);

} // namespace grass
