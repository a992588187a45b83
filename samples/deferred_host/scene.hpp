// grass-deferred's scene, the same in both backends: the target, the camera, the lights and
// the check that the picture holds lit grass. main.cpp draws it with GL, vk_deferred.cpp with
// Vulkan, with the same shaders (shaders/): the ground into the G-buffer, then a full-screen
// lighting pass.
#pragma once

#include "headless_host.hpp"
#include "image_io.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace deferred {

constexpr uint32_t kWidth = 480, kHeight = 270;
// The camera 1.4 m up at the field's edge (a 16 m x 16 m field, 64 x 64 cells), in a late
// afternoon: a low warm sun, an ambient term and three lamps in the grass.
constexpr uint32_t kCells = 64;
constexpr double kEye[3] = {8.0, 1.4, -0.5}, kAt[3] = {8.0, 0.0, 8.0};
constexpr float kFovy = 55.0f, kNear = 0.05f, kFar = 100.0f;
constexpr float kSunDirection[3] = {-0.48f, 0.52f, 0.71f}; // towards the sun, unit
constexpr float kSunColor[3] = {1.0f, 0.82f, 0.62f};
constexpr float kAmbient[3] = {0.12f, 0.15f, 0.22f};
constexpr double kLamps[3][3] = {{6.0, 0.5, 3.0}, {10.5, 0.6, 5.0}, {7.5, 0.4, 9.0}};
constexpr float kLampColors[3][4] = {{2.4f, 1.6f, 0.7f, 0.0f}, {0.6f, 1.2f, 2.6f, 0.0f}, {2.2f, 0.8f, 1.8f, 0.0f}};
constexpr float kLampRange = 6.0f; // m
// The ground (shaders/gbuffer_ground.*): a quad at y = 0 from -40 to 56 m in x and z, soil
// (linear 0.09, 0.065, 0.035), facing up; the sky behind it (shaders/lighting.frag: linear
// 0.30, 0.42, 0.62).

// Camera-relative world -> clip of `view`: its projection times its view's rotation.
inline void view_projection(const grass_view_desc& view, float vp[16]) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            float s = 0.0f;
            for (int k = 0; k < 3; ++k) s += view.projection[4 * k + r] * (c < 3 ? view.view[4 * c + k] : 0.0f);
            vp[4 * c + r] = c < 3 ? s : view.projection[12 + r];
        }
    }
}

// grass's layout in the G-buffer: albedo, normal (n * 0.5 + 0.5), material with its ambient
// occlusion (rgb), at attachments 0, 1 and 2; attachment 3, the velocity (RGBA16F), written
// by the ground alone unless `velocity` (velocity.hpp: then grass writes its velocity's rg and
// 0 in b, a float attachment).
inline grass_view_gbuffer_desc gbuffer_layout(bool velocity) {
    grass_view_gbuffer_desc layout = grass_default_view_gbuffer_desc();
    layout.attachment_count = 4;
    layout.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    layout.attachments[1].semantic = GRASS_GBUFFER_NORMAL;
    layout.attachments[2].semantic = GRASS_GBUFFER_MATERIAL;
    layout.attachments[2].write_mask = 0x7;
    layout.attachments[0].format = GRASS_GBUFFER_FORMAT_FLOAT; // the albedo is RGBA16F
    layout.attachments[3].semantic = velocity ? GRASS_GBUFFER_VELOCITY : GRASS_GBUFFER_NONE;
    layout.attachments[3].format = GRASS_GBUFFER_FORMAT_FLOAT;
    layout.attachments[3].write_mask = velocity ? 0x7 : 0x0;
    return layout;
}

// Writes `rgba` (the lit picture, sRGB bytes, top row first) to `out_path` and says whether it holds lit grass:
// at least a tenth of its pixels green-dominant, and the lamps brightening over 2000 pixels
// by more than 40 levels against `sun_only` (the same G-buffer lit by the sun alone).
inline bool holds_lit_grass(std::vector<uint8_t> rgba, const std::vector<uint8_t>& sun_only,
                            const std::string& out_path) {
    grass_host::Image lit;
    lit.width = kWidth;
    lit.height = kHeight;
    lit.rgba = std::move(rgba);
    long green = 0, lit_by_lamps = 0;
    for (size_t p = 0; p < lit.rgba.size(); p += 4) {
        const uint8_t* c = &lit.rgba[p];
        green += c[1] > c[0] + 8 && c[1] > c[2] + 8 ? 1 : 0;
        int brighter = 0;
        for (int k = 0; k < 3; ++k) brighter = std::max(brighter, int(c[k]) - int(sun_only[p + size_t(k)]));
        lit_by_lamps += brighter > 40 ? 1 : 0;
    }
    std::string error;
    const bool written = grass_host::write_png(out_path, lit, &error);
    std::printf("wrote %s: %ld of %u pixels green, %ld over 40 levels brighter for the lamps\n", out_path.c_str(),
                green, kWidth * kHeight, lit_by_lamps);
    const bool ok = written && green * 10 >= long(kWidth) * kHeight && lit_by_lamps > 2000;
    if (!ok) std::fprintf(stderr, "the picture holds no lit grass (or could not be written: %s)\n", error.c_str());
    return ok;
}

// The Vulkan half (vk_deferred.cpp): 0 when the picture holds lit grass.
// `velocity_path` not empty: the velocity frames and their picture instead (velocity.hpp).
int run_vulkan(const std::string& out_path, const std::string& velocity_path);

} // namespace deferred
