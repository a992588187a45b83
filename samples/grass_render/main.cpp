// grass-render: renders the demo scene (or a JSON scene) headless with the GL or Vulkan
// backend, writes a PNG and prints the frame's stats.
#include "scene.hpp"

#include <grass/grass.h>

#include "headless_host.hpp"
#include "image_io.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

void usage(FILE* out) {
    std::fprintf(out,
                 "usage: grass-render [options]\n"
                 "  --backend gl|vk        GPU backend (default gl)\n"
                 "  --scene FILE.json      scene file (default: the built-in demo)\n"
                 "  --output FILE.png      image to write (default grass.png)\n"
                 "  --size WxH             image size in pixels (default from the scene, 640x360)\n"
                 "  --samples N            1 or 4 (default from the scene, 4)\n"
                 "  --camera X,Y,Z         camera position in metres\n"
                 "  --target X,Y,Z         point the camera looks at\n"
                 "  --fov DEGREES          vertical field of view\n"
                 "  --density D            uniform density multiplier 0..1\n"
                 "  --no-mirror            turn mirrored tiling off\n"
                 "  --no-ground            the host draws no ground under the grass\n"
                 "  --debug-tiers          tint each tier's grass (red geometry, yellow volume, blue image)\n"
                 "  --debug-cells          draw each planned cell or macro-cell as a tier-coloured box\n"
                 "  --far METRES           far plane of the host's projection (default from the scene, 500)\n"
                 "  --cache DIR            cache baked slices in DIR (an existing directory)\n"
                 "  --help                 this text\n");
}

bool parse3(const char* text, double out[3]) {
    return std::sscanf(text, "%lf,%lf,%lf", &out[0], &out[1], &out[2]) == 3;
}

void log_to_stderr(void*, grass_log_level level, grass_message_id id, const char* message) {
    static const char* const names[] = {"error", "warning", "info"};
    std::fprintf(stderr, "grass %s %d: %s\n", names[level], static_cast<int>(id), message);
}

int fail(const std::string& message) {
    std::fprintf(stderr, "grass-render: %s\n", message.c_str());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    grass_backend backend = GRASS_BACKEND_GL;
    std::string scene_path, output = "grass.png", cache_dir;
    grass_render::Scene scene = grass_render::demo_scene();
    // Options that override the scene file are applied after it is loaded.
    double camera[3], target[3];
    bool have_camera = false, have_target = false, no_mirror = false, no_ground = false, debug_tiers = false, debug_cells = false;
    float far_m = 0.0f;
    float fov = 0.0f, density = -1.0f;
    uint32_t width = 0, height = 0, samples = 0;

    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        auto value = [&]() -> const char* {
            if (k + 1 >= argc) {
                std::fprintf(stderr, "grass-render: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++k];
        };
        if (a == "--help" || a == "-h") {
            usage(stdout);
            return 0;
        } else if (a == "--backend") {
            const std::string b = value();
            if (b == "gl") backend = GRASS_BACKEND_GL;
            else if (b == "vk" || b == "vulkan") backend = GRASS_BACKEND_VULKAN;
            else return fail("--backend must be gl or vk, not \"" + b + "\"");
        } else if (a == "--scene") {
            scene_path = value();
        } else if (a == "--output") {
            output = value();
        } else if (a == "--size") {
            if (std::sscanf(value(), "%ux%u", &width, &height) != 2 || width == 0 || height == 0 || width > 8192 || height > 8192) {
                return fail("--size must be WxH with 1..8192 each");
            }
        } else if (a == "--samples") {
            samples = static_cast<uint32_t>(std::atoi(value()));
            if (samples != 1 && samples != 4) return fail("--samples must be 1 or 4");
        } else if (a == "--camera") {
            if (!parse3(value(), camera)) return fail("--camera must be X,Y,Z");
            have_camera = true;
        } else if (a == "--target") {
            if (!parse3(value(), target)) return fail("--target must be X,Y,Z");
            have_target = true;
        } else if (a == "--fov") {
            fov = static_cast<float>(std::atof(value()));
            if (!(fov > 1.0f && fov < 179.0f)) return fail("--fov must be between 1 and 179 degrees");
        } else if (a == "--density") {
            density = static_cast<float>(std::atof(value()));
            if (!(density >= 0.0f && density <= 1.0f)) return fail("--density must be in [0, 1]");
        } else if (a == "--no-mirror") {
            no_mirror = true;
        } else if (a == "--no-ground") {
            no_ground = true;
        } else if (a == "--debug-tiers") {
            debug_tiers = true;
        } else if (a == "--cache") {
            cache_dir = value();
        } else if (a == "--debug-cells") {
            debug_cells = true;
        } else if (a == "--far") {
            far_m = static_cast<float>(std::atof(value()));
            if (!(far_m > 1.0f && far_m < 1e8f)) return fail("--far must be between 1 and 1e8 metres");
        } else {
            usage(stderr);
            return fail("unknown option " + a);
        }
    }

    std::string error;
    if (!scene_path.empty() && !grass_render::load_scene(scene_path, &scene, &error)) return fail(error);
    if (have_camera) std::memcpy(scene.eye, camera, sizeof(camera));
    if (have_target) std::memcpy(scene.target, target, sizeof(target));
    if (fov > 0.0f) scene.fov_degrees = fov;
    if (density >= 0.0f) scene.field.density = density;
    if (no_mirror) scene.field.mirror_tiling = 0;
    if (no_ground) scene.ground = false;
    if (far_m > 0.0f) scene.far_m = far_m;
    if (width) scene.width = width, scene.height = height;
    if (samples) scene.samples = samples;

    grass_host::TargetDesc target_desc;
    target_desc.width = scene.width;
    target_desc.height = scene.height;
    target_desc.samples = scene.samples;
    target_desc.ground = scene.ground;
    std::memcpy(target_desc.ground_color, scene.ground_color, sizeof(scene.ground_color));
    auto host = grass_host::Host::create(backend, target_desc, &error);
    if (!host) return fail("cannot create the headless host: " + error);

    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = log_to_stderr;
    if (!cache_dir.empty()) cd.cache_directory = cache_dir.c_str();
    grass_context* ctx = nullptr;
    grass_result r = host->create_context(cd, &ctx);
    if (r != GRASS_SUCCESS) return fail(std::string("cannot create the grass context: ") + grass_result_string(r));

    int status = 0;
    grass_patch_id patch{};
    grass_field_id field{};
    grass_map_desc map = grass_default_map_desc();
    const auto t0 = std::chrono::steady_clock::now();
    r = grass_create_patch(ctx, &scene.patch, &patch);
    const auto t1 = std::chrono::steady_clock::now();
    const auto t_field = std::chrono::steady_clock::now();
    if (r == GRASS_SUCCESS) {
        scene.field.patch = patch;
        if (!scene.tiers.empty() || !scene.lod_tests.empty()) {
            scene.field.tiers = scene.tiers.data();
            scene.field.tier_count = static_cast<uint32_t>(scene.tiers.size());
            scene.field.lod_tests = scene.lod_tests.data();
            scene.field.lod_test_count = static_cast<uint32_t>(scene.lod_tests.size());
        }
        if (!scene.density_texels.empty()) {
            map.pixels = scene.density_texels.data();
            map.width = scene.density_width;
            map.height = scene.density_height;
            map.format = GRASS_MAP_FORMAT_R8_UNORM;
            scene.field.density_map = &map;
        }
        for (int role = 0; role < 5 && r == GRASS_SUCCESS; ++role) {
            const auto& m = scene.maps[role];
            if (m.pixels.empty()) continue;
            grass_map_desc md = grass_default_map_desc();
            md.pixels = m.pixels.data();
            md.width = m.width;
            md.height = m.height;
            md.format = m.format;
            grass_map_id id{};
            r = grass_create_map(ctx, &md, &id);
            grass_map_id* slots[5] = {&scene.field.maps.density, &scene.field.maps.color, &scene.field.maps.ambient,
                                      &scene.field.maps.diffuse, &scene.field.maps.height};
            *slots[role] = id;
        }
        scene.field.maps.height_scale = scene.height_scale;
        if (r == GRASS_SUCCESS) r = grass_create_field(ctx, &scene.field, &field);
    }
    const double field_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_field).count();
    grass_host::Image image;
    double frame_ms = 0.0;
    const bool scene_ready = r == GRASS_SUCCESS;
    if (scene_ready) {
        grass_view_desc view = grass_host::make_view(*host, scene.eye, scene.target, scene.fov_degrees, 0.05f, scene.far_m);
        if (debug_tiers) view.flags |= GRASS_VIEW_FLAG_DEBUG_TIERS;
        if (debug_cells) view.flags |= GRASS_VIEW_FLAG_DEBUG_CELLS;
        std::memcpy(view.sun_direction, scene.sun_direction, sizeof(scene.sun_direction));
        std::memcpy(view.sun_color, scene.sun_color, sizeof(scene.sun_color));
        std::memcpy(view.ambient_color, scene.ambient_color, sizeof(scene.ambient_color));
        const auto f0 = std::chrono::steady_clock::now();
        r = host->render(ctx, view, nullptr, &image, &error);
        frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - f0).count();
    }
    if (r != GRASS_SUCCESS) {
        status = fail(std::string(scene_ready ? "rendering failed: " : "the scene was refused: ") + grass_result_string(r) +
                      " (" + grass_get_last_error(ctx) + ")" + (error.empty() || error == grass_get_last_error(ctx) ? "" : " " + error));
    } else if (!grass_host::write_png(output, image, &error)) {
        status = fail(error);
    } else {
        grass_frame_stats stats{};
        grass_get_frame_stats(ctx, &stats);
        grass_patch_info info{};
        grass_get_patch_info(ctx, patch, &info);
        std::printf("grass-render: wrote %s (%ux%u, %u samples)\n", output.c_str(), image.width, image.height, scene.samples);
        std::printf("  backend         %s (%s)\n", backend == GRASS_BACKEND_GL ? "gl" : "vk", host->device_name().c_str());
        std::printf("  patch           %u blades, %u triangles, hash %016llx, generated in %.1f ms\n", info.blade_count,
                    info.triangle_count, static_cast<unsigned long long>(info.content_hash),
                    std::chrono::duration<double, std::milli>(t1 - t0).count());
        std::printf("  field           %u x %u cells of %.3f m, created in %.1f ms (slices baked or read from the cache)\n",
                    scene.field.cells_x, scene.field.cells_z, scene.field.cell_size, field_ms);
        std::printf("  quadtree        %llu nodes visited, %llu culled, %llu lod-test calls\n",
                    static_cast<unsigned long long>(stats.nodes_visited), static_cast<unsigned long long>(stats.nodes_culled),
                    static_cast<unsigned long long>(stats.lod_test_calls));
        static const char* const kinds[GRASS_TIER_KIND_COUNT] = {"geometry", "volume", "image"};
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
            std::printf("  %-15s %llu instances (%llu macro-cells) covering %llu cells\n", kinds[k],
                        static_cast<unsigned long long>(stats.instances[k]), static_cast<unsigned long long>(stats.macro_cells[k]),
                        static_cast<unsigned long long>(stats.cells[k]));
        }
        std::printf("  blades          %llu drawn of %llu submitted\n", static_cast<unsigned long long>(stats.blades_drawn),
                    static_cast<unsigned long long>(stats.blades_submitted));
        std::printf("  triangles       %llu\n", static_cast<unsigned long long>(stats.triangles));
        std::printf("  plan            %.3f ms\n", stats.plan_ms);
        std::printf("  frame           %.1f ms (wall, incl. read-back)\n", frame_ms);
        if (host->validation_messages() != 0) {
            std::printf("  validation      %u messages:\n%s\n", host->validation_messages(), host->validation_log().c_str());
            status = 1;
        }
    }
    grass_destroy_context(ctx);
    return status;
}
