// What the sample tools do with a loaded scene, on a CPU-only context: its patch, its design
// maps, its field with its tiers and lod tests, its responsive grass (wind, interaction map,
// mechanics, colliders at a time; grass_sample::apply_responsive) and two frames from its
// camera. Every value the loader let through reaches the library, which must refuse or
// accept it cleanly.
#pragma once

#include "responsive.hpp"
#include "scene.hpp"

#include <grass/grass.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

namespace grass_fuzz {

// A fresh directory for the target's files, made once per process.
inline const std::string& scratch_dir() {
    static const std::string dir = [] {
        char pattern[] = "/tmp/grass-fuzz-XXXXXX";
        if (!mkdtemp(pattern)) std::abort();
        return std::string(pattern);
    }();
    return dir;
}

inline bool write_bytes(const std::string& path, const void* data, size_t size) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = size == 0 || std::fwrite(data, 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

// `colliders`: more colliders for the frames (a glTF scene's), given to grass_set_colliders.
inline void use_scene(const grass_sample::Scene& scene, const std::vector<grass_collider>& colliders = {}) {
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    if (grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) != GRASS_SUCCESS) std::abort();
    grass_patch_desc pd = scene.patch;
    if (pd.blade_count > 2048) pd.blade_count = 2048; // keep an execution fast; the range check is kept
    grass_patch_id patch{};
    if (grass_create_patch(ctx, &pd, &patch) == GRASS_SUCCESS) {
        grass_field_desc fd = scene.field;
        fd.patch = patch;
        if (grass_sample::create_scene_maps(ctx, scene, &fd.maps) == GRASS_SUCCESS) {
            grass_map_desc density = grass_default_map_desc();
            if (!scene.density_texels.empty()) {
                density.pixels = scene.density_texels.data();
                density.width = scene.density_width;
                density.height = scene.density_height;
                fd.density_map = &density;
            }
            if (!scene.tiers.empty()) {
                fd.tiers = scene.tiers.data();
                fd.tier_count = static_cast<uint32_t>(scene.tiers.size());
            }
            if (!scene.lod_tests.empty()) {
                fd.lod_tests = scene.lod_tests.data();
                fd.lod_test_count = static_cast<uint32_t>(scene.lod_tests.size());
            }
            grass_field_id field{};
            if (grass_create_field(ctx, &fd, &field) == GRASS_SUCCESS) {
                // Looking down at the field from the scene's eye: only the eye comes from the
                // scene (the headless host builds the real view from a GPU target).
                grass_view_desc v = grass_default_view_desc();
                std::memcpy(v.camera_position, scene.eye, sizeof(v.camera_position));
                const float view[16] = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1};
                const float proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.0002f, -1, 0, 0, -0.20002f, 0};
                std::memcpy(v.view, view, sizeof(view));
                std::memcpy(v.projection, proj, sizeof(proj));
                v.viewport[2] = v.viewport[3] = 64;
                grass_sample::apply_light(scene, &v);
                for (int frame = 0; frame < 2; ++frame) {
                    v.time = 1.0 + 0.1 * frame;
                    grass_sample::apply_responsive(ctx, patch, scene.responsive, v.time, 0.1, frame == 0);
                    if (!colliders.empty()) {
                        grass_set_colliders(ctx, colliders.data(), static_cast<uint32_t>(colliders.size()));
                    }
                    if (grass_begin_frame(ctx, &v) == GRASS_SUCCESS) grass_end_frame(ctx);
                }
            }
        }
    }
    grass_destroy_context(ctx);
}

} // namespace grass_fuzz
