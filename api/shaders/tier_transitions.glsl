// Seamless transitions between tiers: the GLSL twin of api/src/tier_transitions.cpp (read
// its header for the method: boulanger2006 eq. 2-5, lemme2012 eq. 5.22-5.26). Needs the
// Field block's tier bands.

float band_weight(vec4 band, float d) {
    if (d < band.x || d > band.y) return 0.0;
    float w_in = band.z > 0.0 ? clamp((d - band.x) / band.z, 0.0, 1.0) : 1.0;
    float w_out = band.w > 0.0 ? clamp((band.y - d) / band.w, 0.0, 1.0) : 1.0;
    return w_in * w_out;
}

// Opacity of a blade (threshold in (0, 1]) drawn by this draw's tier at distance d (metres)
// where the local density is `density`.
// An overlay tier (field.tiers.z = 1: hilltops, lemme 6.4.6) takes no share of the
// transitions: it draws every blade the density passes, fully opaque.
float tier_blade_opacity(float d, float threshold, float density) {
    if (!(density > 0.0) || threshold > density) return 0.0;
    if (field.tiers.z != 0u) return 1.0;
    uint tier = field.tiers.x, count = field.tiers.y;
    float total = 0.0, lo = 0.0, self_w = 0.0;
    for (uint t = 0u; t < count; ++t) {
        float w = band_weight(field.bands[t], d);
        total += w;
        if (t > tier) lo += w;
        if (t == tier) self_w = w;
    }
    if (!(total > 0.0) || !(self_w > 0.0)) return 0.0;
    float r = threshold / density;
    float a = lo / total, b = (lo + self_w) / total;
    float window = field.transition.x;
    float enter = a <= 0.0 ? 1.0 : (window > 0.0 ? smoothstep(a - window, a + window, r) : (r > a ? 1.0 : 0.0));
    float leave = b >= 1.0 ? 1.0 : (window > 0.0 ? 1.0 - smoothstep(b - window, b + window, r) : (r <= b ? 1.0 : 0.0));
    return enter * leave;
}
