// Seamless transitions between tiers: the GLSL twin of api/src/tier_transitions.cpp (read
// its header for the method: boulanger2006 eq. 2-5, lemme2012 eq. 5.22-5.26). Needs the
// Field block's tier bands.

float band_weight(vec4 band, float d) {
    if (d < band.x || d > band.y) return 0.0;
    float w_in = band.z > 0.0 ? clamp((d - band.x) / band.z, 0.0, 1.0) : 1.0;
    float w_out = band.w > 0.0 ? clamp((band.y - d) / band.w, 0.0, 1.0) : 1.0;
    return w_in * w_out;
}

// The interval (a, b] of r = threshold / density that this draw's tier draws at distance d
// (metres): its share of the tiers' weights there, after the shares of the tiers beyond it.
// a > b: it draws nothing. A field-edge instance (`field_edge`: a volume tier standing in for
// the image tiers after it along the field's border, api/src/plan/frame_planner.cpp) draws
// the share of every tier after this one instead, (0, their share].
vec2 tier_interval(float d, bool field_edge) {
    uint tier = field.tiers.x, count = field.tiers.y;
    float total = 0.0, lo = 0.0, self_w = 0.0;
    for (uint t = 0u; t < count; ++t) {
        float w = band_weight(field.bands[t], d);
        total += w;
        if (t > tier) lo += w;
        if (t == tier) self_w = w;
    }
    if (!(total > 0.0)) return vec2(1.0, 0.0);
    if (field_edge) return lo > 0.0 ? vec2(0.0, lo / total) : vec2(1.0, 0.0);
    if (!(self_w > 0.0)) return vec2(1.0, 0.0);
    return vec2(lo / total, (lo + self_w) / total);
}

// Opacity of a blade (threshold in (0, 1]) drawn by this draw's tier at distance d (metres)
// where the local density is `density`.
// An overlay tier (field.tiers.z = 1: hilltops, lemme 6.4.6) takes no share of the
// transitions: it draws every blade the density passes, fully opaque.
float tier_blade_opacity(float d, float threshold, float density, bool field_edge) {
    if (!(density > 0.0) || threshold > density) return 0.0;
    if (field.tiers.z != 0u) return 1.0;
    vec2 interval = tier_interval(d, field_edge);
    if (interval.x > interval.y) return 0.0;
    float r = threshold / density;
    float a = interval.x, b = interval.y;
    float window = field.transition.x;
    float enter = a <= 0.0 ? 1.0 : (window > 0.0 ? smoothstep(a - window, a + window, r) : (r > a ? 1.0 : 0.0));
    float leave = b >= 1.0 ? 1.0 : (window > 0.0 ? 1.0 - smoothstep(b - window, b + window, r) : (r <= b ? 1.0 : 0.0));
    // Without multisampling a blade is all or nothing: the tier where its opacity is at
    // least one half draws it, so the crossover is exact (grass_field_desc.transition_window).
    float opacity = enter * leave;
    return sample_count() <= 1 ? step(0.5, opacity) : opacity;
}
float tier_blade_opacity(float d, float threshold, float density) {
    return tier_blade_opacity(d, threshold, density, false);
}

// A slice texel holds several blades. Its coverage curve (api/src/baked_slices.hpp: the
// threshold texture's gba) is the share of its coverage whose blades' thresholds are at most
// x, known at x = 1/4 (g), 1/2 (b), 3/4 (a) and 1 (all). Between the knots the uncovered
// share 1 - c falls geometrically in ln(1 - x), as it does where m blades with uniform
// thresholds overlap a sample ((1 - x)^m): a texel of many blades is mostly covered at a
// low density already, which a straight line from (0, 0) would miss (a volume tier with few,
// thick slices drew thin grass too thin). The last quarter is linear (it ends at 1).
float coverage_curve(vec4 t, float x) {
    x = clamp(x, 0.0, 1.0);
    if (x >= 0.75) return mix(t.a, 1.0, (x - 0.75) * 4.0);
    int k = min(int(x * 4.0), 2);
    float lo = k == 0 ? 0.0 : (k == 1 ? t.g : t.b);
    float hi = k == 0 ? t.g : (k == 1 ? t.b : t.a);
    float x0 = float(k) * 0.25;
    // 0 at x0, 1 at x0 + 1/4: ln((1 - x) / (1 - x0)) / ln((3/4 - x0) / (1 - x0)).
    const float inv_log_step[3] = float[3](1.0 / log(0.75), 1.0 / log(0.5 / 0.75), 1.0 / log(0.25 / 0.5));
    float s = log((1.0 - x) / (1.0 - x0)) * inv_log_step[k];
    float uncovered_lo = max(1.0 - lo, 1e-3), uncovered_hi = clamp(1.0 - hi, 1e-3, uncovered_lo);
    return 1.0 - uncovered_lo * pow(uncovered_hi / uncovered_lo, s);
}

// The share of a slice texel's coverage this draw's tier draws at distance d: that of the
// blades whose thresholds lie in the tier's interval of (0, density] (the texel-level twin
// of tier_blade_opacity: a texel thins with the density, and two tiers sharing a transition
// zone draw complementary shares, instead of all or nothing per texel).
// `whole`: the share of every tier (texel_transition: the tier takes its part of the samples).
float tier_texel_share(float d, vec4 t, float density, bool field_edge, bool whole) {
    if (!(density > 0.0) || t.r <= 0.0) return 0.0;
    if (field.tiers.z != 0u || whole) return coverage_curve(t, density);
    vec2 interval = tier_interval(d, field_edge);
    if (interval.x > interval.y) return 0.0;
    float a = interval.x, b = interval.y;
    // Outside transition zones a tier's interval starts at 0, where the curve is 0.
    float below = a > 0.0 ? coverage_curve(t, a * density) : 0.0;
    return max(coverage_curve(t, b * density) - below, 0.0);
}
float tier_texel_share(float d, vec4 t, float density) {
    return tier_texel_share(d, t, density, false, false);
}

// Between two texel tiers (a transition zone where no geometry tier draws: field.tiers.w
// holds the geometry tiers' bits, set by the core) each tier draws the grass whole and takes
// its part of the pixel's samples, its weight there (sample_coverage.glsl, write_coverage):
// the parts of the two tiers at one distance add up to 1. Drawn as a thinner grass of its own
// (its share), each texel tier covered nearly every sample even for a small share, and the
// depth test chose between them: the nearer tier's colour showed across the zone, an arc where
// the zone began (issue 32, item 5). Beside the blades, which fade blade by blade, a tier
// still draws its share, and so does an overlay tier (the threshold view, whole texels, does
// not call this).
bool texel_transition(float d) {
    if (field.tiers.z != 0u) return false;
    for (uint t = 0u; t < field.tiers.y; ++t) {
        if ((field.tiers.w & (1u << t)) != 0u && band_weight(field.bands[t], d) > 0.0) return false;
    }
    return true;
}

// The part of the samples this draw's tier takes at distance d (texel_transition): the
// length of its interval of thresholds, 0 where it draws nothing, 1 outside transition zones.
float tier_texel_part(float d, bool field_edge) {
    vec2 interval = tier_interval(d, field_edge);
    return max(interval.y - interval.x, 0.0);
}
