// Blade shape (lemme2012 4.1.1): the trajectory p = b t + g t^2 from the root, where b is
// set by length, tilt and rotation and g pulls towards the ground, sampled at equal steps
// of t into a quad strip. Equal steps give smaller quads where the blade bends most. The
// normal at each sample is orthogonal to the tangent v = b + 2 g t. Appearance (4.1.2):
// per-blade and per-vertex colour modulation. Thresholds (4.1.3): density_threshold.cpp.
#include "patch/patch_generator.hpp"

#include "patch/blade_levels.hpp"
#include "patch/density_threshold.hpp"
#include "patch/random.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

namespace {

struct Vec3 {
    double x, y, z;
};
Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(Vec3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }
Vec3 normalized(Vec3 a) { return a * (1.0 / length(a)); }

uint8_t to_unorm8(double v) {
    const double c = std::min(1.0, std::max(0.0, v));
    return static_cast<uint8_t>(std::lround(c * 255.0));
}

// Arc length of p(t) = b t + g t^2 over [0, 1] (midpoint rule on |p'(t)|).
double arc_length(Vec3 b, Vec3 g) {
    constexpr int kSteps = 64;
    double s = 0.0;
    for (int k = 0; k < kSteps; ++k) {
        const double t = (k + 0.5) / kSteps;
        s += length(b + g * (2.0 * t));
    }
    return s / kSteps;
}

struct Blade {
    double root_x, root_z;
    double length, width, tilt, rotation, bend;
    double tint[3]; // per-blade colour modulation
};

} // namespace

void generate_patch(const grass_patch_desc& desc, HostAllocator* host, PatchData* out) {
    const uint32_t n_blades = desc.blade_count;
    const uint32_t n_sub = desc.subdivisions;
    out->blade_count = n_blades;
    out->vertices_per_blade = (n_sub + 1) * 2;
    out->indices_per_blade = n_sub * 6;
    out->vertices.resize(static_cast<size_t>(n_blades) * out->vertices_per_blade);
    out->indices.resize(static_cast<size_t>(n_blades) * out->indices_per_blade);
    out->thresholds.resize(n_blades);
    out->blade_curves.resize(static_cast<size_t>(n_blades) * 8);
    out->ao_impact = desc.ao_impact;
    out->ao_height = desc.ao_height;

    // Blades first (one random stream), so that geometry does not depend on thresholds.
    Random rng(desc.seed);
    Vector<Blade> blades{StlAllocator<Blade>(host)};
    blades.resize(n_blades);
    Vector<float> root_x{StlAllocator<float>(host)}, root_z{StlAllocator<float>(host)};
    root_x.resize(n_blades);
    root_z.resize(n_blades);
    const double cv = desc.blade_color_variation;
    for (uint32_t b = 0; b < n_blades; ++b) {
        Blade& bl = blades[b];
        bl.root_x = rng.uniform();
        bl.root_z = rng.uniform();
        bl.length = rng.uniform(desc.length_min, desc.length_max);
        bl.width = rng.uniform(desc.width_min, desc.width_max);
        bl.tilt = rng.uniform(desc.tilt_min, desc.tilt_max);
        bl.rotation = rng.uniform(0.0, 6.283185307179586);
        bl.bend = rng.uniform(desc.bend_min, desc.bend_max);
        // Age and degradation: darker or yellower blades.
        const double darken = 1.0 - cv * 0.6 * rng.uniform();
        const double yellow = cv * (rng.uniform() - 0.35);
        bl.tint[0] = darken * (1.0 + 0.9 * yellow);
        bl.tint[1] = darken * (1.0 + 0.15 * yellow);
        bl.tint[2] = darken * (1.0 - 0.6 * yellow);
        root_x[b] = static_cast<float>(bl.root_x);
        root_z[b] = static_cast<float>(bl.root_z);
    }

    ThresholdParams tp;
    tp.mode = desc.threshold_mode;
    tp.cluster_sigma = desc.cluster_sigma;
    tp.cluster_frequency = desc.cluster_frequency;
    tp.seed = desc.seed;
    assign_density_thresholds(tp, root_x.data(), root_z.data(), n_blades, host, out->thresholds.data());

    Random vertex_rng(desc.seed ^ 0x766572746578ull); // "vertex"
    const Vec3 up{0, 1, 0};
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (uint32_t b = 0; b < n_blades; ++b) {
        const Blade& bl = blades[b];
        const Vec3 facing{std::cos(bl.rotation), 0.0, std::sin(bl.rotation)};
        const Vec3 side{-facing.z, 0.0, facing.x}; // horizontal, perpendicular to the blade's plane
        Vec3 vb = facing * std::sin(bl.tilt) + up * std::cos(bl.tilt);
        Vec3 vg = up * -bl.bend;
        const double scale = bl.length / arc_length(vb, vg); // arc length = blade length
        vb = vb * scale;
        vg = vg * scale;
        // The same curve as jahrmann's quadratic Bezier (v0 = root): v1 = b / 2, v2 = b + g.
        // Not part of the content hash, which pins the vertices and indices.
        float* curve = &out->blade_curves[static_cast<size_t>(b) * 8];
        const Vec3 v1 = vb * 0.5, v2 = vb + vg;
        curve[0] = static_cast<float>(v1.x);
        curve[1] = static_cast<float>(v1.y);
        curve[2] = static_cast<float>(v1.z);
        curve[3] = static_cast<float>(bl.length); // the arc length: the scale made it so
        curve[4] = static_cast<float>(v2.x);
        curve[5] = static_cast<float>(v2.y);
        curve[6] = static_cast<float>(v2.z);
        curve[7] = static_cast<float>(bl.rotation); // facing: the width runs along (-sin, 0, cos)

        BladeVertex* v = &out->vertices[static_cast<size_t>(b) * out->vertices_per_blade];
        for (uint32_t k = 0; k <= n_sub; ++k) {
            const double t = static_cast<double>(k) / n_sub;
            const Vec3 p = Vec3{bl.root_x, 0.0, bl.root_z} + vb * t + vg * (t * t);
            const Vec3 tangent = vb + vg * (2.0 * t);
            const Vec3 normal = normalized(cross(side, tangent));
            const double half_width = 0.5 * bl.width * (1.0 - t * t); // pointed tip
            for (uint32_t e = 0; e < 2; ++e) {
                BladeVertex& out_v = v[k * 2 + e];
                const Vec3 q = p + side * (e == 0 ? -half_width : half_width);
                out_v.position[0] = static_cast<float>(q.x);
                out_v.position[1] = static_cast<float>(q.y);
                out_v.position[2] = static_cast<float>(q.z);
                out_v.normal[0] = static_cast<float>(normal.x);
                out_v.normal[1] = static_cast<float>(normal.y);
                out_v.normal[2] = static_cast<float>(normal.z);
                out_v.root_shape[0] = static_cast<float>(bl.root_x);
                out_v.root_shape[1] = static_cast<float>(bl.root_z);
                out_v.root_shape[2] = static_cast<float>(e);
                out_v.root_shape[3] = static_cast<float>(t);
                const double vary = 1.0 + desc.vertex_color_variation * (2.0 * vertex_rng.uniform() - 1.0);
                for (int c = 0; c < 3; ++c) {
                    const double base = desc.root_color[c] + (desc.tip_color[c] - desc.root_color[c]) * t;
                    out_v.color[c] = to_unorm8(base * bl.tint[c] * vary);
                }
                out_v.color[3] = 255;
                out_v.threshold = out->thresholds[b];
                for (int c = 0; c < 3; ++c) {
                    lo[c] = std::min(lo[c], out_v.position[c]);
                    hi[c] = std::max(hi[c], out_v.position[c]);
                }
            }
        }
        uint32_t* idx = &out->indices[static_cast<size_t>(b) * out->indices_per_blade];
        const uint32_t base = b * out->vertices_per_blade;
        for (uint32_t k = 0; k < n_sub; ++k) {
            const uint32_t a = base + 2 * k;
            idx[6 * k + 0] = a;
            idx[6 * k + 1] = a + 1;
            idx[6 * k + 2] = a + 2;
            idx[6 * k + 3] = a + 2;
            idx[6 * k + 4] = a + 1;
            idx[6 * k + 5] = a + 3;
        }
    }
    for (int c = 0; c < 3; ++c) {
        out->bounds_min[c] = lo[c];
        out->bounds_max[c] = hi[c];
    }
    uint64_t h = fnv1a64(out->vertices.data(), out->vertices.size() * sizeof(BladeVertex), kFnvOffset);
    out->content_hash = fnv1a64(out->indices.data(), out->indices.size() * sizeof(uint32_t), h);
    add_blade_levels(n_sub, out); // after the hash: the coarser levels follow from level 0
}

} // namespace grass
