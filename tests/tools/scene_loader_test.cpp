// The tools' scene loader (tools/scene/scene.cpp) with hostile files: the inputs
// fuzz_scene and fuzz_png_map found, kept as regressions.
#include "png_chunks.hpp"
#include "scene.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

const std::string kCorpus = GRASS_FUZZ_CORPUS_DIR;

// In the temporary directory, under the running test's name: ctest runs each test in its
// own process, two at a time, and two tests writing one file raced (one read it empty).
std::string write_scene(const std::string& name, const std::string& text) {
    const std::string path =
        ::testing::TempDir() + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" + name;
    std::ofstream(path) << text;
    return path;
}

// A scene file's text and the words its refusal must hold.
struct Case {
    const char* text;
    const char* named;
};

// Loads the case's file over *scene: refused, with an error that names what is wrong.
void expect_refused(const Case& c, grass_sample::Scene* scene) {
    std::string error;
    EXPECT_FALSE(grass_sample::load_scene(write_scene("refused.json", c.text), scene, &error)) << c.text;
    EXPECT_NE(error.find(c.named), std::string::npos) << c.text << ": " << error;
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

// fuzz_png_map: a 136-byte PNG whose tEXt chunk claims 1,950,701,684 bytes made libpng
// allocate them before reading the chunk (an out-of-memory stop at 2 GB). A chunk that claims
// more than the file has left is refused before libpng sees the file.
TEST(SceneLoader, APngChunkLongerThanItsFileIsRefusedBeforeLibpngAllocatesIt) {
    const std::string file = kCorpus + "/png_map/text-chunk-claims-2gb.png";
    for (const char* key : {R"("maps": {"density": "%s"})", R"("maps": {"color": "%s"})", R"("density_map": "%s")"}) {
        char field[512];
        std::snprintf(field, sizeof(field), key, file.c_str());
        const std::string path = write_scene("long-chunk.json", std::string(R"({"field": {)") + field + "}}");
        grass_sample::Scene scene;
        std::string error;
        EXPECT_FALSE(grass_sample::load_scene(path, &scene, &error)) << key;
        EXPECT_NE(error.find("text-chunk-claims-2gb.png is refused: its chunk \"tEXt\" at byte 33 claims 1950701684 "
                             "bytes; the file has 95 left"),
                  std::string::npos)
            << error;
    }
    const unsigned char bytes[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0,
                                   0,    0,   'I', 'E', 'N',  'D',  1,    2,    3, 4};
    EXPECT_EQ(grass_sample::png_chunk_problem(bytes, sizeof(bytes)), "") << "a chunk that fits";
    EXPECT_NE(grass_sample::png_chunk_problem(bytes, sizeof(bytes) - 1), "") << "its CRC cut off";
}

// fuzz_scene: "blade_count": 1e308 went through nlohmann's get<uint32_t>, a plain cast of a
// double no unsigned can hold (undefined behaviour, UBSan's float-cast-overflow). Every
// number is now checked against what its field can hold and refused by name.
TEST(SceneLoader, ANumberItsFieldCannotHoldIsRefusedByName) {
    const Case cases[] = {
        {R"({"patch": {"blade_count": 1e308}})", "\"patch.blade_count\" is 1e+308, out of range"},
        {R"({"patch": {"blade_count": -1}})", "\"patch.blade_count\" is -1, out of range"},
        {R"({"patch": {"blade_count": 2.5}})", "\"patch.blade_count\" is 2.5, out of range"},
        {R"({"patch": {"blade_count": 4294967296}})", "\"patch.blade_count\" is 4294967296, out of range"},
        {R"({"field": {"cells": [1e30, 4]}})", "\"field.cells\" is 1e+30, out of range"},
        {R"({"patch": {"ao_height": 1e300}})", "\"patch.ao_height\" is 1e+300, out of range"},
        {R"({"camera": {"fov": 1e300}})", "\"camera.fov\" is 1e+300, out of range"},
        {R"({"patch": {"blade_count": "many"}})", "\"patch.blade_count\" must be a number, not \"many\""},
    };
    for (const Case& c : cases) {
        grass_sample::Scene scene;
        const uint32_t blades_before = scene.patch.blade_count;
        expect_refused(c, &scene);
        EXPECT_EQ(scene.patch.blade_count, blades_before) << c.text;
    }
    // The file fuzz_scene found, kept in its corpus.
    grass_sample::Scene scene;
    std::string error;
    EXPECT_FALSE(grass_sample::load_scene(kCorpus + "/scene/blade-count-1e308.json", &scene, &error));
    EXPECT_NE(error.find("\"patch.blade_count\" is 1e+308, out of range"), std::string::npos) << error;
}

} // namespace

namespace {

// The responsive-grass keys (docs/scene-format.md) are refused by name, as the others are:
// an unknown key, a value of the wrong kind, a path that cannot be followed. A refused file
// leaves the scene's responsive settings as they were.
TEST(SceneLoader, ResponsiveKeysAreRefusedByName) {
    const Case cases[] = {
        {R"({"wind": {"speeed": 3}})", "unknown key \"speeed\" in \"wind\""},
        {R"({"wind": 3})", "\"wind\" must be an object, not 3"},
        {R"({"wind": {"speed": 1e300}})", "\"wind.speed\" is 1e+300, out of range"},
        {R"({"wind": {"direction": [1, 0]}})", "\"wind.direction\" must have 3 numbers"},
        {R"({"wind": {"sources": [{"kind": "fan", "position": [0, 0, 0]}]}})",
         "\"wind.sources[0].kind\" must be point, cone or blast, not \"fan\""},
        {R"({"wind": {"sources": [{"kind": "point"}]}})", "\"wind.sources[0]\" needs a \"position\""},
        {R"({"wind": {"sources": [{"position": [0, 0, 0], "colour": 1}]}})",
         "unknown key \"colour\" in \"wind.sources[0]\""},
        {R"({"interaction": {"resolution": -256}})", "\"interaction.resolution\" is -256, out of range"},
        {R"({"interaction": {"texel_size": [0.1, 1, 2]}})", "\"interaction.texel_size\" must be [level 0]"},
        {R"({"interaction": {"level": 2}})", "unknown key \"level\" in \"interaction\""},
        {R"({"patch": {"mechanics": {"stifness": 3}}})", "unknown key \"stifness\" in \"patch.mechanics\""},
        {R"({"patch": {"mechanics": {"recovery_time": "slow"}}})",
         "\"patch.mechanics.recovery_time\" must be a number, not \"slow\""},
        {R"({"colliders": {"shape": "sphere"}})", "\"colliders\" must be a list"},
        {R"({"colliders": [{"shape": "cube", "centre": [0, 0, 0]}]})",
         "\"colliders[0].shape\" must be sphere or capsule, not \"cube\""},
        {R"({"colliders": [{"radius": 1}]})", "\"colliders[0]\" needs a \"centre\""},
        {R"({"colliders": [{"shape": "capsule", "centre": [0, 0, 0]}]})",
         "\"colliders[0]\" is a capsule: it needs an \"end\""},
        {R"({"colliders": [{"centre": [0, 0, 0], "end": [0, 1, 0]}]})",
         "\"colliders[0]\" is a sphere: \"end\" is a capsule's key"},
        {R"({"colliders": [{"centre": [0, 0, 0], "velocity": [1, 0, 0]}]})",
         "unknown key \"velocity\" in \"colliders[0]\""},
        {R"({"colliders": [{"centre": {"keyframes": [[0, 0, 0, 0], [0, 1, 0, 0]]}}]})",
         "\"colliders[0].centre.keyframes\" times must ascend: [0,1,0,0] after time 0"},
        {R"({"colliders": [{"centre": {"keyframes": [[0, 0, 0]]}}]})",
         "\"colliders[0].centre.keyframes\" has [0,0,0]; each is [t, x, y, z]"},
        {R"({"colliders": [{"centre": {"from": [0, 0, 0], "to": [1, 0, 0], "speed": 0}}]})",
         "\"colliders[0].centre.speed\" is 0; it must be > 0"},
        {R"({"colliders": [{"centre": {"from": [0, 0, 0], "speed": 1}}]})",
         "\"colliders[0].centre\" needs \"keyframes\" or \"from\", \"to\" and \"speed\"; \"to\" is missing"},
        {R"({"colliders": [{"centre": {"keyframes": [[0, 0, 0, 0]], "speed": 1}}]})",
         "\"colliders[0].centre\" has \"keyframes\" and a line's keys"},
        {R"({"wind": {"sources": [{"position": [0, 0, 0], "radius": 1e39}]}})",
         "\"wind.sources[0].radius\" is 1e+39, out of range"},
    };
    for (const Case& c : cases) {
        grass_sample::Scene scene;
        scene.responsive.colliders.resize(1); // what the scene had before: kept
        expect_refused(c, &scene);
        EXPECT_EQ(scene.responsive.colliders.size(), 1u) << c.text;
        EXPECT_FALSE(scene.responsive.wind_given) << c.text;
    }
}

} // namespace
