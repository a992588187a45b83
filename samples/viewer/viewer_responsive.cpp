#include "viewer_responsive.hpp"

#include <cmath>
#include <vector>

namespace grass_viewer {

namespace {

constexpr float kBallRadius = 0.3f;
constexpr double kBallSpeed = 2.5;  // m/s
constexpr double kBallRoll = 600.0; // s: it rolls on for as long as anyone watches

} // namespace

ViewerResponsive::ViewerResponsive(const grass_sample::Responsive& scene) : scene_(scene), wind_on_(scene.wind_given) {
    if (!scene_.wind_given) {
        // A gusty breeze for scenes that bring no wind of their own.
        scene_.wind.speed = 4.0f;
        scene_.wind.gust_strength = 0.8f;
    }
}

void ViewerResponsive::toggle_wind() { wind_on_ = !wind_on_; }

void ViewerResponsive::toggle_ball(const glm::dvec3& camera, const glm::dvec3& forward, double ground_y, double time) {
    ball_on_ = !ball_on_;
    if (!ball_on_) return;
    glm::dvec3 along(forward.x, 0.0, forward.z);
    along = glm::length(along) > 1e-6 ? glm::normalize(along) : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 from = glm::dvec3(camera.x, ground_y + kBallRadius, camera.z) + 2.0 * along;
    const glm::dvec3 to = from + kBallSpeed * kBallRoll * along;
    ball_.shape = GRASS_COLLIDER_SPHERE;
    ball_.radius = kBallRadius;
    ball_.centre = grass_sample::Path::line(&from.x, &to.x, kBallSpeed, time);
}

grass_result ViewerResponsive::apply(grass_context* ctx, grass_patch_id patch, double time, double step,
                                     std::string* error) {
    grass_result r = GRASS_SUCCESS;
    const char* call = "";
    if (ctx != applied_ctx_ || !grass_patch_id_equal(patch, applied_patch_)) {
        if (scene_.mechanics_given)
            r = grass_set_blade_mechanics(ctx, patch, &scene_.mechanics), call = "grass_set_blade_mechanics";
        if (r == GRASS_SUCCESS && scene_.interaction_given)
            r = grass_set_interaction(ctx, &scene_.interaction), call = "grass_set_interaction";
        applied_ctx_ = ctx;
        applied_patch_ = patch;
    }
    if (r == GRASS_SUCCESS) {
        const std::vector<grass_wind_source> sources = grass_sample::wind_sources_at(scene_, time);
        grass_wind_desc wind = scene_.wind;
        wind.sources = sources.empty() ? nullptr : sources.data();
        wind.source_count = static_cast<uint32_t>(sources.size());
        r = grass_set_wind(ctx, wind_on_ ? &wind : nullptr);
        call = "grass_set_wind";
    }
    if (r == GRASS_SUCCESS) {
        grass_sample::Responsive moving = scene_;
        if (ball_on_) moving.colliders.push_back(ball_);
        const std::vector<grass_collider> colliders =
            grass_sample::colliders_at(moving, time, step > 0.0 ? step : 1e-3);
        r = grass_set_colliders(ctx, colliders.empty() ? nullptr : colliders.data(),
                                static_cast<uint32_t>(colliders.size()));
        call = "grass_set_colliders";
    }
    if (r != GRASS_SUCCESS && error) *error = std::string(call) + ": " + grass_get_last_error(ctx);
    return r;
}

} // namespace grass_viewer
