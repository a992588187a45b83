// The sample tools' scene files (samples/common/scene.*, docs/scene-format.md): what a scene
// file that leaves a setting out starts from. Nothing is rendered.
#include "scene.hpp"

#include <gtest/gtest.h>

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
