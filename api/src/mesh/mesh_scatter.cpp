#include "mesh/mesh_scatter.hpp"

#include "foundation/validate.hpp"
#include "mesh/poisson_disk.hpp"
#include "patch/random.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace grass {

namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr uint32_t kNoTuft = 0xffffffffu;

// A point on the surface: a kept triangle picked by area, uniform barycentrics in it.
struct SurfacePoint {
    uint32_t triangle; // the host's triangle
    double bary[3];
};

SurfacePoint sample_point(const MeshSurface& s, Random& rng) {
    SurfacePoint p{};
    p.triangle = s.host_triangle(s.triangle_at_area(rng.uniform() * s.total_area()));
    const double r1 = std::sqrt(rng.uniform()), r2 = rng.uniform();
    p.bary[0] = 1.0 - r1;
    p.bary[1] = r1 * (1.0 - r2);
    p.bary[2] = r1 * r2;
    return p;
}

void normalize(double v[3]) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; ++i) v[i] /= l;
}

// The mesh-space corners of a host triangle.
void corner_positions(const MeshSurface& s, uint32_t triangle, double out[3][3]) {
    uint32_t c[3];
    s.corners(triangle, c);
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) out[k][i] = s.mesh().positions[uint64_t{c[k]} * 3 + i];
}

// A blade at a surface point: its root, the interpolated normal (the face's where the
// corners' normals cancel) and UV.
MeshBlade blade_at(const MeshSurface& s, const SurfacePoint& p) {
    uint32_t c[3];
    s.corners(p.triangle, c);
    const MeshSurfaceDesc& m = s.mesh();
    double root[3] = {0, 0, 0}, up[3] = {0, 0, 0}, uv[2] = {0, 0};
    for (int k = 0; k < 3; ++k) {
        const double w = p.bary[k];
        const float* pos = m.positions + uint64_t{c[k]} * 3;
        double n[3] = {m.normals[uint64_t{c[k]} * 3], m.normals[uint64_t{c[k]} * 3 + 1],
                       m.normals[uint64_t{c[k]} * 3 + 2]};
        normalize(n);
        for (int i = 0; i < 3; ++i) root[i] += w * pos[i], up[i] += w * n[i];
        if (m.uvs)
            for (int i = 0; i < 2; ++i) uv[i] += w * m.uvs[uint64_t{c[k]} * 2 + i];
    }
    if (!(up[0] * up[0] + up[1] * up[1] + up[2] * up[2] > 1e-12)) {
        double v[3][3];
        corner_positions(s, p.triangle, v);
        const double e1[3] = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
        const double e2[3] = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
        up[0] = e1[1] * e2[2] - e1[2] * e2[1];
        up[1] = e1[2] * e2[0] - e1[0] * e2[2];
        up[2] = e1[0] * e2[1] - e1[1] * e2[0];
    }
    normalize(up);
    MeshBlade b{};
    for (int i = 0; i < 3; ++i) b.root[i] = static_cast<float>(root[i]), b.up[i] = static_cast<float>(up[i]);
    b.uv[0] = static_cast<float>(uv[0]);
    b.uv[1] = static_cast<float>(uv[1]);
    b.triangle = p.triangle;
    b.tuft = kNoTuft;
    return b;
}

void world_point(const MeshSurface& s, const MeshBlade& b, double out[3]) {
    const double v[3] = {b.root[0], b.root[1], b.root[2]};
    s.to_world_linear(v, out);
}

grass_result check_params(Log* log, const char* fn, const MeshSurface& s, const MeshScatterParams& p,
                          uint64_t* blade_count) {
    if (s.triangle_count() == 0) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: the mesh surface has no triangles (it was never built)", fn);
    }
    GRASS_TRY(check_range_above(log, fn, "params->density", p.density, 0.0, 1e5));
    GRASS_TRY(check_range(log, fn, "params->patch_blades", p.patch_blades, 64, 16384));
    if (p.seeding != MeshSeeding::kSingleBlades && p.seeding != MeshSeeding::kTufts) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: params->seeding is %u; it must be 0 (single blades) or 1 (tufts)", fn,
                         static_cast<unsigned>(p.seeding));
    }
    if (p.seeding == MeshSeeding::kTufts) {
        GRASS_TRY(check_range_above(log, fn, "params->tuft_min_distance", p.tuft_min_distance, 0.0, 1e4));
        GRASS_TRY(check_range(log, fn, "params->tuft_radius", p.tuft_radius, 0.0, 1e4));
        GRASS_TRY(check_range(log, fn, "params->blades_per_tuft", p.blades_per_tuft, 1, 4096));
    }
    if (p.thresholds.mode == GRASS_THRESHOLD_CLUSTERED && !s.has_uvs()) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: params->thresholds.mode is GRASS_THRESHOLD_CLUSTERED, which clusters over the mesh's "
                         "UVs; desc->uvs is NULL",
                         fn);
    }
    const double wanted = s.total_area() * p.density;
    const double patches = std::max(1.0, std::round(wanted / p.patch_blades));
    if (!(patches * p.patch_blades <= static_cast<double>(kMaxMeshBlades))) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: params->density %g on %g m^2 of surface asks for %.0f blades; at most %llu", fn,
                         p.density, s.total_area(), wanted, static_cast<unsigned long long>(kMaxMeshBlades));
    }
    *blade_count = static_cast<uint64_t>(patches) * p.patch_blades;
    return GRASS_SUCCESS;
}

void scatter_single(const MeshSurface& s, Random& rng, uint64_t count, Vector<MeshBlade>& blades) {
    for (uint64_t k = 0; k < count; ++k) {
        MeshBlade b = blade_at(s, sample_point(s, rng));
        b.facing = static_cast<float>(rng.uniform() * kTwoPi);
        blades.push_back(b);
    }
}

grass_result scatter_tufts(Log* log, const char* fn, const MeshSurface& s, const MeshScatterParams& p, Random& rng,
                           uint64_t count, Vector<MeshBlade>& blades, Vector<float>& centres) {
    const auto tufts = static_cast<uint32_t>((count + p.blades_per_tuft - 1) / p.blades_per_tuft);
    PoissonDiskSet set(p.tuft_min_distance, tufts, blades.get_allocator().host());
    // Dart throwing: a budget of candidates per tuft before the surface counts as full.
    const uint64_t budget = uint64_t{tufts} * 64 + 1024;
    Vector<MeshBlade> centre_blades{StlAllocator<MeshBlade>(blades.get_allocator().host())};
    for (uint64_t tries = 0; tries < budget && set.size() < tufts; ++tries) {
        const MeshBlade c = blade_at(s, sample_point(s, rng));
        double w[3];
        world_point(s, c, w);
        if (set.try_insert(w)) centre_blades.push_back(c);
    }
    if (set.size() < tufts) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: params->tuft_min_distance %g m lets %u tufts fit on %g m^2 of surface; %u tufts of %u "
                         "blades are needed (lower it, or the density)",
                         fn, p.tuft_min_distance, set.size(), s.total_area(), tufts, p.blades_per_tuft);
    }
    for (uint32_t t = 0; t < tufts; ++t) {
        const MeshBlade& c = centre_blades[t];
        for (int i = 0; i < 3; ++i) centres.push_back(c.root[i]);
        // The tuft's plane: its triangle's, in world space, so that the radius is in metres.
        double v[3][3], w[3][3];
        corner_positions(s, c.triangle, v);
        for (int k = 0; k < 3; ++k) s.to_world_linear(v[k], w[k]);
        const double e1[3] = {w[1][0] - w[0][0], w[1][1] - w[0][1], w[1][2] - w[0][2]};
        const double e2[3] = {w[2][0] - w[0][0], w[2][1] - w[0][1], w[2][2] - w[0][2]};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        normalize(n);
        double tangent[3], bitangent[3];
        orthonormal_basis(n, tangent, bitangent);
        for (uint32_t k = 0; k < p.blades_per_tuft && blades.size() < count; ++k) {
            const double r = p.tuft_radius * std::sqrt(rng.uniform()), phi = rng.uniform() * kTwoPi;
            double offset[3], mesh_offset[3];
            for (int i = 0; i < 3; ++i) offset[i] = r * (std::cos(phi) * tangent[i] + std::sin(phi) * bitangent[i]);
            s.to_mesh_linear(offset, mesh_offset);
            MeshBlade b = c;
            for (int i = 0; i < 3; ++i) b.root[i] = static_cast<float>(c.root[i] + mesh_offset[i]);
            b.facing = static_cast<float>(rng.uniform() * kTwoPi);
            b.tuft = t;
            blades.push_back(b);
        }
    }
    return GRASS_SUCCESS;
}

} // namespace

void orthonormal_basis(const double n[3], double tangent[3], double bitangent[3]) {
    const double sign = std::copysign(1.0, n[2]);
    const double a = -1.0 / (sign + n[2]);
    const double b = n[0] * n[1] * a;
    tangent[0] = 1.0 + sign * n[0] * n[0] * a;
    tangent[1] = sign * b;
    tangent[2] = -sign * n[0];
    bitangent[0] = b;
    bitangent[1] = sign + n[1] * n[1] * a;
    bitangent[2] = -n[1];
}

grass_result scatter_mesh_blades(Log* log, const char* fn, const MeshSurface& s, const MeshScatterParams& p,
                                 MeshScatter* out) {
    uint64_t count = 0;
    GRASS_TRY(check_params(log, fn, s, p, &count));
    HostAllocator* host = out->blades.get_allocator().host();
    MeshScatter result(host);
    result.blades.reserve(count);
    Random rng(p.seed ^ 0x6d65736873636174ull); // "meshscat"
    if (p.seeding == MeshSeeding::kTufts) {
        GRASS_TRY(scatter_tufts(log, fn, s, p, rng, count, result.blades, result.tuft_centres));
    } else {
        scatter_single(s, rng, count, result.blades);
    }

    // Thresholds as the flat patch's (lemme2012 4.1.3): clustered over the UVs' unit square.
    Vector<float> x{StlAllocator<float>(host)}, z{StlAllocator<float>(host)}, t{StlAllocator<float>(host)};
    x.resize(count);
    z.resize(count);
    t.resize(count);
    for (uint64_t b = 0; b < count; ++b) {
        x[b] = result.blades[b].uv[0] - std::floor(result.blades[b].uv[0]);
        z[b] = result.blades[b].uv[1] - std::floor(result.blades[b].uv[1]);
    }
    ThresholdParams thresholds = p.thresholds;
    thresholds.seed ^= p.seed;
    assign_density_thresholds(thresholds, x.data(), z.data(), static_cast<uint32_t>(count), host, t.data());
    for (uint64_t b = 0; b < count; ++b) result.blades[b].threshold = t[b];

    group_into_patches(result.blades, p.patch_blades, result.patches);
    result.patch_blades = p.patch_blades;
    *out = std::move(result);
    return GRASS_SUCCESS;
}

} // namespace grass
