// Dynamic tessellation of the geometry tier (jahrmann2017 6.3): per cell, the level of the
// patch's blades (patch/blade_levels.hpp) from the cell's distance and the view's pixels per
// metre, so that a far blade is drawn with fewer quads where that moves its outline by less
// than a set part of a pixel. The frame planner splits each geometry draw's instances by
// level (one draw per level, the finer first).
#pragma once

#include "foundation/log.hpp"
#include "patch/patch_data.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// A field's tessellation. Off: every cell draws level 0 (the patch's full blades).
struct BladeTessellation {
    bool enabled = false;
    float error_pixels = 0.5f; // the most a coarser level may move a blade's outline on screen
};

grass_blade_tessellation_desc default_blade_tessellation_desc();
grass_blade_tessellation_desc quality_blade_tessellation(grass_quality_level level);

// Checks `desc` (named "tessellation") and writes what the planner reads.
grass_result resolve_blade_tessellation(Log* log, const char* fn, const grass_blade_tessellation_desc& desc,
                                        BladeTessellation* out);

// How many pixels a metre is on screen: `scale` / distance for a perspective view, `scale`
// for an orthographic one (its pixels per metre are the same everywhere).
struct ScreenScale {
    double scale = 0.0;
    bool orthographic = false;
    double pixels_per_metre(double distance) const;
};

// The view's screen scale from its projection (column-major) and viewport height: half the
// height times the projection's vertical scale |P[1][1]|.
ScreenScale screen_scale(const float projection[16], int32_t viewport_height, bool orthographic);

// The level a cell `distance` metres away (its nearest point) draws: the coarsest whose
// error (BladeLevel::error, in patch units of `metres_per_unit`) is at most t.error_pixels
// on screen (0 when off or the patch has one level).
uint32_t blade_level(const BladeTessellation& t, const PatchData& patch, double metres_per_unit,
                     const ScreenScale& screen, double distance);

} // namespace grass
