#include "dynamics/colliders.hpp"

#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grass {

namespace {

double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

grass_result check_position(Log* log, const char* fn, const char* name, const double p[3]) {
    GRASS_TRY(check_finite_array(log, fn, name, p, 3));
    for (int c = 0; c < 3; ++c) {
        if (std::fabs(p[c]) > 1e12) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: %s[%d] is %g; it must be within +-1e12 m", fn, name, c, p[c]);
        }
    }
    return GRASS_SUCCESS;
}

// The collider's point `p` (world) in the map's frame: u, v relative to the camera, h above
// the anchor.
void to_map(const MapFrame& f, const double p[3], float out[3]) {
    const double rel[3] = {p[0] - f.camera[0], p[1] - f.camera[1], p[2] - f.camera[2]};
    out[0] = static_cast<float>(dot3(rel, f.u));
    out[1] = static_cast<float>(dot3(rel, f.v));
    out[2] = static_cast<float>(dot3(rel, f.up) + f.camera_height);
}

// The tiles of `level` that the footprint [lo, hi] (u, v metres relative to the camera),
// grown by the level's least radius (a narrow collider's widened footprint), reaches, clamped
// to the window: bounded work for any footprint.
TileRect tiles_of(const InteractionLevelUniforms& level, const double lo[2], const double hi[2]) {
    const double tile = double(level.origin[2]) * level.counts[1];
    const double reach = level.least_radius[0];
    const int32_t last = static_cast<int32_t>(level.counts[2]) - 1;
    int32_t r[4];
    for (int a = 0; a < 2; ++a) {
        const double t0 = std::floor((lo[a] - reach - level.origin[a]) / tile);
        const double t1 = std::floor((hi[a] + reach - level.origin[a]) / tile);
        if (t1 < 0.0 || t0 > last) return TileRect{1, 1, 0, 0}; // outside the window
        r[a] = static_cast<int32_t>(std::max(t0, 0.0));
        r[a + 2] = static_cast<int32_t>(std::min(t1, double(last)));
    }
    return TileRect{r[0], r[1], r[2], r[3]};
}

bool empty(const TileRect& r) { return r.x0 > r.x1 || r.z0 > r.z1; }

// Cuts every tile list of one level to kMaxCollidersPerTile: the colliders reaching lowest
// (`low`, ties: the lower index) stay, in index order, and the lists are packed again.
// Below the cap nothing moves. Updates scratch's overflow counts.
void cap_tiles(uint32_t level, const Vector<float>& low, Vector<uint32_t>* offsets_io, Vector<uint32_t>* list_io,
               DynamicsState* scratch) {
    Vector<uint32_t>& offsets = *offsets_io;
    Vector<uint32_t>& list = *list_io;
    bool over = false;
    for (size_t t = 0; t + 1 < offsets.size(); ++t) {
        const uint32_t count = offsets[t + 1] - offsets[t];
        if (count > scratch->most_in_tile) {
            scratch->most_in_tile = count;
            scratch->most_level = level;
        }
        over = over || count > kMaxCollidersPerTile;
    }
    if (!over) return;
    const auto lower = [&low](uint32_t a, uint32_t b) { return low[a] < low[b] || (low[a] == low[b] && a < b); };
    uint32_t write = 0, begin = offsets[0];
    for (size_t t = 0; t + 1 < offsets.size(); ++t) {
        const uint32_t end = offsets[t + 1];
        uint32_t keep = end - begin;
        if (keep > kMaxCollidersPerTile) {
            keep = kMaxCollidersPerTile;
            std::nth_element(list.begin() + begin, list.begin() + begin + keep, list.begin() + end, lower);
            std::sort(list.begin() + begin, list.begin() + begin + keep);
            scratch->full_tiles += 1;
        }
        offsets[t] = write;
        std::copy(list.begin() + begin, list.begin() + begin + keep, list.begin() + write); // write <= begin
        write += keep;
        begin = end;
    }
    offsets.back() = write;
    list.resize(write);
}

// bin_colliders: whether `c` was at `before` (the last frame) where its sweep starts now.
bool continues_passage(const grass_collider& c, const grass_collider* before, double dt) {
    if (before == nullptr || before->shape != c.shape) return false;
    for (int end = 0; end < (c.shape == GRASS_COLLIDER_CAPSULE ? 2 : 1); ++end) {
        const double* now = end == 0 ? c.center : c.end;
        const double* then = end == 0 ? before->center : before->end;
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double d = then[k] - (now[k] - double(c.velocity[k]) * dt);
            d2 += d * d;
        }
        if (!(d2 < double(c.radius) * c.radius)) return false;
    }
    return true;
}

} // namespace

grass_result validate_colliders(Log* log, const char* fn, const grass_collider* colliders, uint32_t count) {
    GRASS_TRY(check_range(log, fn, "count", count, 0, GRASS_MAX_COLLIDERS));
    if (count > 0) GRASS_TRY(check_not_null(log, fn, "colliders", colliders));
    char name[64];
    auto arg = [&](uint32_t i, const char* field) {
        std::snprintf(name, sizeof name, "colliders[%u].%s", i, field);
        return name;
    };
    for (uint32_t i = 0; i < count; ++i) {
        const grass_collider& c = colliders[i];
        const int64_t shape = raw_enum(c.shape);
        if (shape != GRASS_COLLIDER_SPHERE && shape != GRASS_COLLIDER_CAPSULE) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: %s is %lld; it must be GRASS_COLLIDER_SPHERE or GRASS_COLLIDER_CAPSULE", fn,
                             arg(i, "shape"), static_cast<long long>(shape));
        }
        GRASS_TRY(check_range(log, fn, arg(i, "radius"), c.radius, 0.0, 1e6));
        GRASS_TRY(check_position(log, fn, arg(i, "center"), c.center));
        // A sphere's end is unused: finite all the same (a NaN anywhere is a host's bug).
        if (shape == GRASS_COLLIDER_CAPSULE) {
            GRASS_TRY(check_position(log, fn, arg(i, "end"), c.end));
        } else {
            GRASS_TRY(check_finite_array(log, fn, arg(i, "end"), c.end, 3));
        }
        for (int k = 0; k < 3; ++k) {
            char component[64];
            std::snprintf(component, sizeof component, "colliders[%u].velocity[%d]", i, k);
            GRASS_TRY(check_range(log, fn, component, c.velocity[k], -1e5, 1e5));
        }
    }
    return GRASS_SUCCESS;
}

grass_result check_collider_sweeps(Log* log, const char* fn, const DynamicsState& state, double time) {
    const double dt = state.has_time ? time - state.previous_time : 0.0; // as plan_dynamics steps
    if (!(dt > 0.0)) return GRASS_SUCCESS;
    for (size_t i = 0; i < state.colliders.size(); ++i) {
        const float* v = state.colliders[i].velocity;
        const double speed = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
        if (speed * dt <= kMaxColliderSweep) continue;
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: colliders[%zu].velocity is (%g, %g, %g) m/s: over the time step of %.9g s it sweeps %g "
                         "m; a sweep must be at most %g m a step (set the colliders again: a collider that jumped "
                         "has velocity 0)",
                         fn, i, double(v[0]), double(v[1]), double(v[2]), dt, speed * dt, kMaxColliderSweep);
    }
    return GRASS_SUCCESS;
}

uint64_t bin_colliders(const Vector<grass_collider>& colliders, const Vector<grass_collider>& previous,
                       const MapFrame& frame, double dt, DynamicsState* scratch, InteractionPlan* plan) {
    const uint32_t levels = plan->levels;
    Vector<TileRect>& rects = scratch->tile_rects;
    rects.clear();
    scratch->collider_low.clear();
    scratch->full_tiles = scratch->most_in_tile = scratch->most_level = 0;
    plan->colliders.clear();
    for (size_t i = 0; i < colliders.size(); ++i) {
        const grass_collider& c = colliders[i];
        if (!(c.radius > 0.0f)) continue; // radius 0 touches nothing
        GpuCollider g{};
        to_map(frame, c.center, g.a);
        to_map(frame, c.shape == GRASS_COLLIDER_CAPSULE ? c.end : c.center, g.b);
        const double vel[3] = {c.velocity[0], c.velocity[1], c.velocity[2]};
        g.velocity[0] = static_cast<float>(dot3(vel, frame.u));
        g.velocity[1] = static_cast<float>(dot3(vel, frame.v));
        g.velocity[2] = static_cast<float>(dot3(vel, frame.up));
        g.velocity[3] = continues_passage(c, i < previous.size() ? &previous[i] : nullptr, dt) ? 1.0f : 0.0f;
        g.a[3] = c.radius;
        g.b[3] = static_cast<float>(c.shape);
        // The swept footprint across up: both ends now and a step ago, grown by the radius.
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (int a = 0; a < 2; ++a) {
            const double ends[4] = {g.a[a], g.b[a], g.a[a] - g.velocity[a] * dt, g.b[a] - g.velocity[a] * dt};
            for (double e : ends) {
                lo[a] = std::min(lo[a], e - c.radius);
                hi[a] = std::max(hi[a], e + c.radius);
            }
        }
        TileRect r[2] = {{1, 1, 0, 0}, {1, 1, 0, 0}};
        bool in_map = false;
        for (uint32_t l = 0; l < levels; ++l) {
            r[l] = tiles_of(plan->level[l], lo, hi);
            in_map = in_map || !empty(r[l]);
        }
        if (!in_map) continue;
        plan->colliders.push_back(g);
        const double lower_end = std::min(g.a[2], g.b[2]); // the lower end now, then a step ago
        const double low = std::min(double(lower_end), lower_end - double(g.velocity[2]) * dt);
        scratch->collider_low.push_back(static_cast<float>(low - c.radius));
        rects.push_back(r[0]);
        rects.push_back(r[1]);
    }
    // Per level: count the colliders of each tile, prefix sums, then fill (a counting sort).
    const uint32_t n = static_cast<uint32_t>(plan->colliders.size());
    for (uint32_t l = 0; l < levels; ++l) {
        const uint32_t tiles = plan->level[l].counts[2];
        Vector<uint32_t>& offsets = plan->tile_offsets[l];
        offsets.assign(size_t(tiles) * tiles + 1, 0u);
        for (uint32_t i = 0; i < n; ++i) {
            const TileRect& r = rects[2 * i + l];
            for (int32_t z = r.z0; z <= r.z1; ++z) {
                for (int32_t x = r.x0; x <= r.x1; ++x) offsets[size_t(z) * tiles + x + 1] += 1;
            }
        }
        for (size_t t = 1; t < offsets.size(); ++t) offsets[t] += offsets[t - 1];
        Vector<uint32_t>& fill = scratch->tile_fill;
        fill.assign(offsets.begin(), offsets.end() - 1);
        plan->tile_colliders[l].resize(offsets.back());
        for (uint32_t i = 0; i < n; ++i) {
            const TileRect& r = rects[2 * i + l];
            for (int32_t z = r.z0; z <= r.z1; ++z) {
                for (int32_t x = r.x0; x <= r.x1; ++x) plan->tile_colliders[l][fill[size_t(z) * tiles + x]++] = i;
            }
        }
        cap_tiles(l, scratch->collider_low, &offsets, &plan->tile_colliders[l], scratch);
    }
    return n;
}

} // namespace grass
