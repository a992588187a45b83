// The responsive grass calls of fuzz_api_sequence (grass.h "Responsive grass"): wind with its
// sources, colliders, the interaction map, blade mechanics, all from hostile descs, and the
// frame clock stepping forwards and backwards by any amount. After each begun frame the
// interaction map is kept on the CPU by the core's reference of the pass (as a backend keeps
// it on the GPU), and everything the frame hands a backend for responsive grass must be
// finite: the frame's wind and map uniforms, each draw's mechanics, the binned colliders.
#pragma once

#include "fuzz_values.hpp"

#include "context/context.hpp"
#include "dynamics/interaction_pass.hpp"

#include <grass/grass.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace grass_fuzz {

// A struct's type field: the right one, or any value (which grass must refuse).
inline void pick_struct_type(FuzzedDataProvider& in, grass_struct_type* type, grass_struct_type right) {
    if (in.ConsumeIntegralInRange<int>(0, 15) != 0) {
        *type = right;
        return;
    }
    const uint32_t bits = in.ConsumeIntegral<uint32_t>();
    std::memcpy(type, &bits, sizeof(bits));
}

inline void pick_raw_enum(FuzzedDataProvider& in, void* field, int64_t lo, int64_t hi) {
    const uint32_t bits = in.ConsumeIntegralInRange<int>(0, 7) == 0
                              ? in.ConsumeIntegral<uint32_t>()
                              : static_cast<uint32_t>(in.ConsumeIntegralInRange<int64_t>(lo, hi));
    std::memcpy(field, &bits, sizeof(bits));
}

// A desc is mostly sane (every value in its documented range, so that the call goes through
// and its frames run) or hostile (each value may be anything): `sane` says which.
inline bool pick_sane(FuzzedDataProvider& in) { return in.ConsumeIntegralInRange<int>(0, 3) != 0; }

inline double value(FuzzedDataProvider& in, bool sane, double lo, double hi) {
    return sane ? in.ConsumeFloatingPointInRange<double>(lo, hi) : hostile_double(in, lo, hi);
}
inline float value_f(FuzzedDataProvider& in, bool sane, double lo, double hi) {
    return static_cast<float>(value(in, sane, lo, hi));
}

// Near the fields (+-`near` m) or anywhere within the documented +-1e12 m, or (hostile) anything.
inline void pick_position(FuzzedDataProvider& in, bool sane, double p[3], double near) {
    for (int c = 0; c < 3; ++c) {
        p[c] = in.ConsumeIntegralInRange<int>(0, 7) == 0 ? value(in, sane, -1e12, 1e12) : value(in, sane, -near, near);
    }
}

inline grass_wind_source make_wind_source(FuzzedDataProvider& in, bool sane) {
    grass_wind_source s;
    std::memset(&s, 0, sizeof(s));
    if (sane) {
        s.kind = static_cast<grass_wind_source_kind>(in.ConsumeIntegralInRange<int>(0, 2));
    } else {
        pick_raw_enum(in, &s.kind, -1, 3);
    }
    pick_position(in, sane, s.position, 20.0);
    for (float& d : s.direction) d = value_f(in, sane, -1.0, 1.0);
    s.direction[1] = sane ? -1.0f : s.direction[1]; // not zero
    s.cone_angle = value_f(in, sane, 0.01, 1.57);
    s.speed = value_f(in, sane, 0.0, 1e3);
    s.radius = value_f(in, sane, 1e-3, in.ConsumeBool() ? 50.0 : 1e6);
    s.start_time = value(in, sane, -10.0, 100.0);
    s.duration = value_f(in, sane, 0.01, 1e4);
    s.front_speed = value_f(in, sane, 0.01, 1e4);
    return s;
}

// grass_set_wind: NULL, or a desc with hostile numbers and sources. source_count is any
// count; the array holds exactly the sources the count claims up to the documented maximum
// (a host whose array is shorter than a valid count is out of reach), and only a few
// beyond it, so that a count past GRASS_MAX_WIND_SOURCES read before it is refused shows.
inline grass_result set_wind(FuzzedDataProvider& in, grass_context* ctx) {
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) return grass_set_wind(ctx, nullptr);
    grass_wind_desc w = grass_default_wind_desc();
    pick_struct_type(in, &w.type, GRASS_STRUCT_TYPE_WIND_DESC);
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) w.next = &w;
    const bool sane = pick_sane(in);
    const int edits = in.ConsumeIntegralInRange<int>(0, 6);
    for (int e = 0; e < edits; ++e) {
        switch (in.ConsumeIntegralInRange<int>(0, 5)) {
        case 0:
            w.direction[in.ConsumeIntegralInRange<int>(0, 2)] = value_f(in, sane, -1.0, 1.0);
            break;
        case 1:
            w.speed = value_f(in, sane, 0.0, in.ConsumeBool() ? 20.0 : 1e3);
            break;
        case 2:
            w.gust_strength = value_f(in, sane, 0.0, 4.0);
            break;
        case 3:
            w.gust_length = value_f(in, sane, 0.1, 1e5);
            break;
        case 4:
            w.turbulence = value_f(in, sane, 0.0, 1.0);
            break;
        default:
            w.gravity[in.ConsumeIntegralInRange<int>(0, 2)] = value_f(in, sane, -1e3, 1e3);
            break;
        }
    }
    std::vector<grass_wind_source> sources;
    w.source_count = sane ? in.ConsumeIntegralInRange<uint32_t>(0, in.ConsumeBool() ? 2 : GRASS_MAX_WIND_SOURCES)
                          : hostile_u32(in, 0, GRASS_MAX_WIND_SOURCES + 1);
    const uint32_t backed =
        w.source_count <= GRASS_MAX_WIND_SOURCES ? w.source_count : in.ConsumeIntegralInRange<uint32_t>(0, 2);
    for (uint32_t k = 0; k < backed; ++k) sources.push_back(make_wind_source(in, sane));
    w.sources = sources.empty() || (!sane && in.ConsumeBool()) ? nullptr : sources.data();
    return grass_set_wind(ctx, &w);
}

inline grass_collider make_collider(FuzzedDataProvider& in, bool sane) {
    grass_collider c;
    std::memset(&c, 0, sizeof(c));
    if (sane) {
        c.shape = in.ConsumeBool() ? GRASS_COLLIDER_SPHERE : GRASS_COLLIDER_CAPSULE;
    } else {
        pick_raw_enum(in, &c.shape, -1, 2);
    }
    c.radius = value_f(in, sane, 0.0, in.ConsumeIntegralInRange<int>(0, 7) == 0 ? 1e6 : 3.0);
    pick_position(in, sane, c.center, 20.0);
    if (in.ConsumeBool()) {
        pick_position(in, sane, c.end, 20.0);
    } else {
        std::memcpy(c.end, c.center, sizeof(c.end));
    }
    if (in.ConsumeBool()) {
        const double most = in.ConsumeIntegralInRange<int>(0, 7) == 0 ? 1e5 : 20.0;
        for (float& v : c.velocity) v = value_f(in, sane, -most, most);
    }
    return c;
}

// grass_set_colliders: counts 0 .. a few with that many colliders, now and then the
// documented maximum (copies of a few), NULL with a count, and counts past the maximum
// with a short array: grass must refuse those before reading past the array.
inline grass_result set_colliders(FuzzedDataProvider& in, grass_context* ctx) {
    std::vector<grass_collider> colliders;
    uint32_t count = 0;
    const bool sane = pick_sane(in);
    // The maximum is rare: 65536 colliders as large as the map bin into 16M tile entries a
    // level, a second a frame under the sanitizers (the documented worst case).
    switch (in.ConsumeIntegralInRange<int>(0, 63)) {
    case 0:
    case 3:
    case 4:
    case 5:
        return grass_set_colliders(ctx, nullptr, in.ConsumeBool() ? 0 : hostile_u32(in, 1, 8));
    case 1: { // the maximum: 65536 colliders, copies of a few
        count = in.ConsumeBool() ? GRASS_MAX_COLLIDERS : GRASS_MAX_COLLIDERS - 1;
        const uint32_t distinct = in.ConsumeIntegralInRange<uint32_t>(1, 4);
        for (uint32_t k = 0; k < distinct; ++k) colliders.push_back(make_collider(in, sane));
        colliders.resize(count);
        for (uint32_t k = distinct; k < count; ++k) colliders[k] = colliders[k % distinct];
        break;
    }
    case 2: // past the maximum, with a short array
    case 6:
    case 7:
    case 8:
        count = in.ConsumeBool() ? GRASS_MAX_COLLIDERS + 1 : hostile_u32(in, GRASS_MAX_COLLIDERS + 1, 0xffffffffu);
        if (count <= GRASS_MAX_COLLIDERS) count = GRASS_MAX_COLLIDERS + 1 + count % 7;
        for (uint32_t k = 0, n = in.ConsumeIntegralInRange<uint32_t>(1, 3); k < n; ++k)
            colliders.push_back(make_collider(in, true));
        break;
    default:
        count = in.ConsumeIntegralInRange<uint32_t>(0, 8);
        for (uint32_t k = 0; k < count; ++k) colliders.push_back(make_collider(in, sane));
        break;
    }
    return grass_set_colliders(ctx, colliders.empty() ? nullptr : colliders.data(), count);
}

// grass_set_interaction: NULL (the default), or hostile resolutions, levels, texel sizes, ups.
inline grass_result set_interaction(FuzzedDataProvider& in, grass_context* ctx) {
    if (in.ConsumeIntegralInRange<int>(0, 7) == 0) return grass_set_interaction(ctx, nullptr);
    grass_interaction_desc d = grass_default_interaction_desc();
    pick_struct_type(in, &d.type, GRASS_STRUCT_TYPE_INTERACTION_DESC);
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) d.next = &d;
    // Mostly small maps (the CPU pass below runs over every texel).
    switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 0:
        d.resolution = hostile_u32(in, 0, 4096);
        break;
    case 1:
        d.resolution = 1u << in.ConsumeIntegralInRange<int>(0, 31);
        break;
    default:
        d.resolution = in.ConsumeBool() ? 64 : 128;
        break;
    }
    const bool sane = pick_sane(in);
    if (in.ConsumeBool()) d.level_count = sane ? in.ConsumeIntegralInRange<uint32_t>(1, 2) : hostile_u32(in, 1, 3);
    if (in.ConsumeBool()) d.texel_size[0] = value_f(in, sane, 1e-3, 1.0);
    if (in.ConsumeBool())
        d.texel_size[1] =
            sane ? d.texel_size[0] * in.ConsumeFloatingPointInRange<float>(1.0f, 1e3f) : hostile_float(in, 1e-3, 1e3);
    if (in.ConsumeBool()) {
        for (float& u : d.up) u = value_f(in, sane, -1.0, 1.0);
        if (sane) d.up[1] = 1.0f; // not zero
    }
    return grass_set_interaction(ctx, &d);
}

// grass_set_blade_mechanics on `patch` (any id): NULL, or hostile values.
inline grass_result set_blade_mechanics(FuzzedDataProvider& in, grass_context* ctx, grass_patch_id patch) {
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) return grass_set_blade_mechanics(ctx, patch, nullptr);
    grass_blade_mechanics m = grass_default_blade_mechanics();
    pick_struct_type(in, &m.type, GRASS_STRUCT_TYPE_BLADE_MECHANICS);
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) m.next = &m;
    const bool sane = pick_sane(in);
    const int edits = in.ConsumeIntegralInRange<int>(0, 4);
    for (int e = 0; e < edits; ++e) {
        switch (in.ConsumeIntegralInRange<int>(0, 5)) {
        case 0:
            m.stiffness = value_f(in, sane, 0.1, 1e5);
            break;
        case 1:
            m.mass = value_f(in, sane, 0.0, 100.0);
            break;
        case 2:
            m.wind_response = value_f(in, sane, 0.0, 100.0);
            break;
        case 3:
            m.trample_depth = value_f(in, sane, 0.0, 1.0);
            break;
        case 4:
            m.recovery_time = value_f(in, sane, 0.01, 1e5);
            break;
        default:
            m.variation = value_f(in, sane, 0.0, 0.9);
            break;
        }
    }
    return grass_set_blade_mechanics(ctx, patch, &m);
}

// grass_set_blade_culling on `field` (any id): NULL, or hostile values.
inline grass_result set_blade_culling(FuzzedDataProvider& in, grass_context* ctx, grass_field_id field) {
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) return grass_set_blade_culling(ctx, field, nullptr);
    grass_blade_culling_desc c = grass_default_blade_culling_desc();
    pick_struct_type(in, &c.type, GRASS_STRUCT_TYPE_BLADE_CULLING_DESC);
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) c.next = &c;
    const bool sane = pick_sane(in);
    const int edits = in.ConsumeIntegralInRange<int>(0, 5);
    for (int e = 0; e < edits; ++e) {
        switch (in.ConsumeIntegralInRange<int>(0, 6)) {
        case 0:
            pick_raw_enum(in, &c.orientation, sane ? 0 : -1, sane ? 1 : 3);
            break;
        case 1:
            c.orientation_limit = value_f(in, sane, 0.5, 1.0);
            break;
        case 2:
            pick_raw_enum(in, &c.view_frustum, sane ? 0 : -1, sane ? 1 : 3);
            break;
        case 3:
            c.frustum_tolerance = value_f(in, sane, 0.0, 1.0);
            break;
        case 4:
            pick_raw_enum(in, &c.distance, sane ? 0 : -1, sane ? 2 : 4);
            break;
        case 5:
            pick_raw_enum(in, &c.distance_levels, sane ? 1 : 0, sane ? 64 : 100);
            break;
        default:
            c.distance_max = value_f(in, sane, 0.0, 1e4);
            break;
        }
    }
    return grass_set_blade_culling(ctx, field, &c);
}

// grass_set_field_wind_map on `field` with `map` (any ids): NULL, a null map, or hostile values.
inline grass_result set_field_wind_map(FuzzedDataProvider& in, grass_context* ctx, grass_field_id field,
                                       grass_map_id map) {
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) return grass_set_field_wind_map(ctx, field, nullptr);
    grass_wind_map_desc d = grass_default_wind_map_desc();
    pick_struct_type(in, &d.type, GRASS_STRUCT_TYPE_WIND_MAP_DESC);
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) d.next = &d;
    if (in.ConsumeIntegralInRange<int>(0, 7) != 0) d.map = map;
    const bool sane = pick_sane(in);
    d.speed = value_f(in, sane, 0.0, 1e3);
    if (in.ConsumeBool()) {
        for (double& m : d.cell_to_map) m = value(in, sane, -2.0, 2.0);
    }
    return grass_set_field_wind_map(ctx, field, &d);
}

// The next frame's time from the previous one: small steps either way, huge steps either
// way, the documented bounds, and values past them (NaN, infinities, beyond +-1e9).
inline double next_time(FuzzedDataProvider& in, double previous) {
    switch (in.ConsumeIntegralInRange<int>(0, 11)) {
    case 0:
        return previous - in.ConsumeFloatingPointInRange<double>(0.0, 1.0); // backwards a little
    case 1:
        return previous + (in.ConsumeBool() ? 1e9 : -1e9); // a huge step, maybe past the bound
    case 2:
        return in.ConsumeBool() ? 1e9 : -1e9;
    case 3:
        return hostile_double(in, -1e9, 1e9);
    case 4:
        return previous + in.ConsumeFloatingPointInRange<double>(0.0, 1e6);
    default:
        return previous + in.ConsumeFloatingPointInRange<double>(0.0, 0.1); // a frame
    }
}

inline void require_finite(const float* v, size_t n, const char* what) {
    for (size_t k = 0; k < n; ++k) {
        if (!std::isfinite(v[k])) {
            std::fprintf(stderr, "%s[%zu] is %g after a frame grass began\n", what, k, static_cast<double>(v[k]));
            std::abort();
        }
    }
}

// After a begun frame: what the plan hands a backend for responsive grass is finite, the
// time step is a step grass documents (0 .. 2e9 s), and the interaction pass runs on the CPU
// map (`map`, kept across frames as a backend keeps its textures) when the map is small and
// the colliders few enough for a fuzzer's execution (nullptr: a device keeps the map).
inline void check_and_run_pass(const grass_context* ctx, std::vector<grass::InteractionTexel> map[2]) {
    const grass::FramePlan& plan = ctx->plan;
    const double dt = plan.stats.time_step;
    if (!(dt >= 0.0 && dt <= 2e9)) {
        std::fprintf(stderr, "a frame stepped %g s\n", dt);
        std::abort();
    }
    if (plan.stats.colliders_in_map > plan.stats.colliders) std::abort();
    const grass::FrameUniforms& f = plan.frame;
    const size_t responsive = (sizeof(f) - offsetof(grass::FrameUniforms, wind)) / sizeof(float);
    require_finite(f.wind, responsive, "frame.wind..wind_sources");
    for (const grass::TierDraw& d : plan.draws) {
        static_assert(offsetof(grass::FieldUniforms, culling) + sizeof(float[4]) -
                              offsetof(grass::FieldUniforms, mechanics) ==
                          24 * sizeof(float),
                      "mechanics, trample, field_up, wind map and culling are contiguous");
        require_finite(d.uniforms.mechanics, 24, "draw.uniforms.mechanics..culling");
    }
    const grass::InteractionPlan& ip = plan.interaction;
    for (const grass::GpuCollider& c : ip.colliders) require_finite(c.a, 12, "interaction.colliders");
    for (uint32_t l = 0; l < ip.levels; ++l) require_finite(ip.level[l].origin, 4, "interaction.level.origin");
    if (!map) return;
    if (ip.levels == 0) {
        map[0].clear();
        map[1].clear();
        return;
    }
    if (ip.resolution > 256) return; // too slow a pass for a fuzzer's execution
    // The pass tests each texel against its tile's colliders: 65536 colliders over the whole
    // map are 4e9 tests a level (the GPU's documented worst case, seconds on the CPU).
    for (uint32_t l = 0; l < ip.levels; ++l) {
        const uint64_t tile_texels = uint64_t(ip.level[l].counts[1]) * ip.level[l].counts[1];
        if (ip.tile_colliders[l].size() * tile_texels > 20000000u) return;
    }
    const size_t texels = size_t(ip.resolution) * ip.resolution;
    for (uint32_t l = 0; l < ip.levels; ++l) {
        if (ip.map_is_new || map[l].size() != texels) map[l].assign(texels, grass::cleared_texel());
        grass::run_interaction_pass(ip, l, map[l].data());
        for (const grass::InteractionTexel& t : map[l]) {
            // A cleared texel is (0, 0, 1e30, 1e30); every other value finite.
            require_finite(&t.dir[0], 4, "interaction map texel");
        }
    }
}

} // namespace grass_fuzz
