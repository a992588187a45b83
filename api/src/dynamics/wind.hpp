// The wind of a context (bakay2003 3.3, jahrmann2017 5.1): a mean wind with gusts and
// turbulence, local sources (a downwash, a cone, a blast) and the environmental gravity.
// The shaders evaluate it where blades and slices are drawn (api/shaders/wind.glsl); the
// core validates it and packs its parameters, with the gust phases at the camera computed
// in double so that a shader needs only camera-relative floats.
#pragma once

#include "foundation/frame_plan.hpp"
#include "foundation/log.hpp"

#include <grass/grass.h>

namespace grass {

// Standard gravity, world m/s^2: the patch's blades have their generated shape under it.
constexpr float kStandardGravity[3] = {0.0f, -9.81f, 0.0f};

// The gust waves k = 0, 1, 2 (docs/responsive.md): wavelength = gust_length x ratio,
// speed = wind speed x factor, phase offset.
constexpr double kGustWavelength[3] = {1.0, 0.618034, 0.381966};
constexpr double kGustSpeed[3] = {1.0, 1.13, 0.87};
constexpr double kGustOffset[3] = {0.0, 0.37, 0.71};

grass_wind_desc default_wind_desc();

// The desc and each source: finite numbers in their documented ranges, known kinds.
grass_result validate_wind(Log* log, const char* fn, const grass_wind_desc& wind);

// Wind blows or gravity differs from standard: the draws need the kFeatureWind variant.
bool wind_is_active(const grass_wind_desc& wind);

// Fills frame->wind, wind_shape (x, y, z), wind_phase, gravity and wind_sources for the
// camera at `camera` (world metres) at `time`; `up` is the interaction map's up (unit),
// across which wind_phase.w runs.
void pack_wind(const grass_wind_desc& wind, const double camera[3], double time, const double up[3],
               FrameUniforms* frame);

// x - floor(x): the fraction in [0, 1) (1 rounds down to 0).
double fract(double x);

} // namespace grass
