// grass-tier-cost: the frame cost of each tier per basic cell (the analogues of lemme2012
// Tables 7.1 and 7.2), measured in one run: 1024 cells (32 x 32 of 0.25 m) drawn by each
// tier alone, then by the volume (8 slices) and image tiers in macro-cells of 1, 2, 4, 8 and
// 16 cells a side. Wall time of a rendered and read-back frame, median of 5, minus the
// same frame with no grass; per basic cell. Prints a Markdown table.
// Usage: grass-tier-cost [--backend gl|vk] [--size WxH]
#include <grass/grass.h>

#include "headless_host.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Setup {
    const char* name;
    grass_tier_kind kind;
    uint32_t slices;
    uint32_t macro; // largest macro-cell side; 1 = single cells
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv) {
    grass_backend backend = GRASS_BACKEND_GL;
    grass_host::TargetDesc target;
    target.width = 320;
    target.height = 240;
    for (int k = 1; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--backend") && k + 1 < argc) {
            backend = std::strcmp(argv[++k], "vk") == 0 ? GRASS_BACKEND_VULKAN : GRASS_BACKEND_GL;
        } else if (!std::strcmp(argv[k], "--size") && k + 1 < argc) {
            std::sscanf(argv[++k], "%ux%u", &target.width, &target.height);
        } else {
            std::fprintf(stderr, "usage: grass-tier-cost [--backend gl|vk] [--size WxH]\n");
            return 2;
        }
    }
    std::string error;
    auto host = grass_host::Host::create(backend, target, &error);
    if (!host) {
        std::fprintf(stderr, "grass-tier-cost: %s\n", error.c_str());
        return 1;
    }
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    if (host->create_context(cd, &ctx) != GRASS_SUCCESS) return 1;
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    grass_create_patch(ctx, &pd, &patch);

    // The whole 8 m x 8 m field in view, seen at 30 degrees from 9 m away.
    const double eye[3] = {4.0, 4.5, -4.0}, look[3] = {4.0, 0.0, 4.0};
    const grass_view_desc view = grass_host::make_view(*host, eye, look, 55.0f, 0.05f, 200.0f);
    auto frame_ms = [&]() {
        std::vector<double> times;
        grass_host::Image image;
        for (int r = 0; r < 6; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            host->render(ctx, view, nullptr, &image, &error);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (r > 0) times.push_back(ms); // the first frame uploads
        }
        return median(times);
    };
    const double empty = frame_ms();

    const Setup setups[] = {
        {"geometry", GRASS_TIER_GEOMETRY, 0, 1}, {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
        {"volume, 2 slices", GRASS_TIER_VOLUME, 2, 1}, {"volume, 1 slice", GRASS_TIER_VOLUME, 1, 1},
        {"image", GRASS_TIER_IMAGE, 0, 1},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 2}, {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 4},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 8}, {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 16},
        {"image", GRASS_TIER_IMAGE, 0, 2}, {"image", GRASS_TIER_IMAGE, 0, 4},
        {"image", GRASS_TIER_IMAGE, 0, 8}, {"image", GRASS_TIER_IMAGE, 0, 16},
    };
    std::printf("grass-tier-cost: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms\n\n",
                backend == GRASS_BACKEND_GL ? "gl" : "vk", host->device_name().c_str(), target.width, target.height, empty);
    std::printf("| tier | macro-cells up to | instances | frame (ms) | per basic cell (us) |\n|---|---|---|---|---|\n");
    for (const Setup& s : setups) {
        grass_tier_desc tier{s.kind, s.slices};
        grass_lod_test tests[2] = {};
        tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[0].end = INFINITY;
        tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
        tests[1].max_macro_cells = s.macro;
        grass_field_desc fd = grass_default_field_desc();
        fd.patch = patch;
        fd.cells_x = fd.cells_z = 32;
        fd.tiers = &tier;
        fd.tier_count = 1;
        fd.lod_tests = tests;
        fd.lod_test_count = s.kind == GRASS_TIER_GEOMETRY ? 1 : 2;
        grass_field_id field{};
        if (grass_create_field(ctx, &fd, &field) != GRASS_SUCCESS) {
            std::fprintf(stderr, "grass-tier-cost: %s\n", grass_last_error(ctx));
            return 1;
        }
        const double ms = frame_ms();
        grass_frame_stats stats{};
        grass_get_frame_stats(ctx, &stats);
        std::printf("| %s | %u | %llu | %.1f | %.1f |\n", s.name, s.macro,
                    static_cast<unsigned long long>(stats.instances[s.kind]), ms, 1000.0 * (ms - empty) / 1024.0);
        grass_destroy_field(ctx, field);
    }
    const uint32_t messages = host->validation_messages();
    grass_destroy_context(ctx);
    if (messages) {
        std::fprintf(stderr, "grass-tier-cost: %u validation messages\n%s\n", messages, host->validation_log().c_str());
        return 1;
    }
    return 0;
}
