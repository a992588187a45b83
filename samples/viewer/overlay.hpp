// The viewer's overlay (Dear ImGui): frame and plan time, each tier kind's instances and GPU
// time, the camera, and the keys.
#pragma once

#include <grass/grass.h>

#include <string>

namespace grass_viewer {

struct OverlayInfo {
    const char* backend = "";
    std::string device, scene;
    const char* quality = "";
    uint32_t width = 0, height = 0, samples = 1;
    double frame_ms = 0.0; // wall time between frames, smoothed
    grass_frame_stats stats{};
    double gpu_ms[GRASS_TIER_KIND_COUNT] = {};
    bool gpu_available = false;
    double camera[3] = {}, speed = 0.0;
    bool debug_tiers = false, debug_cells = false, help = false;
    bool wind = false, ball = false; // F2, B
    std::string status;              // the last screenshot or error
};

// The keys, one per line, as the overlay's help and --help show them.
extern const char* const kKeysHelp;

// Builds the overlay's window between ImGui::NewFrame and ImGui::Render.
void build_overlay(const OverlayInfo& info);

} // namespace grass_viewer
