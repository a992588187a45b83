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

} // namespace
