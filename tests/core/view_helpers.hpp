// Views for tests that run without a host: a look-at camera with a GL projection,
// perspective or orthographic.
#pragma once

#include <grass/grass.h>

#include <cmath>

// A 256 x 256 view from `eye` towards `target` (y up), its projection left zero.
inline grass_view_desc look_at_view(const double eye[3], const double target[3]) {
    grass_view_desc v = grass_default_view_desc();
    for (int c = 0; c < 3; ++c) v.camera_position[c] = eye[c];
    double f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& x : f) x /= fl;
    const double up0[3] = {0, 1, 0}, alt[3] = {0, 0, -1};
    const double* u0 = std::fabs(f[1]) > 0.9999 ? alt : up0;
    double r[3] = {f[1] * u0[2] - f[2] * u0[1], f[2] * u0[0] - f[0] * u0[2], f[0] * u0[1] - f[1] * u0[0]};
    const double rl = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (double& x : r) x /= rl;
    const double u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    for (int k = 0; k < 16; ++k) v.view[k] = 0.0f;
    for (int c = 0; c < 3; ++c) {
        v.view[4 * c + 0] = static_cast<float>(r[c]);
        v.view[4 * c + 1] = static_cast<float>(u[c]);
        v.view[4 * c + 2] = static_cast<float>(-f[c]);
    }
    v.view[15] = 1.0f;
    for (float& p : v.projection) p = 0.0f;
    v.viewport[2] = 256;
    v.viewport[3] = 256;
    return v;
}

inline grass_view_desc test_view(const double eye[3], const double target[3], float fovy_degrees = 60.0f,
                                 float aspect = 1.0f, float near_m = 0.05f, float far_m = 500.0f) {
    grass_view_desc v = look_at_view(eye, target);
    const float t = 1.0f / std::tan(fovy_degrees * 3.14159265f / 360.0f);
    v.projection[0] = t / aspect;
    v.projection[5] = t;
    v.projection[10] = (far_m + near_m) / (near_m - far_m);
    v.projection[11] = -1.0f;
    v.projection[14] = 2.0f * far_m * near_m / (near_m - far_m);
    return v;
}

// An orthographic view (glOrtho's projection): `half_height` metres above and below the
// axis, `aspect` times that across; near_m may be negative (a shadow cascade's box starts
// behind its eye).
inline grass_view_desc test_ortho_view(const double eye[3], const double target[3], float half_height, float aspect,
                                       float near_m, float far_m) {
    grass_view_desc v = look_at_view(eye, target);
    v.projection[0] = 1.0f / (half_height * aspect);
    v.projection[5] = 1.0f / half_height;
    v.projection[10] = -2.0f / (far_m - near_m);
    v.projection[14] = -(far_m + near_m) / (far_m - near_m);
    v.projection[15] = 1.0f;
    return v;
}
