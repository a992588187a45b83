// Separate contexts share nothing (grass.h, "Thread safety"): four contexts on four threads
// at once, CPU-only and GL (each thread its own headless host: its own EGL context, current
// on that thread), give the same results as one alone. Built with -fsanitize=thread
// (GRASS_TSAN=ON; scripts/test.sh) ThreadSanitizer watches them and must stay silent.
#include "headless_host.hpp"

#include <grass/grass.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr int kThreads = 4;

struct CpuResult {
    uint64_t patch_hash = 0;
    uint64_t cells_drawn = 0; // summed over the frames
    uint64_t host_bytes_after = 0;
    std::string error;
};

grass_view_desc top_view(double x) {
    grass_view_desc v = grass_default_view_desc();
    v.camera_position[0] = x;
    v.camera_position[1] = 3.0; // within the geometry tier (20 cells)
    v.camera_position[2] = 4.0;
    const float view[16] = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1}; // looking straight down
    const float proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.0002f, -1, 0, 0, -0.20002f, 0};
    std::memcpy(v.view, view, sizeof(view));
    std::memcpy(v.projection, proj, sizeof(proj));
    v.viewport[2] = v.viewport[3] = 128;
    return v;
}

// A context's life on one thread: patch, a density map updated every frame, a field made
// and destroyed every 10 frames, 60 frames.
void cpu_context_life(CpuResult* out) {
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    if (grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) != GRASS_SUCCESS) {
        out->error = "grass_create_context failed";
        return;
    }
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 96;
    grass_patch_id patch{};
    grass_patch_info info{};
    std::vector<uint8_t> texels(32 * 32, 200);
    grass_map_desc md = grass_default_map_desc();
    md.pixels = texels.data();
    md.width = md.height = 32;
    grass_map_id map{};
    if (grass_create_patch(ctx, &pd, &patch) != GRASS_SUCCESS || grass_get_patch_info(ctx, patch, &info) ||
        grass_create_map(ctx, &md, &map) != GRASS_SUCCESS) {
        out->error = grass_get_last_error(ctx);
        grass_destroy_context(ctx);
        return;
    }
    out->patch_hash = info.content_hash;
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 32;
    fd.maps.density = map;
    grass_field_id field{};
    for (int frame = 0; frame < 60 && out->error.empty(); ++frame) {
        if (frame % 10 == 0) {
            if (frame > 0) grass_destroy_field(ctx, field);
            if (grass_create_field(ctx, &fd, &field) != GRASS_SUCCESS) out->error = grass_get_last_error(ctx);
        }
        uint8_t row[8];
        for (int k = 0; k < 8; ++k) row[k] = static_cast<uint8_t>((frame * 13 + k * 31) & 0xff);
        grass_map_desc region = grass_default_map_desc();
        region.pixels = row;
        region.width = 8;
        region.height = 1;
        if (grass_update_map(ctx, map, static_cast<uint32_t>(frame % 24), static_cast<uint32_t>(frame % 32), &region) !=
            GRASS_SUCCESS) {
            out->error = grass_get_last_error(ctx);
        }
        const grass_view_desc v = top_view(2.0 + 0.1 * frame);
        if (grass_begin_frame(ctx, &v) != GRASS_SUCCESS) out->error = grass_get_last_error(ctx);
        grass_frame_stats stats{};
        grass_get_frame_stats(ctx, &stats);
        out->cells_drawn += stats.cells_drawn;
        grass_end_frame(ctx);
    }
    grass_memory_stats m{};
    grass_get_memory_stats(ctx, &m);
    out->host_bytes_after = m.host_bytes;
    grass_destroy_context(ctx);
}

TEST(Threads, FourCpuContextsOnFourThreadsAgreeWithOneAlone) {
    CpuResult alone;
    cpu_context_life(&alone);
    ASSERT_EQ(alone.error, "");
    ASSERT_GT(alone.cells_drawn, 0u);
    std::vector<CpuResult> results(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) threads.emplace_back(cpu_context_life, &results[t]);
    for (auto& t : threads) t.join();
    for (int t = 0; t < kThreads; ++t) {
        EXPECT_EQ(results[t].error, "") << "thread " << t;
        EXPECT_EQ(results[t].patch_hash, alone.patch_hash) << "thread " << t;
        EXPECT_EQ(results[t].cells_drawn, alone.cells_drawn) << "thread " << t;
        EXPECT_EQ(results[t].host_bytes_after, alone.host_bytes_after) << "thread " << t;
    }
}

#if GRASS_HOST_HAS_GL
struct GlResult {
    grass_host::Image image;
    std::string error;
};

// One headless GL host per thread (its own EGL context), a field, 5 frames.
void gl_context_life(GlResult* out) {
    grass_host::TargetDesc t;
    t.width = t.height = 64;
    t.ground = true;
    auto host = grass_host::Host::create(GRASS_BACKEND_GL, t, &out->error);
    if (!host) return;
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    if (host->create_context(cd, &ctx) != GRASS_SUCCESS) {
        out->error = "grass_gl_create_context failed";
        return;
    }
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 96;
    grass_patch_id patch{};
    grass_field_desc fd = grass_default_field_desc();
    fd.cells_x = fd.cells_z = 32;
    grass_field_id field{};
    if (grass_create_patch(ctx, &pd, &patch) != GRASS_SUCCESS ||
        (fd.patch = patch, grass_create_field(ctx, &fd, &field)) != GRASS_SUCCESS) {
        out->error = grass_get_last_error(ctx);
    }
    const double eye[3] = {4.0, 1.5, -1.0}, look[3] = {4.0, 0.0, 4.0};
    for (int frame = 0; frame < 5 && out->error.empty(); ++frame) {
        const grass_view_desc v = grass_host::make_view(*host, eye, look, 50.0f);
        if (host->render(ctx, v, nullptr, &out->image, &out->error) != GRASS_SUCCESS && out->error.empty())
            out->error = grass_get_last_error(ctx);
    }
    grass_destroy_context(ctx);
    if (host->validation_messages() != 0) out->error += host->validation_log();
}

TEST(Threads, FourGlContextsOnFourThreadsDrawTheSamePicture) {
    GlResult alone;
    gl_context_life(&alone);
    if (alone.error.find("EGL") != std::string::npos && alone.image.rgba.empty()) GTEST_SKIP() << alone.error;
    ASSERT_EQ(alone.error, "");
    // Not a comparison of two empty pictures: a fair share is grass (not the sky's blue).
    size_t green = 0;
    for (size_t p = 0; p + 3 < alone.image.rgba.size(); p += 4)
        green += alone.image.rgba[p + 1] > alone.image.rgba[p + 2];
    ASSERT_GT(green, alone.image.rgba.size() / 4 / 5) << "a fifth of the pixels are grass or ground";
    std::vector<GlResult> results(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) threads.emplace_back(gl_context_life, &results[t]);
    for (auto& t : threads) t.join();
    for (int t = 0; t < kThreads; ++t) {
        EXPECT_EQ(results[t].error, "") << "thread " << t;
        EXPECT_EQ(results[t].image.rgba, alone.image.rgba) << "thread " << t;
    }
}
#endif

} // namespace
