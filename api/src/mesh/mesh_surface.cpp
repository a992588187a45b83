#include "mesh/mesh_surface.hpp"

#include "foundation/validate.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace grass {

namespace {

using u64 = unsigned long long;

grass_result check_vectors(Log* log, const char* fn, const char* name, const float* v, uint64_t count, int n,
                           bool nonzero) {
    for (uint64_t k = 0; k < count; ++k) {
        const float* p = v + k * n;
        double length2 = 0.0;
        for (int i = 0; i < n; ++i) {
            if (!std::isfinite(p[i])) {
                return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NOT_FINITE,
                                 "%s: desc->%s[%llu] has %g in component %d; it must be finite", fn, name,
                                 static_cast<u64>(k), static_cast<double>(p[i]), i);
            }
            length2 += static_cast<double>(p[i]) * p[i];
        }
        if (nonzero && !(length2 > 1e-12)) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_ZERO_VECTOR,
                             "%s: desc->%s[%llu] is (%g, %g, %g); it must not be zero (length > 1e-6)", fn, name,
                             static_cast<u64>(k), static_cast<double>(p[0]), static_cast<double>(p[1]),
                             static_cast<double>(p[2]));
        }
    }
    return GRASS_SUCCESS;
}

double determinant3(const double m[9]) {
    return m[0] * (m[4] * m[8] - m[7] * m[5]) - m[3] * (m[1] * m[8] - m[7] * m[2]) + m[6] * (m[1] * m[5] - m[4] * m[2]);
}

void invert3(const double m[9], double det, double out[9]) {
    const double s = 1.0 / det;
    out[0] = (m[4] * m[8] - m[5] * m[7]) * s;
    out[1] = (m[2] * m[7] - m[1] * m[8]) * s;
    out[2] = (m[1] * m[5] - m[2] * m[4]) * s;
    out[3] = (m[5] * m[6] - m[3] * m[8]) * s;
    out[4] = (m[0] * m[8] - m[2] * m[6]) * s;
    out[5] = (m[2] * m[3] - m[0] * m[5]) * s;
    out[6] = (m[3] * m[7] - m[4] * m[6]) * s;
    out[7] = (m[1] * m[6] - m[0] * m[7]) * s;
    out[8] = (m[0] * m[4] - m[1] * m[3]) * s;
}

void apply3(const double m[9], const double v[3], double out[3]) {
    for (int r = 0; r < 3; ++r) out[r] = m[r] * v[0] + m[3 + r] * v[1] + m[6 + r] * v[2];
}

grass_result check_transform(Log* log, const char* fn, const double t[16], double linear[9], double inverse[9]) {
    GRASS_TRY(check_finite_array(log, fn, "desc->transform", t, 16));
    if (t[3] != 0.0 || t[7] != 0.0 || t[11] != 0.0 || t[15] != 1.0) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: desc->transform's last row is (%g, %g, %g, %g); it must be (0, 0, 0, 1) (an affine "
                         "transform, column-major)",
                         fn, t[3], t[7], t[11], t[15]);
    }
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) linear[c * 3 + r] = t[c * 4 + r];
    const double det = determinant3(linear);
    double scale = 0.0;
    for (int k = 0; k < 9; ++k) scale = std::max(scale, std::fabs(linear[k]));
    if (!(std::fabs(det) > 1e-12 * scale * scale * scale)) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_TRANSFORM,
                         "%s: desc->transform flattens the mesh (determinant %g); it must be invertible", fn, det);
    }
    invert3(linear, det, inverse);
    return GRASS_SUCCESS;
}

grass_result check_counts(Log* log, const char* fn, const MeshSurfaceDesc& d) {
    GRASS_TRY(check_not_null(log, fn, "desc->positions", d.positions));
    GRASS_TRY(check_not_null(log, fn, "desc->normals", d.normals));
    GRASS_TRY(check_not_null(log, fn, "desc->indices", d.indices));
    return check_mesh_counts(log, fn, d.vertex_count, d.index_count);
}

} // namespace

grass_result check_mesh_counts(Log* log, const char* fn, uint64_t vertex_count, uint64_t index_count) {
    if (vertex_count < 1 || vertex_count > kMaxMeshVertices) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: desc->vertex_count is %llu; it must be in [1, %llu]", fn, static_cast<u64>(vertex_count),
                         static_cast<u64>(kMaxMeshVertices));
    }
    if (index_count < 3 || index_count > kMaxMeshIndices || index_count % 3 != 0) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: desc->index_count is %llu; it must be a multiple of 3 in [3, %llu] (32-bit indices, "
                         "fewer than 2^31)",
                         fn, static_cast<u64>(index_count), static_cast<u64>(kMaxMeshIndices));
    }
    return GRASS_SUCCESS;
}

uint32_t MeshSurface::triangle_at_area(double a) const {
    const auto it = std::upper_bound(cumulative_area_.begin(), cumulative_area_.end(), a);
    const auto k = static_cast<uint32_t>(it - cumulative_area_.begin());
    return std::min(k, triangle_count() - 1); // a == total_area() by rounding lands on the last
}

void MeshSurface::corners(uint32_t host_triangle, uint32_t out[3]) const {
    for (int i = 0; i < 3; ++i) out[i] = mesh_.indices[uint64_t{host_triangle} * 3 + i];
}

void MeshSurface::to_world_linear(const double v[3], double out[3]) const { apply3(linear_, v, out); }

void MeshSurface::to_mesh_linear(const double v[3], double out[3]) const { apply3(inverse_, v, out); }

grass_result build_mesh_surface(Log* log, const char* fn, const MeshSurfaceDesc& d, MeshSurface* out) {
    GRASS_TRY(check_counts(log, fn, d));
    MeshSurface s(out->triangles_.get_allocator().host());
    GRASS_TRY(check_transform(log, fn, d.transform, s.linear_, s.inverse_));
    GRASS_TRY(check_vectors(log, fn, "positions", d.positions, d.vertex_count, 3, false));
    GRASS_TRY(check_vectors(log, fn, "normals", d.normals, d.vertex_count, 3, true));
    if (d.uvs) GRASS_TRY(check_vectors(log, fn, "uvs", d.uvs, d.vertex_count, 2, false));
    for (uint64_t k = 0; k < d.index_count; ++k) {
        if (d.indices[k] >= d.vertex_count) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: desc->indices[%llu] is %u; it must be below desc->vertex_count (%llu)", fn,
                             static_cast<u64>(k), d.indices[k], static_cast<u64>(d.vertex_count));
        }
    }
    s.mesh_ = d;
    const uint64_t triangles = d.index_count / 3;
    s.triangles_.reserve(triangles);
    s.cumulative_area_.reserve(triangles);
    double sum = 0.0;
    for (uint64_t t = 0; t < triangles; ++t) {
        double w[3][3];
        for (int i = 0; i < 3; ++i) {
            const float* p = d.positions + uint64_t{d.indices[t * 3 + i]} * 3;
            const double v[3] = {p[0], p[1], p[2]};
            s.to_world_linear(v, w[i]);
        }
        double e1[3], e2[3], e3[3];
        for (int i = 0; i < 3; ++i) e1[i] = w[1][i] - w[0][i], e2[i] = w[2][i] - w[0][i], e3[i] = w[2][i] - w[1][i];
        const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                     cz = e1[0] * e2[1] - e1[1] * e2[0];
        const double cross = std::sqrt(cx * cx + cy * cy + cz * cz);
        double longest2 = 0.0;
        for (const double* e : {e1, e2, e3}) longest2 = std::max(longest2, e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        // Zero area: repeated or collinear corners, or a sliver below float precision.
        if (!(cross > 1e-9 * longest2)) {
            ++s.degenerate_count_;
            continue;
        }
        sum += 0.5 * cross;
        s.triangles_.push_back(static_cast<uint32_t>(t));
        s.cumulative_area_.push_back(sum);
    }
    if (s.triangles_.empty()) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: desc->indices: all %llu triangles are degenerate (zero area); the mesh has no surface "
                         "to grow grass on",
                         fn, static_cast<u64>(triangles));
    }
    s.total_area_ = sum;
    *out = std::move(s);
    return GRASS_SUCCESS;
}

} // namespace grass
