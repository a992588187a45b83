// View-frustum culling of quadtree nodes (lemme2012 6.1.4). All positions are relative to
// the camera, in double.
//   - Fast reject: the frustum is approximated by a sphere (centre half-way to the far
//     plane, through the far corners) and a cone (apex at the centre of projection, through
//     the corners); a node's bounding sphere must meet both (sphere-cone test after Eberly
//     2002). The centre of projection is the matrix's own (the null vector of its x, y and w
//     rows): the camera for a perspective built at the view's origin, elsewhere for an
//     off-centre or warped one, at infinity for parallel rays. A view with parallel rays (an
//     orthographic box: a shadow cascade's, a top-down map's; a light-space perspective
//     shadow map's warp of one) gets a sphere through its 8 corners and no cone.
//   - Exact test before a node is drawn: its box against the six clip planes.
#pragma once

#include <grass/grass.h>

#include <cstdint>

namespace grass {

class ViewCulling {
public:
    // `view_projection`: camera-relative world -> clip, column-major.
    ViewCulling(const double view_projection[16], grass_depth_mode depth_mode);

    // False when the sphere (centre relative to the camera) surely misses the frustum.
    bool sphere_may_be_visible(const double center[3], double radius) const;
    // False when the box (8 corners relative to the camera) is entirely outside a plane.
    bool box_may_be_visible(const double corners[8][3]) const;

    const double* axis() const { return axis_; }
    // A view whose rays are parallel (an orthographic view, m[3] = m[7] = m[11] = 0, whose
    // box has a depth, or a warped one whose centre of projection lies at infinity); axis()
    // is then their direction, the way the depth grows (falls for reversed depth).
    bool orthographic() const { return orthographic_; }
    // Otherwise the centre of projection, the point every ray starts from, relative to the
    // camera: zero for a perspective built at the view's origin.
    const double* apex() const { return apex_; }

private:
    void orthographic_box(const double inverse_view_projection[16], grass_depth_mode depth_mode);
    void parallel_rays(const double m[16], const double inverse_view_projection[16], const double centre[4],
                       grass_depth_mode depth_mode);
    void perspective(const double inverse_view_projection[16], grass_depth_mode depth_mode);

    double planes_[6][4];
    double axis_[3] = {0, 0, -1};
    double apex_[3] = {0, 0, 0};
    bool orthographic_ = false;
    bool has_cone_ = false;
    double sin_angle_ = 1.0, cos_angle_ = 0.0;
    bool has_sphere_ = false;
    double sphere_center_[3] = {0, 0, 0};
    double sphere_radius_ = 0.0;
};

// The frusta a node must meet one of: the camera's, or a stereo frame's two eyes', each
// with the eye's position relative to the plan's origin (positions are tested relative to it).
struct Frusta {
    const ViewCulling* culling[2];
    double eye[2][3];
    uint32_t count;
    bool sphere_may_be_visible(const double center[3], double radius) const {
        for (uint32_t k = 0; k < count; ++k) {
            const double c[3] = {center[0] - eye[k][0], center[1] - eye[k][1], center[2] - eye[k][2]};
            if (culling[k]->sphere_may_be_visible(c, radius)) return true;
        }
        return false;
    }
    bool box_may_be_visible(const double corners[8][3]) const {
        for (uint32_t k = 0; k < count; ++k) {
            double c[8][3];
            for (int i = 0; i < 8; ++i) {
                for (int a = 0; a < 3; ++a) c[i][a] = corners[i][a] - eye[k][a];
            }
            if (culling[k]->box_may_be_visible(c)) return true;
        }
        return false;
    }
};

} // namespace grass
