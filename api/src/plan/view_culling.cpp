#include "plan/view_culling.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

namespace {

// Inverse of a column-major 4x4 matrix; false when it is singular.
bool invert4(const double m[16], double out[16]) {
    double inv[16];
    inv[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] + m[9] * m[7] * m[14] +
             m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
    inv[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] - m[8] * m[7] * m[14] -
             m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
    inv[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] + m[8] * m[7] * m[13] +
             m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
    inv[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] - m[8] * m[6] * m[13] -
              m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
    inv[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] - m[9] * m[3] * m[14] -
             m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
    inv[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] + m[8] * m[3] * m[14] +
             m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
    inv[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] - m[8] * m[3] * m[13] -
             m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
    inv[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] + m[8] * m[2] * m[13] +
              m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
    inv[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] +
             m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
    inv[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] - m[4] * m[3] * m[14] -
             m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
    inv[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] + m[4] * m[3] * m[13] +
              m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
    inv[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] - m[4] * m[2] * m[13] -
              m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
    inv[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] - m[5] * m[3] * m[10] -
             m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
    inv[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] +
             m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
    inv[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] -
              m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
    inv[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] + m[8] * m[1] * m[6] -
              m[8] * m[2] * m[5];
    const double det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
    if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return false;
    for (int k = 0; k < 16; ++k) out[k] = inv[k] / det;
    return true;
}

// Clip-space point -> camera-relative position; false at infinity.
bool unproject(const double inv[16], double x, double y, double z, double out[3]) {
    const double w = inv[3] * x + inv[7] * y + inv[11] * z + inv[15];
    if (!(std::fabs(w) > 1e-300)) return false;
    for (int c = 0; c < 3; ++c) out[c] = (inv[c] * x + inv[4 + c] * y + inv[8 + c] * z + inv[12 + c]) / w;
    return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]);
}

double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

} // namespace

ViewCulling::ViewCulling(const double m[16], grass_depth_mode depth_mode) {
    // Gribb & Hartmann planes; row r of m is (m[r], m[4+r], m[8+r], m[12+r]). The near plane
    // w + z >= 0 is GL's; for 0..1 depth it is looser than z >= 0, so conservative.
    const int sign[6] = {1, -1, 1, -1, 1, -1};
    const int axis[6] = {0, 0, 1, 1, 2, 2};
    for (int p = 0; p < 6; ++p) {
        for (int k = 0; k < 4; ++k) planes_[p][k] = m[4 * k + 3] + sign[p] * m[4 * k + axis[p]];
    }

    double inv[16];
    if (!invert4(m, inv)) return; // degenerate projection: only the plane test
    // An orthographic view (clip w does not depend on the position) is a box: no cone, whose
    // apex at the camera would cut off the box's sides near it, but a sphere through the
    // box's 8 corners.
    if (m[3] == 0.0 && m[7] == 0.0 && m[11] == 0.0) {
        orthographic_box(inv, depth_mode);
        return;
    }
    // Directions through the centre and the corners, from points inside the depth range of
    // both conventions; the far plane at depth 1 (or 0 for reversed depth).
    double centre[3], corner[4][3];
    if (!unproject(inv, 0.0, 0.0, 0.5, centre)) return;
    const double len = std::sqrt(dot(centre, centre));
    for (int c = 0; c < 3; ++c) axis_[c] = centre[c] / len;
    double cos_min = 1.0;
    bool corners_ok = true;
    for (int k = 0; k < 4; ++k) {
        const double x = (k & 1) ? 1.0 : -1.0, y = (k & 2) ? 1.0 : -1.0;
        if (!unproject(inv, x, y, 0.5, corner[k])) {
            corners_ok = false;
            break;
        }
        const double l = std::sqrt(dot(corner[k], corner[k]));
        cos_min = std::min(cos_min, dot(corner[k], axis_) / l);
    }
    if (!corners_ok) return;
    // A cone that is nearly a half-space rejects nothing: skip it.
    if (cos_min > 0.02) {
        has_cone_ = true;
        cos_angle_ = cos_min;
        sin_angle_ = std::sqrt(std::max(0.0, 1.0 - cos_min * cos_min));
    }
    // The far plane: NDC z 1 for classic depth in either clip convention. Reversed depth puts
    // it at -1 in GL's default -1..1 and at 0 in 0..1 (Vulkan, GL clip control), which the
    // core does not know: -1 first, which for a 0..1 projection lies beyond its far plane,
    // behind the camera, then 0.
    double far_corner[4][3];
    double far_distance = 0.0;
    const auto far_corners = [&](double far_depth) {
        far_distance = 0.0;
        for (int k = 0; k < 4; ++k) {
            const double x = (k & 1) ? 1.0 : -1.0, y = (k & 2) ? 1.0 : -1.0;
            if (!unproject(inv, x, y, far_depth, far_corner[k]) || dot(far_corner[k], axis_) <= 0.0) return false;
            far_distance = std::max(far_distance, dot(far_corner[k], axis_));
        }
        return true;
    };
    if (depth_mode == GRASS_DEPTH_GREATER) {
        if (!far_corners(-1.0) && !far_corners(0.0)) return; // infinite far plane
    } else if (!far_corners(1.0)) {
        return; // infinite far plane
    }
    // Centre half-way to the far plane (the near plane is ~0 away); radius through the far
    // corners, which also covers the camera.
    for (int c = 0; c < 3; ++c) sphere_center_[c] = axis_[c] * 0.5 * far_distance;
    double r2 = dot(sphere_center_, sphere_center_);
    for (const auto& q : far_corner) {
        const double d[3] = {q[0] - sphere_center_[0], q[1] - sphere_center_[1], q[2] - sphere_center_[2]};
        r2 = std::max(r2, dot(d, d));
    }
    sphere_radius_ = std::sqrt(r2) * (1.0 + 1e-9);
    has_sphere_ = std::isfinite(sphere_radius_);
}

void ViewCulling::orthographic_box(const double inv[16], grass_depth_mode depth_mode) {
    // Corners at NDC z -1 and 1: the whole box in GL's depth range, and more in 0..1 (z -1
    // lies behind the near plane, or beyond the far plane for reversed depth): conservative
    // in every convention. The axis runs from the near face to the far face.
    double corner[8][3], mean[3] = {0, 0, 0}, near_centre[3] = {0, 0, 0}, far_centre[3] = {0, 0, 0};
    for (int k = 0; k < 8; ++k) {
        const double x = (k & 1) ? 1.0 : -1.0, y = (k & 2) ? 1.0 : -1.0, z = (k & 4) ? 1.0 : -1.0;
        if (!unproject(inv, x, y, z, corner[k])) return;
        for (int c = 0; c < 3; ++c) {
            mean[c] += corner[k][c] / 8.0;
            ((k & 4) ? far_centre : near_centre)[c] += corner[k][c] / 4.0;
        }
    }
    double d[3];
    for (int c = 0; c < 3; ++c) d[c] = (far_centre[c] - near_centre[c]) * (depth_mode == GRASS_DEPTH_GREATER ? -1 : 1);
    const double len = std::sqrt(dot(d, d));
    if (len > 0.0 && std::isfinite(len)) {
        for (int c = 0; c < 3; ++c) axis_[c] = d[c] / len;
        orthographic_ = true;
    }
    double r2 = 0.0;
    for (const auto& q : corner) {
        const double e[3] = {q[0] - mean[0], q[1] - mean[1], q[2] - mean[2]};
        r2 = std::max(r2, dot(e, e));
    }
    for (int c = 0; c < 3; ++c) sphere_center_[c] = mean[c];
    sphere_radius_ = std::sqrt(r2) * (1.0 + 1e-9);
    has_sphere_ = std::isfinite(sphere_radius_);
}

bool ViewCulling::sphere_may_be_visible(const double s[3], double r) const {
    if (has_sphere_) {
        const double d[3] = {s[0] - sphere_center_[0], s[1] - sphere_center_[1], s[2] - sphere_center_[2]};
        const double reach = r + sphere_radius_;
        if (dot(d, d) > reach * reach) return false;
    }
    if (has_cone_) {
        // Eberly: move the apex back by r / sin(angle) along the axis; the sphere meets the
        // cone if its centre is inside that larger cone and not behind the real apex beyond r.
        const double back = r / sin_angle_;
        const double u[3] = {s[0] + axis_[0] * back, s[1] + axis_[1] * back, s[2] + axis_[2] * back};
        const double e = dot(axis_, u);
        if (!(e > 0.0 && e * e >= dot(u, u) * cos_angle_ * cos_angle_)) return false;
        const double e2 = -dot(axis_, s);
        if (e2 > 0.0 && e2 * e2 >= dot(s, s) * sin_angle_ * sin_angle_) return dot(s, s) <= r * r;
    }
    return true;
}

bool ViewCulling::box_may_be_visible(const double corners[8][3]) const {
    for (const auto& p : planes_) {
        bool all_out = true;
        for (int k = 0; k < 8 && all_out; ++k) {
            all_out = p[0] * corners[k][0] + p[1] * corners[k][1] + p[2] * corners[k][2] + p[3] < 0.0;
        }
        if (all_out) return false;
    }
    return true;
}

} // namespace grass
