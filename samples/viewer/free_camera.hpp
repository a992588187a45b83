// The viewer's free camera (GLM): a position and a yaw/pitch heading, moved with WASD and
// turned with the mouse; its speed changes on the wheel. A look-at from grass-render's
// --camera/--target gives the same view as the headless tool.
#pragma once

#include <glm/glm.hpp>

namespace grass_viewer {

class FreeCamera {
public:
    // Looks from `eye` at `target` (y up), as grass_host::make_view does.
    void look_at(const glm::dvec3& eye, const glm::dvec3& target);

    // Turns by a mouse movement in pixels (x right, y down); pitch stays within +-89 degrees.
    void turn(double dx_pixels, double dy_pixels);
    // Moves by `forward`, `right` and `up` steps (-1..1 each) for `seconds` at the current speed.
    void move(double forward, double right, double up, double seconds);
    // One wheel notch multiplies (or divides) the speed by 1.25, within 0.1..1000 m/s.
    void scale_speed(double notches);

    const glm::dvec3& position() const { return position_; }
    glm::dvec3 forward() const;
    double speed() const { return speed_; }

    // World-to-eye rotation (the translation is grass_view_desc.camera_position), column-major.
    glm::mat4 view_rotation() const;

private:
    glm::dvec3 position_{0.0, 1.7, 0.0};
    glm::dvec3 forward_{0.0, 0.0, 1.0}; // unit; kept exact for a look-at, rebuilt from yaw/pitch on turns
    double speed_ = 4.0;                // metres per second
};

} // namespace grass_viewer
