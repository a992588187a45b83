// A small deterministic CPU triangle rasteriser for the slice baking (lemme2012 4.2.1,
// boulanger2006 3.3): orthographic projection into a W x H target, 4 x 4 supersampling per
// texel, a depth test keeping the sample nearest the viewer, and barycentric attributes.
// Only +, -, *, / on float and double (the core builds with -ffp-contract=off), so the
// same triangles give the same bits on every platform.
#pragma once

#include "bake/slice_image.hpp"
#include "foundation/allocator.hpp"

#include <cstdint>

namespace grass {

struct RasterVertex {
    double s = 0, t = 0;         // target coordinates, [0, 1] across the target (row 0 at t = 0)
    double depth = 0;            // smaller is nearer the viewer
    float albedo[3] = {0, 0, 0}; // linear rgb
    float normal[3] = {0, 0, 0}; // patch space (need not face the viewer, nor be unit)
    float height = 0;            // height above the ground / the slice's height, for normal.w
};

class SliceRasterizer {
public:
    static constexpr uint32_t kSamplesPerAxis = 4;
    static constexpr uint32_t kSamplesPerTexel = kSamplesPerAxis * kSamplesPerAxis;

    // `toward_viewer`: unit vector from the slice towards its viewer, in patch space;
    // sample normals are flipped to face it.
    SliceRasterizer(uint32_t width, uint32_t height, const float toward_viewer[3], HostAllocator* host);

    void set_toward_viewer(const float toward_viewer[3]) {
        for (int c = 0; c < 3; ++c) toward_viewer_[c] = toward_viewer[c];
    }
    void clear();
    // Draws one triangle of the blade with density threshold `threshold` (unorm16, > 0).
    // Samples on an edge count as inside (the rasteriser keeps the nearer of two).
    void draw_triangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, uint16_t threshold);
    // Per texel: alpha = covered samples / samples; colour, normal (renormalised) and height
    // = averages over the covered samples; threshold = the one covering most samples (ties:
    // the smaller); coverage curve = the share of covered samples that some blade with a
    // threshold at most 1/4, 1/2, 3/4 covers (nearest or not: at that density the blades in
    // front are gone). Empty texels get colour 0, the normal towards the viewer, height 0.
    void resolve(SliceImage* out) const;

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

private:
    uint32_t width_, height_;
    uint32_t samples_w_, samples_h_; // sample grid: row-major, kSamplesPerAxis per texel
    float toward_viewer_[3];
    Vector<float> depth_;
    Vector<uint16_t> threshold_;               // 0 = not covered
    Vector<uint16_t> min_threshold_;           // the lowest threshold of any blade over the sample (0xffff: none)
    Vector<float> attributes_;                 // kAttributes per sample
    static constexpr uint32_t kAttributes = 7; // albedo rgb, normal xyz, height
};

} // namespace grass
