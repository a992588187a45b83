// The surface checks GBufferTest (GL) and GBufferVkTest (Vulkan) share: a G-buffer of four
// RGBA8 attachments in the layout {albedo, normal (UNORM), material, NONE} with default
// write masks, as each backend read it back.
#pragma once

#include "render_fixture.hpp"

#include <grass/grass.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <vector>

namespace grass_test {

// The four-attachment layout: albedo, normal (UNORM), material, NONE; default masks.
inline grass_view_gbuffer_desc four_attachments() {
    grass_view_gbuffer_desc g = grass_default_view_gbuffer_desc();
    g.attachment_count = 4;
    g.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    g.attachments[1].semantic = GRASS_GBUFFER_NORMAL;
    g.attachments[2].semantic = GRASS_GBUFFER_MATERIAL;
    g.attachments[3].semantic = GRASS_GBUFFER_NONE;
    return g;
}

// A G-buffer pass of `layout`, to chain on a view.
inline grass_view_pass_desc gbuffer_pass(const grass_view_gbuffer_desc* layout) {
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = layout;
    return pass;
}

// The motion desc of `v` with the previous camera 0.15 m along -x and 0.1 m along -z of it,
// the same time, its velocity at attachment 1.
inline grass_view_motion_desc panned_motion(const grass_view_desc& v) {
    grass_view_desc before = v;
    before.camera_position[0] -= 0.15;
    before.camera_position[2] -= 0.1;
    grass_view_motion_desc motion = grass_default_view_motion_desc();
    std::memcpy(motion.previous_camera_position, before.camera_position, sizeof motion.previous_camera_position);
    std::memcpy(motion.previous_view, before.view, sizeof motion.previous_view);
    std::memcpy(motion.previous_projection, before.projection, sizeof motion.previous_projection);
    motion.previous_time = v.time;
    motion.velocity_attachment = 1;
    return motion;
}

// The velocity test's layout: albedo at attachment 0, velocity (a float attachment) at 1.
inline grass_view_gbuffer_desc albedo_velocity() {
    grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
    layout.attachment_count = 2;
    layout.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    layout.attachments[1].semantic = GRASS_GBUFFER_VELOCITY;
    layout.attachments[1].format = GRASS_GBUFFER_FORMAT_FLOAT;
    return layout;
}

// The G-buffer view's velocity `g` (RGBA floats per pixel, its window depth `g_depth`) equals
// the motion view's `colour` (depth `colour_depth`) within 1e-5 at 99% of the pixels where both
// drew grass (depth < 1) at the same depth, over a fifth of the image and over half of them
// moving; its .ba kept `clear`.
inline void expect_same_velocity(const std::vector<float>& colour, const std::vector<float>& colour_depth,
                                 const std::vector<float>& g, const std::vector<float>& g_depth, const float clear[4]) {
    const size_t n = colour_depth.size();
    ASSERT_EQ(colour.size(), n * 4);
    ASSERT_EQ(g.size(), n * 4);
    size_t both = 0, equal = 0, ba_changed = 0, moved = 0;
    for (size_t p = 0; p < n; ++p) {
        const float* a = &colour[p * 4];
        const float* b = &g[p * 4];
        ba_changed += b[2] != clear[2] || b[3] != clear[3] ? 1u : 0u;
        if (colour_depth[p] >= 1.0f || g_depth[p] >= 1.0f || colour_depth[p] != g_depth[p]) continue;
        ++both;
        moved += std::fabs(a[0]) + std::fabs(a[1]) > 1e-3f ? 1u : 0u;
        equal += std::fabs(a[0] - b[0]) <= 1e-5f && std::fabs(a[1] - b[1]) <= 1e-5f ? 1u : 0u;
    }
    EXPECT_GT(both, n / 5) << "grass pixels at the same depth in both views";
    EXPECT_GT(moved * 2, both) << "pixels that moved (the test would pass on zeros)";
    EXPECT_GE(equal * 100, both * 99) << equal << " of " << both << " pixels with the motion view's velocity";
    EXPECT_EQ(ba_changed, 0u) << "velocity pixels whose .ba grass wrote";
}

// How far from 1 a normal's length may be: the rounding of three 8-bit channels moves it by
// at most sqrt(3) * 0.5 / 127.5 = 0.007 (a 4-sample resolve of one surface's normals rounds
// once more: 0.014); 0.03 leaves room.
constexpr double kUnitTolerance = 0.03;

// What a four-attachment G-buffer holds: `byte(a, p, c)` the stored byte of attachment `a`,
// pixel `p`, channel `c`; `before(a, p, c)` what it held before grass drew; `grass(p)`
// whether grass drew pixel p (its depth; multisampled: every sample of it); `touched(p)`
// (multisampled: some sample of it; empty: grass(p)) where grass may have written.
// `mean_normals`: a pixel's normal is the resolve's mean of its samples' unit normals, of
// several surfaces (4-sample blades: a pixel holds several blades at angles of their own), so
// no longer than 1 (within kUnitTolerance) but not unit length; else it is unit length.
struct GBufferRead {
    size_t pixels = 0;
    std::function<uint8_t(int, size_t, int)> byte;
    std::function<uint8_t(int, size_t, int)> before;
    std::function<bool(size_t)> grass;
    std::function<bool(size_t)> touched;
    bool mean_normals = false;
};

// Where no depth is read back (a multisampled target, or Vulkan's dynamic rendering), the
// material attachment (2) tells where grass drew: *g's grass(p) where it holds grass's 255,
// 64 (in every sample: the resolve of a partly covered pixel falls between that and the
// clear), touched(p) where it differs from what it held before. `g` must outlive its use.
inline void by_material(GBufferRead* g) {
    g->grass = [g](size_t p) { return g->byte(2, p, 0) == 255 && g->byte(2, p, 1) == 64; };
    g->touched = [g](size_t p) {
        return g->byte(2, p, 0) != g->before(2, p, 0) || g->byte(2, p, 1) != g->before(2, p, 1);
    };
}

// The byte channel `c` of attachment `a` is cleared to where the tests clear the G-buffer
// (the material's .rg are not grass's 255, 64, as by_material needs).
inline uint8_t gbuffer_clear_byte(int a, int c) { return static_cast<uint8_t>(17 + 40 * a + 11 * c); }

// Per pixel of grass: the albedo grass-coloured (green above red and blue), the normal unit
// length and facing `eye` from `at` (roughly: the view axis reversed), the material 255, 64
// (roughness 1, translucency 0.25); and every byte grass must not write (attachment 3, albedo
// and normal .a, material .ba, every pixel grass did not touch) as it was. `name`: the tier.
inline void expect_surface(const GBufferRead& g, const double eye[3], const double at[3], const char* name) {
    double to_camera[3] = {eye[0] - at[0], eye[1] - at[1], eye[2] - at[2]};
    const double len =
        std::sqrt(to_camera[0] * to_camera[0] + to_camera[1] * to_camera[1] + to_camera[2] * to_camera[2]);
    for (double& c : to_camera) c /= len;
    double shortest = 2.0, mean_length = 0.0;
    size_t grass = 0, green = 0, unit = 0, facing = 0, material = 0, kept = 0, changed = 0;
    for (size_t p = 0; p < g.pixels; ++p) {
        const bool here = g.grass(p), touched = g.touched ? g.touched(p) : here;
        for (int a = 0; a < 4; ++a) {
            for (int c = 0; c < 4; ++c) {
                if (touched && (a == 0 || a == 1 ? c < 3 : a == 2 ? c < 2 : false)) continue; // written
                ++kept;
                changed += g.byte(a, p, c) != g.before(a, p, c) ? 1u : 0u;
            }
        }
        if (!here) continue;
        ++grass;
        green += g.byte(0, p, 1) > g.byte(0, p, 0) && g.byte(0, p, 1) > g.byte(0, p, 2) ? 1u : 0u;
        double n2 = 0.0, dot = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double v = g.byte(1, p, c) / 255.0 * 2.0 - 1.0;
            n2 += v * v;
            dot += v * to_camera[c];
        }
        const double length = std::sqrt(n2);
        unit += (g.mean_normals ? length <= 1.0 + kUnitTolerance : std::fabs(length - 1.0) < kUnitTolerance) ? 1u : 0u;
        shortest = std::min(shortest, length);
        mean_length += length;
        facing += dot > 0.0 ? 1u : 0u;
        material += g.byte(2, p, 0) == 255 && g.byte(2, p, 1) == 64 ? 1u : 0u;
    }
    std::printf("%s: %zu of %zu pixels grass; green albedo %zu, unit normals %zu (shortest %.3f, mean %.3f), facing "
                "%zu\n",
                name, grass, g.pixels, green, unit, shortest, mean_length / double(grass ? grass : 1), facing);
    EXPECT_GT(grass, g.pixels / 5) << name << ": grass pixels";
    EXPECT_EQ(changed, 0u) << name << ": of " << kept << " bytes grass must not write";
    EXPECT_GE(green * 100, grass * 95) << name << ": green albedo, " << green << " of " << grass;
    EXPECT_GE(unit * 100, grass * 98) << name << ": unit normals, " << unit << " of " << grass;
    EXPECT_GE(facing * 100, grass * 90) << name << ": normals facing the camera, " << facing << " of " << grass;
    EXPECT_EQ(material, grass) << name << ": roughness 1 and translucency 0.25";
}

// The fixture of GBufferTest (GL) and GBufferVkTest.
class GBufferFixture : public RenderTest {
protected:
    // Per tier (a 16 x 16-cell field of it alone, destroyed after): `check(kind, name, v)`, v
    // the G-buffer view of the four-attachment layout from `eye` to `at`.
    void each_tier(const double eye[3], const double at[3],
                   const std::function<void(grass_tier_kind, const char*, const grass_view_desc&)>& check) {
        const grass_tier_kind kinds[3] = {GRASS_TIER_GEOMETRY, GRASS_TIER_VOLUME, GRASS_TIER_IMAGE};
        const char* const names[3] = {"geometry", "volume", "image"};
        for (int k = 0; k < 3; ++k) {
            const grass_field_id field =
                make_field(solo_tier_field(16, kinds[k], kinds[k] == GRASS_TIER_VOLUME ? 2u : 0u, 4));
            grass_view_gbuffer_desc layout = four_attachments();
            grass_view_pass_desc pass = gbuffer_pass(&layout);
            grass_view_desc v = view(eye, at);
            v.next = &pass;
            check(kinds[k], names[k], v);
            EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
        }
    }
};

} // namespace grass_test
