// Responsive grass in the frame plan: still grass costs nothing; wind and gravity set the
// wind variant on every draw and their uniforms as docs/responsive.md gives them; the
// interaction map is made at the first frame with colliders and its windows follow the camera.
#include "dynamics_fixture.hpp"

#include "context/backend.hpp"
#include "dynamics/wind.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>

namespace {

// The responsive part of the Frame block (from `wind` on) is all zero.
bool responsive_uniforms_zero(const grass::FrameUniforms& f) {
    const char* p = reinterpret_cast<const char*>(&f);
    for (size_t i = offsetof(grass::FrameUniforms, wind); i < sizeof(f); ++i) {
        if (p[i] != 0) return false;
    }
    return true;
}

constexpr uint32_t kDynamicsBits = grass::kFeatureWind | grass::kFeatureInteraction;

class DynamicsPlanTest : public DynamicsTest {
protected:
    // Every draw's feature bits past the maps' (all draws must agree), and tiling[3] checked.
    uint32_t dynamics_bits() {
        EXPECT_FALSE(plan().draws.empty());
        uint32_t bits = 0xffffffffu;
        for (const auto& d : plan().draws) {
            EXPECT_EQ(d.features, d.uniforms.tiling[3]);
            const uint32_t b = d.features & kDynamicsBits;
            if (bits != 0xffffffffu) {
                EXPECT_EQ(b, bits);
            }
            bits = b;
        }
        return bits;
    }
};

TEST_F(DynamicsPlanTest, StillGrassCostsNothing) {
    // A context that never had wind, colliders or a gravity change, then one whose wind is
    // set to its default (still) values: no variant bit, no pass, no uniforms, no memory.
    const grass_wind_desc still = grass_default_wind_desc();
    for (int round = 0; round < 2; ++round) {
        if (round == 1) {
            ASSERT_EQ(grass_set_wind(ctx, &still), GRASS_SUCCESS);
            ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS);
        }
        for (int k = 0; k < 3; ++k) ASSERT_EQ(frame(1.0 + k * 0.5), GRASS_SUCCESS) << last_message();
        EXPECT_EQ(dynamics_bits(), 0u);
        EXPECT_EQ(plan().interaction.levels, 0u);
        EXPECT_TRUE(plan().interaction.colliders.empty());
        EXPECT_TRUE(responsive_uniforms_zero(plan().frame));
        EXPECT_EQ(plan().stats.interaction_texels, 0u);
        EXPECT_EQ(plan().stats.colliders, 0u);
        EXPECT_EQ(backend->curve_uploads, 0u);
        grass_memory_stats m{};
        ASSERT_EQ(grass_get_memory_stats(ctx, &m), GRASS_SUCCESS);
        EXPECT_EQ(m.dynamics_gpu_bytes, 0u);
    }
    EXPECT_EQ(plan().stats.time_step, 0.5); // the clock runs all the same
}

TEST_F(DynamicsPlanTest, WindOrGravitySetTheWindVariantOnEveryDraw) {
    grass_wind_desc w = grass_default_wind_desc();
    w.speed = 3.0f;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.0), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(dynamics_bits(), grass::kFeatureWind);
    EXPECT_EQ(plan().interaction.levels, 0u); // no colliders: no map
    // The patch's blade curves went to the backend once, and count as dynamics memory.
    EXPECT_EQ(backend->curve_uploads, 1u);
    ASSERT_EQ(frame(2.0), GRASS_SUCCESS);
    EXPECT_EQ(backend->curve_uploads, 1u);
    grass_memory_stats m{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &m), GRASS_SUCCESS);
    EXPECT_EQ(m.dynamics_gpu_bytes, 384u * 8 * sizeof(float)); // the default patch's 384 blades
    EXPECT_EQ(m.gpu_bytes, m.dynamics_gpu_bytes);
    // Gravity alone, and a source alone.
    w = grass_default_wind_desc();
    w.gravity[1] = -3.0f;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS);
    ASSERT_EQ(frame(3.0), GRASS_SUCCESS);
    EXPECT_EQ(dynamics_bits(), grass::kFeatureWind);
    EXPECT_FLOAT_EQ(plan().frame.gravity[1], 9.81f - 3.0f);
    grass_wind_source s{};
    s.kind = GRASS_WIND_SOURCE_POINT;
    s.speed = 10.0f;
    s.radius = 3.0f;
    w = grass_default_wind_desc();
    w.sources = &s;
    w.source_count = 1;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS);
    ASSERT_EQ(frame(4.0), GRASS_SUCCESS);
    EXPECT_EQ(dynamics_bits(), grass::kFeatureWind);
    // NULL: still grass again.
    ASSERT_EQ(grass_set_wind(ctx, nullptr), GRASS_SUCCESS);
    ASSERT_EQ(frame(5.0), GRASS_SUCCESS);
    EXPECT_EQ(dynamics_bits(), 0u);
    EXPECT_TRUE(responsive_uniforms_zero(plan().frame));
}

TEST_F(DynamicsPlanTest, WindUniformsAreTheDocumentedFormulas) {
    grass_wind_desc w = grass_default_wind_desc();
    w.direction[0] = 3.0f, w.direction[1] = 0.0f, w.direction[2] = 4.0f; // unit (0.6, 0, 0.8)
    w.speed = 7.0f;
    w.gust_strength = 1.5f;
    w.gust_length = 20.0f;
    w.turbulence = 0.4f;
    grass_wind_source src[3]{};
    src[0].kind = GRASS_WIND_SOURCE_POINT;
    src[1].kind = GRASS_WIND_SOURCE_CONE;
    src[2].kind = GRASS_WIND_SOURCE_BLAST;
    for (auto& s : src) {
        s.position[0] = 1e6 + 5.0, s.position[1] = 30.0, s.position[2] = -2e6 - 7.0;
        s.direction[0] = 0.0f, s.direction[1] = -2.0f, s.direction[2] = 0.0f;
        s.cone_angle = 0.6f, s.speed = 25.0f, s.radius = 4.0f;
        s.start_time = 1000.0, s.duration = 3.0f, s.front_speed = 12.0f;
    }
    w.sources = src;
    w.source_count = 3;
    ASSERT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS);
    // A camera far from the origin at a late time: the phases need double precision.
    const double eye[3] = {1e6, 3.0, -2e6};
    const double time = 1001.25;
    ASSERT_EQ(frame(time, eye), GRASS_SUCCESS) << last_message();
    const grass::FrameUniforms& f = plan().frame;
    EXPECT_FLOAT_EQ(f.wind[0], 0.6f * 7.0f);
    EXPECT_FLOAT_EQ(f.wind[1], 0.0f);
    EXPECT_FLOAT_EQ(f.wind[2], 0.8f * 7.0f);
    EXPECT_FLOAT_EQ(f.wind[3], 1.5f);
    EXPECT_FLOAT_EQ(f.wind_shape[0], 1.0f / 20.0f);
    EXPECT_FLOAT_EQ(f.wind_shape[1], 0.4f);
    EXPECT_EQ(f.wind_shape[2], 3.0f);
    EXPECT_EQ(f.wind_shape[3], 0.0f); // the first frame steps 0
    const double lambda[3] = {20.0, 20.0 * 0.618034, 20.0 * 0.381966};
    const double speed[3] = {7.0, 7.0 * 1.13, 7.0 * 0.87}, offset[3] = {0.0, 0.37, 0.71};
    const double along = eye[0] * 0.6 + eye[2] * 0.8;
    for (int k = 0; k < 3; ++k) {
        const double x = along / lambda[k] - time * speed[k] / lambda[k] + offset[k];
        EXPECT_NEAR(f.wind_phase[k], x - std::floor(x), 1e-6) << k;
    }
    // cross(up, dir) = (0,1,0) x (0.6,0,0.8) = (0.8, 0, -0.6).
    const double cross = eye[0] * 0.8 - eye[2] * 0.6, y = cross / 10.0;
    EXPECT_NEAR(f.wind_phase[3], y - std::floor(y), 1e-6);
    for (int k = 0; k < 3; ++k) {
        const float(&s)[4][4] = f.wind_sources[k];
        EXPECT_FLOAT_EQ(s[0][0], 5.0f); // relative to the camera
        EXPECT_FLOAT_EQ(s[0][1], 27.0f);
        EXPECT_FLOAT_EQ(s[0][2], -7.0f);
        EXPECT_EQ(s[0][3], float(k));
        EXPECT_FLOAT_EQ(s[2][0], 25.0f);
        EXPECT_FLOAT_EQ(s[2][1], 4.0f);
    }
    EXPECT_FLOAT_EQ(f.wind_sources[1][1][1], -1.0f); // the cone's unit axis
    EXPECT_FLOAT_EQ(f.wind_sources[1][1][3], std::cos(0.6f));
    EXPECT_FLOAT_EQ(f.wind_sources[2][2][2], 1.25f); // seconds since the blast
    EXPECT_FLOAT_EQ(f.wind_sources[2][2][3], 3.0f);
    EXPECT_FLOAT_EQ(f.wind_sources[2][3][0], 12.0f);
    EXPECT_EQ(f.wind_sources[3][2][0], 0.0f); // past the count: zero
    ASSERT_EQ(frame(time + 0.125, eye), GRASS_SUCCESS);
    EXPECT_EQ(plan().frame.wind_shape[3], 0.125f);
}

TEST_F(DynamicsPlanTest, TheMapIsMadeAtTheFirstFrameWithCollidersAndFollowsTheCamera) {
    ASSERT_EQ(frame(1.0), GRASS_SUCCESS);
    EXPECT_EQ(plan().interaction.levels, 0u);
    const grass_collider c = sphere(2.0, 0.1, 3.0, 0.3f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    double eye[3] = {2.0, 3.0, 2.0};
    ASSERT_EQ(frame(1.5, eye), GRASS_SUCCESS);
    const grass::InteractionPlan& ip = plan().interaction;
    ASSERT_EQ(ip.levels, 2u);
    EXPECT_TRUE(ip.map_is_new);
    EXPECT_EQ(ip.level[0].counts[3], 1u); // a new map is cleared
    EXPECT_EQ(dynamics_bits(), grass::kFeatureInteraction);
    for (const auto& d : plan().draws) EXPECT_EQ(d.uniforms.trample[2], 1.0f);
    EXPECT_EQ(plan().stats.colliders, 1u);
    EXPECT_EQ(plan().stats.colliders_in_map, 1u);
    EXPECT_EQ(plan().stats.interaction_texels, 2u * 256 * 256);
    EXPECT_EQ(plan().frame.map_up[3], 2.0f);
    EXPECT_EQ(plan().frame.map_axis_v[3], 0.0f); // the anchor is at the camera
    EXPECT_EQ(backend->curve_uploads, 1u);
    grass_memory_stats m{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &m), GRASS_SUCCESS);
    EXPECT_EQ(m.dynamics_gpu_bytes, 2u * 256 * 256 * 16 + 384u * 32);
    // Level 0: 0.05 m texels. The camera at u = 2.0 m is world texel 40; W = 40 - 128.
    for (int level = 0; level < 2; ++level) {
        const double texel = level == 0 ? double(0.05f) : double(1.0f); // the desc's floats
        const auto& lu = ip.level[level];
        const int64_t k = static_cast<int64_t>(std::floor(2.0 / texel)), w = k - 128;
        EXPECT_EQ(lu.window[0], ((w % 256) + 256) % 256) << level;
        EXPECT_NEAR(lu.origin[0], w * texel - 2.0, 1e-5) << level;
        EXPECT_FLOAT_EQ(lu.origin[2], float(texel));
        EXPECT_EQ(lu.counts[0], 256u);
        EXPECT_EQ(lu.counts[1], 16u);
        EXPECT_EQ(lu.counts[2], 16u);
        EXPECT_NEAR(plan().frame.map_levels[level][0], std::fmod(2.0 / texel, 256.0), 1e-4);
        EXPECT_FLOAT_EQ(plan().frame.map_levels[level][2], float(1.0 / texel));
        EXPECT_FLOAT_EQ(lu.least_radius[0], level == 0 ? 0.0f : float(0.7072 * texel)); // coarse: half a diagonal
    }
    // The next frame: not new, not cleared; a move of 3 level-0 texels along u shifts by 3.
    eye[0] += 0.15;
    ASSERT_EQ(frame(2.0, eye), GRASS_SUCCESS);
    EXPECT_FALSE(ip.map_is_new);
    EXPECT_EQ(ip.level[0].counts[3], 0u);
    EXPECT_EQ(ip.level[0].window[2], 3);
    EXPECT_EQ(ip.level[0].window[3], 0);
    EXPECT_EQ(ip.level[1].window[2], 0);
    // A move of 1 km: the shift is clamped to N (everything leaves the window).
    eye[2] -= 1000.0;
    ASSERT_EQ(frame(2.5, eye), GRASS_SUCCESS);
    EXPECT_EQ(ip.level[0].window[3], -256);
    EXPECT_EQ(ip.level[1].window[3], -256);
    EXPECT_EQ(plan().stats.colliders_in_map, 0u); // the collider stayed behind
    EXPECT_EQ(plan().stats.colliders, 1u);
    eye[2] += 1000.0; // back over the field
    ASSERT_EQ(frame(2.75, eye), GRASS_SUCCESS);
    EXPECT_EQ(ip.level[0].window[3], 256);
    // Colliders gone: the map stays (trails recover), the pass goes on.
    ASSERT_EQ(grass_set_colliders(ctx, nullptr, 0), GRASS_SUCCESS);
    ASSERT_EQ(frame(3.0, eye), GRASS_SUCCESS);
    EXPECT_EQ(ip.levels, 2u);
    EXPECT_EQ(dynamics_bits(), grass::kFeatureInteraction);
    // grass_set_interaction: no map until the next frame with colliders, which makes it anew.
    grass_interaction_desc d = grass_default_interaction_desc();
    d.resolution = 64;
    d.level_count = 1;
    ASSERT_EQ(grass_set_interaction(ctx, &d), GRASS_SUCCESS);
    ASSERT_EQ(frame(3.5, eye), GRASS_SUCCESS);
    EXPECT_EQ(ip.levels, 0u);
    EXPECT_EQ(dynamics_bits(), 0u);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(4.0, eye), GRASS_SUCCESS);
    EXPECT_EQ(ip.levels, 1u);
    EXPECT_TRUE(ip.map_is_new);
    EXPECT_EQ(ip.level[0].counts[3], 1u);
    EXPECT_EQ(plan().stats.interaction_texels, 64u * 64);
}

// grass.h "Frames and views": the frame steps once, at view 0, whose camera moves the map; a
// later view (a shadow camera 20 m up and 5 m aside) reads view 0's map from its own camera
// (FrameUniforms::map_offset) and plans no pass; the next frame's window moves from view 0's.
TEST_F(DynamicsPlanTest, LaterViewsOfAFrameReadTheMapOfView0) {
    const grass_collider c = sphere(2.0, 0.1, 3.0, 0.3f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    grass_wind_desc wind = grass_default_wind_desc();
    wind.speed = 4.0f;
    ASSERT_EQ(grass_set_wind(ctx, &wind), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(frame(1.0), GRASS_SUCCESS); // the map is made around (2, 3, 2)
    const double main_eye[3] = {2.0, 3.0, 2.0}, shadow_eye[3] = {7.0, 23.0, 2.5};
    grass_frame_desc f = grass_default_frame_desc();
    f.frame_index = 10;
    f.time = 1.5;
    ASSERT_EQ(grass_begin_host_frame(ctx, &f), GRASS_SUCCESS) << last_message();
    const grass_view_desc main_view = view_at(main_eye, 99.0); // the frame's time wins
    const grass_view_desc shadow = view_at(shadow_eye, 99.0);
    uint32_t i0 = 9, i1 = 9;
    ASSERT_EQ(grass_plan_view(ctx, &main_view, &i0), GRASS_SUCCESS) << last_message();
    ASSERT_EQ(grass_plan_view(ctx, &shadow, &i1), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(i0, 0u);
    EXPECT_EQ(i1, 1u);
    const grass::FramePlan& p0 = ctx->views.plan(0);
    const grass::FramePlan& p1 = ctx->views.plan(1);
    EXPECT_EQ(&p0, &plan());
    EXPECT_DOUBLE_EQ(p0.stats.time_step, 0.5);
    EXPECT_DOUBLE_EQ(p1.stats.time_step, 0.5);
    EXPECT_FLOAT_EQ(p0.frame.params[0], 1.5f);
    EXPECT_FLOAT_EQ(p1.frame.params[0], 1.5f);
    EXPECT_TRUE(p0.interaction.pass);
    EXPECT_FALSE(p1.interaction.pass);
    EXPECT_TRUE(p1.interaction.colliders.empty());
    EXPECT_EQ(p1.interaction.levels, p0.interaction.levels);
    EXPECT_EQ(0, std::memcmp(p1.frame.map_levels, p0.frame.map_levels, sizeof p0.frame.map_levels));
    EXPECT_EQ(0, std::memcmp(p1.frame.map_axis_v, p0.frame.map_axis_v, sizeof p0.frame.map_axis_v));
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(p0.frame.map_offset[k], 0.0f);
        EXPECT_FLOAT_EQ(p1.frame.map_offset[k], float(shadow_eye[k] - main_eye[k])) << k;
    }
    // Both views draw the responsive variants; the wind is the frame's, from each camera.
    for (const auto& d : p1.draws) EXPECT_EQ(d.features & grass::kFeatureInteraction, grass::kFeatureInteraction);
    EXPECT_NE(0, std::memcmp(p0.frame.wind_phase, p1.frame.wind_phase, sizeof p0.frame.wind_phase));
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    // The shadow camera moved nothing: view 0 back at the main camera shifts no texel.
    ASSERT_EQ(frame(2.0, main_eye), GRASS_SUCCESS);
    EXPECT_EQ(plan().interaction.level[0].window[2], 0);
    EXPECT_EQ(plan().interaction.level[0].window[3], 0);
    EXPECT_DOUBLE_EQ(plan().stats.time_step, 0.5);
}

TEST_F(DynamicsPlanTest, FarAlongUpTheMapIsReanchoredAndCleared) {
    const grass_collider c = sphere(2.0, 0.1, 3.0, 0.3f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    double eye[3] = {2.0, 3.0, 2.0};
    ASSERT_EQ(frame(1.0, eye), GRASS_SUCCESS);
    eye[1] = 3.0 + 9999.0; // within 1e4 m of the anchor: kept
    ASSERT_EQ(frame(1.1, eye), GRASS_SUCCESS);
    EXPECT_EQ(plan().interaction.level[0].counts[3], 0u);
    EXPECT_FLOAT_EQ(plan().frame.map_axis_v[3], 9999.0f);
    eye[1] = 3.0 + 10001.0; // beyond: a new anchor at the camera, the map cleared
    ASSERT_EQ(frame(1.2, eye), GRASS_SUCCESS);
    EXPECT_EQ(plan().interaction.level[0].counts[3], 1u);
    EXPECT_EQ(plan().interaction.level[1].counts[3], 1u);
    EXPECT_EQ(plan().frame.map_axis_v[3], 0.0f);
    EXPECT_FALSE(plan().interaction.map_is_new); // the same textures
    // The collider's height is above the new anchor.
    ASSERT_EQ(plan().interaction.colliders.size(), 1u);
    EXPECT_FLOAT_EQ(plan().interaction.colliders[0].a[2], float(0.1 - (3.0 + 10001.0)));
}

TEST_F(DynamicsPlanTest, AFieldTiltedAwayFromTheMapsUpDoesNotReadIt) {
    // A second field, rotated 70 degrees about x: its up is 70 degrees from the map's.
    grass_field_desc d = one_tier_field(patch, 4, &tier, &band);
    const double a = 70.0 * 3.14159265358979 / 180.0;
    d.base_transform[5] = std::cos(a), d.base_transform[6] = std::sin(a);
    d.base_transform[9] = -std::sin(a), d.base_transform[10] = std::cos(a);
    d.base_transform[12] = 1.5, d.base_transform[14] = 2.5; // in view, under the camera
    grass_field_id tilted{};
    ASSERT_EQ(grass_create_field(ctx, &d, &tilted), GRASS_SUCCESS) << last_message();
    grass_blade_mechanics m = grass_default_blade_mechanics();
    m.stiffness = 123.0f, m.mass = 2.5f, m.wind_response = 7.0f, m.variation = 0.5f;
    m.trample_depth = 0.8f, m.recovery_time = 9.0f;
    ASSERT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS);
    const grass_collider c = sphere(2.0, 0.1, 3.0, 0.3f);
    ASSERT_EQ(grass_set_colliders(ctx, &c, 1), GRASS_SUCCESS);
    ASSERT_EQ(frame(1.0), GRASS_SUCCESS) << last_message();
    int flat = 0, steep = 0;
    for (const auto& draw : plan().draws) {
        const bool reads = draw.field_slot == field.index - 1;
        EXPECT_EQ((draw.features & grass::kFeatureInteraction) != 0, reads);
        EXPECT_EQ(draw.uniforms.trample[2], reads ? 1.0f : 0.0f);
        (reads ? flat : steep) += 1;
        EXPECT_NEAR(draw.uniforms.field_up[1], reads ? 1.0f : std::cos(a), 1e-6);
        EXPECT_FLOAT_EQ(draw.uniforms.field_up[3], 0.25f); // metres per patch unit
        EXPECT_EQ(draw.uniforms.mechanics[0], 123.0f);
        EXPECT_EQ(draw.uniforms.mechanics[1], 2.5f);
        EXPECT_EQ(draw.uniforms.mechanics[2], 7.0f);
        EXPECT_EQ(draw.uniforms.mechanics[3], 0.5f);
        EXPECT_EQ(draw.uniforms.trample[0], 0.8f);
        EXPECT_EQ(draw.uniforms.trample[1], 9.0f);
    }
    EXPECT_GT(flat, 0);
    EXPECT_GT(steep, 0);
}

} // namespace
