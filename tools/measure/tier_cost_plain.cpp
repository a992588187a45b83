// grass-measure tier-cost without --maps or --features: 1024 cells drawn by each tier alone,
// then by the volume (8 slices) and image tiers in macro-cells of up to 2, 4, 8 and 16 cells a
// side; the median frame, and per basic cell the frame minus the empty one, in wall and in CPU
// time. --single: the first, third and fifth rows only (kSingleTiers); --tier: one tier's rows.
// --depth-pass: run_depth_pass below instead; --receive: run_receive; --motion: run_motion;
// --lights: run_lights; --gbuffer: run_gbuffer
// (tier_cost_motion.cpp).
#include "tier_cost.hpp"

#include "cli.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <GL/glcorearb.h>

#include <cstdio>
#include <cstring>
#include <iterator>
#include <string>
#include <vector>

namespace grass_measure {
namespace tier_cost {

namespace {

// The rows as colour and as depth passes of the same view: `rounds` rounds of `frames`
// frames each, colour then depth, pooled per pass (a load that comes and goes falls on both);
// per basic cell, the median frame minus the empty one, in wall and CPU time, and the ratios.
int run_depth_pass(Rig& rig, const std::vector<Setup>& rows) {
    const Options& o = rig.options();
    grass_context* ctx = rig.ctx();
    grass_view_pass_desc depth = grass_default_view_pass_desc();
    depth.pass = GRASS_PASS_DEPTH;
    std::printf("grass-tier-cost --depth-pass: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms (CPU "
                "%.2f ms)\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height,
                rig.empty_ms(), rig.empty_cpu_ms());
    std::printf("| tier | colour per basic cell (us) | depth per basic cell (us) | depth / colour | CPU: colour (us) | "
                "CPU: depth (us) | CPU: depth / colour |\n|---|---|---|---|---|---|---|\n");
    for (const Setup& s : rows) {
        if (!o.tier.empty() && std::strncmp(s.name, o.tier.c_str(), o.tier.size()) != 0) continue;
        const TierField tf(s, rig.patch());
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
        std::vector<double> wall[2], cpu[2];
        for (int round = 0; round < 3; ++round) {
            for (int pass = 0; pass < 2; ++pass) {
                rig.set_pass(pass == 1 ? &depth : nullptr);
                std::vector<double> c;
                const std::vector<double> w = rig.frame_times(o.frames, nullptr, &c);
                wall[pass].insert(wall[pass].end(), w.begin(), w.end());
                cpu[pass].insert(cpu[pass].end(), c.begin(), c.end());
            }
        }
        rig.set_pass(nullptr);
        double us[2], cpu_us[2];
        for (int pass = 0; pass < 2; ++pass) {
            us[pass] = 1000.0 * (grass_sample::median_high(wall[pass]) - rig.empty_ms()) / 1024.0;
            cpu_us[pass] = 1000.0 * (grass_sample::median_high(cpu[pass]) - rig.empty_cpu_ms()) / 1024.0;
        }
        std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", s.name, us[0], us[1], us[1] / us[0],
                    cpu_us[0], cpu_us[1], cpu_us[1] / cpu_us[0]);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    }
    return rig.finish();
}

// The rows plain and receiving a shadow map: 2 layers of 1024^2 depths whose occluder covers
// the field's half x < 4 m (the rig's 32 x 32 cells of 0.25 m), read top-down (GL: a
// GL_TEXTURE_2D_ARRAY; Vulkan: the host's D32 2D array in DEPTH_STENCIL_READ_ONLY_OPTIMAL,
// Host::make_vk_shadow_map); filter_radius 0 and 1.5. `rounds` rounds of `frames` frames each,
// the three in turn, pooled per variant; per basic cell, the median frame minus the empty one.
int run_receive(Rig& rig, const std::vector<Setup>& rows) {
    const Options& o = rig.options();
    grass_context* ctx = rig.ctx();
    constexpr int kTexels = 1024, kLayers = 2;
    std::vector<float> depths(size_t(kTexels) * kTexels * kLayers);
    for (size_t k = 0; k < depths.size(); ++k) depths[k] = (k % kTexels) < kTexels / 2 ? 0.0f : 1.0f;
    GLuint map = 0;
    PFNGLDELETETEXTURESPROC destroy = nullptr;
    uint64_t handle = 0;
    if (o.backend == GRASS_BACKEND_VULKAN) {
        std::string error;
        const uint32_t kDepthStencilReadOnly = 4; // VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
        handle = rig.host().make_vk_shadow_map(kTexels, kLayers, depths.data(), kDepthStencilReadOnly, &error);
        if (handle == 0) {
            std::fprintf(stderr, "grass-tier-cost --receive: the shadow map: %s\n", error.c_str());
            return 1;
        }
    } else {
        const auto create = reinterpret_cast<PFNGLCREATETEXTURESPROC>(rig.host().gl_proc_address("glCreateTextures"));
        const auto storage =
            reinterpret_cast<PFNGLTEXTURESTORAGE3DPROC>(rig.host().gl_proc_address("glTextureStorage3D"));
        const auto upload =
            reinterpret_cast<PFNGLTEXTURESUBIMAGE3DPROC>(rig.host().gl_proc_address("glTextureSubImage3D"));
        destroy = reinterpret_cast<PFNGLDELETETEXTURESPROC>(rig.host().gl_proc_address("glDeleteTextures"));
        create(GL_TEXTURE_2D_ARRAY, 1, &map);
        storage(map, 1, GL_DEPTH_COMPONENT32F, kTexels, kTexels, kLayers);
        upload(map, 0, 0, 0, 0, kTexels, kTexels, kLayers, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
        handle = map;
    }
    grass_shadow_receive_desc shadow[2] = {grass_default_shadow_receive_desc(), grass_default_shadow_receive_desc()};
    for (int k = 0; k < 2; ++k) {
        shadow[k].shadow_map = handle;
        shadow[k].vk_image_layout = 4; // Vulkan: the layout the map was left in (GL ignores it)
        shadow[k].cascade_count = kLayers;
        shadow[k].cascade_end[0] = 6.0f;
        shadow[k].cascade_end[1] = 1000.0f;
        shadow[k].filter_radius = k == 0 ? 0.0f : 1.5f;
        for (int c = 0; c < kLayers; ++c) {
            float* m = shadow[k].world_to_shadow[c];
            std::memset(m, 0, sizeof(float) * 16);
            m[0] = m[9] = 1.0f / 8.0f; // u from x, v from z
            m[14] = 0.5f;              // depth
            m[15] = 1.0f;
        }
    }
    std::printf("grass-tier-cost --receive: %s (%s), %ux%u, 1024 cells of 0.25 m, half in shadow, frame with no grass "
                "%.2f ms (CPU %.2f ms)\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height,
                rig.empty_ms(), rig.empty_cpu_ms());
    std::printf("| tier | plain per basic cell (us) | receiving, radius 0 | receiving, radius 1.5 | CPU: plain (us) | "
                "CPU: radius 0 / plain | CPU: radius 1.5 / plain |\n|---|---|---|---|---|---|---|\n");
    for (const Setup& s : rows) {
        if (!o.tier.empty() && std::strncmp(s.name, o.tier.c_str(), o.tier.size()) != 0) continue;
        const TierField tf(s, rig.patch());
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
        std::vector<double> wall[3], cpu[3];
        for (int round = 0; round < 3; ++round) {
            for (int variant = 0; variant < 3; ++variant) {
                rig.set_shadow(variant == 0 ? nullptr : &shadow[variant - 1]);
                std::vector<double> c;
                const std::vector<double> w = rig.frame_times(o.frames, nullptr, &c);
                wall[variant].insert(wall[variant].end(), w.begin(), w.end());
                cpu[variant].insert(cpu[variant].end(), c.begin(), c.end());
            }
        }
        rig.set_shadow(nullptr);
        double us[3], cpu_us[3];
        for (int v = 0; v < 3; ++v) {
            us[v] = 1000.0 * (grass_sample::median_high(wall[v]) - rig.empty_ms()) / 1024.0;
            cpu_us[v] = 1000.0 * (grass_sample::median_high(cpu[v]) - rig.empty_cpu_ms()) / 1024.0;
        }
        std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", s.name, us[0], us[1], us[2], cpu_us[0],
                    cpu_us[1] / cpu_us[0], cpu_us[2] / cpu_us[0]);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    }
    if (destroy) destroy(1, &map);
    return rig.finish();
}

} // namespace

int run_plain(Rig& rig) {
    const Setup setups[] = {
        {"geometry", GRASS_TIER_GEOMETRY, 0, 1},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
        {"volume, 2 slices", GRASS_TIER_VOLUME, 2, 1},
        {"volume, 1 slice", GRASS_TIER_VOLUME, 1, 1},
        {"image", GRASS_TIER_IMAGE, 0, 1},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 2},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 4},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 8},
        {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 16},
        {"image", GRASS_TIER_IMAGE, 0, 2},
        {"image", GRASS_TIER_IMAGE, 0, 4},
        {"image", GRASS_TIER_IMAGE, 0, 8},
        {"image", GRASS_TIER_IMAGE, 0, 16},
    };
    const Options& o = rig.options();
    const std::vector<Setup> rows = o.single ? std::vector<Setup>(std::begin(kSingleTiers), std::end(kSingleTiers))
                                             : std::vector<Setup>(std::begin(setups), std::end(setups));
    if (o.depth_pass) return run_depth_pass(rig, rows);
    if (o.receive) return run_receive(rig, rows);
    if (o.motion) return run_motion(rig, rows);
    if (o.lights) return run_lights(rig, rows);
    if (o.gbuffer) return run_gbuffer(rig, rows);
    grass_context* ctx = rig.ctx();
    std::printf("grass-tier-cost: %s (%s), %ux%u, 1024 cells of 0.25 m, frame with no grass %.2f ms (CPU %.2f ms)\n\n",
                grass_sample::backend_name(o.backend), rig.host().device_name().c_str(), o.width, o.height,
                rig.empty_ms(), rig.empty_cpu_ms());
    std::printf("| tier | macro-cells up to | instances | frame (ms) | per basic cell (us) | CPU per basic cell (us) "
                "|\n|---|---|---|---|---|---|\n");
    for (const Setup& s : rows) {
        if (!o.tier.empty() && std::strncmp(s.name, o.tier.c_str(), o.tier.size()) != 0) continue;
        const TierField tf(s, rig.patch());
        grass_field_id field{};
        grass_sample::check(grass_create_field(ctx, &tf.desc, &field), "grass_create_field", ctx);
        std::vector<double> cpu;
        const double ms = grass_sample::median_high(rig.frame_times(o.frames, nullptr, &cpu));
        const grass_frame_stats stats = rig.frame_stats();
        std::printf("| %s | %u | %llu | %.1f | %.1f | %.1f |\n", s.name, s.macro,
                    static_cast<unsigned long long>(stats.instances[s.kind]), ms,
                    1000.0 * (ms - rig.empty_ms()) / 1024.0,
                    1000.0 * (grass_sample::median_high(cpu) - rig.empty_cpu_ms()) / 1024.0);
        grass_sample::check(grass_destroy_field(ctx, field), "grass_destroy_field", ctx);
    }
    return rig.finish();
}

} // namespace tier_cost
} // namespace grass_measure
