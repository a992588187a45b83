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

// The centre of projection of `m`: the homogeneous point (camera-relative) that every ray
// passes through, the null vector of its x, y and w rows (each ray is where clip x and y are
// fixed multiples of clip w). w = 0: at infinity, the rays parallel to xyz.
void centre_of_projection(const double m[16], double out[4]) {
    const double rows[3][4] = {{m[0], m[4], m[8], m[12]}, {m[1], m[5], m[9], m[13]}, {m[3], m[7], m[11], m[15]}};
    for (int i = 0; i < 4; ++i) {
        int col[3], n = 0;
        for (int k = 0; k < 4; ++k) {
            if (k != i) col[n++] = k;
        }
        const double det = rows[0][col[0]] * (rows[1][col[1]] * rows[2][col[2]] - rows[1][col[2]] * rows[2][col[1]]) -
                           rows[0][col[1]] * (rows[1][col[0]] * rows[2][col[2]] - rows[1][col[2]] * rows[2][col[0]]) +
                           rows[0][col[2]] * (rows[1][col[0]] * rows[2][col[1]] - rows[1][col[1]] * rows[2][col[0]]);
        out[i] = (i % 2 ? -1.0 : 1.0) * det;
    }
}

// NDC z of a camera-relative point; false at infinity.
bool ndc_depth(const double m[16], const double p[3], double* z) {
    const double w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
    if (!(std::fabs(w) > 1e-300)) return false;
    *z = (m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]) / w;
    return std::isfinite(*z);
}

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
    // Any other projection: its rays meet at its centre of projection, which is the camera
    // for a perspective built at the view's origin (exactly: its x, y and w rows have no
    // translation), and elsewhere for an off-centre or warped one (a spot light's frustum
    // placed off camera_position, a light-space perspective shadow map's warp, whose rays stay
    // parallel to the light: its centre lies at infinity).
    double c[4];
    centre_of_projection(m, c);
    const double c_len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (c_len > 0.0) {
        // Parallel rays when the centre lies so far that the rays across the view diverge by
        // less than 1e-5 radians (a warp in float rarely gives w = 0 exactly).
        double a[3], b[3];
        const bool spans = unproject(inv, -1.0, -1.0, 0.5, a) && unproject(inv, 1.0, 1.0, 0.5, b);
        const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double extent = spans ? std::sqrt(dot(d, d)) : 0.0;
        if (std::fabs(c[3]) * extent <= 1e-5 * c_len) {
            parallel_rays(m, inv, c, depth_mode);
            return;
        }
        for (int k = 0; k < 3; ++k) apex_[k] = c[k] / c[3];
    }
    perspective(inv, depth_mode);
}

void ViewCulling::parallel_rays(const double m[16], const double inv[16], const double c[4],
                                grass_depth_mode depth_mode) {
    // A box's sphere where the frustum is bounded; the axis is the rays' direction, the way
    // the depth grows (falls for reversed depth) along them.
    orthographic_box(inv, depth_mode);
    double p[3], q[3], z0 = 0.0, z1 = 0.0;
    if (!unproject(inv, 0.0, 0.0, 0.5, p)) return;
    const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (int k = 0; k < 3; ++k) q[k] = p[k] + c[k] / len;
    if (!ndc_depth(m, p, &z0) || !ndc_depth(m, q, &z1) || z0 == z1) return;
    const double s = ((z1 > z0) == (depth_mode != GRASS_DEPTH_GREATER)) ? 1.0 : -1.0;
    for (int k = 0; k < 3; ++k) axis_[k] = s * c[k] / len;
    orthographic_ = true;
}

void ViewCulling::perspective(const double inv[16], grass_depth_mode depth_mode) {
    // Points relative to the apex (the centre of projection).
    const auto unproject_from_apex = [&](double x, double y, double z, double out[3]) {
        if (!unproject(inv, x, y, z, out)) return false;
        for (int k = 0; k < 3; ++k) out[k] -= apex_[k];
        return true;
    };
    // Directions through the centre and the corners, from points inside the depth range of
    // both conventions; the far plane at depth 1 (or 0 for reversed depth).
    double centre[3], corner[4][3];
    if (!unproject_from_apex(0.0, 0.0, 0.5, centre)) return;
    const double len = std::sqrt(dot(centre, centre));
    for (int c = 0; c < 3; ++c) axis_[c] = centre[c] / len;
    double cos_min = 1.0;
    bool corners_ok = true;
    for (int k = 0; k < 4; ++k) {
        const double x = (k & 1) ? 1.0 : -1.0, y = (k & 2) ? 1.0 : -1.0;
        if (!unproject_from_apex(x, y, 0.5, corner[k])) {
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
            if (!unproject_from_apex(x, y, far_depth, far_corner[k]) || dot(far_corner[k], axis_) <= 0.0) return false;
            far_distance = std::max(far_distance, dot(far_corner[k], axis_));
        }
        return true;
    };
    if (depth_mode == GRASS_DEPTH_GREATER) {
        if (!far_corners(-1.0) && !far_corners(0.0)) return; // infinite far plane
    } else if (!far_corners(1.0)) {
        return; // infinite far plane
    }
    // Off the camera (an off-centre or warped projection) the near plane need not lie between
    // the apex and the far plane: the sphere below holds the frustum only where each near
    // corner lies on its ray between them (near at NDC z -1 or 0, 1 for reversed depth).
    if (apex_[0] != 0.0 || apex_[1] != 0.0 || apex_[2] != 0.0) {
        const auto near_inside = [&](double near_depth) {
            for (int k = 0; k < 4; ++k) {
                const double x = (k & 1) ? 1.0 : -1.0, y = (k & 2) ? 1.0 : -1.0;
                double q[3];
                if (!unproject_from_apex(x, y, near_depth, q)) return false;
                const double along = dot(q, axis_);
                if (!(along > 0.0 && along <= dot(far_corner[k], axis_))) return false;
            }
            return true;
        };
        const bool inside =
            depth_mode == GRASS_DEPTH_GREATER ? near_inside(1.0) : near_inside(-1.0) || near_inside(0.0);
        if (!inside) return;
    }
    // Centre half-way to the far plane (the near plane lies between the apex and it); radius
    // through the far corners, which also covers the apex.
    double centre_from_apex[3];
    for (int c = 0; c < 3; ++c) centre_from_apex[c] = axis_[c] * 0.5 * far_distance;
    double r2 = dot(centre_from_apex, centre_from_apex);
    for (const auto& q : far_corner) {
        const double d[3] = {q[0] - centre_from_apex[0], q[1] - centre_from_apex[1], q[2] - centre_from_apex[2]};
        r2 = std::max(r2, dot(d, d));
    }
    for (int c = 0; c < 3; ++c) sphere_center_[c] = apex_[c] + centre_from_apex[c];
    sphere_radius_ = std::sqrt(r2) * (1.0 + 1e-9);
    has_sphere_ = std::isfinite(sphere_radius_);
}

void ViewCulling::orthographic_box(const double inv[16], grass_depth_mode depth_mode) {
    // Corners at NDC z -1 and 1: the whole box in GL's depth range, and more in 0..1 (z -1
    // lies behind the near plane, or beyond the far plane for reversed depth): conservative
    // in every convention. The axis runs from the near face to the far face.
    // A warped projection's cube may reach through infinity (its corners' w of both signs):
    // no sphere then.
    double corner[8][3], mean[3] = {0, 0, 0}, near_centre[3] = {0, 0, 0}, far_centre[3] = {0, 0, 0};
    int positive_w = 0;
    for (int k = 0; k < 8; ++k) {
        const double x = (k & 1) ? 1.0 : -1.0, y = (k & 2) ? 1.0 : -1.0, z = (k & 4) ? 1.0 : -1.0;
        positive_w += inv[3] * x + inv[7] * y + inv[11] * z + inv[15] > 0.0;
    }
    if (positive_w != 0 && positive_w != 8) return;
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

bool ViewCulling::sphere_may_be_visible(const double centre[3], double r) const {
    if (has_sphere_) {
        const double d[3] = {centre[0] - sphere_center_[0], centre[1] - sphere_center_[1],
                             centre[2] - sphere_center_[2]};
        const double reach = r + sphere_radius_;
        if (dot(d, d) > reach * reach) return false;
    }
    if (has_cone_) {
        const double s[3] = {centre[0] - apex_[0], centre[1] - apex_[1], centre[2] - apex_[2]};
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
