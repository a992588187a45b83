#include "mesh/mesh_field.hpp"

#include "foundation/validate.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace grass {
namespace {

// The per-vertex density at a blade's root: barycentric in its triangle (a tuft's blade,
// off its triangle in the triangle's plane, takes the nearest point's weights, clamped).
float root_density(const MeshSurface& s, const MeshBlade& b, const float* vertex_density) {
    uint32_t c[3];
    s.corners(b.triangle, c);
    double v[3][3];
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) v[k][i] = s.mesh().positions[uint64_t{c[k]} * 3 + i];
    const double e1[3] = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
    const double e2[3] = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
    const double r[3] = {b.root[0] - v[0][0], b.root[1] - v[0][1], b.root[2] - v[0][2]};
    const auto dot = [](const double* a, const double* d) { return a[0] * d[0] + a[1] * d[1] + a[2] * d[2]; };
    const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), r1 = dot(r, e1), r2 = dot(r, e2);
    const double det = d11 * d22 - d12 * d12; // > 0: degenerate triangles carry no blades
    double w1 = std::clamp((d22 * r1 - d12 * r2) / det, 0.0, 1.0);
    double w2 = std::clamp((d11 * r2 - d12 * r1) / det, 0.0, 1.0);
    if (w1 + w2 > 1.0) {
        const double sum = w1 + w2;
        w1 /= sum;
        w2 /= sum;
    }
    const double w0 = 1.0 - w1 - w2;
    return static_cast<float>(w0 * vertex_density[c[0]] + w1 * vertex_density[c[1]] + w2 * vertex_density[c[2]]);
}

// A patch's world box: the 8 corners of its mesh-space box transformed, grown by `reach`.
MeshPatchBounds world_bounds(const double m[16], const MeshPatch& p, double reach) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (int corner = 0; corner < 8; ++corner) {
        const double x = (corner & 1) ? p.bounds_max[0] : p.bounds_min[0];
        const double y = (corner & 2) ? p.bounds_max[1] : p.bounds_min[1];
        const double z = (corner & 4) ? p.bounds_max[2] : p.bounds_min[2];
        for (int i = 0; i < 3; ++i) {
            const double w = m[i] * x + m[4 + i] * y + m[8 + i] * z + m[12 + i];
            lo[i] = std::min(lo[i], w);
            hi[i] = std::max(hi[i], w);
        }
    }
    MeshPatchBounds b{};
    for (int i = 0; i < 3; ++i) {
        b.centre[i] = 0.5 * (lo[i] + hi[i]);
        b.half[i] = 0.5 * (hi[i] - lo[i]) + reach;
    }
    return b;
}

} // namespace

grass_result build_mesh_field(Log* log, const char* fn, const MeshSurface& surface, const MeshScatterParams& params,
                              const float* vertex_density, double reach, MeshField* out) {
    HostAllocator* host = out->blade_density.get_allocator().host();
    MeshField field(host);
    GRASS_TRY(scatter_mesh_blades(log, fn, surface, params, &field.scatter));
    const Vector<MeshBlade>& blades = field.scatter.blades;
    field.blade_density.resize(blades.size(), 1.0f);
    if (vertex_density) {
        for (size_t b = 0; b < blades.size(); ++b)
            field.blade_density[b] = root_density(surface, blades[b], vertex_density);
    }
    for (int k = 0; k < 16; ++k) field.transform[k] = surface.mesh().transform[k];
    field.reach = reach;
    field.bounds.reserve(field.scatter.patches.size());
    for (const MeshPatch& p : field.scatter.patches) field.bounds.push_back(world_bounds(field.transform, p, reach));
    field.patch_scale = out->patch_scale;
    field.density_source = out->density_source;
    *out = std::move(field);
    return GRASS_SUCCESS;
}

void write_mesh_blades(const MeshField& field, uint32_t patch_blade_count, MeshBladeGpu* out) {
    const Vector<MeshBlade>& blades = field.scatter.blades;
    const uint32_t shapes = std::max(patch_blade_count, 1u);
    for (size_t b = 0; b < blades.size(); ++b) {
        const MeshBlade& m = blades[b];
        MeshBladeGpu& g = out[b];
        for (int i = 0; i < 3; ++i) g.root_threshold[i] = m.root[i], g.up_facing[i] = m.up[i];
        g.root_threshold[3] = m.threshold;
        g.up_facing[3] = m.facing;
        g.uv_density[0] = m.uv[0];
        g.uv_density[1] = m.uv[1];
        g.uv_density[2] = field.blade_density[b];
        g.uv_density[3] = static_cast<float>(b % shapes);
    }
}

} // namespace grass
