// 4x4 matrices of the hosts, the tests and the samples: column-major, double.
#pragma once

#include <cmath>
#include <utility>

namespace grass_host {

// The product a * b of column-major 4x4 matrices into `out` (not a or b).
inline void multiply4(const double a[16], const double b[16], double out[16]) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) s += a[4 * k + r] * b[4 * c + k];
            out[4 * c + r] = s;
        }
    }
}

// The inverse of `m` (Gauss-Jordan with partial pivoting) into `out`; false when `m` is
// singular (out then undefined).
inline bool invert4(const double m[16], double out[16]) {
    double a[4][8];
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            a[r][c] = m[4 * c + r];
            a[r][4 + c] = r == c ? 1.0 : 0.0;
        }
    }
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r) p = std::fabs(a[r][c]) > std::fabs(a[p][c]) ? r : p;
        if (std::fabs(a[p][c]) < 1e-300) return false;
        for (int k = 0; k < 8; ++k) std::swap(a[c][k], a[p][k]);
        const double d = a[c][c];
        for (int k = 0; k < 8; ++k) a[c][k] /= d;
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            const double f = a[r][c];
            for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
        }
    }
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) out[4 * c + r] = a[r][4 + c];
    }
    return true;
}

} // namespace grass_host
