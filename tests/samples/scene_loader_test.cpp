// The sample tools' scene loader (samples/common/scene.cpp) with hostile files: the inputs
// fuzz_scene and fuzz_png_map found, kept as regressions.
#include "scene.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

const std::string kCorpus = GRASS_FUZZ_CORPUS_DIR;

std::string write_scene(const std::string& name, const std::string& text) {
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

// A 100-byte PNG whose header claims 100000 x 100000 texels made the loader allocate and
// clear gigabytes (39 s, 1.4 GB) before libpng found the data missing. Now refused at once,
// naming the file and its size, for every map key.
TEST(SceneLoader, APngLargerThanAMapMayBeIsRefusedBeforeItsPixelsAreAllocated) {
    for (const char* key : {R"("maps": {"density": "%s"})", R"("maps": {"color": "%s"})", R"("density_map": "%s")"}) {
        for (const char* file : {"huge-dimensions.png", "one-past-the-limit.png"}) {
            char field[512];
            std::snprintf(field, sizeof(field), key, (kCorpus + "/png_map/" + file).c_str());
            const std::string path = write_scene("big-map.json", std::string(R"({"field": {)") + field + "}}");
            grass_sample::Scene scene;
            std::string error;
            const auto start = std::chrono::steady_clock::now();
            EXPECT_FALSE(grass_sample::load_scene(path, &scene, &error)) << key << " " << file;
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            EXPECT_NE(error.find("a design map is at most 16384 x 16384"), std::string::npos) << error;
            EXPECT_NE(error.find(file), std::string::npos) << error;
            EXPECT_LT(seconds, 1.0) << "refused before decoding";
        }
    }
}

// fuzz_scene: "blade_count": 1e308 went through nlohmann's get<uint32_t>, a plain cast of a
// double no unsigned can hold (undefined behaviour, UBSan's float-cast-overflow). Every
// number is now checked against what its field can hold and refused by name.
TEST(SceneLoader, ANumberItsFieldCannotHoldIsRefusedByName) {
    struct Case {
        const char* text;
        const char* named;
    };
    const Case cases[] = {
        {R"({"patch": {"blade_count": 1e308}})", "\"blade_count\" is 1e+308, out of range"},
        {R"({"patch": {"blade_count": -1}})", "\"blade_count\" is -1, out of range"},
        {R"({"patch": {"blade_count": 2.5}})", "\"blade_count\" is 2.5, out of range"},
        {R"({"patch": {"blade_count": 4294967296}})", "\"blade_count\" is 4294967296, out of range"},
        {R"({"field": {"cells": [1e30, 4]}})", "\"field.cells\" is 1e+30, out of range"},
        {R"({"patch": {"ao_height": 1e300}})", "\"ao_height\" is 1e+300, out of range"},
        {R"({"camera": {"fov": 1e300}})", "\"fov\" is 1e+300, out of range"},
        {R"({"patch": {"blade_count": "many"}})", "\"blade_count\" must be a number, not \"many\""},
    };
    for (const Case& c : cases) {
        const std::string path = write_scene("number-range.json", c.text);
        grass_sample::Scene scene;
        const uint32_t blades_before = scene.patch.blade_count;
        std::string error;
        EXPECT_FALSE(grass_sample::load_scene(path, &scene, &error)) << c.text;
        EXPECT_NE(error.find(c.named), std::string::npos) << c.text << ": " << error;
        EXPECT_EQ(scene.patch.blade_count, blades_before) << c.text;
    }
    // The file fuzz_scene found, kept in its corpus.
    grass_sample::Scene scene;
    std::string error;
    EXPECT_FALSE(grass_sample::load_scene(kCorpus + "/scene/blade-count-1e308.json", &scene, &error));
    EXPECT_NE(error.find("\"blade_count\" is 1e+308, out of range"), std::string::npos) << error;
}

} // namespace
