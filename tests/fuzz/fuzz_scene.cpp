// libFuzzer target: the tools' scene JSON loader (tools/scene/scene.cpp) and what
// they then do with the scene on a CPU-only context. The input is the scene file; a small
// valid PNG, map.png, lies beside it for the "maps" and "density_map" keys to name.
#include "fuzz_scene_use.hpp"

#include <png.h>

#include <cstdio>
#include <vector>

namespace {

void write_map_png(const std::string& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png.height = 4;
    png.format = PNG_FORMAT_GRAY;
    std::vector<uint8_t> pixels(16);
    for (size_t k = 0; k < pixels.size(); ++k) pixels[k] = static_cast<uint8_t>(k * 17);
    if (!png_image_write_to_file(&png, path.c_str(), 0, pixels.data(), 0, nullptr)) std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string dir = [] {
        write_map_png(grass_fuzz::scratch_dir() + "/map.png");
        return grass_fuzz::scratch_dir();
    }();
    const std::string path = dir + "/scene.json";
    if (!grass_fuzz::write_bytes(path, data, size)) std::abort();
    grass_sample::Scene scene = grass_sample::demo_scene();
    std::string error;
    if (grass_sample::load_scene(path, &scene, &error)) {
        grass_fuzz::use_scene(scene);
    } else if (error.empty()) {
        std::abort(); // a refused scene says why
    } else if (error.size() > path.size() + 1000) {
        // in a few words: values are cut, never echoed whole (a 64 MB string was, issue 37)
        std::fprintf(stderr, "a refused scene gave a message of %zu bytes\n", error.size());
        std::abort();
    }
    return 0;
}
