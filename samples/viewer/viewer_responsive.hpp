// The viewer's responsive grass (docs/viewer.md): the scene file's wind and colliders on
// their paths, F2 to turn the wind on and off, B to roll a ball from in front of the camera.
#pragma once

#include <grass/grass.h>

#include "scene.hpp"

#include <glm/glm.hpp>

#include <string>

namespace grass_viewer {

class ViewerResponsive {
public:
    explicit ViewerResponsive(const grass_sample::Responsive& scene);

    // F2: the scene's wind (or, for a scene without one, a gusty breeze) on or off.
    void toggle_wind();
    // B: a ball of 0.3 m radius rolls at 2.5 m/s from 2 m in front of the camera along its
    // horizontal view direction, on the ground at height `ground_y`; B again takes it away
    // (its trail recovers).
    void toggle_ball(const glm::dvec3& camera, const glm::dvec3& forward, double ground_y, double time);
    bool wind_on() const { return wind_on_; }
    bool ball_on() const { return ball_on_; }

    // Hands the frame at `time` (seconds; `step` since the previous frame) to grass: once
    // per patch (a new context or quality makes another) the mechanics and map, every frame
    // the wind and the colliders. The first failing result; *error names the call.
    grass_result apply(grass_context* ctx, grass_patch_id patch, double time, double step, std::string* error);

private:
    grass_sample::Responsive scene_;
    bool wind_on_ = false, ball_on_ = false;
    grass_sample::SceneCollider ball_;
    grass_context* applied_ctx_ = nullptr;
    grass_patch_id applied_patch_{};
};

} // namespace grass_viewer
