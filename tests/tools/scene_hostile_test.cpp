// The scene loader (tools/scene/scene.cpp) with the hostile and careless files of issue 37:
// deep nesting, files that are not regular files or too large, counts past the library's
// limits, values the tools cannot honour, values too long to echo. Each is refused at once,
// naming the key (by its path) or the file, and the value.
#include "file_bytes.hpp"
#include "json_depth.hpp"
#include "scene.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

const std::string kCorpus = GRASS_FUZZ_CORPUS_DIR;

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" + name;
}

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = temp_path(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// Loads `path` over a scene: refused within `seconds`, with an error holding `named`; the
// scene unchanged (its blade count and colliders as they were). The bound tells "refused
// before the work" from "did the work": 70,000 colliders took 37 s and 4.5 GB before they were
// refused first, 0.1 s after; it leaves a wide margin for a loaded machine and the sanitizers
// (1 s failed at 1.16 s with four builds running beside it).
void expect_refused_file(const std::string& path, const std::string& named, double seconds = 8.0) {
    grass_sample::Scene scene;
    scene.patch.blade_count = 77;
    scene.responsive.colliders.resize(1);
    std::string error;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(grass_sample::load_scene(path, &scene, &error)) << named;
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(error.find(named), std::string::npos) << "expected \"" << named << "\" in: " << error.substr(0, 300);
    EXPECT_LT(error.size(), 600u) << "a short message: " << error.substr(0, 300);
    EXPECT_LT(took, seconds) << named;
    EXPECT_EQ(scene.patch.blade_count, 77u) << named;
    EXPECT_EQ(scene.responsive.colliders.size(), 1u) << named;
}

void expect_refused(const std::string& text, const std::string& named, double seconds = 8.0) {
    expect_refused_file(write_file("scene.json", text), named, seconds);
}

std::string nest(size_t depth, const std::string& inner) {
    return std::string(depth, '[') + inner + std::string(depth, ']');
}

// A scene nested 300,000 deep (600 KB) crashed grass-render in nlohmann's recursive dump()
// while the error message was built; 60,000 deep is the reported file. Both are refused
// before parsing; 100 levels are parsed (and refused for the value), 101 are not.
TEST(SceneHostile, DeepNestingIsRefusedBeforeItIsParsed) {
    for (size_t depth : {size_t(101), size_t(60000), size_t(300000)}) {
        expect_refused(R"({"patch": {"blade_count": )" + nest(depth - 2, "1") + "}}",
                       "the scene nests arrays and objects deeper than 100 levels");
    }
    expect_refused(R"({"patch": {"blade_count": )" + nest(98, "1") + "}}",
                   R"("patch.blade_count" must be a number, not [[...]])");
    // Brackets in strings and comments do not count.
    const std::string brackets(5000, '[');
    expect_refused("// " + brackets + "\n/* " + brackets + " */ {\"patch\": {\"threshold_mode\": \"" + brackets +
                       "\"}}",
                   R"("patch.threshold_mode" must be "uniform" or "clustered", not "[[[[)");
    // The corpus entries fuzz_scene starts from.
    expect_refused_file(kCorpus + "/scene/deep-101.json", "deeper than 100 levels (at byte 124)");
    expect_refused_file(kCorpus + "/scene/deep-60000.json", "deeper than 100 levels (at byte 124)");
    expect_refused_file(kCorpus + "/scene/deep-100.json", R"("patch.blade_count" must be a number)");
}

TEST(SceneHostile, JsonDepthCountsOutsideStringsAndComments) {
    auto problem = [](const std::string& text, bool comments) {
        return grass_sample::json_depth_problem(text.data(), text.size(), 2, comments);
    };
    EXPECT_EQ(problem("[[1]]", false), "");
    EXPECT_EQ(problem("[[[1]]]", false), "nests arrays and objects deeper than 2 levels (at byte 2)");
    EXPECT_EQ(problem(R"([["[[\"[["]])", false), "") << "brackets in a string, past an escaped quote";
    EXPECT_EQ(problem("[[1]] // [[[\n", true), "");
    EXPECT_NE(problem("[[1]] // [[[\n", false), "") << "a comment where comments are not allowed";
    EXPECT_EQ(problem("[/* [[[ */[1]]", true), "");
    EXPECT_NE(problem("[/* [[[ */[[1]]]", true), "") << "after the comment";
}

// A density map at /dev/zero read until the tool was killed; /dev/urandom until bad_alloc at
// 4.2 GB. A FIFO blocked in open, a directory was refused without its name. Each is refused
// by name now, and a scene file too large or not a regular file as well.
TEST(SceneHostile, FilesThatAreNotRegularOrTooLargeAreRefusedUnread) {
    const std::string fifo = temp_path("fifo.png");
    unlink(fifo.c_str());
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const std::string dir = ::testing::TempDir();
    const std::string big = temp_path("big.png");
    { std::ofstream(big) << ""; }
    ASSERT_EQ(truncate(big.c_str(), off_t(grass_sample::kMaxFileBytes) + 1), 0); // sparse: no disk
    const struct {
        std::string file, named;
    } maps[] = {
        {"/dev/zero", "/dev/zero is a character device, not a regular file"},
        {"/dev/urandom", "/dev/urandom is a character device, not a regular file"},
        {fifo, fifo + " is a FIFO, not a regular file"},
        {dir, dir + " is a directory, not a regular file"},
        {big, big + " has 268435457 bytes; at most 268435456 are read"},
        {dir + "/no-such-map.png", "cannot open " + dir + "/no-such-map.png: No such file or directory"},
    };
    for (const auto& m : maps) {
        for (const char* key : {R"({"field": {"density_map": "%s"}})", R"({"field": {"maps": {"height": "%s"}}})",
                                R"({"field": {"wind_map": {"map": "%s"}}})"}) {
            char text[1024];
            std::snprintf(text, sizeof(text), key, m.file.c_str());
            expect_refused(text, m.named);
        }
    }
    expect_refused_file("/dev/zero", "/dev/zero is a character device, not a regular file");
    expect_refused_file(fifo, fifo + " is a FIFO, not a regular file");
    const std::string big_scene = temp_path("big.json");
    { std::ofstream(big_scene) << "{}"; }
    ASSERT_EQ(truncate(big_scene.c_str(), off_t(grass_sample::kMaxSceneFileBytes) + 1), 0);
    expect_refused_file(big_scene, "has 16777217 bytes; at most 16777216 are read");
    unlink(fifo.c_str());
    unlink(big.c_str());
    unlink(big_scene.c_str());
}

// 70,000 colliders took 37 s and 4.5 GB of the tool's meshes before the library refused the
// count: the list is counted before any collider is read.
TEST(SceneHostile, CountsPastTheLibrarysLimitsAreRefusedFirst) {
    std::string colliders = R"({"colliders": [)";
    for (int k = 0; k < 70000; ++k) colliders += std::string(k ? "," : "") + R"({"centre": [0, 0, 0]})";
    expect_refused(colliders + "]}", R"("colliders" has 70000 colliders; grass takes at most 65536)");
    std::string sources = R"({"wind": {"sources": [)";
    for (int k = 0; k < 17; ++k) sources += std::string(k ? "," : "") + R"({"position": [0, 0, 0]})";
    expect_refused(sources + "]}}", R"("wind.sources" has 17 sources; grass takes at most 16)");
    std::string tiers = R"({"field": {"tiers": [)";
    for (int k = 0; k < 9; ++k) tiers += std::string(k ? "," : "") + R"({"kind": "geometry"})";
    expect_refused(tiers + "]}}", R"("field.tiers" has 9 entries; at most 8)");
}

// Values the tools cannot honour, each refused naming its key and value: a camera upside down
// or seeing nothing, a far plane at 0, sample counts the CLI does not allow, a root that is
// not an object, empty lists where the library needs entries.
TEST(SceneHostile, ValuesTheToolsCannotHonourAreRefusedByName) {
    const struct {
        const char* text;
        const char* named;
    } cases[] = {
        {R"({"camera": {"fov": -55}})", R"("camera.fov" is -55; it must lie between 0 and 180 degrees)"},
        {R"({"camera": {"fov": 180}})", R"("camera.fov" is 180; it must lie between 0 and 180 degrees)"},
        {R"({"camera": {"fov": 0}})", R"("camera.fov" is 0; it must lie between 0 and 180 degrees)"},
        {R"({"camera": {"far": 0}})", R"("camera.far" is 0; it must lie beyond the near plane)"},
        {R"({"camera": {"far": 0.01}})", R"("camera.far" is 0.01; it must lie beyond the near plane)"},
        {R"({"camera": {"far": 1e400}})", "number overflow parsing '1e400'"}, // nlohmann's parse
        {R"({"image": {"samples": 3}})", R"("image.samples" is 3; it must be 1 or 4)"},
        {R"({"image": {"samples": 0}})", R"("image.samples" is 0; it must be 1 or 4)"},
        {R"({"image": {"width": 0}})", R"("image.width" is 0; it must be 1..8192)"},
        {R"({"image": {"height": 9000}})", R"("image.height" is 9000; it must be 1..8192)"},
        {"null", "the scene must be an object, not null"},
        {"[1, 2]", "the scene must be an object, not [1,2]"},
        {"5", "the scene must be an object, not 5"},
        {R"({"field": {"tiers": []}})", R"("field.tiers" is empty)"},
        {R"({"field": {"lod_tests": []}})", R"("field.lod_tests" is empty)"},
        {R"({"field": {"tiers": {}}})", R"("field.tiers" must be a list of tiers, not {})"},
        {R"({"field": {"tiers": [{"slices": 4}]}})", R"("field.tiers[0]" needs a "kind")"},
        {R"({"field": {"tiers": [{"kind": "cloud"}]}})", R"("field.tiers[0].kind" must be geometry, volume or image)"},
        {R"({"field": {"lod_tests": [{"kind": 3}]}})", R"("field.lod_tests[0].kind" must be a string, not 3)"},
        {R"({"field": {"lod_tests": [{"kind": "band", "end": "far"}]}})",
         R"("field.lod_tests[0].end" must be a number, not "far")"},
    };
    for (const auto& c : cases) expect_refused(c.text, c.named);
    // What is allowed loads: the edges of the allowed ranges.
    grass_sample::Scene scene;
    std::string error;
    EXPECT_TRUE(grass_sample::load_scene(
        write_file("ok.json", R"({"camera": {"fov": 179.5, "far": 0.06}, "image": {"samples": 1, "width": 8192}})"),
        &scene, &error))
        << error;
    EXPECT_EQ(scene.samples, 1u);
}

// Messages that named no key ("cannot use key() for non-object iterators", "type must be
// string, but is number") name it now; a directory as a map path is named.
TEST(SceneHostile, TypeErrorsNameTheKey) {
    const struct {
        const char* text;
        const char* named;
    } cases[] = {
        {R"({"patch": 5})", R"("patch" must be an object, not 5)"},
        {R"({"field": {"maps": [1]}})", R"("field.maps" must be an object, not [1])"},
        {R"({"camera": "front"})", R"("camera" must be an object, not "front")"},
        {R"({"field": {"density_map": 5}})", R"("field.density_map" must be a string, not 5)"},
        {R"({"field": {"density_map": ""}})", R"("field.density_map" is an empty file name)"},
        {R"({"field": {"maps": {"color": true}}})", R"("field.maps.color" must be a string, not true)"},
        {R"({"field": {"wind_map": {"map": [1]}}})", R"("field.wind_map.map" must be a string, not [1])"},
        {R"({"field": {"mirror_tiling": 1}})", R"("field.mirror_tiling" must be true or false, not 1)"},
        {R"({"patch": {"threshold_mode": 1}})", R"("patch.threshold_mode" must be a string, not 1)"},
        {R"({"ground": 1})", R"("ground" must be an object, not 1)"},
        {R"({"light": {"sun_color": [1, 1]}})", R"("light.sun_color" must have 3 numbers, not [1,1])"},
        {R"({"field": {"cells": [1e30, 4]}})", R"("field.cells" is 1e+30, out of range)"},
    };
    for (const auto& c : cases) expect_refused(c.text, c.named);
}

// A 64 MB string was echoed whole in the message (2 MB here). Values, keys and file names are cut now
// (80 characters and "..."), and a value nested deep is shown by its first level.
TEST(SceneHostile, LongValuesAreCutInMessages) {
    const std::string huge(2 << 20, 'x'); // parsed in about 0.3 s under ASan, on a loaded machine
    const double slow = 5.0;
    expect_refused(R"({"patch": {"blade_count": ")" + huge + R"("}})",
                   R"("patch.blade_count" must be a number, not ")" + std::string(80, 'x') + R"(...")", slow);
    expect_refused(R"({"patch": {")" + huge + R"(": 1}})",
                   "unknown key \"" + std::string(80, 'x') + "...\" in \"patch\"", slow);
    expect_refused(R"({"patch": {"threshold_mode": ")" + huge + R"("}})", "not \"" + std::string(80, 'x') + "...\"",
                   slow);
    expect_refused(R"({"field": {"density_map": ")" + std::string(3000, 'y') + R"("}})",
                   "cannot open ..." + std::string(120, 'y') + ": File name too long");
    std::string many = "[";
    for (int k = 0; k < 100000; ++k) many += std::string(k ? "," : "") + "[1, 2]";
    expect_refused(R"({"light": {"sun_color": )" + many + "]}}", R"("light.sun_color" must be a number, not [1,2])");
    expect_refused(R"({"patch": {"blade_count": )" + many + "]}}",
                   R"("patch.blade_count" must be a number, not [[...],[...],)");
    expect_refused(R"({"light": {"sun_direction": )" + many + "]}}", R"("light.sun_direction" must be a number)");
    expect_refused(
        R"({"light": {"sun_direction": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19,
                   20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30]}})",
        R"("light.sun_direction" must have 3 numbers, not [1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,23,24,25,26,27,28,29,3...])");
    // A parse error quotes the token it stopped in: cut as well.
    expect_refused(R"({"patch": {"threshold_mode": ")" + huge, "syntax error", slow);
}

// A palette PNG whose indices ran past its palette gave zero density where it had them: the
// file and the first such pixel are named now.
TEST(SceneHostile, PaletteIndicesPastThePaletteAreRefused) {
    const std::string png = kCorpus + "/png_map/palette-index-past-palette.png";
    for (const char* key : {R"({"field": {"density_map": "%s"}})", R"({"field": {"maps": {"density": "%s"}}})",
                            R"({"field": {"maps": {"color": "%s"}}})"}) {
        char text[1024];
        std::snprintf(text, sizeof(text), key, png.c_str());
        expect_refused(text, "palette-index-past-palette.png is refused: pixel (0, 1) has palette index 5; the "
                             "palette has 2 colours");
    }
    grass_sample::Scene scene;
    std::string error;
    EXPECT_TRUE(grass_sample::load_scene(
        write_file("ok.json", R"({"field": {"density_map": ")" + kCorpus + R"(/png_map/palette-2x2.png"}})"), &scene,
        &error))
        << "a palette PNG whose indices fit: " << error;
}

} // namespace
