// grass-deferred --velocity-output FILE.png (docs/engine-frames.md, "Motion vectors"): the
// G-buffer's velocity attachment (attachment 3, RGBA16F) of one frame drawn with a previous
// camera kPan metres to the left and in a gust of wind, the same in both halves. grass writes
// its blades' velocity there on the GPU (a GRASS_GBUFFER_VELOCITY attachment, the camera's
// and the wind's motion), the ground its own camera motion (shaders/gbuffer_ground.frag);
// this file checks the read-back values and turns them into a picture on the CPU (a
// visualisation of a read-back attachment, not part of the renderer).
#pragma once

#include "headless_host.hpp"

#include <grass/grass.h>

#include <string>
#include <vector>

namespace deferred {

// The velocity frame: this frame's time, the previous frame's (1/30 s before) and the camera's
// pan since then (the previous eye and target kPan metres along -x, the camera's right).
constexpr double kTime = 2.0, kPreviousTime = kTime - 1.0 / 30.0;
constexpr double kPan = 0.02; // metres
// The colours of the picture: red and green 128 where nothing moves; red rises kLevelsPerPixel
// levels for each pixel of motion to the right (falls for the left), green for each pixel
// upwards (whatever the backend's y), clamped to 0..255; blue 128 on grass, 192 on the ground
// (to tell them apart); black on the sky (nothing wrote velocity there).
constexpr float kLevelsPerPixel = 32.0f;

// The wind of the velocity frames: 20 m/s along the default direction (1, 0, 0.3), gusts of
// the strongest (4) and full turbulence.
grass_wind_desc gust_wind();

// The previous camera of `view` (its eye kPan metres along -x) for a view's chain, the wind's
// motion from kPreviousTime (`wind_moves`) or none (previous_time == this frame's time), the
// velocity written to attachment 3.
grass_view_motion_desc pan_motion(const grass_host::Host& host, bool wind_moves);

// The ground's matrices (shaders/gbuffer_ground.vert): world -> this frame's clip and world ->
// the previous frame's clip, from `view` and the grass_view_motion_desc on its chain (none:
// the previous is this frame's, so the ground writes zero velocity).
void ground_matrices(const grass_view_desc& view, float world_to_clip[16], float world_to_previous_clip[16]);

// The velocity attachment read back: RGBA floats, top row first, as the backend stores it
// (`y_down`: Vulkan's +y down the framebuffer; GL's +y up).
struct VelocityImage {
    std::vector<float> rgba;
    bool y_down = false;
};

// Checks the two frames of `view` (`still`: no wind motion; `gust`: the wind's motion from
// kPreviousTime) and writes `gust`'s picture to out_path. 0 when: the ground's velocity matches
// its expected camera motion at sampled ground points (within 2 % + 1e-4 viewport units);
// grass covers a tenth of the picture; without wind motion the pan moves grass sideways
// (mean |vy| under 2 % of mean |vx|, vx with the ground's sign) and at its depth (at 99 % of
// grass pixels vx is 0.98 to 1.5 times that of the ground seen through the pixel: grass lies
// between the camera and that ground, under 0.47 m); the gust changes grass's
// velocity by a mean of over 0.1 pixel and the ground's by nothing.
int check_and_write_velocity(const grass_view_desc& view, const VelocityImage& still, const VelocityImage& gust,
                             const std::string& out_path);

} // namespace deferred
