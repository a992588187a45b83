// OSG's camera at draw time, in grass's terms. Private to the adapter.
#pragma once

#include <grass/grass.h>

#include <osg/State>

#include <string>

namespace grass_osg {

// Fills the camera of `view` (camera_position, view, projection, viewport, time) from the
// model-view and projection matrices, viewport and frame stamp OSG has applied for the
// drawable being drawn. The drawable's local coordinates are grass's world; the model-view
// is OSG's double-precision matrix, so the camera position keeps its precision far from
// the origin. False and *error when the model-view is not rigid (a scale or shear above the
// drawable) or OSG has no viewport.
bool view_from_state(const osg::State& state, grass_view_desc* view, std::string* error);

// Whether the bound draw framebuffer encodes linear colour to sRGB as it stores it:
// GL_FRAMEBUFFER_SRGB on and draw buffer 0 of an sRGB encoding. Reads GL state, changes none.
bool target_encodes_srgb();

} // namespace grass_osg
