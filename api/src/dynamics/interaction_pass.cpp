#include "dynamics/interaction_pass.hpp"

#include <algorithm>
#include <cmath>

namespace grass {

namespace {

struct V2 {
    float x, y;
};
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
float dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
float length(V2 a) { return std::sqrt(dot(a, a)); }

struct Contact {
    bool found = false;
    float underside = kNoContact;
    float age = 0.0f;
    float dir[2] = {0.0f, 0.0f};
    bool dir_known = false;
    bool continues = false; // the collider touched the texel at the start of the sweep
};

// Keeps the deeper contact (ties: the younger).
void offer(Contact* best, float underside, float age, V2 away, float distance, float radius, V2 velocity,
           bool continues) {
    if (best->found && (underside > best->underside || (underside == best->underside && age >= best->age))) return;
    best->found = true;
    best->continues = continues;
    best->underside = underside;
    best->age = age;
    best->dir_known = true;
    if (distance >= 1e-6f * radius) {
        best->dir[0] = away.x / distance;
        best->dir[1] = away.y / distance;
    } else if (dot(velocity, velocity) > 0.0f) { // under its centre: along its motion
        const float l = length(velocity);
        best->dir[0] = velocity.x / l;
        best->dir[1] = velocity.y / l;
    } else {
        best->dir_known = false;
    }
}

// The point of segment a..b (u, v) nearest `p`: its parameter in [0, 1].
float nearest(V2 p, V2 a, V2 b) {
    const V2 ab = b - a;
    const float l2 = dot(ab, ab);
    return l2 > 0.0f ? std::min(std::max(dot(p - a, ab) / l2, 0.0f), 1.0f) : 0.0f;
}

// The distance at which a texel centre d from a collider of radius r is pressed: a footprint
// narrower than the level's least radius widened to it (interaction.comp).
float reached(float d, float r, float least) { return least > r ? d * (r / least) : d; }

void test_sphere(const GpuCollider& c, V2 p, float dt, float least, Contact* best) {
    const float r = c.a[3];
    const float c0[3] = {c.a[0] - c.velocity[0] * dt, c.a[1] - c.velocity[1] * dt, c.a[2] - c.velocity[2] * dt};
    const V2 from{c0[0], c0[1]}, to{c.a[0], c.a[1]};
    const V2 ab = to - from;
    const float s = dot(ab, ab) > 0.0f ? nearest(p, from, to) : 1.0f;
    const float cu = from.x + (to.x - from.x) * s, cv = from.y + (to.y - from.y) * s;
    const float ch = c0[2] + (c.a[2] - c0[2]) * s;
    const V2 away = p - V2{cu, cv};
    const float d = length(away);
    const float e = reached(d, r, least);
    if (!(e < r)) return;
    const bool continues = c.velocity[3] > 0.5f && reached(length(p - from), r, least) < r; // bin_colliders: not new
    offer(best, ch - std::sqrt(r * r - e * e), (1.0f - s) * dt, away, d, r, V2{c.velocity[0], c.velocity[1]},
          continues);
}

void test_capsule(const GpuCollider& c, V2 p, float dt, float texel, float least, Contact* best) {
    const float r = c.a[3];
    const float speed =
        std::sqrt(c.velocity[0] * c.velocity[0] + c.velocity[1] * c.velocity[1] + c.velocity[2] * c.velocity[2]);
    const float steps = std::min(std::max(std::ceil(speed * dt / std::max(r, texel)), 1.0f), 8.0f);
    const int k_max = static_cast<int>(steps);
    bool continues = false;
    for (int k = 0; k <= k_max; ++k) {
        const float s = float(k) / steps;
        const float back = (1.0f - s) * dt;
        float a[3], b[3];
        for (int i = 0; i < 3; ++i) {
            a[i] = c.a[i] - c.velocity[i] * back;
            b[i] = c.b[i] - c.velocity[i] * back;
        }
        // The closest point of the axis across up; a vertical capsule: its lower end.
        const bool vertical = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) <= 0.0f;
        const float t = vertical ? (b[2] < a[2] ? 1.0f : 0.0f) : nearest(p, V2{a[0], a[1]}, V2{b[0], b[1]});
        const float q[3] = {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
        const V2 away = p - V2{q[0], q[1]};
        const float d = length(away);
        const float e = reached(d, r, least);
        if (!(e < r)) continue;
        continues = continues || (k == 0 && c.velocity[3] > 0.5f);
        offer(best, q[2] - std::sqrt(r * r - e * e), back, away, d, r, V2{c.velocity[0], c.velocity[1]}, continues);
    }
}

int32_t wrap(int32_t a, int32_t n) {
    const int32_t m = a % n;
    return m < 0 ? m + n : m;
}

} // namespace

void run_interaction_pass(const InteractionPlan& plan, uint32_t level, InteractionTexel* texels) {
    const InteractionLevelUniforms& u = plan.level[level];
    const int32_t n = static_cast<int32_t>(u.counts[0]);
    const int32_t tile_size = static_cast<int32_t>(u.counts[1]), tiles = static_cast<int32_t>(u.counts[2]);
    const float texel = u.origin[2], dt = u.origin[3], least = u.least_radius[0];
    const auto& offsets = plan.tile_offsets[level];
    const auto& list = plan.tile_colliders[level];
    for (int32_t y = 0; y < n; ++y) {
        for (int32_t x = 0; x < n; ++x) {
            InteractionTexel& out = texels[size_t(y) * n + x];
            const int32_t j[2] = {wrap(x - u.window[0], n), wrap(y - u.window[1], n)};
            bool stale = u.counts[3] == 1u;
            for (int a = 0; a < 2; ++a) stale = stale || j[a] + u.window[2 + a] < 0 || j[a] + u.window[2 + a] >= n;
            if (stale) out = cleared_texel();
            if (out.age < kAgeNone) out.age += dt;
            const V2 p{u.origin[0] + (float(j[0]) + 0.5f) * texel, u.origin[1] + (float(j[1]) + 0.5f) * texel};
            const int32_t tile = (j[1] / tile_size) * tiles + j[0] / tile_size;
            Contact best;
            for (uint32_t e = offsets[tile]; e < offsets[tile + 1]; ++e) {
                const GpuCollider& c = plan.colliders[list[e]];
                if (c.b[3] == float(GRASS_COLLIDER_CAPSULE)) {
                    test_capsule(c, p, dt, texel, least, &best);
                } else {
                    test_sphere(c, p, dt, least, &best);
                }
            }
            if (!best.found) continue;
            const bool keep =
                best.continues && out.age < kAgeNone &&
                (out.underside < best.underside || (out.underside == best.underside && out.age < best.age));
            if (keep) continue;
            if (best.dir_known) {
                out.dir[0] = best.dir[0];
                out.dir[1] = best.dir[1];
            }
            out.underside = best.underside;
            out.age = best.age;
        }
    }
}

} // namespace grass
