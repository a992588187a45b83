#include "plan/tier_transitions.hpp"

#include <algorithm>

namespace grass {

namespace {

// GLSL's smoothstep (edge0 < edge1).
float smoothstep(float e0, float e1, float x) {
    const float t = std::min(1.0f, std::max(0.0f, (x - e0) / (e1 - e0)));
    return t * t * (3.0f - 2.0f * t);
}

} // namespace

float band_weight(const TierBand& b, float d) {
    if (d < b.begin || d > b.end) return 0.0f;
    const float w_in = b.transition_in > 0.0f ? std::min(1.0f, std::max(0.0f, (d - b.begin) / b.transition_in)) : 1.0f;
    const float w_out = b.transition_out > 0.0f ? std::min(1.0f, std::max(0.0f, (b.end - d) / b.transition_out)) : 1.0f;
    return w_in * w_out;
}

float tier_blade_opacity(const TierBand* bands, uint32_t count, uint32_t tier, float d, float threshold, float density,
                         float window) {
    if (!(density > 0.0f) || threshold > density) return 0.0f;
    float total = 0.0f, lo = 0.0f, self = 0.0f;
    for (uint32_t t = 0; t < count; ++t) {
        const float w = band_weight(bands[t], d);
        total += w;
        if (t > tier) lo += w;
        if (t == tier) self = w;
    }
    if (!(total > 0.0f) || !(self > 0.0f)) return 0.0f;
    const float r = threshold / density;
    const float a = lo / total, b = (lo + self) / total;
    // Interval (a, b]; its open ends at 0 and 1 need no window.
    const float enter =
        a <= 0.0f ? 1.0f : (window > 0.0f ? smoothstep(a - window, a + window, r) : (r > a ? 1.0f : 0.0f));
    const float leave =
        b >= 1.0f ? 1.0f : (window > 0.0f ? 1.0f - smoothstep(b - window, b + window, r) : (r <= b ? 1.0f : 0.0f));
    return enter * leave;
}

} // namespace grass
