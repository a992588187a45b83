// grass-render: renders the demo scene (or a JSON scene) headless with the GL or Vulkan
// backend, writes a PNG and prints the frame's stats; with --frames, an animation (wind,
// moving colliders and their trails: docs/responsive.md).
#include <grass/grass.h>

#include "animation.hpp"
#include "cli.hpp"
#include "gltf_scene.hpp"
#include "headless_host.hpp"
#include "host_scene_options.hpp"
#include "image_io.hpp"
#include "scene.hpp"
#include "tool.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// grass_view_desc.time's range (docs/api.md): every frame's time is checked against it before
// the first is drawn.
constexpr double kMaxViewTime = 1e9;

struct Options {
    grass_backend backend = GRASS_BACKEND_GL;
    std::string scene_path, output = "grass.png", cache_dir;
    // Options that override the scene file are applied after it is loaded.
    double camera[3] = {0, 0, 0}, target[3] = {0, 0, 0}, lod_origin[3] = {0, 0, 0};
    bool have_camera = false, have_target = false, have_lod_origin = false, no_mirror = false, no_ground = false,
         debug_tiers = false;
    bool debug_cells = false;
    float far_m = 0.0f, fov = 0.0f, density = -1.0f;
    uint32_t width = 0, height = 0, samples = 0;
    // Responsive grass: the frames' times and what moves.
    double time = 0.0, fps = 24.0;
    uint32_t frames = 1;
    std::string wind, animation_dir;
    std::vector<std::string> colliders;
    std::vector<std::string> blade_culling;    // per-blade culling tests (grass_set_blade_culling)
    float tessellation = 0.0f;                 // error pixels of the blades' dynamic tessellation; 0: off
    grass_sample::HostSceneOptions host_scene; // --box, --tree, --host-shadows
};

void add_options(CLI::App& app, Options* o) {
    grass_sample::add_backend_option(app, &o->backend);
    app.add_option("--scene", o->scene_path,
                   "scene file (FILE.json, FILE.gltf or FILE.glb; default: the built-in demo)");
    app.add_option("--output", o->output, "image to write (FILE.png)")->capture_default_str();
    grass_sample::add_size_option(app, &o->width, &o->height, 1, grass_sample::kMaxImageSide,
                                  "image size in pixels (default from the scene, 640x360)")
        ->default_str("");
    app.add_option("--samples", o->samples, "1 or 4 (default from the scene, 4)")->check(CLI::IsMember({1, 4}));
    grass_sample::add_point_option(app, "--camera", o->camera, &o->have_camera, "camera position in metres");
    grass_sample::add_point_option(app, "--target", o->target, &o->have_target, "point the camera looks at");
    grass_sample::add_point_option(app, "--lod-origin", o->lod_origin, &o->have_lod_origin,
                                   "the point the tiers' distances are measured from (grass_lod_origin_desc; default "
                                   "the camera): a third-person camera gives its character's feet");
    app.add_option("--fov", o->fov, "vertical field of view in degrees")->check(grass_sample::open_range(0, 180));
    app.add_option("--density", o->density, "uniform density multiplier 0..1")
        ->check(grass_sample::closed_range(0.0, 1.0));
    app.add_flag("--no-mirror", o->no_mirror, "turn mirrored tiling off");
    app.add_flag("--no-ground", o->no_ground, "the host draws no ground under the grass");
    app.add_flag("--debug-tiers", o->debug_tiers, "tint each tier's grass (red geometry, yellow volume, blue image)");
    app.add_flag("--debug-cells", o->debug_cells, "draw each planned cell or macro-cell as a tier-coloured box");
    app.add_option("--far", o->far_m, "far plane of the host's projection in metres (default from the scene, 500)")
        ->check(grass_sample::open_range(1, 1e8));
    app.add_option("--cache", o->cache_dir, "cache baked slices in DIR (an existing directory)");
    app.add_option("--time", o->time, "time of the first frame in seconds (grass_view_desc.time: wind, paths)")
        ->check(grass_sample::closed_range(-kMaxViewTime, kMaxViewTime))
        ->capture_default_str();
    app.add_option("--frames", o->frames, "frames to render, 1/fps apart (the last one is --output)")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    app.add_option("--fps", o->fps, "frames per second: the time step between frames is 1/fps")
        ->check(grass_sample::open_range(0, 1e4))
        ->capture_default_str();
    app.add_option("--wind", o->wind, "mean wind DX,DZ,SPEED[,GUST]: direction across y, m/s, gust strength")
        ->check(CLI::Validator(
            [](std::string& text) {
                grass_wind_desc w = grass_default_wind_desc();
                std::string error;
                return grass_sample::parse_wind(text, &w, &error) ? std::string() : error;
            },
            "DX,DZ,SPEED[,GUST]"));
    grass_sample::add_blade_culling_option(app, &o->blade_culling, "in the geometry tier");
    grass_sample::add_tessellation_option(app, &o->tessellation, "in the geometry tier");
    app.add_option("--collider", o->colliders,
                   "a collider (repeatable): sphere:X,Y,Z,R[,VX,VY,VZ] or capsule:AX,AY,AZ,BX,BY,BZ,R[,VX,VY,VZ], "
                   "metres, moving at the velocity in m/s from --time on")
        ->check(CLI::Validator(
            [](std::string& text) {
                grass_sample::SceneCollider c;
                std::string error;
                return grass_sample::parse_collider(text, 0.0, 1.0, &c, &error) ? std::string() : error;
            },
            "SHAPE:NUMBERS"));
    grass_sample::add_host_scene_options(app, &o->host_scene);
    app.add_option("--animation", o->animation_dir,
                   "write every frame to DIR/frame-NNNN.png, then DIR/animation.gif and DIR/animation.mp4 (ffmpeg)");
}

// The command line's wind and colliders over the scene file's.
void apply_responsive_options(const Options& o, grass_sample::Responsive* r) {
    std::string error;
    if (!o.wind.empty()) {
        grass_sample::parse_wind(o.wind, &r->wind, &error);
        r->wind_given = true;
    }
    const double end = o.time + (o.frames - 1) / o.fps;
    for (const std::string& text : o.colliders) {
        grass_sample::SceneCollider c;
        grass_sample::parse_collider(text, o.time, end, &c, &error);
        r->colliders.push_back(c);
    }
}

// What a glTF scene brought besides grass.
void print_gltf(const grass_sample::GltfInfo& g, const grass_sample::Scene& scene) {
    std::printf("  glTF terrain    %s: %llu triangles, maps of %u x %u texels\n", g.terrain.c_str(),
                static_cast<unsigned long long>(g.terrain_triangles), g.map_width, g.map_height);
    std::printf("  glTF meshes     %zu drawn by the host, %llu triangles\n", scene.meshes.size(),
                static_cast<unsigned long long>(g.mesh_triangles));
    std::printf("  glTF camera     %s\n", g.camera.empty() ? "none (the defaults or --camera)" : g.camera.c_str());
    for (const grass_sample::GltfCollider& c : g.colliders) {
        const bool sphere = c.shape == grass_sample::GltfCollider::Shape::sphere;
        std::printf("  glTF collider   %s: %s radius %.3f m at (%.3f, %.3f, %.3f)", c.node.c_str(),
                    sphere ? "sphere" : "capsule", c.radius, c.a[0], c.a[1], c.a[2]);
        if (!sphere) std::printf(" to (%.3f, %.3f, %.3f)", c.b[0], c.b[1], c.b[2]);
        std::printf(" (not passed to grass by the sample tools)\n");
    }
    for (const std::string& note : g.notes) std::printf("  glTF note       %s\n", note.c_str());
}

int fail(const std::string& message) { return grass_sample::fail("grass-render", message); }

// What the options ask that no frame could honour, checked before anything is drawn: the
// last frame's time (--time 1e9 --frames 3 failed only after the first frame).
std::string option_problem(const Options& o) {
    const double last = o.time + (o.frames - 1) / o.fps;
    if (!(std::fabs(last) <= kMaxViewTime)) {
        char text[200];
        std::snprintf(text, sizeof(text),
                      "--time %.17g with --frames %u at --fps %.17g puts the last frame at %.17g s; a frame's time "
                      "lies in [-1e9, 1e9]",
                      o.time, o.frames, o.fps, last);
        return text;
    }
    return "";
}

// What the scene, with the options over it, asks that grass-render cannot honour: a camera
// that sees nothing, more colliders than grass takes, more moving meshes than it draws.
std::string scene_problem(const Options& o, const grass_sample::Scene& scene) {
    if (!(scene.far_m > scene.near_m)) {
        return (o.far_m > 0.0f ? "--far " + std::to_string(o.far_m)
                               : "the scene's far plane " + std::to_string(scene.far_m)) +
               " m is not beyond the near plane (" + std::to_string(scene.near_m) + " m)";
    }
    const size_t colliders = scene.responsive.colliders.size();
    if (colliders > GRASS_MAX_COLLIDERS) {
        return "the scene and --collider give " + std::to_string(colliders) + " colliders; grass takes at most " +
               std::to_string(GRASS_MAX_COLLIDERS);
    }
    const size_t meshes = grass_sample::moving_mesh_count(scene.responsive);
    if (meshes > grass_sample::kMaxMovingMeshes) {
        return "the colliders and wind sources need " + std::to_string(meshes) +
               " meshes to draw; grass-render draws at most " + std::to_string(grass_sample::kMaxMovingMeshes);
    }
    return "";
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app("grass-render: renders the demo scene (or a JSON scene) headless with the GL or Vulkan backend, "
                 "writes a PNG and prints the frame's stats.",
                 "grass-render");
    Options o;
    add_options(app, &o);
    const int parsed = grass_sample::parse(app, argc, argv);
    if (parsed >= 0) return parsed;
    const std::string bad_options = option_problem(o);
    if (!bad_options.empty()) {
        fail(bad_options);
        return 2;
    }
    const grass_backend backend = o.backend;
    const std::string& output = o.output;
    grass_sample::Scene scene = grass_sample::demo_scene();

    std::string error;
    grass_sample::GltfInfo gltf;
    const bool is_gltf = grass_sample::is_gltf_path(o.scene_path);
    if (!o.scene_path.empty() && !grass_sample::load_scene_file(o.scene_path, &scene, &gltf, &error)) {
        fail(error);
        return is_gltf ? 2 : 1; // a bad glTF file is refused like a bad option value
    }
    if (o.have_camera) std::memcpy(scene.eye, o.camera, sizeof(o.camera));
    if (o.have_target) std::memcpy(scene.target, o.target, sizeof(o.target));
    if (o.fov > 0.0f) scene.fov_degrees = o.fov;
    if (o.density >= 0.0f) scene.field.density = o.density;
    if (o.no_mirror) scene.field.mirror_tiling = 0;
    if (o.no_ground) scene.ground = false;
    if (o.far_m > 0.0f) scene.far_m = o.far_m;
    if (o.width) scene.width = o.width, scene.height = o.height;
    if (o.samples) scene.samples = o.samples;
    apply_responsive_options(o, &scene.responsive);
    const std::string bad_scene = scene_problem(o, scene);
    if (!bad_scene.empty()) return fail(bad_scene);
    grass_sample::add_host_meshes(o.host_scene, &scene.meshes);
    // The host draws the colliders (balls, legs) and point wind sources and moves them every frame.
    const size_t first_mesh = scene.meshes.size();
    for (grass_host::HostMesh& m : grass_sample::moving_meshes(scene.responsive, o.time))
        scene.meshes.push_back(std::move(m));

    grass_host::TargetDesc target = grass_sample::target_desc(scene);
    grass_sample::apply_host_shadows(o.host_scene, &target);
    auto host = grass_host::Host::create(backend, target, &error);
    if (!host) return fail("cannot create the headless host: " + error);

    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = grass_sample::log_to_stderr;
    if (!o.cache_dir.empty()) cd.cache_directory = o.cache_dir.c_str();
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
        r = grass_sample::create_scene_maps(ctx, scene, &scene.field.maps);
        if (r == GRASS_SUCCESS) r = grass_create_field(ctx, &scene.field, &field);
        grass_wind_map_desc wind_map{};
        if (r == GRASS_SUCCESS) r = grass_sample::create_scene_wind_map(ctx, scene, &wind_map);
        if (r == GRASS_SUCCESS) r = grass_sample::set_scene_wind_map(ctx, wind_map, field);
        if (r == GRASS_SUCCESS && !o.blade_culling.empty()) {
            const grass_blade_culling_desc culling = grass_sample::blade_culling_desc(o.blade_culling);
            r = grass_set_blade_culling(ctx, field, &culling);
        }
        if (r == GRASS_SUCCESS) r = grass_sample::set_tessellation(ctx, field, o.tessellation);
    }
    const double field_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_field).count();
    grass_host::Image image;
    double frame_ms = 0.0;
    std::string animation_error; // the animation's directory, frames, GIF or MP4 failed
    const bool scene_ready = r == GRASS_SUCCESS;
    if (scene_ready) {
        grass_view_desc view =
            grass_host::make_view(*host, scene.eye, scene.target, scene.fov_degrees, scene.near_m, scene.far_m);
        grass_lod_origin_desc lod_origin = grass_default_lod_origin_desc();
        if (o.have_lod_origin) {
            std::memcpy(lod_origin.position, o.lod_origin, sizeof(o.lod_origin));
            view.next = &lod_origin;
        }
        if (o.debug_tiers) view.flags |= GRASS_VIEW_FLAG_DEBUG_TIERS;
        if (o.debug_cells) view.flags |= GRASS_VIEW_FLAG_DEBUG_CELLS;
        grass_sample::apply_light(scene, &view);
        grass_sample::Animation animation;
        const bool animate = !o.animation_dir.empty();
        if (animate) animation.open(o.animation_dir, o.fps, &animation_error);
        // Each frame 1/fps after the previous: the wind's time and the paths' positions; the
        // colliders' velocities sweep what they did over that step.
        const double step = 1.0 / o.fps;
        for (uint32_t k = 0; k < o.frames && r == GRASS_SUCCESS && animation_error.empty(); ++k) {
            view.time = o.time + k * step;
            r = grass_sample::apply_responsive(ctx, patch, scene.responsive, view.time, step, k == 0);
            if (r != GRASS_SUCCESS) break;
            const auto origins = grass_sample::moving_mesh_origins(scene.responsive, view.time);
            for (size_t i = 0; i < origins.size(); ++i) host->move_mesh(first_mesh + i, origins[i].data());
            const auto f0 = std::chrono::steady_clock::now();
            r = host->render(ctx, view, nullptr, &image, &error);
            frame_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - f0).count();
            if (r == GRASS_SUCCESS && animate) animation.add(image, &animation_error);
        }
        if (r == GRASS_SUCCESS && animate && animation_error.empty() && animation.finish(&animation_error)) {
            std::printf("grass-render: wrote %zu frames to %s/, %s and %s\n", animation.frames().size(),
                        o.animation_dir.c_str(), animation.gif().c_str(), animation.mp4().c_str());
        }
    }
    if (r != GRASS_SUCCESS) {
        status = fail(std::string(scene_ready ? "rendering failed: " : "the scene was refused: ") +
                      grass_result_string(r) + " (" + grass_get_last_error(ctx) + ")" +
                      (error.empty() || error == grass_get_last_error(ctx) ? "" : " " + error));
    } else if (!animation_error.empty()) {
        status = fail("cannot write the animation: " + animation_error);
    } else if (!grass_host::write_png(output, image, &error)) {
        status = fail(error);
    } else {
        grass_frame_stats stats{};
        grass_get_frame_stats(ctx, &stats);
        grass_patch_info info{};
        grass_get_patch_info(ctx, patch, &info);
        std::printf("grass-render: wrote %s (%ux%u, %u samples)\n", output.c_str(), image.width, image.height,
                    scene.samples);
        std::printf("  backend         %s (%s)\n", grass_sample::backend_name(backend), host->device_name().c_str());
        std::printf("  patch           %u blades, %u triangles, hash %016llx, generated in %.1f ms\n", info.blade_count,
                    info.triangle_count, static_cast<unsigned long long>(info.content_hash),
                    std::chrono::duration<double, std::milli>(t1 - t0).count());
        std::printf(
            "  field           %u x %u cells of %.3f m, created in %.1f ms (slices baked or read from the cache)\n",
            scene.field.cells_x, scene.field.cells_z, scene.field.cell_size, field_ms);
        std::printf("  quadtree        %llu nodes visited, %llu culled, %llu lod-test calls\n",
                    static_cast<unsigned long long>(stats.nodes_visited),
                    static_cast<unsigned long long>(stats.nodes_culled),
                    static_cast<unsigned long long>(stats.lod_test_calls));
        static const char* const kinds[GRASS_TIER_KIND_COUNT] = {"geometry", "volume", "image"};
        for (int k = 0; k < GRASS_TIER_KIND_COUNT; ++k) {
            std::printf("  %-15s %llu instances (%llu macro-cells) covering %llu cells\n", kinds[k],
                        static_cast<unsigned long long>(stats.instances[k]),
                        static_cast<unsigned long long>(stats.macro_cells[k]),
                        static_cast<unsigned long long>(stats.cells[k]));
        }
        std::printf("  blades          %llu drawn of %llu submitted\n",
                    static_cast<unsigned long long>(stats.blades_drawn),
                    static_cast<unsigned long long>(stats.blades_submitted));
        std::printf("  triangles       %llu\n", static_cast<unsigned long long>(stats.triangles));
        std::printf("  plan            %.3f ms\n", stats.plan_ms);
        if (scene.responsive.any()) {
            grass_memory_stats memory{};
            grass_get_memory_stats(ctx, &memory);
            std::printf("  responsive      %llu colliders (%llu in the map), %llu map texels updated, step %.4f s, "
                        "%.2f MiB of GPU memory\n",
                        static_cast<unsigned long long>(stats.colliders),
                        static_cast<unsigned long long>(stats.colliders_in_map),
                        static_cast<unsigned long long>(stats.interaction_texels), stats.time_step,
                        static_cast<double>(memory.dynamics_gpu_bytes) / (1024.0 * 1024.0));
        }
        std::printf("  frame           %.1f ms (wall, incl. read-back)%s\n", frame_ms,
                    o.frames > 1 ? ", the last of the frames" : "");
        if (is_gltf) print_gltf(gltf, scene);
        if (host->validation_messages() != 0) {
            std::printf("  validation      %u messages:\n%s\n", host->validation_messages(),
                        host->validation_log().c_str());
            status = 1;
        }
    }
    grass_destroy_context(ctx);
    return status;
}
