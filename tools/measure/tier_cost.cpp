// grass-measure tier-cost: the subcommand, the rig every mode measures with, and what the
// modes share (tier_cost.hpp explains the measures).
#include "tier_cost.hpp"

#include "cli.hpp"
#include "measure.hpp"
#include "scene.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

namespace grass_measure {
namespace tier_cost {

const Setup kSingleTiers[3] = {{"geometry", GRASS_TIER_GEOMETRY, 0, 1},
                               {"volume, 8 slices", GRASS_TIER_VOLUME, 8, 1},
                               {"image", GRASS_TIER_IMAGE, 0, 1}};

Rig::Rig(const Options& options) : options_(options) {
    // The scene file first: a bad one is refused before a host starts.
    grass_patch_desc pd = grass_default_patch_desc();
    if (!options.patch_scene.empty()) {
        grass_sample::Scene scene;
        std::string scene_error;
        if (!grass_sample::load_scene(options.patch_scene, &scene, &scene_error)) {
            throw grass_sample::Failure("--patch-of: " + scene_error);
        }
        pd = scene.patch;
    }
    grass_host::TargetDesc target;
    target.width = options.width;
    target.height = options.height;
    // --depth-pass on Vulkan: the host's depth-only pass, given to grass (grass_vk_depth_pass_desc).
    target.vk_depth_pass = target.read_depth = options.depth_pass && options.backend == GRASS_BACKEND_VULKAN;
    // --motion on Vulkan: the host's pass with an RGBA32F velocity target at colour attachment 1,
    // given to grass (grass_vk_velocity_target_desc).
    if (options.motion && options.backend == GRASS_BACKEND_VULKAN) target.vk_velocity_attachment = 1;
    // --gbuffer on Vulkan: the host's pass with two more RGBA8 UNORM colour attachments (normal,
    // material), given to grass (grass_vk_gbuffer_target_desc); albedo into its colour.
    if (options.gbuffer && options.backend == GRASS_BACKEND_VULKAN) {
        target.vk_gbuffer_formats[0] = target.vk_gbuffer_formats[1] = 37; // VK_FORMAT_R8G8B8A8_UNORM
    }
    std::string error;
    host_ = grass_host::Host::create(options.backend, target, &error);
    if (!host_) throw grass_sample::Failure("cannot create the headless host: " + error);
    const grass_context_desc cd = grass_default_context_desc();
    grass_sample::check(host_->create_context(cd, &ctx_), "grass_create_context");
    grass_sample::check(grass_create_patch(ctx_, &pd, &patch_), "grass_create_patch", ctx_);
    view_ = grass_host::make_view(*host_, eye_, look_, 55.0f, 0.05f, 200.0f);
    std::vector<double> cpu;
    empty_ms_ = grass_sample::median_high(frame_times(options.frames, nullptr, &cpu));
    empty_cpu_ms_ = grass_sample::median_high(cpu);
}

Rig::~Rig() {
    if (ctx_) grass_destroy_context(ctx_);
}

std::vector<double> Rig::frame_times(int count, std::vector<double>* plan_ms, std::vector<double>* cpu_ms) {
    std::vector<double> times;
    grass_host::Image image;
    std::string error;
    for (int r = 0; r < count + 1; ++r) {
        view_.time += time_step_;
        const auto t0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock(); // the process's CPU time, all threads
        const grass_result result = host_->render(ctx_, view_, nullptr, &image, &error);
        const double cpu = 1000.0 * double(std::clock() - c0) / CLOCKS_PER_SEC;
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (result != GRASS_SUCCESS) {
            throw grass_sample::Failure(std::string("rendering failed: ") + grass_result_string(result) + " (" +
                                        grass_get_last_error(ctx_) + ") " + error);
        }
        if (r == 0) continue; // the first frame uploads
        times.push_back(ms);
        if (cpu_ms) cpu_ms->push_back(cpu);
        if (plan_ms) plan_ms->push_back(frame_stats().plan_ms);
    }
    return times;
}

void Rig::per_cell_variants(int variants, const std::function<void(int)>& set_variant, double* us, double* cpu_us) {
    std::vector<std::vector<double>> wall(static_cast<size_t>(variants)), cpu(static_cast<size_t>(variants));
    for (int round = 0; round < 3; ++round) {
        for (int v = 0; v < variants; ++v) {
            set_variant(v);
            std::vector<double> c;
            const std::vector<double> w = frame_times(options_.frames, nullptr, &c);
            wall[size_t(v)].insert(wall[size_t(v)].end(), w.begin(), w.end());
            cpu[size_t(v)].insert(cpu[size_t(v)].end(), c.begin(), c.end());
        }
    }
    for (int v = 0; v < variants; ++v) {
        us[v] = 1000.0 * (grass_sample::median_high(wall[size_t(v)]) - empty_ms_) / 1024.0;
        cpu_us[v] = 1000.0 * (grass_sample::median_high(cpu[size_t(v)]) - empty_cpu_ms_) / 1024.0;
    }
}

grass_frame_stats Rig::frame_stats() {
    grass_frame_stats stats{};
    grass_sample::check(grass_get_frame_stats(ctx_, &stats), "grass_get_frame_stats", ctx_);
    return stats;
}

grass_memory_stats Rig::memory_stats() {
    grass_memory_stats mem{};
    grass_sample::check(grass_get_memory_stats(ctx_, &mem), "grass_get_memory_stats", ctx_);
    return mem;
}

int Rig::finish() {
    const uint32_t messages = host_->validation_messages();
    grass_destroy_context(ctx_);
    ctx_ = nullptr;
    if (messages) {
        std::fprintf(stderr, "grass-measure tier-cost: %u validation messages\n%s\n", messages,
                     host_->validation_log().c_str());
        return 1;
    }
    return 0;
}

TierField::TierField(const Setup& s, grass_patch_id patch) : tier{s.kind, s.slices} {
    tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[0].end = INFINITY;
    tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[1].max_macro_cells = s.macro;
    desc = grass_default_field_desc();
    desc.patch = patch;
    desc.cells_x = desc.cells_z = kCells;
    desc.tiers = &tier;
    desc.tier_count = 1;
    desc.lod_tests = tests;
    desc.lod_test_count = s.kind == GRASS_TIER_GEOMETRY ? 1 : 2;
}

uint32_t band_tests(const Setup& s, uint32_t tier, float begin, float end, float in, float out, grass_lod_test* tests) {
    tests[0] = {};
    tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    tests[0].tier = tier;
    tests[0].begin = begin;
    tests[0].end = end;
    tests[0].transition_in = in;
    tests[0].transition_out = out;
    if (s.kind == GRASS_TIER_GEOMETRY) return 1; // the geometry tier draws single cells by itself
    tests[1] = {};
    tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
    tests[1].tier = tier;
    tests[1].max_macro_cells = s.macro;
    return 2;
}

void make_maps(grass_context* ctx, uint32_t bits, double cell_size, grass_map_stack* stack,
               std::vector<grass_map_id>* made) {
    const uint32_t n = kMapSize;
    auto create = [&](const void* pixels, grass_map_format format, grass_map_id* id) {
        grass_map_desc md = grass_default_map_desc();
        md.pixels = pixels;
        md.width = md.height = n;
        md.format = format;
        grass_sample::check(grass_create_map(ctx, &md, id), "grass_create_map", ctx);
        made->push_back(*id);
    };
    std::vector<uint8_t> r8(n * n);
    if (bits & kDensity) { // density 1 everywhere: every blade passes, the map is still sampled
        std::fill(r8.begin(), r8.end(), uint8_t(255));
        create(r8.data(), GRASS_MAP_FORMAT_R8_UNORM, &stack->density);
    }
    if (bits & kColor) { // a straw-to-green wash along x, stripes along z, alpha 0.3
        std::vector<uint8_t> rgba(n * n * 4);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                uint8_t* t = &rgba[4 * (y * n + x)];
                t[0] = uint8_t(120 + 100 * x / n);
                t[1] = uint8_t((y / 16) % 2 ? 170 : 140);
                t[2] = uint8_t(60);
                t[3] = uint8_t(77); // 0.3
            }
        create(rgba.data(), GRASS_MAP_FORMAT_RGBA8_UNORM, &stack->color);
    }
    if (bits & kAmbient) { // ambient occlusion: darker towards one corner, 0.5 .. 1
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) r8[y * n + x] = uint8_t(255 - 64 * (x + y) / n);
        create(r8.data(), GRASS_MAP_FORMAT_R8_UNORM, &stack->ambient);
    }
    if (bits & kDiffuse) { // a soft shadow band across the middle of the field, 0.3 .. 1
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const double d = std::fabs(double(x) - 0.5 * n) / (0.25 * n);
                r8[y * n + x] = uint8_t(255 * (0.3 + 0.7 * std::min(1.0, d)));
            }
        create(r8.data(), GRASS_MAP_FORMAT_R8_UNORM, &stack->diffuse);
    }
    if (bits & kHeight) { // a gentle ramp along x: 0 .. 1 cell over the 32 cells
        std::vector<uint16_t> r16(n * n);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) r16[y * n + x] = uint16_t(65535u * x / (n - 1));
        create(r16.data(), GRASS_MAP_FORMAT_R16_UNORM, &stack->height);
        stack->height_scale = float(cell_size);
    }
}

Cost cost(const std::vector<double>& times, const std::vector<double>& empties) {
    return {grass_sample::median_high(times) - grass_sample::median_high(empties),
            grass_sample::fastest(times) - grass_sample::fastest(empties)};
}

} // namespace tier_cost

Subcommand add_tier_cost(CLI::App& measure) {
    auto o = std::make_shared<tier_cost::Options>();
    CLI::App* app = measure.add_subcommand(
        "tier-cost", "The frame cost of each tier per basic cell (1024 cells drawn by each tier alone, and in "
                     "macro-cells); --maps: of each design map; --features: of the other optional features. "
                     "Prints a Markdown table.");
    grass_sample::add_backend_option(*app, &o->backend);
    grass_sample::add_size_option(*app, &o->width, &o->height, 16, 4096, "image size in pixels");
    CLI::Option* maps =
        app->add_flag("--maps", o->maps, "the cost of each design map instead (docs/records/feature-cost.md)");
    CLI::Option* features =
        app->add_flag("--features", o->features,
                      "the cost of the other optional features instead (docs/records/feature-cost.md)")
            ->excludes(maps);
    app->add_flag("--single", o->single, "only the tiers alone in single cells (geometry, volume 8 slices, image)")
        ->excludes(maps)
        ->excludes(features);
    app->add_option("--frames", o->frames, "frames measured per row (after one that uploads; median)")
        ->capture_default_str()
        ->check(grass_sample::at_least(1));
    app->add_option("--patch-of", o->patch_scene,
                    "draw the patch of this scene file (FILE.json: its \"patch\"), not the default patch")
        ->check(CLI::ExistingFile);
    app->add_option("--tier", o->tier, "only the rows of this tier (to profile one)")
        ->check(CLI::IsMember({"geometry", "volume", "image"}))
        ->excludes(maps)
        ->excludes(features);
    app->add_flag("--depth-pass", o->depth_pass,
                  "each row of the plain table also as a depth pass of the same view (docs/records/depth-pass.md)")
        ->excludes(maps)
        ->excludes(features);
    auto* receive = app->add_flag("--receive", o->receive,
                                  "each row of the plain table also receiving a shadow map over half the field "
                                  "(docs/records/shadow-receiving.md)");
    receive->excludes(maps)->excludes(features)->excludes("--depth-pass");
    app->add_flag("--motion", o->motion,
                  "each row of the plain table also writing motion vectors, still and in wind "
                  "(docs/records/motion-vectors.md)")
        ->excludes(maps)
        ->excludes(features)
        ->excludes("--depth-pass")
        ->excludes(receive);
    app->add_flag("--lights", o->lights,
                  "each row of the plain table also lit by the host's lights: 1, 8, and 8 with specular and "
                  "harmonics, GL (docs/records/host-lights.md)")
        ->excludes(maps)
        ->excludes(features)
        ->excludes("--depth-pass")
        ->excludes(receive)
        ->excludes("--motion");
    app->add_flag("--gbuffer", o->gbuffer,
                  "each row of the plain table also as a G-buffer view (albedo, normal, material), GL "
                  "(docs/records/gbuffer.md)")
        ->excludes(maps)
        ->excludes(features)
        ->excludes("--depth-pass")
        ->excludes(receive)
        ->excludes("--motion")
        ->excludes("--lights");
    app->add_option("--rounds", o->rounds, "--maps and --features: rounds, each drawing every row once")
        ->capture_default_str()
        ->check(grass_sample::at_least(1));
    return {app, [o]() {
                tier_cost::Rig rig(*o);
                if (o->maps) return tier_cost::run_maps(rig);
                if (o->features) return tier_cost::run_features(rig);
                return tier_cost::run_plain(rig);
            }};
}

} // namespace grass_measure
