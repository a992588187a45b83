// The plan of a view lit by the host's lights (grass_view_lights_desc), without a GPU: the
// core decides once that every draw of such a colour view runs the lit variant
// (kFeatureHostLights) and hands the backend the GrassLights block: positions relative to the
// camera in double (a light 1.25 m from a camera 1e7 m out is 1.25 m away, not 1), unit
// directions, a spot's cone as cosines, colour x intensity, the specular and the harmonics;
// a view without it, and a depth pass with it, get none of it.
#include "core_fixture.hpp"
#include "view_helpers.hpp"

#include "context/context.hpp"
#include "foundation/shader_interface.hpp"

#include <cmath>
#include <cstring>

namespace {

class LightsPlanTest : public CoreTest {};

TEST_F(LightsPlanTest, EveryDrawOfALitColourViewAndNoOtherRunsTheLitVariantWithCameraRelativeLights) {
    const grass_patch_id patch = make_patch();
    const grass_tier_desc tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test band{};
    band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    band.end = INFINITY;
    grass_field_desc d = one_tier_field(patch, 16, &tier, &band);
    d.base_transform[12] = 1e7; // the field 1e7 m out along x
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &d, &field), GRASS_SUCCESS) << last_message();

    const double eye[3] = {1e7 + 2.0, 1.5, -1.0}, look[3] = {1e7 + 2.0, 0.0, 2.0};
    const grass_view_desc plain = test_view(eye, look);
    grass_light lights[3] = {grass_default_light(), grass_default_light(), grass_default_light()};
    lights[0].kind = GRASS_LIGHT_DIRECTIONAL;
    lights[0].direction[0] = 3.0f;
    lights[0].direction[1] = 4.0f;
    lights[0].direction[2] = 0.0f;
    lights[0].color[1] = 0.5f;
    lights[0].intensity = 2.0f;
    lights[1].position[0] = 1e7 + 3.25; // 1.25 m right of the camera (float's steps are 1 m there), 1 m up
    lights[1].position[1] = 2.5;
    lights[1].position[2] = -1.0;
    lights[1].range = 7.0f;
    lights[2].kind = GRASS_LIGHT_SPOT;
    lights[2].position[0] = 1e7;
    lights[2].direction[0] = 0.0f;
    lights[2].direction[1] = -2.0f;
    lights[2].direction[2] = 0.0f;
    lights[2].inner_cone_angle = 0.25f;
    lights[2].outer_cone_angle = 0.5f;
    grass_view_lights_desc lit_desc = grass_default_view_lights_desc();
    lit_desc.light_count = 3;
    lit_desc.lights = lights;
    lit_desc.specular_strength = 0.25f;
    lit_desc.specular_exponent = 16.0f;
    lit_desc.ambient_sh_enabled = 1;
    lit_desc.ambient_sh[8][2] = -0.5f;
    grass_view_desc lit = plain;
    lit.next = &lit_desc;
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_DEPTH;
    pass.next = &lit_desc;
    grass_view_desc depth = plain;
    depth.next = &pass;

    plan_frame({&plain, &lit, &depth});
    const grass::FramePlan& a = ctx->views.plan(0);
    const grass::FramePlan& b = ctx->views.plan(1);
    const grass::FramePlan& c = ctx->views.plan(2);
    EXPECT_FALSE(a.host_lights);
    EXPECT_TRUE(b.host_lights);
    EXPECT_FALSE(c.host_lights) << "a depth pass ignores the struct";

    const grass::LightUniforms& u = b.lights;
    EXPECT_EQ(u.counts[0], 3.0f);
    EXPECT_EQ(u.counts[1], 0.25f);
    EXPECT_EQ(u.counts[2], 16.0f);
    EXPECT_EQ(u.counts[3], 1.0f);
    EXPECT_EQ(u.ambient_sh[8][2], -0.5f);
    // Directional: the unit direction towards the light, kind 0, colour x intensity.
    EXPECT_FLOAT_EQ(u.light[0].position_kind[0], 0.6f);
    EXPECT_FLOAT_EQ(u.light[0].position_kind[1], 0.8f);
    EXPECT_EQ(u.light[0].position_kind[3], 0.0f);
    EXPECT_FLOAT_EQ(u.light[0].color_range[1], 1.0f);
    EXPECT_FLOAT_EQ(u.light[0].color_range[0], 2.0f);
    // Point: relative to the camera, exactly (float has 1 m steps at 1e7).
    EXPECT_EQ(u.light[1].position_kind[0], 1.25f);
    EXPECT_EQ(u.light[1].position_kind[1], 1.0f);
    EXPECT_EQ(u.light[1].position_kind[2], 0.0f);
    EXPECT_EQ(u.light[1].position_kind[3], 1.0f);
    EXPECT_EQ(u.light[1].color_range[3], 7.0f);
    // Spot: its unit axis and the cone's cosines.
    EXPECT_EQ(u.light[2].position_kind[0], -2.0f);
    EXPECT_EQ(u.light[2].position_kind[3], 2.0f);
    EXPECT_FLOAT_EQ(u.light[2].axis[1], -1.0f);
    EXPECT_FLOAT_EQ(u.light[2].cone[0], std::cos(0.25f));
    EXPECT_FLOAT_EQ(u.light[2].cone[1], std::cos(0.5f));

    ASSERT_EQ(a.draws.size(), b.draws.size());
    ASSERT_GT(a.draws.size(), 0u);
    for (size_t i = 0; i < a.draws.size(); ++i) {
        EXPECT_EQ(a.draws[i].features & grass::kFeatureHostLights, 0u) << "plain draw " << i;
        EXPECT_EQ(c.draws[i].features & grass::kFeatureHostLights, 0u) << "depth draw " << i;
        EXPECT_EQ(b.draws[i].features, a.draws[i].features | grass::kFeatureHostLights) << "lit draw " << i;
        EXPECT_EQ(b.draws[i].uniforms.tiling[3], b.draws[i].features) << "lit draw " << i;
    }
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
}

} // namespace
