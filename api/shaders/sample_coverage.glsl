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

bool write_coverage(float alpha) {
    int n = sample_count();
    if (n <= 1 || alpha >= min(kOpaqueAlpha, 1.0 - 0.5 / float(n))) {
        gl_SampleMask[0] = -1;
        return alpha >= 0.5;
    }
    // The 4 x 4 Bayer matrix, (2 m + 1) / 32 with m's bits, high to low, x0^y0, y0, x1^y1,
    // y1: arithmetic, not a table (lavapipe reads a table indexed per pixel lane by lane).
    uvec2 p = uvec2(ivec2(gl_FragCoord.xy)) & 3u;
    uint a = p.x ^ p.y;
    uint m = ((a & 1u) << 3) | ((p.y & 1u) << 2) | (a & 2u) | ((p.y & 2u) >> 1);
    bool from_last = (field.tiers.x & 1u) != 0u;
    float dither = (float(m) + 0.5) / 16.0;
    int k = int(clamp(floor(alpha * float(n) + (from_last ? 1.0 - dither : dither)), 0.0, float(n)));
    if (k == 0) return false;
    uint mask = k >= 32 ? 0xffffffffu : (1u << uint(k)) - 1u;
    if (from_last) mask <<= uint(n - k);
    gl_SampleMask[0] = int(mask);
    return true;
}
