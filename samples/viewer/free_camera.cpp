#include "free_camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace grass_viewer {

namespace {
constexpr double kRadiansPerPixel = 0.0035;
constexpr double kMaxPitch = 1.5533; // 89 degrees
} // namespace

void FreeCamera::look_at(const glm::dvec3& eye, const glm::dvec3& target) {
    position_ = eye;
    const glm::dvec3 d = target - eye;
    if (glm::length(d) > 0.0) forward_ = glm::normalize(d);
}

glm::dvec3 FreeCamera::forward() const { return forward_; }

void FreeCamera::turn(double dx, double dy) {
    double yaw = std::atan2(forward_.x, forward_.z);
    double pitch = std::asin(std::clamp(forward_.y, -1.0, 1.0));
    yaw -= dx * kRadiansPerPixel; // mouse right turns right (towards -x when looking down +z)
    pitch = std::clamp(pitch - dy * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
    forward_ = glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

void FreeCamera::move(double forward, double right, double up, double seconds) {
    const glm::dvec3 f = forward_;
    glm::dvec3 r = glm::cross(f, glm::dvec3(0.0, 1.0, 0.0));
    r = glm::length(r) > 1e-9 ? glm::normalize(r) : glm::dvec3(1.0, 0.0, 0.0);
    position_ += (f * forward + r * right + glm::dvec3(0.0, 1.0, 0.0) * up) * (speed_ * seconds);
}

void FreeCamera::scale_speed(double notches) { speed_ = std::clamp(speed_ * std::pow(1.25, notches), 0.1, 1000.0); }

glm::mat4 FreeCamera::view_rotation() const {
    // Looking straight up or down: -z is "up" for the image, as grass_host::make_view.
    const glm::dvec3 up = std::fabs(forward_.y) > 0.9999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::mat4(glm::lookAtRH(glm::dvec3(0.0), forward_, up));
}

} // namespace grass_viewer
