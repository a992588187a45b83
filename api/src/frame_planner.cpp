#include "frame_planner.hpp"

#include "design_map.hpp"
#include "mirror_tiling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace grass {

namespace {

// c = a * b for column-major 4x4 matrices.
void mul4(const double a[16], const double b[16], double c[16]) {
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) s += a[4 * k + row] * b[4 * col + k];
            c[4 * col + row] = s;
        }
    }
}

struct Candidate {
    double distance2;
    BladeInstance instance;
};

// Blades passing a density d: thresholds are (k+1)/N (density_threshold.cpp), so floor(d N).
uint64_t blades_passing(double density, uint32_t blade_count) {
    const double n = std::floor(density * blade_count + 1e-6);
    return static_cast<uint64_t>(std::min<double>(std::max(n, 0.0), blade_count));
}

void plan_field(grass_context* ctx, uint32_t slot, const Field& field, const Patch& patch, const double camera[3],
                const Frustum& frustum, Vector<Candidate>& candidates) {
    const grass_field_desc& d = field.desc;
    const double cs = d.cell_size;
    const double* R = field.rotation; // column-major 3x3
    // Camera in field space, in cells: R^T (camera - T) / cell_size.
    const double rel[3] = {camera[0] - field.translation[0], camera[1] - field.translation[1],
                           camera[2] - field.translation[2]};
    double local[3];
    for (int c = 0; c < 3; ++c) local[c] = (R[3 * c] * rel[0] + R[3 * c + 1] * rel[1] + R[3 * c + 2] * rel[2]) / cs;

    // Blade bounds: tips may leave the cell; mirroring makes the overhang symmetric.
    const PatchData& pd = patch.data;
    const double overhang = std::max({0.0, -static_cast<double>(pd.bounds_min[0]), pd.bounds_max[0] - 1.0,
                                      -static_cast<double>(pd.bounds_min[2]), pd.bounds_max[2] - 1.0});
    const double top = std::max(0.0, static_cast<double>(pd.bounds_max[1]));
    const double reach = d.draw_distance / cs; // in cells

    const double i_lo = std::max(0.0, std::floor(local[0] - reach - overhang));
    const double i_hi = std::min(static_cast<double>(d.cells_x) - 1.0, std::floor(local[0] + reach + overhang));
    const double j_lo = std::max(0.0, std::floor(local[2] - reach - overhang));
    const double j_hi = std::min(static_cast<double>(d.cells_z) - 1.0, std::floor(local[2] + reach + overhang));
    if (i_lo > i_hi || j_lo > j_hi) return;

    // Field origin relative to the camera, in double until it is small.
    const double origin_rel[3] = {-rel[0], -rel[1], -rel[2]};
    const double ux[3] = {R[0] * cs, R[1] * cs, R[2] * cs}; // one cell along field x, world metres
    const double uy[3] = {R[3] * cs, R[4] * cs, R[5] * cs};
    const double uz[3] = {R[6] * cs, R[7] * cs, R[8] * cs};
    const float inv_x = static_cast<float>(1.0 / d.cells_x), inv_z = static_cast<float>(1.0 / d.cells_z);

    const size_t first = candidates.size();
    uint64_t considered = 0;
    for (double j = j_lo; j <= j_hi; j += 1.0) {
        for (double i = i_lo; i <= i_hi; i += 1.0) {
            ++considered;
            // Nearest point of the cell's box to the camera, in cells.
            const double nx = std::min(std::max(local[0], i), i + 1.0) - local[0];
            const double ny = std::min(std::max(local[1], 0.0), top) - local[1];
            const double nz = std::min(std::max(local[2], j), j + 1.0) - local[2];
            if (nx * nx + ny * ny + nz * nz > reach * reach) continue;

            double corners[8][3];
            for (int k = 0; k < 8; ++k) {
                const double cx = (k & 1) ? i + 1.0 + overhang : i - overhang;
                const double cy = (k & 2) ? top : 0.0;
                const double cz = (k & 4) ? j + 1.0 + overhang : j - overhang;
                for (int a = 0; a < 3; ++a) corners[k][a] = origin_rel[a] + ux[a] * cx + uy[a] * cy + uz[a] * cz;
            }
            if (frustum.outside(corners)) continue;

            Candidate c;
            const double ccx = i + 0.5 - local[0], ccz = j + 0.5 - local[2], ccy = -local[1];
            c.distance2 = ccx * ccx + ccy * ccy + ccz * ccz;
            for (int a = 0; a < 3; ++a) c.instance.origin[a] = static_cast<float>(origin_rel[a] + ux[a] * i + uz[a] * j);
            const auto ci = static_cast<uint64_t>(i), cj = static_cast<uint64_t>(j);
            c.instance.mirror = d.mirror_tiling ? static_cast<float>(mirror_bits(ci, cj, d.mirror_seed)) : 0.0f;
            c.instance.map_uv[0] = static_cast<float>(i / d.cells_x);
            c.instance.map_uv[1] = static_cast<float>(j / d.cells_z);
            double density = d.density;
            if (!field.density_texels.empty()) {
                density *= sample_map(field.density_texels.data(), field.density_width, field.density_height,
                                      (i + 0.5) / d.cells_x, (j + 0.5) / d.cells_z);
            }
            c.instance.reserved[0] = static_cast<float>(density); // the cell-centre density, for stats
            c.instance.reserved[1] = 0.0f;
            candidates.push_back(c);
        }
    }

    // Front to back: the nearest cells first, so early depth rejects the rest.
    std::sort(candidates.begin() + static_cast<std::ptrdiff_t>(first), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.distance2 < b.distance2; });

    FramePlan& plan = ctx->plan;
    plan.stats.cells_considered += considered;
    const uint32_t count = static_cast<uint32_t>(candidates.size() - first);
    if (count == 0) return;

    BladeDraw draw;
    draw.field_slot = slot;
    draw.patch_slot = field.patch_slot;
    draw.first_instance = static_cast<uint32_t>(plan.blade_instances.size());
    draw.instance_count = count;
    FieldUniforms& u = draw.uniforms;
    const double* cols[3] = {ux, uy, uz};
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) u.patch_to_world[4 * c + r] = (c < 3 && r < 3) ? static_cast<float>(cols[c][r]) : (c == 3 && r == 3 ? 1.0f : 0.0f);
    }
    u.map_params[0] = inv_x;
    u.map_params[1] = inv_z;
    u.map_params[2] = d.density;
    u.map_params[3] = field.density_texels.empty() ? 0.0f : 1.0f;
    u.blade_params[0] = pd.ao_impact;
    u.blade_params[1] = pd.ao_height;
    u.blade_params[2] = 0.0f;
    u.blade_params[3] = 0.0f;
    plan.blade_draws.push_back(draw);

    const uint64_t triangles_per_blade = pd.indices_per_blade / 3;
    for (size_t k = first; k < candidates.size(); ++k) {
        plan.blade_instances.push_back(candidates[k].instance);
        const uint64_t passing = blades_passing(candidates[k].instance.reserved[0], pd.blade_count);
        plan.stats.blades_drawn += passing;
        plan.stats.triangles += passing * triangles_per_blade;
    }
    plan.stats.fields_drawn += 1;
    plan.stats.cells_drawn += count;
    plan.stats.blades_submitted += static_cast<uint64_t>(count) * pd.blade_count;
}

} // namespace

Frustum Frustum::from_view_projection(const double m[16]) {
    // Gribb & Hartmann: rows of the matrix. Row r = (m[r], m[4+r], m[8+r], m[12+r]).
    auto row = [&](int r, int k) { return m[4 * k + r]; };
    Frustum f;
    const int sign[6] = {1, -1, 1, -1, 1, -1};
    const int axis[6] = {0, 0, 1, 1, 2, 2};
    for (int p = 0; p < 6; ++p) {
        for (int k = 0; k < 4; ++k) f.planes[p][k] = row(3, k) + sign[p] * row(axis[p], k);
    }
    // The near plane w + z >= 0 is the GL convention; for 0..1 depth (Vulkan) it is looser
    // than z >= 0, so it only keeps a few more cells: conservative for both.
    return f;
}

bool Frustum::outside(const double corners[8][3]) const {
    for (const auto& p : planes) {
        bool all_out = true;
        for (int k = 0; k < 8 && all_out; ++k) {
            all_out = p[0] * corners[k][0] + p[1] * corners[k][1] + p[2] * corners[k][2] + p[3] < 0.0;
        }
        if (all_out) return true;
    }
    return false;
}

void build_frame_plan(grass_context* ctx, const grass_view_desc& view) {
    const auto start = std::chrono::steady_clock::now();
    FramePlan& plan = ctx->plan;
    plan.clear();

    // Camera-relative view: the host's rotation only; the translation is the camera position.
    double rotation[16] = {0};
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) rotation[4 * c + r] = view.view[4 * c + r];
    }
    rotation[15] = 1.0;
    double projection[16], view_projection[16];
    for (int k = 0; k < 16; ++k) projection[k] = view.projection[k];
    mul4(projection, rotation, view_projection);
    for (int k = 0; k < 16; ++k) plan.frame.view_projection[k] = static_cast<float>(view_projection[k]);

    const double* s = nullptr;
    double sun[3] = {view.sun_direction[0], view.sun_direction[1], view.sun_direction[2]};
    const double len = std::sqrt(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2]);
    s = sun;
    for (int c = 0; c < 3; ++c) {
        plan.frame.sun_direction[c] = static_cast<float>(s[c] / len);
        plan.frame.sun_color[c] = view.sun_color[c];
        plan.frame.ambient_color[c] = view.ambient_color[c];
    }
    plan.frame.sun_direction[3] = plan.frame.sun_color[3] = plan.frame.ambient_color[3] = 0.0f;
    plan.frame.params[0] = static_cast<float>(std::fmod(view.time, 86400.0));
    plan.frame.params[1] = static_cast<float>(view.flags);
    plan.frame.params[2] = plan.frame.params[3] = 0.0f;
    for (int k = 0; k < 4; ++k) plan.viewport[k] = view.viewport[k];
    plan.flags = view.flags;

    const Frustum frustum = Frustum::from_view_projection(view_projection);
    Vector<Candidate> candidates{StlAllocator<Candidate>(&ctx->host)};
    for (uint32_t slot = 0; slot < ctx->fields.capacity(); ++slot) {
        const Field* field = ctx->fields.get(slot);
        if (!field) continue;
        candidates.clear();
        plan_field(ctx, slot, *field, *ctx->patches.get(field->patch_slot), view.camera_position, frustum, candidates);
    }
    plan.stats.plan_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace grass
