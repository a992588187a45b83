// The frame plan for flat fields: which cells each field draws this frame, where they are
// relative to the camera, and how they are mirrored. No GPU involved.
#pragma once

#include "context.hpp"

#include <grass/grass.h>

namespace grass {

// Camera-relative clip-space planes (a x + b y + c z + d >= 0 inside) of a view-projection.
struct Frustum {
    double planes[6][4];
    static Frustum from_view_projection(const double m[16]);
    // True when the box with these 8 corners is entirely outside one plane.
    bool outside(const double corners[8][3]) const;
};

// Rebuilds ctx->plan from a validated view. Cells are chosen among those within the
// field's draw distance (a disc of cells around the camera, so the cost does not grow with
// the field), kept when their box (cell + blade bounds) meets the view frustum, and
// ordered front to back.
void build_frame_plan(grass_context* ctx, const grass_view_desc& view);

} // namespace grass
