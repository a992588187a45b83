#include "bake/srgb_encode.hpp"

namespace grass {

namespace {

// x^(1/5) for x in (0, 1.1] by Newton's method from a fixed start: deterministic bits.
double fifth_root(double x) {
    double y = 1.0;
    for (int k = 0; k < 60; ++k) {
        const double y2 = y * y;
        const double y4 = y2 * y2;
        const double next = y - (y4 * y - x) / (5.0 * y4);
        if (next == y) break;
        y = next;
    }
    return y;
}

// The sRGB decode curve: ((e + 0.055) / 1.055)^2.4 = u^2 * (u^(1/5))^2.
double decode(double e) {
    if (e <= 0.04045) return e / 12.92;
    const double u = (e + 0.055) / 1.055;
    const double r = fifth_root(u);
    return u * u * r * r;
}

struct Midpoints {
    double linear[255]; // linear value of the boundary between code k and k + 1
    Midpoints() {
        for (int k = 0; k < 255; ++k) linear[k] = decode((k + 0.5) / 255.0);
    }
};

const Midpoints& midpoints() {
    static const Midpoints table;
    return table;
}

} // namespace

uint8_t linear_to_srgb8(float linear) {
    if (!(linear > 0.0f)) return 0;
    const double v = linear;
    const double* m = midpoints().linear;
    // The code is the number of midpoints at or below v (a value on a boundary rounds up).
    int lo = 0, hi = 255;
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (m[mid] <= v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return static_cast<uint8_t>(lo);
}

uint8_t float_to_unorm8(float value) {
    if (!(value > 0.0f)) return 0;
    if (value >= 1.0f) return 255;
    return static_cast<uint8_t>(static_cast<int>(value * 255.0f + 0.5f));
}

} // namespace grass
