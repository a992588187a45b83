// The patch is drawn 9 times, translated by (dx, dz) in {-1, 0, 1}^2, so that tips leaning in
// from a neighbour cell appear and blades leaving the cell carry on at the opposite border:
// the slices tile. The slab of a vertical slice is cut out by clipping each triangle against
// its two planes (Sutherland-Hodgman in patch space, all attributes interpolated); the target
// rectangle clips s and t.
#include "bake/slice_baker.hpp"

#include "bake/slice_mips.hpp"
#include "bake/slice_rasterizer.hpp"
#include "bake/slice_set_hash.hpp"
#include "bake/srgb_encode.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

namespace {

struct ClipVertex {
    double p[3];
    float albedo[3];
    float normal[3];
};

struct Triangle {
    ClipVertex v[3];
    double lo[3], hi[3];
    uint16_t threshold;
};

// What a layer sees: depth axis and its slab, the axes of s and t, the viewer side.
struct View {
    int depth_axis; // 0 = x, 2 = z, 1 = y (horizontal: depth = -y)
    double slab_lo, slab_hi;
    bool clip_slab;
    int s_axis, t_axis; // patch axes of s and t
    double t_scale;     // t = p[t_axis] * t_scale
    float toward_viewer[3];
};

uint16_t quantise_threshold(float threshold) {
    const long q = std::lround(static_cast<double>(threshold) * 65535.0);
    return static_cast<uint16_t>(std::min(65535L, std::max(1L, q)));
}

void prepare_triangles(const PatchData& patch, Vector<Triangle>* out) {
    const size_t count = patch.full_index_count() / 3; // level 0: the full blades
    out->resize(count);
    for (size_t k = 0; k < count; ++k) {
        Triangle& tri = (*out)[k];
        for (int c = 0; c < 3; ++c) {
            tri.lo[c] = 1e300;
            tri.hi[c] = -1e300;
        }
        for (int e = 0; e < 3; ++e) {
            const BladeVertex& bv = patch.vertices[patch.indices[k * 3 + e]];
            ClipVertex& v = tri.v[e];
            for (int c = 0; c < 3; ++c) {
                v.p[c] = bv.position[c];
                v.albedo[c] = static_cast<float>(bv.color[c]) / 255.0f;
                v.normal[c] = bv.normal[c];
                tri.lo[c] = std::min(tri.lo[c], v.p[c]);
                tri.hi[c] = std::max(tri.hi[c], v.p[c]);
            }
        }
        const uint32_t blade = patch.vertices_per_blade ? patch.indices[k * 3] / patch.vertices_per_blade : 0;
        tri.threshold = quantise_threshold(
            blade < patch.thresholds.size() ? patch.thresholds[blade] : patch.vertices[patch.indices[k * 3]].threshold);
    }
}

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double f) {
    ClipVertex r;
    const float ff = static_cast<float>(f);
    for (int c = 0; c < 3; ++c) {
        r.p[c] = a.p[c] + (b.p[c] - a.p[c]) * f;
        r.albedo[c] = a.albedo[c] + (b.albedo[c] - a.albedo[c]) * ff;
        r.normal[c] = a.normal[c] + (b.normal[c] - a.normal[c]) * ff;
    }
    return r;
}

// Keeps the part of the polygon with sign * (p[axis] - bound) >= 0. Returns the new count.
int clip_polygon(const ClipVertex* in, int count, int axis, double bound, double sign, ClipVertex* out) {
    int n = 0;
    for (int k = 0; k < count; ++k) {
        const ClipVertex& a = in[k];
        const ClipVertex& b = in[(k + 1) % count];
        const double da = sign * (a.p[axis] - bound), db = sign * (b.p[axis] - bound);
        if (da >= 0.0) out[n++] = a;
        if ((da >= 0.0) != (db >= 0.0)) {
            ClipVertex v = lerp(a, b, da / (da - db));
            v.p[axis] = bound; // exactly on the plane
            out[n++] = v;
        }
    }
    return n;
}

RasterVertex project(const ClipVertex& v, const View& view, double height_scale) {
    RasterVertex r;
    r.s = v.p[view.s_axis];
    r.t = v.p[view.t_axis] * view.t_scale;
    r.depth = view.depth_axis == 1 ? -v.p[1] : v.p[view.depth_axis];
    for (int c = 0; c < 3; ++c) {
        r.albedo[c] = v.albedo[c];
        r.normal[c] = v.normal[c];
    }
    r.height = static_cast<float>(v.p[1] * height_scale);
    return r;
}

void draw_view(const Vector<Triangle>& triangles, const View& view, double height_scale, SliceRasterizer* raster) {
    ClipVertex poly[8], tmp[8];
    RasterVertex projected[8];
    for (int dz = -1; dz <= 1; ++dz) {
        for (int dx = -1; dx <= 1; ++dx) {
            const double offset[3] = {static_cast<double>(dx), 0.0, static_cast<double>(dz)};
            for (const Triangle& tri : triangles) {
                // Quick rejection against the slab and the target rectangle.
                const int sa = view.s_axis, ta = view.t_axis;
                if (tri.hi[sa] + offset[sa] < 0.0 || tri.lo[sa] + offset[sa] > 1.0) continue;
                if ((tri.hi[ta] + offset[ta]) * view.t_scale < 0.0 || (tri.lo[ta] + offset[ta]) * view.t_scale > 1.0) {
                    continue;
                }
                const int da = view.depth_axis;
                if (view.clip_slab &&
                    (tri.hi[da] + offset[da] < view.slab_lo || tri.lo[da] + offset[da] > view.slab_hi)) {
                    continue;
                }
                int n = 3;
                for (int e = 0; e < 3; ++e) {
                    poly[e] = tri.v[e];
                    for (int c = 0; c < 3; ++c) poly[e].p[c] += offset[c];
                }
                if (view.clip_slab) {
                    if (tri.lo[da] + offset[da] < view.slab_lo) {
                        n = clip_polygon(poly, n, da, view.slab_lo, 1.0, tmp);
                        std::copy(tmp, tmp + n, poly);
                    }
                    if (n >= 3 && tri.hi[da] + offset[da] > view.slab_hi) {
                        n = clip_polygon(poly, n, da, view.slab_hi, -1.0, tmp);
                        std::copy(tmp, tmp + n, poly);
                    }
                }
                if (n < 3) continue;
                for (int e = 0; e < n; ++e) projected[e] = project(poly[e], view, height_scale);
                for (int e = 1; e + 1 < n; ++e) {
                    raster->draw_triangle(projected[0], projected[e], projected[e + 1], tri.threshold);
                }
            }
        }
    }
}

View layer_view(uint32_t slices_per_axis, uint32_t layer, double height_units) {
    View view{};
    // The horizontal slice: the image tier's only layer, and the last layer of a volume
    // tier's set (boulanger2006 3.3 keeps one in the volume for views from above).
    if (slices_per_axis == 0 || layer == 2 * slices_per_axis) {
        view.depth_axis = 1;
        view.clip_slab = false;
        view.s_axis = 0;
        view.t_axis = 2;
        view.t_scale = 1.0;
        view.toward_viewer[1] = 1.0f;
        return view;
    }
    const bool along_x = layer < slices_per_axis;
    const uint32_t i = along_x ? layer : layer - slices_per_axis;
    view.depth_axis = along_x ? 0 : 2;
    view.slab_lo = static_cast<double>(i) / slices_per_axis;
    view.slab_hi = static_cast<double>(i + 1) / slices_per_axis;
    view.clip_slab = true;
    view.s_axis = along_x ? 2 : 0;
    view.t_axis = 1;
    view.t_scale = 1.0 / height_units;
    view.toward_viewer[view.depth_axis] = -1.0f;
    return view;
}

// The image tier's colour (issue 12): the horizontal slice's coverage is the grass seen from
// above, but the tier is drawn far away, where the view grazes the blade layer and meets the
// blades' upper, lighter parts first; from above one also sees their darker lower parts and
// bases through the gaps (the image tier came out 7-19 sRGB levels darker than the blades).
// Its colour in layers 1 and 2 is therefore what a ray at kImageTierElevation sees first,
// along the four axis headings: each blade point is projected along the ray onto the ground
// (the texel the ray lands in), the nearest along the ray kept, and the four headings
// averaged, weighted by their coverage; likewise the height of what it sees (for the blades'
// ambient occlusion). Layer 0 keeps the colour and heights seen from above, for steep views.
// The alpha and thresholds of every layer stay those seen from above.
// Its normals depend on the heading (issue 12, the light from the side): a ray heading along
// z sees the blades that face it broadside, whose normals lean along z, and few of those
// that face x, which a sun from the side lights best; along x the other way round. Averaged
// over the headings, or seen from above, a sun from the side lit the image tier 11-13 levels
// brighter than the blades. So the set keeps three layers (slice_layer_count): the normals
// (and colour) seen from above (layer 0, for steep views), and those seen grazing along x (layer 1) and
// along z (layer 2), each the mean over the two opposite headings, folded as the slice's
// normals are (up signed, x and z as magnitudes); image.frag lights with both and weighs them
// by the view's heading.
constexpr double kImageTierElevation = 10.0 * 3.14159265358979323846 / 180.0;
constexpr uint32_t kGrazingReduction = 2;

void draw_grazing_view(const Vector<Triangle>& triangles, double heading_x, double heading_z, double height_scale,
                       SliceRasterizer* raster) {
    const double c = std::cos(kImageTierElevation), sn = std::sin(kImageTierElevation), reach = c / sn;
    const double dir[3] = {c * heading_x, -sn, c * heading_z}; // the ray, from the viewer into the grass
    RasterVertex v[3];
    for (const Triangle& tri : triangles) {
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (int e = 0; e < 3; ++e) {
            const ClipVertex& p = tri.v[e];
            // Where the ray through p reaches the ground (y = 0).
            v[e].s = p.p[0] + p.p[1] * reach * heading_x;
            v[e].t = p.p[2] + p.p[1] * reach * heading_z;
            v[e].depth = p.p[0] * dir[0] + p.p[1] * dir[1] + p.p[2] * dir[2];
            for (int k = 0; k < 3; ++k) {
                v[e].albedo[k] = p.albedo[k];
                v[e].normal[k] = p.normal[k];
            }
            v[e].height = static_cast<float>(p.p[1] * height_scale);
            lo[0] = std::min(lo[0], v[e].s), hi[0] = std::max(hi[0], v[e].s);
            lo[1] = std::min(lo[1], v[e].t), hi[1] = std::max(hi[1], v[e].t);
        }
        // The copies of the tiled patch whose projection reaches the target [0, 1]^2.
        for (double oz = std::ceil(-hi[1]); oz <= std::floor(1.0 - lo[1]); oz += 1.0) {
            for (double ox = std::ceil(-hi[0]); ox <= std::floor(1.0 - lo[0]); ox += 1.0) {
                RasterVertex w[3] = {v[0], v[1], v[2]};
                for (RasterVertex& q : w) {
                    q.s += ox;
                    q.t += oz;
                    q.depth += ox * dir[0] + oz * dir[2];
                }
                raster->draw_triangle(w[0], w[1], w[2], tri.threshold);
            }
        }
    }
}

// What the grazing rays see, per texel of the reduced grid: colour (rgb), height and
// coverage over the four headings, then the normal (xyz) and coverage along x and along z.
struct GrazingView {
    explicit GrazingView(HostAllocator* host) : sum(StlAllocator<double>(host)) {}
    static constexpr int kValues = 13;
    uint32_t w = 0, h = 0;
    Vector<double> sum;
};

void see_grazing(const Vector<Triangle>& triangles, double height_scale, uint32_t width, uint32_t height,
                 HostAllocator* host, GrazingView* out) {
    const double headings[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    out->w = std::max(1u, width / kGrazingReduction);
    out->h = std::max(1u, height / kGrazingReduction);
    const size_t n = static_cast<size_t>(out->w) * out->h;
    out->sum.assign(n * GrazingView::kValues, 0.0);
    float toward_viewer[3] = {0, 1, 0};
    SliceRasterizer raster(out->w, out->h, toward_viewer, host);
    SliceImage seen(host);
    for (const auto& heading : headings) {
        raster.clear();
        draw_grazing_view(triangles, heading[0], heading[1], height_scale, &raster);
        raster.resolve(&seen);
        const int family = heading[0] != 0.0 ? 5 : 9; // along x, along z
        for (size_t i = 0; i < n; ++i) {
            double* acc = &out->sum[i * GrazingView::kValues];
            const double a = seen.alpha[i];
            for (int c = 0; c < 3; ++c) acc[c] += a * static_cast<double>(seen.color[i * 3 + c]);
            acc[3] += a * static_cast<double>(seen.normal[i * 4 + 3]);
            acc[4] += a;
            for (int c = 0; c < 3; ++c) acc[family + c] += a * static_cast<double>(seen.normal[i * 4 + c]);
            acc[family + 3] += a;
        }
    }
}

// Gives the covered texels of `level0` (the horizontal slice from above) the grazing view's
// colour and heights, and for `normals` 1 (along x) or 2 (along z) that heading's normals.
// Layer 0 (`normals` 0) keeps the colour, heights and normals seen from above, which steep
// views turn to (image.frag): seen from 90 degrees, the grazing colour made the image tier
// 18-20 levels lighter than the blades (docs/records/tier-sweep.md).
void apply_grazing(const GrazingView& g, uint32_t normals, SliceImage* level0) {
    if (normals == 0) return;
    for (size_t i = 0; i < level0->texels(); ++i) {
        const size_t x = (i % level0->width) * g.w / level0->width, y = (i / level0->width) * g.h / level0->height;
        const double* acc = &g.sum[(y * g.w + x) * GrazingView::kValues];
        if (!(level0->alpha[i] > 0.0f) || !(acc[4] > 0.0)) continue;
        for (int c = 0; c < 3; ++c) level0->color[i * 3 + c] = static_cast<float>(acc[c] / acc[4]);
        level0->normal[i * 4 + 3] = static_cast<float>(acc[3] / acc[4]);
        const double* family = acc + (normals == 1 ? 5 : 9);
        if (!(family[3] > 0.0)) continue; // no ray of that heading lands here
        for (int c = 0; c < 3; ++c) level0->normal[i * 4 + c] = static_cast<float>(family[c] / family[3]);
    }
}

void default_sizes(uint32_t slices_per_axis, uint32_t* width, uint32_t* height) {
    if (*width == 0) *width = slices_per_axis ? kDefaultVerticalSliceWidth : kDefaultHorizontalSliceSize;
    if (*height == 0) *height = slices_per_axis ? kDefaultVerticalSliceHeight : kDefaultHorizontalSliceSize;
}

double patch_height(const PatchData& patch) {
    const double h = patch.bounds_max[1];
    return h > 0.0 && std::isfinite(h) ? h : 1.0;
}

void encode_layer(const Vector<SliceImage>& levels, uint32_t layer, SliceSet* out) {
    for (uint32_t k = 0; k < levels.size(); ++k) {
        const SliceImage& img = levels[k];
        const uint64_t base = out->offset(layer, k);
        for (size_t i = 0; i < img.texels(); ++i) {
            uint8_t* color = &out->color[(base + i) * 4];
            uint8_t* normal = &out->normal[(base + i) * 4];
            for (int c = 0; c < 3; ++c) color[c] = linear_to_srgb8(img.color[i * 3 + c]);
            color[3] = float_to_unorm8(img.alpha[i]);
            for (int c = 0; c < 3; ++c) normal[c] = float_to_unorm8(img.normal[i * 4 + c] * 0.5f + 0.5f);
            normal[3] = float_to_unorm8(img.normal[i * 4 + 3]);
            uint16_t* threshold = &out->threshold[(base + i) * 4];
            threshold[0] = img.threshold[i];
            for (int c = 0; c < 3; ++c) {
                const double v = std::min(1.0, std::max(0.0, static_cast<double>(img.coverage[i * 3 + c])));
                threshold[1 + c] = static_cast<uint16_t>(std::lround(v * 65535.0));
            }
        }
    }
}

} // namespace

void rasterize_slice_layer(const PatchData& patch, uint32_t slices_per_axis, uint32_t layer, uint32_t width,
                           uint32_t height, HostAllocator* host, SliceImage* out) {
    default_sizes(slices_per_axis, &width, &height);
    Vector<Triangle> triangles{StlAllocator<Triangle>(host)};
    prepare_triangles(patch, &triangles);
    const double h = patch_height(patch);
    const View view = layer_view(slices_per_axis, layer, h);
    SliceRasterizer raster(width, height, view.toward_viewer, host);
    draw_view(triangles, view, 1.0 / h, &raster);
    raster.resolve(out);
    if (slices_per_axis == 0) {
        GrazingView grazing(host);
        see_grazing(triangles, 1.0 / h, width, height, host, &grazing);
        apply_grazing(grazing, layer, out);
    }
}

void bake_slices(const PatchData& patch, uint32_t slices_per_axis, uint32_t width, uint32_t height, HostAllocator* host,
                 SliceSet* out) {
    default_sizes(slices_per_axis, &width, &height);
    const double h = patch_height(patch);
    out->slices_per_axis = slices_per_axis;
    out->layers = slice_layer_count(slices_per_axis);
    out->width = width;
    out->height = height;
    out->mip_levels = full_mip_count(width, height);
    out->height_patch_units = static_cast<float>(h);
    const uint64_t texels = out->offset(out->layers, 0);
    out->color.assign(texels * 4, 0);
    out->normal.assign(texels * 4, 0);
    out->threshold.assign(texels * 4, 0);

    Vector<Triangle> triangles{StlAllocator<Triangle>(host)};
    prepare_triangles(patch, &triangles);
    const float up[3] = {0, 1, 0};
    SliceRasterizer raster(width, height, up, host);
    Vector<SliceImage> levels{StlAllocator<SliceImage>(host)};
    levels.reserve(out->mip_levels);
    GrazingView grazing(host); // the image tier's: once for its three layers
    if (slices_per_axis == 0) see_grazing(triangles, 1.0 / h, width, height, host, &grazing);
    for (uint32_t layer = 0; layer < out->layers; ++layer) {
        const View view = layer_view(slices_per_axis, layer, h);
        // The image tier's layers share the view from above: drawn once.
        if (slices_per_axis != 0 || layer == 0) {
            raster.set_toward_viewer(view.toward_viewer);
            raster.clear();
            draw_view(triangles, view, 1.0 / h, &raster);
        }
        levels.clear();
        levels.emplace_back(host);
        raster.resolve(&levels[0]);
        if (slices_per_axis == 0) apply_grazing(grazing, layer, &levels[0]);
        // The horizontal slice (the image tier's layers, the volume's last) keeps its mean
        // opacity; the vertical slices their alpha-tested coverage (slice_mips.hpp).
        const bool horizontal = (slices_per_axis == 0 || layer == 2 * slices_per_axis);
        build_coverage_mips(&levels, out->mip_levels, host,
                            horizontal ? MipAlphaBase::kMeanOpacity : MipAlphaBase::kMean);
        bleed_colours(&levels);
        encode_layer(levels, layer, out);
    }
    out->content_hash = slice_content_hash(*out);
    set_alpha_test_scales(out, host);
}

} // namespace grass
