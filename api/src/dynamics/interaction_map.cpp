#include "dynamics/interaction_map.hpp"

#include "foundation/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace grass {

namespace {

double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

int64_t mod(int64_t a, int64_t n) {
    const int64_t r = a % n;
    return r < 0 ? r + n : r;
}

} // namespace

grass_interaction_desc default_interaction_desc() {
    grass_interaction_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_INTERACTION_DESC;
    d.up[1] = 1.0f;
    d.resolution = 256;
    d.level_count = 2;
    d.texel_size[0] = 0.05f;
    d.texel_size[1] = 1.0f;
    return d;
}

grass_result validate_interaction(Log* log, const char* fn, const grass_interaction_desc& d) {
    GRASS_TRY(check_direction(log, fn, "desc->up", d.up));
    const uint32_t n = d.resolution;
    if (n < 64 || n > 2048 || (n & (n - 1)) != 0) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: desc->resolution is %u; it must be a power of two in [64, 2048]", fn, n);
    }
    GRASS_TRY(check_range(log, fn, "desc->level_count", d.level_count, 1, 2));
    GRASS_TRY(check_range(log, fn, "desc->texel_size[0]", d.texel_size[0], 1e-3, 1e3));
    if (d.level_count == 2) {
        GRASS_TRY(check_range(log, fn, "desc->texel_size[1]", d.texel_size[1], 1e-3, 1e3));
        if (d.texel_size[1] < d.texel_size[0]) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_RANGE_INVERTED,
                             "%s: desc->texel_size[0] (%g) is greater than desc->texel_size[1] (%g); the coarse level "
                             "(1) must not be finer than level 0",
                             fn, static_cast<double>(d.texel_size[0]), static_cast<double>(d.texel_size[1]));
        }
    } else {
        GRASS_TRY(check_finite(log, fn, "desc->texel_size[1]", d.texel_size[1])); // unused, finite all the same
    }
    return GRASS_SUCCESS;
}

MapFrame map_frame(const grass_interaction_desc& d, const double camera[3], double anchor) {
    MapFrame f;
    const double len = std::sqrt(double(d.up[0]) * d.up[0] + double(d.up[1]) * d.up[1] + double(d.up[2]) * d.up[2]);
    for (int c = 0; c < 3; ++c) f.up[c] = d.up[c] / len;
    // u: world x made orthogonal to up (world z when up is near x); v = u x up. For up = +y
    // that is u = +x, v = +z: texel x runs along world x, texel y along world z.
    const double ex[3] = {1, 0, 0}, ez[3] = {0, 0, 1};
    const double* e = std::fabs(f.up[0]) > 0.9 ? ez : ex;
    const double along = dot3(e, f.up);
    double u[3] = {e[0] - along * f.up[0], e[1] - along * f.up[1], e[2] - along * f.up[2]};
    const double ul = std::sqrt(dot3(u, u));
    for (int c = 0; c < 3; ++c) f.u[c] = u[c] / ul;
    f.v[0] = f.u[1] * f.up[2] - f.u[2] * f.up[1];
    f.v[1] = f.u[2] * f.up[0] - f.u[0] * f.up[2];
    f.v[2] = f.u[0] * f.up[1] - f.u[1] * f.up[0];
    for (int c = 0; c < 3; ++c) f.camera[c] = camera[c];
    f.camera_height = dot3(camera, f.up) - anchor;
    return f;
}

void plan_interaction(const DynamicsState& state, const double camera[3], double dt, DynamicsState* scratch,
                      FramePlan* plan, InteractionMapState* next) {
    FrameUniforms& fu = plan->frame;
    InteractionPlan& ip = plan->interaction;
    *next = state.map;
    scratch->pending_colliders.assign(state.colliders.begin(), state.colliders.end());
    const bool exists = state.map.exists || !state.colliders.empty(); // made at the first frame with colliders
    plan->stats.colliders = state.colliders.size();
    if (!exists) return; // no map: levels 0, the uniforms stay zero
    const grass_interaction_desc& d = state.interaction;
    ip.pass = true;
    ip.map_is_new = !state.map.exists;
    bool clear_all = ip.map_is_new || state.map.clear_pending;
    // The height anchor: at the camera when the map is (re)made, moved when the camera is
    // more than kReanchorDistance from it along up (the map is cleared then).
    MapFrame frame = map_frame(d, camera, state.map.anchor);
    if (clear_all || std::fabs(frame.camera_height) > kReanchorDistance) {
        clear_all = true;
        next->anchor = dot3(camera, frame.up);
        frame = map_frame(d, camera, next->anchor);
    }
    const uint32_t n = d.resolution;
    ip.levels = d.level_count;
    ip.resolution = n;
    for (int c = 0; c < 3; ++c) {
        fu.map_up[c] = static_cast<float>(frame.up[c]);
        fu.map_axis_u[c] = static_cast<float>(frame.u[c]);
        fu.map_axis_v[c] = static_cast<float>(frame.v[c]);
    }
    fu.map_up[3] = static_cast<float>(ip.levels);
    fu.map_axis_u[3] = 0.0f;
    fu.map_axis_v[3] = static_cast<float>(frame.camera_height);
    const double camera_uv[2] = {dot3(camera, frame.u), dot3(camera, frame.v)};
    for (uint32_t l = 0; l < ip.levels; ++l) {
        const double texel = d.texel_size[l];
        InteractionLevelUniforms& lu = ip.level[l];
        for (int a = 0; a < 2; ++a) {
            const double q = camera_uv[a] / texel; // the camera in world texels (|q| < 2e15: exact in int64)
            const int64_t k = static_cast<int64_t>(std::floor(q));
            const int64_t w = k - int64_t(n / 2); // the window's first world texel
            const int64_t shift = std::min<int64_t>(std::max<int64_t>(w - state.map.window[l][a], -int64_t(n)), n);
            lu.window[a] = static_cast<int32_t>(mod(w, n));
            lu.window[2 + a] = clear_all ? 0 : static_cast<int32_t>(shift);
            // Texel W's lower corner relative to the camera, and the camera's map coordinate
            // modulo N, both from q - k so that the pass and the readers agree exactly.
            lu.origin[a] = static_cast<float>((-double(n / 2) - (q - double(k))) * texel);
            fu.map_levels[l][a] = static_cast<float>(double(mod(k, n)) + (q - double(k)));
            next->window[l][a] = w;
        }
        lu.origin[2] = static_cast<float>(texel);
        lu.origin[3] = static_cast<float>(dt);
        lu.counts[0] = n;
        lu.counts[1] = kInteractionTileSize;
        lu.counts[2] = n / kInteractionTileSize;
        lu.counts[3] = clear_all ? 1u : 0u;
        lu.least_radius[0] = l == 0 ? 0.0f : static_cast<float>(kCoarseLeastRadius * texel);
        fu.map_levels[l][2] = static_cast<float>(1.0 / texel);
        fu.map_levels[l][3] = static_cast<float>(n);
    }
    next->exists = true;
    next->clear_pending = false;
    plan->stats.colliders_in_map = bin_colliders(state.colliders, state.previous_colliders, frame, dt, scratch, &ip);
    plan->stats.interaction_texels = uint64_t(ip.levels) * n * n;
}

} // namespace grass
