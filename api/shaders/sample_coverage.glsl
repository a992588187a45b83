// Coverage as a sample mask, for the fragment shaders of the volume and image tiers
// (blade_interface.glsl first: it reads frame.params.w and field.tiers).
// The volume and image tiers write their coverage as a sample mask instead of alpha to
// coverage (whose dither the driver picks). alpha x samples is rounded to whole samples
// by a 4 x 4 ordered dither per pixel, the same for every draw, so that
// - carriers of one tier nest: a ray composited by the nearer carrier also covers the
//   samples the farther carrier's own fragment covers (it goes on into the farther cell,
//   volume.frag), and the union is the nearer one's, not their sum;
// - the two tiers of a transition zone complement each other: even tiers fill the samples
//   from the first, odd tiers from the last, so two tiers that each draw part of the
//   blades cover the sum of their parts, where nested masks would give the larger.
// A fragment that leaves less than half a sample uncovered covers every sample (rounded to
// the nearest, as a single-sampled target keeps a fragment of alpha 1/2), and so does an
// opaque ray: the volume's rays stop compositing once their alpha reaches kOpaqueAlpha
// (volume.frag). The dither rounds each pixel the same way in every draw, so a sample it
// leaves empty in a nearly opaque fragment stays empty in every draw behind (farther
// carriers of the tier nest): dithered, 0.99 x 4 samples left one sample empty wherever the
// dither is below 0.04, on a regular 4 x 4-pixel grid, and with no ground under the grass
// the clear colour showed through grass that blades make opaque (FarTiersTest).
// Returns false when no sample is covered: the caller discards. Single-sampled targets
// keep a fragment whose alpha reaches 1/2.
const float kOpaqueAlpha = 0.99;

// The horizontal slice's alpha at mip `lod` as this target draws it. Its mips keep the mean
// opacity (slice_mips.hpp), which a multisampled target draws as a share of its samples. A
// single-sampled one keeps a fragment whose alpha reaches 1/2 (write_coverage), which a mean
// of 0.8 passes everywhere: there the coverage-preserving scale of the level (lemme eq.
// 4.13-4.15, per level in field.alpha_test_scale) makes the share of texels that pass that
// of level 0.
float horizontal_slice_alpha(float alpha, float lod) {
    if (sample_count() > 1) return alpha;
    float l = clamp(lod, 0.0, 15.0);
    int k = int(l);
    int k1 = min(k + 1, 15);
    float s = mix(field.alpha_test_scale[k >> 2][k & 3], field.alpha_test_scale[k1 >> 2][k1 & 3], l - float(k));
    return min(alpha * s, 1.0);
}

// The pixel the dither is read at, the same on both backends: GL's window rows run up the
// picture from its bottom, Vulkan's down from its top (a host drawing the same picture there
// flips its projection's y), so a dither read at gl_FragCoord differed between the backends.
// Vulkan counts its rows from the bottom as GL does: the viewport's height (2 / the fragment's
// NDC y step from row to row) minus gl_FragCoord.y. `position`: the fragment's point,
// camera-relative world (metres). Call it where derivatives are defined: before any discard,
// outside loops.
vec2 g_pixel = vec2(0.0);
void note_pixel(vec3 position) {
    g_pixel = gl_FragCoord.xy;
#ifdef VULKAN
    vec4 clip = GRASS_VIEW_PROJECTION * vec4(position, 1.0);
    float per_row = abs(dFdy(clip.y / clip.w));
    if (per_row > 0.0) g_pixel.y = floor(2.0 / per_row + 0.5) - gl_FragCoord.y;
#endif
}

// The 4 x 4 Bayer matrix at the pixel, (m + 1/2) / 16 with m's bits, high to low, x0^y0, y0,
// x1^y1, y1: arithmetic, not a table (lavapipe reads a table indexed per pixel lane by lane).
float pixel_dither() {
    uvec2 p = uvec2(ivec2(floor(g_pixel))) & 3u;
    uint a = p.x ^ p.y;
    uint m = ((a & 1u) << 3) | ((p.y & 1u) << 2) | (a & 2u) | ((p.y & 2u) >> 1);
    return (float(m) + 0.5) / 16.0;
}

// `part`: between two texel tiers (tier_texel_part), the share of the samples this tier
// takes, from the first or the last by `from_last`; the two tiers' parts at one pixel add up
// to 1, and with the same dither their sample counts add up to the target's (from the last:
// floor(p n + 1 - dither) = n - floor((1 - p) n + dither)). Within its part a tier covers
// alpha of the samples; an opaque fragment (as above) its whole part. One sample: the tier
// whose part reaches the pixel's dither keeps the pixel (a screen door, complemented).
bool write_coverage(float alpha, float part, bool from_last) {
    int n = sample_count();
    bool opaque = alpha >= min(kOpaqueAlpha, 1.0 - 0.5 / float(n));
    if (part >= 1.0 && (n <= 1 || opaque)) {
        gl_SampleMask[0] = -1;
        return alpha >= 0.5;
    }
    float dither = pixel_dither();
    if (n <= 1) {
        gl_SampleMask[0] = -1;
        return alpha >= 0.5 && (from_last ? dither >= 1.0 - part : dither < part);
    }
    float covered = (opaque ? 1.0 : alpha) * part * float(n);
    int k = int(clamp(floor(covered + (from_last ? 1.0 - dither : dither)), 0.0, float(n)));
    if (k == 0) return false;
    uint mask = k >= 32 ? 0xffffffffu : (1u << uint(k)) - 1u;
    if (from_last) mask <<= uint(n - k);
    gl_SampleMask[0] = int(mask);
    return true;
}
bool write_coverage(float alpha) {
    return write_coverage(alpha, 1.0, (field.tiers.x & 1u) != 0u);
}
