// libFuzzer target: the tools' PNG design-map loader (libpng's simplified API in
// tools/scene/scene.cpp) for every map role, and the maps made from what it decodes on a
// CPU-only context. The input is the PNG file; a fixed scene names it for each role.
#include "fuzz_scene_use.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string dir = [] {
        const std::string d = grass_fuzz::scratch_dir();
        // One scene per map role (a scene stops at its first bad map) and the density_map key.
        const char* const scenes[] = {
            R"({"field": {"cells": [8, 8], "maps": {"density": "map.png"}}})",
            R"({"field": {"cells": [8, 8], "maps": {"color": "map.png"}}})",
            R"({"field": {"cells": [8, 8], "maps": {"height": "map.png", "height_scale": 2}}})",
            R"({"field": {"cells": [8, 8], "density_map": "map.png"}})",
        };
        for (size_t k = 0; k < sizeof(scenes) / sizeof(scenes[0]); ++k) {
            const std::string text = scenes[k];
            if (!grass_fuzz::write_bytes(d + "/scene" + std::to_string(k) + ".json", text.data(), text.size()))
                std::abort();
        }
        return d;
    }();
    if (!grass_fuzz::write_bytes(dir + "/map.png", data, size)) std::abort();
    for (int k = 0; k < 4; ++k) {
        grass_sample::Scene scene;
        std::string error;
        if (grass_sample::load_scene(dir + "/scene" + std::to_string(k) + ".json", &scene, &error)) {
            grass_fuzz::use_scene(scene);
        } else if (error.empty()) {
            std::abort();
        }
    }
    return 0;
}
