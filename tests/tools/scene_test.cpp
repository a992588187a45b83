// The tools' scene files (tools/scene/scene.*, docs/scene-format.md): what a scene
// file that leaves a setting out starts from. Nothing is rendered.
#include "scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

// Writes `text` to a scene file of the test's own and loads it over the demo.
grass_sample::Scene load(const std::string& name, const std::string& text) {
    const std::string path = testing::TempDir() + "grass_scene_test_" + name + ".json";
    std::ofstream(path) << text;
    grass_sample::Scene scene = grass_sample::demo_scene();
    std::string error;
    EXPECT_TRUE(grass_sample::load_scene(path, &scene, &error)) << error;
    std::remove(path.c_str());
    return scene;
}

// The demo's winding path of thin grass belongs to its lawn. A scene file without a
// "density_map" inherited it, stretched over its own field: in a low view of a large field
// with no ground the far tiers showed the clear colour along an arc through the thin grass,
// over a ground a darker seam, which were taken for artefacts of the tiers (issue 12).
TEST(SceneFile, StartsFromUniformDensity) {
    ASSERT_FALSE(grass_sample::demo_scene().density_texels.empty()) << "the demo has its path (not vacuous)";
    const grass_sample::Scene scene = load("no_density", R"({"field": {"cells": [80, 80]}})");
    EXPECT_TRUE(scene.density_texels.empty());
    EXPECT_EQ(scene.density_width, 0u);
    EXPECT_EQ(scene.density_height, 0u);
    EXPECT_EQ(scene.field.cells_x, 80u);
    // The demo's lod setup does not carry over either: the library's default tiers.
    EXPECT_TRUE(scene.tiers.empty());
    EXPECT_TRUE(scene.lod_tests.empty());
}

// What a scene file does give is kept: other settings still start from the demo's.
TEST(SceneFile, KeepsWhatItGives) {
    const grass_sample::Scene scene =
        load("camera", R"({"camera": {"position": [1, 2, 3]}, "field": {"density": 0.5}})");
    EXPECT_EQ(scene.eye[0], 1.0);
    EXPECT_EQ(scene.eye[1], 2.0);
    EXPECT_EQ(scene.eye[2], 3.0);
    EXPECT_FLOAT_EQ(scene.field.density, 0.5f);
    EXPECT_TRUE(scene.density_texels.empty());
    const grass_sample::Scene demo = grass_sample::demo_scene();
    EXPECT_EQ(scene.patch.blade_count, demo.patch.blade_count);
    EXPECT_EQ(scene.target[2], demo.target[2]);
}

} // namespace

namespace {

// Responsive grass (docs/responsive.md): a file without its keys is still grass, as before.
TEST(SceneFile, WithoutResponsiveKeysIsStillGrass) {
    const grass_sample::Scene scene = load("still", R"({"field": {"cells": [8, 8]}})");
    EXPECT_FALSE(scene.responsive.any());
    EXPECT_TRUE(grass_sample::colliders_at(scene.responsive, 1.0, 0.1).empty());
}

// The wind (with a moving source), the interaction map, the mechanics and colliders on
// paths are read into the desc fields the API takes.
TEST(SceneFile, ReadsWindMapMechanicsAndColliders) {
    const grass_sample::Scene scene = load("responsive", R"({
      "patch": {"mechanics": {"stiffness": 60, "mass": 2, "wind_response": 3, "trample_depth": 0.8,
                              "recovery_time": 6, "variation": 0.1}},
      "wind": {"direction": [0, 0, 1], "speed": 5, "gust_strength": 1.2, "gust_length": 20, "turbulence": 0.5,
               "gravity": [0, -5, 0],
               "sources": [{"kind": "point", "position": {"from": [0, 8, 0], "to": [30, 8, 0], "speed": 10},
                            "speed": 40, "radius": 6},
                           {"kind": "blast", "position": [1, 2, 3], "speed": 9, "radius": 2, "start_time": 1.5,
                            "duration": 2, "front_speed": 20}]},
      "interaction": {"up": [0, 1, 0], "resolution": 512, "levels": 1, "texel_size": [0.1]},
      "colliders": [{"shape": "sphere", "radius": 0.3, "centre": {"from": [0, 0.3, 0], "to": [10, 0.3, 0], "speed": 2}},
                    {"shape": "capsule", "radius": 0.07, "centre": [0, 0.9, 0],
                     "end": {"keyframes": [[0, 0, 0.07, 0], [1, 1, 0.2, 0], [2, 2, 0.07, 0]]}}]
    })");
    const grass_sample::Responsive& r = scene.responsive;
    ASSERT_TRUE(r.any());
    EXPECT_TRUE(r.mechanics_given);
    EXPECT_FLOAT_EQ(r.mechanics.stiffness, 60.0f);
    EXPECT_FLOAT_EQ(r.mechanics.recovery_time, 6.0f);
    EXPECT_FLOAT_EQ(r.mechanics.trample_depth, 0.8f);
    EXPECT_TRUE(r.wind_given);
    EXPECT_FLOAT_EQ(r.wind.speed, 5.0f);
    EXPECT_FLOAT_EQ(r.wind.gravity[1], -5.0f);
    EXPECT_FLOAT_EQ(r.wind.gust_length, 20.0f);
    EXPECT_EQ(r.interaction.resolution, 512u);
    EXPECT_EQ(r.interaction.level_count, 1u);
    EXPECT_FLOAT_EQ(r.interaction.texel_size[0], 0.1f);
    // The helicopter flies at 10 m/s from x = 0: at 1.5 s it is at x = 15, and stays at the
    // line's end after 3 s.
    ASSERT_EQ(r.sources.size(), 2u);
    auto sources = grass_sample::wind_sources_at(r, 1.5);
    EXPECT_EQ(sources[0].kind, GRASS_WIND_SOURCE_POINT);
    EXPECT_DOUBLE_EQ(sources[0].position[0], 15.0);
    EXPECT_DOUBLE_EQ(sources[0].position[1], 8.0);
    EXPECT_FLOAT_EQ(sources[0].speed, 40.0f);
    EXPECT_EQ(sources[1].kind, GRASS_WIND_SOURCE_BLAST);
    EXPECT_DOUBLE_EQ(sources[1].start_time, 1.5);
    EXPECT_FLOAT_EQ(sources[1].front_speed, 20.0f);
    EXPECT_DOUBLE_EQ(grass_sample::wind_sources_at(r, 100.0)[0].position[0], 30.0);
    // The ball rolls at 2 m/s: at 2 s it is at x = 4 and moved 0.2 m over the last 0.1 s.
    const auto colliders = grass_sample::colliders_at(r, 2.0, 0.1);
    ASSERT_EQ(colliders.size(), 2u);
    EXPECT_EQ(colliders[0].shape, GRASS_COLLIDER_SPHERE);
    EXPECT_DOUBLE_EQ(colliders[0].center[0], 4.0);
    EXPECT_NEAR(colliders[0].velocity[0], 2.0f, 1e-4f);
    EXPECT_FLOAT_EQ(colliders[0].velocity[1], 0.0f);
    // The leg: its hip stays, its foot follows the keyframes (linear between them); the
    // velocity is the foot's, the end that touches the grass.
    EXPECT_EQ(colliders[1].shape, GRASS_COLLIDER_CAPSULE);
    const auto leg = grass_sample::colliders_at(r, 0.5, 0.5)[1];
    EXPECT_DOUBLE_EQ(leg.center[1], 0.9);
    EXPECT_DOUBLE_EQ(leg.end[0], 0.5);
    EXPECT_NEAR(leg.end[1], 0.135, 1e-12);
    EXPECT_NEAR(leg.velocity[0], 1.0f, 1e-5f);
    EXPECT_NEAR(leg.velocity[1], 0.13f, 1e-5f);
    // Before the first keyframe and after the last, the foot is held.
    EXPECT_DOUBLE_EQ(grass_sample::colliders_at(r, -1.0, 0.1)[1].end[0], 0.0);
    EXPECT_DOUBLE_EQ(grass_sample::colliders_at(r, 9.0, 0.1)[1].end[0], 2.0);
    EXPECT_FLOAT_EQ(grass_sample::colliders_at(r, 9.0, 0.1)[1].velocity[0], 0.0f);
}

// grass-render's --wind and --collider forms.
TEST(SceneFile, CommandLineWindAndColliders) {
    grass_wind_desc wind = grass_default_wind_desc();
    std::string error;
    ASSERT_TRUE(grass_sample::parse_wind("1,0.5,6,0.9", &wind, &error)) << error;
    EXPECT_FLOAT_EQ(wind.direction[2], 0.5f);
    EXPECT_FLOAT_EQ(wind.speed, 6.0f);
    EXPECT_FLOAT_EQ(wind.gust_strength, 0.9f);
    for (const char* bad : {"1,0", "1,0,6,0.9,3", "0,0,6", "1,x,6", "1,0,nan", "1,,6", "1,0,6,"}) {
        const grass_wind_desc before = wind;
        EXPECT_FALSE(grass_sample::parse_wind(bad, &wind, &error)) << bad;
        EXPECT_NE(error.find(std::string("\"") + bad + "\""), std::string::npos) << error;
        EXPECT_FLOAT_EQ(wind.speed, before.speed) << "unchanged after " << bad;
    }
    grass_sample::SceneCollider c;
    ASSERT_TRUE(grass_sample::parse_collider("sphere:1,0.3,2,0.3,2,0,0", 1.0, 3.0, &c, &error)) << error;
    EXPECT_EQ(c.shape, GRASS_COLLIDER_SPHERE);
    EXPECT_FLOAT_EQ(c.radius, 0.3f);
    double p[3];
    c.centre.at(2.0, p);
    EXPECT_DOUBLE_EQ(p[0], 3.0); // 2 m/s for 1 s from x = 1
    ASSERT_TRUE(grass_sample::parse_collider("capsule:0,0.9,0,0,0.1,0,0.08", 0.0, 1.0, &c, &error)) << error;
    EXPECT_EQ(c.shape, GRASS_COLLIDER_CAPSULE);
    c.end.at(0.5, p);
    EXPECT_DOUBLE_EQ(p[1], 0.1);
    for (const char* bad : {"cube:0,0,0,1", "sphere:0,0,0", "sphere:0,0,0,1,2", "capsule:0,0,0,1", "sphere"}) {
        EXPECT_FALSE(grass_sample::parse_collider(bad, 0.0, 1.0, &c, &error)) << bad;
        EXPECT_NE(error.find(std::string("\"") + bad + "\""), std::string::npos) << error;
    }
}

} // namespace

namespace {

// The three responsive sample scenes load and hold what their renders show: a rolling ball,
// two legs whose feet step, a helicopter that flies.
TEST(SceneFile, TheResponsiveSamplesLoad) {
    const std::string dir = GRASS_SCENE_DIR;
    grass_sample::Scene ball, walker, helicopter;
    std::string error;
    ASSERT_TRUE(grass_sample::load_scene(dir + "/football-ball.json", &ball, &error)) << error;
    ASSERT_TRUE(grass_sample::load_scene(dir + "/park-walker.json", &walker, &error)) << error;
    ASSERT_TRUE(grass_sample::load_scene(dir + "/hills-helicopter.json", &helicopter, &error)) << error;

    ASSERT_EQ(ball.responsive.colliders.size(), 1u);
    const auto b0 = grass_sample::colliders_at(ball.responsive, 0.0, 0.1)[0];
    const auto b2 = grass_sample::colliders_at(ball.responsive, 2.0, 0.1)[0];
    EXPECT_EQ(b0.shape, GRASS_COLLIDER_SPHERE);
    EXPECT_NEAR(std::hypot(b2.center[0] - b0.center[0], b2.center[2] - b0.center[2]), 5.2, 1e-9) << "2.6 m/s";
    EXPECT_NEAR(b2.center[1], 0.3, 1e-9) << "on the ground";
    EXPECT_FLOAT_EQ(b0.radius, 0.3f);

    // The legs: capsules whose feet touch the ground in turn (one planted while the other swings).
    ASSERT_EQ(walker.responsive.colliders.size(), 2u);
    for (double t = 0.1; t < 3.0; t += 0.25) {
        const auto legs = grass_sample::colliders_at(walker.responsive, t, 0.05);
        EXPECT_EQ(legs[0].shape, GRASS_COLLIDER_CAPSULE);
        const double low = std::min(legs[0].end[1], legs[1].end[1]), high = std::max(legs[0].end[1], legs[1].end[1]);
        EXPECT_NEAR(low, 0.08, 1e-9) << "a foot is planted at t = " << t;
        EXPECT_GT(high, 0.09) << "the other swings at t = " << t;
    }

    ASSERT_EQ(helicopter.responsive.sources.size(), 1u);
    EXPECT_EQ(helicopter.responsive.sources[0].source.kind, GRASS_WIND_SOURCE_POINT);
    EXPECT_GT(helicopter.responsive.wind.gust_strength, 0.0f);
    const auto s0 = grass_sample::wind_sources_at(helicopter.responsive, 0.0)[0];
    const auto s2 = grass_sample::wind_sources_at(helicopter.responsive, 2.0)[0];
    EXPECT_NEAR(std::hypot(s2.position[0] - s0.position[0], s2.position[2] - s0.position[2]), 9.0, 1e-9) << "4.5 m/s";
}

} // namespace

namespace {

// The wind-map sample: "field.wind_map" reaches the scene's map (an 8-bit RGBA PNG), its
// speed and transform; a field created from it takes the map (grass_set_field_wind_map
// through create_scene_wind_map); a transform of the wrong length is refused by name.
TEST(SceneFile, TheWindMapSampleLoadsItsMap) {
    const std::string dir = GRASS_SCENE_DIR;
    grass_sample::Scene scene;
    std::string error;
    ASSERT_TRUE(grass_sample::load_scene(dir + "/meadow-windmap.json", &scene, &error)) << error;
    const grass_sample::Scene::MapImage& m = scene.wind_map;
    ASSERT_EQ(m.width, 32u);
    ASSERT_EQ(m.height, 32u);
    EXPECT_EQ(m.format, GRASS_MAP_FORMAT_RGBA8_UNORM);
    EXPECT_EQ(m.pixels[(0 * 32 + 5) * 4 + 0], 128) << "calm outside the corridor";
    EXPECT_EQ(m.pixels[(16 * 32 + 5) * 4 + 0], 255) << "+x in the corridor";
    EXPECT_EQ(scene.wind_map_desc.speed, 8.0f);
    for (double v : scene.wind_map_desc.cell_to_map) EXPECT_EQ(v, 0.0);

    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx), GRASS_SUCCESS);
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(ctx, &scene.patch, &patch), GRASS_SUCCESS) << grass_get_last_error(ctx);
    scene.field.patch = patch;
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &scene.field, &field), GRASS_SUCCESS) << grass_get_last_error(ctx);
    grass_wind_map_desc wind{};
    ASSERT_EQ(grass_sample::create_scene_wind_map(ctx, scene, &wind), GRASS_SUCCESS) << grass_get_last_error(ctx);
    EXPECT_EQ(wind.speed, 8.0f);
    ASSERT_FALSE(grass_map_id_is_null(wind.map));
    ASSERT_EQ(grass_sample::set_scene_wind_map(ctx, wind, field), GRASS_SUCCESS) << grass_get_last_error(ctx);
    EXPECT_EQ(grass_destroy_map(ctx, wind.map), GRASS_ERROR_IN_USE) << "the field uses it";
    ASSERT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS);
    EXPECT_EQ(grass_destroy_map(ctx, wind.map), GRASS_SUCCESS);
    grass_destroy_context(ctx);

    const std::string cell_to_map =
        R"({"field": {"wind_map": {"map": ")" + dir +
        R"(/windmap/corridor.png", "speed": 2, "cell_to_map": [0.5, 0, 0, 0.5, 0.25, 0]}}})";
    const grass_sample::Scene t = load("wind_map_transform", cell_to_map);
    EXPECT_EQ(t.wind_map_desc.speed, 2.0f);
    EXPECT_EQ(t.wind_map_desc.cell_to_map[4], 0.25);

    const std::string path = testing::TempDir() + "grass_scene_test_wind_map_bad.json";
    std::ofstream(path) << R"({"field": {"wind_map": {"map": ")" + dir +
                               R"(/windmap/corridor.png", "cell_to_map": [1, 0, 0, 1, 0]}}})";
    grass_sample::Scene bad = grass_sample::demo_scene();
    EXPECT_FALSE(grass_sample::load_scene(path, &bad, &error));
    EXPECT_NE(error.find("field.wind_map.cell_to_map"), std::string::npos) << error;
    std::remove(path.c_str());
}

} // namespace
