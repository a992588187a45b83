// grass-viewer: the sample scenes (JSON or glTF, whose host meshes the window draws) in a
// window, with the GL 4.5 or the Vulkan backend: a free camera, quality presets, debug
// views, MSAA, an overlay with the frame's figures and screenshots. With --frames N
// --screenshot FILE --exit it renders N frames of the camera given as grass-render takes it
// and writes the presented image (the window test).
#include <grass/grass.h>

#include "cli.hpp"
#include "free_camera.hpp"
#include "gltf_scene.hpp"
#include "image_io.hpp"
#include "overlay.hpp"
#include "scene.hpp"
#include "tool.hpp"
#include "viewer_responsive.hpp"
#include "viewer_scene.hpp"
#include "viewer_script.hpp"
#include "window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

using grass_viewer::FreeCamera;
using grass_viewer::ViewerScene;
using grass_viewer::Window;

struct Options {
    grass_backend backend = GRASS_BACKEND_GL;
    std::string scene = "demo", screenshot, cache_dir;
    double camera[3] = {0, 0, 0}, target[3] = {0, 0, 0};
    bool have_camera = false, have_target = false;
    float fov = 0.0f, far_m = 0.0f;
    uint32_t width = 0, height = 0, samples = 0, frames = 0;
    int quality = grass_viewer::kSceneSetup;
    std::vector<grass_viewer::ScriptStep> script;
    bool no_ground = false, debug_tiers = false, debug_cells = false, exit = false, no_overlay = false;
    bool no_vsync = false, no_validation = false;
};

const char* const kScenes[] = {"football",      "park",        "hills",           "meadow",
                               "football-ball", "park-walker", "hills-helicopter"};

void add_options(CLI::App& app, Options* o) {
    grass_sample::add_backend_option(app, &o->backend);
    app.add_option("--scene", o->scene,
                   "demo (built in), football, park, hills, meadow, football-ball, park-walker, hills-helicopter "
                   "(samples/grass_render/scenes) or a scene file "
                   "(FILE.json, FILE.gltf or FILE.glb)")
        ->capture_default_str();
    grass_sample::add_size_option(app, &o->width, &o->height, 16, 8192,
                                  "window size in pixels (default from the scene, 640x360)")
        ->default_str("");
    app.add_option("--samples", o->samples, "1 or 4 (default from the scene); M switches")
        ->check(CLI::IsMember({1, 4}));
    grass_sample::add_point_option(app, "--camera", o->camera, &o->have_camera,
                                   "camera position in metres (as grass-render)");
    grass_sample::add_point_option(app, "--target", o->target, &o->have_target, "point the camera looks at");
    app.add_option("--fov", o->fov, "vertical field of view in degrees")->check(grass_sample::open_range(1, 179));
    app.add_option("--far", o->far_m, "far plane in metres (default from the scene)")
        ->check(grass_sample::open_range(1, 1e8));
    app.add_option_function<std::string>(
           "--quality",
           [o](const std::string& text) {
               for (int q = grass_viewer::kSceneSetup; q < GRASS_QUALITY_LEVEL_COUNT; ++q) {
                   if (text == grass_viewer::quality_name(q)) o->quality = q;
               }
           },
           "scene (its own lod setup), reference, high, default, low or fastest; keys 0..5")
        ->check(CLI::IsMember({"scene", "reference", "high", "default", "low", "fastest"}))
        ->default_str("scene");
    app.add_flag("--no-ground", o->no_ground, "draw no ground under the grass");
    app.add_flag("--debug-tiers", o->debug_tiers, "start with the tiers debug view (key T)");
    app.add_flag("--debug-cells", o->debug_cells, "start with the cells debug view (key C)");
    app.add_option("--frames", o->frames, "render N frames, then take the --screenshot")->check(CLI::Range(1, 100000));
    app.add_option("--screenshot", o->screenshot, "after --frames N, write the presented image (FILE.png)");
    app.add_flag("--exit", o->exit, "quit after --frames N");
    app.add_option_function<std::string>(
           "--script",
           [o](const std::string& text) {
               std::string ignored;
               grass_viewer::parse_script(text, &o->script, &ignored);
           },
           "keys and window sizes at given frames: FRAME:KEY or FRAME:size=WxH, comma-separated "
           "(e.g. 2:m,3:5,4:size=320x180)")
        ->check(CLI::Validator(
            [](std::string& text) {
                std::vector<grass_viewer::ScriptStep> steps;
                std::string error;
                return grass_viewer::parse_script(text, &steps, &error) ? std::string() : error;
            },
            "STEPS"));
    app.add_flag("--no-overlay", o->no_overlay, "start without the overlay (key F1)");
    app.add_flag("--no-vsync", o->no_vsync, "present without waiting for the display");
    app.add_flag("--no-validation", o->no_validation, "Vulkan: without the validation layers");
    app.add_option("--cache", o->cache_dir, "cache baked slices in DIR (an existing directory), as grass-render");
    app.footer(std::string("Keys:\n") + grass_viewer::kKeysHelp);
}

int fail(const std::string& message) { return grass_sample::fail("grass-viewer", message); }

bool load_named_scene(const std::string& name, grass_sample::Scene* scene, std::string* error) {
    *scene = grass_sample::demo_scene();
    if (name == "demo") return true;
    for (const char* known : kScenes) {
        if (name == known)
            return grass_sample::load_scene(std::string(GRASS_SCENE_DIR) + "/" + name + ".json", scene, error);
    }
    return grass_sample::load_scene_file(name, scene, nullptr, error); // JSON or glTF
}

// The most movement one frame applies, in seconds of travel at the camera's speed.
constexpr double kMaxMoveSeconds = 0.1;

// A key's press since the last frame.
class Keys {
public:
    explicit Keys(GLFWwindow* w) : window_(w) {}
    bool pressed(int key) {
        if (injected(key)) return true;
        const bool down = glfwGetKey(window_, key) == GLFW_PRESS;
        const bool was = down_[key];
        down_[key] = down;
        return down && !was;
    }
    bool down(int key) const { return glfwGetKey(window_, key) == GLFW_PRESS; }
    // A scripted press: pressed(key) answers true once.
    void press(int key) { down_[key] = false, injected_[key] = true; }
    bool injected(int key) {
        const bool was = injected_[key];
        injected_[key] = false;
        return was;
    }

private:
    GLFWwindow* window_;
    bool down_[GLFW_KEY_LAST + 1] = {};
    bool injected_[GLFW_KEY_LAST + 1] = {};
};

void glfw_error(int code, const char* message) {
    std::fprintf(stderr, "grass-viewer: GLFW error %d: %s\n", code, message);
}

// The grass context with the scene's grass, made again when the window's sample count changes
// the render pass.
struct Grass {
    explicit Grass(Window& w) : window(w) {}
    Window& window;
    grass_context* ctx = nullptr;
    ViewerScene scene;
    ~Grass() { reset(); }
    void reset() {
        if (ctx) window.wait_idle();
        scene.destroy();
        if (ctx) grass_destroy_context(ctx);
        ctx = nullptr;
    }
    std::string cache_dir;
    bool make(const grass_sample::Scene& s, int quality, std::string* error) {
        reset();
        grass_context_desc cd = grass_default_context_desc();
        cd.log_fn = grass_sample::log_to_stderr;
        if (!cache_dir.empty()) cd.cache_directory = cache_dir.c_str();
        const grass_result r = window.create_context(cd, &ctx);
        if (r != GRASS_SUCCESS) {
            *error = std::string("cannot create the grass context: ") + grass_result_string(r);
            return false;
        }
        return scene.create(ctx, s, quality, error) == GRASS_SUCCESS;
    }
};

int run(const Options& o, grass_sample::Scene& scene, grass_viewer::ValidationLog* validation) {
    grass_viewer::WindowDesc wd;
    wd.width = scene.width;
    wd.height = scene.height;
    wd.samples = scene.samples;
    wd.vsync = !o.no_vsync;
    wd.validation = !o.no_validation;
    wd.validation_log = validation;
    wd.scene = grass_sample::target_desc(scene);
    std::string error;
    auto window = Window::create(o.backend, wd, &error);
    if (!window) return fail("cannot open the window: " + error);
    Grass grass(*window);
    grass.cache_dir = o.cache_dir;
    if (!grass.make(scene, o.quality, &error)) return fail(error);

    FreeCamera camera;
    camera.look_at(glm::dvec3(scene.eye[0], scene.eye[1], scene.eye[2]),
                   glm::dvec3(scene.target[0], scene.target[1], scene.target[2]));
    // A key pressed and released between two frames still counts (slow frames, scripted input).
    glfwSetInputMode(window->glfw(), GLFW_STICKY_KEYS, GLFW_TRUE);
    Keys keys(window->glfw());
    grass_viewer::OverlayInfo info;
    info.backend = grass_sample::backend_name(o.backend);
    info.device = window->device_name();
    info.scene = o.scene;
    info.debug_tiers = o.debug_tiers;
    info.debug_cells = o.debug_cells;
    bool overlay = !o.no_overlay;
    uint32_t frame = 0, shots = 0;
    double last_x = 0.0, last_y = 0.0;
    bool looking = false;
    auto last = std::chrono::steady_clock::now();
    // Responsive grass runs on the wall clock: grass_view_desc.time in seconds since the start.
    const auto start = last;
    double last_time = 0.0;
    grass_viewer::ViewerResponsive responsive(scene.responsive);
    info.wind = responsive.wind_on();
    int status = 0;
    while (!glfwWindowShouldClose(window->glfw())) {
        glfwPollEvents();
        for (const grass_viewer::ScriptStep& step : o.script) {
            if (step.frame != frame + 1) continue;
            if (step.key) keys.press(step.key);
            if (step.width) glfwSetWindowSize(window->glfw(), int(step.width), int(step.height));
        }
        const auto now = std::chrono::steady_clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        const double time = std::chrono::duration<double>(now - start).count();
        last = now;
        info.frame_ms = info.frame_ms == 0.0 ? dt * 1000.0 : 0.9 * info.frame_ms + 0.1 * dt * 1000.0;

        window->overlay_new_frame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const ImGuiIO& io = ImGui::GetIO();
        bool shoot = false;
        if (!io.WantCaptureKeyboard) {
            if (keys.pressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window->glfw(), GLFW_TRUE);
            for (int q = grass_viewer::kSceneSetup; q < GRASS_QUALITY_LEVEL_COUNT; ++q) {
                if (!keys.pressed(GLFW_KEY_1 + q) || q == grass.scene.quality()) continue;
                window->wait_idle(); // the old patch and field go
                info.status = grass.scene.set_quality(q, &error) == GRASS_SUCCESS
                                  ? std::string("quality ") + grass_viewer::quality_name(q)
                                  : error;
            }
            if (keys.pressed(GLFW_KEY_T)) info.debug_tiers = !info.debug_tiers;
            if (keys.pressed(GLFW_KEY_C)) info.debug_cells = !info.debug_cells;
            if (keys.pressed(GLFW_KEY_H)) info.help = !info.help;
            if (keys.pressed(GLFW_KEY_F1)) overlay = !overlay;
            if (keys.pressed(GLFW_KEY_F2)) responsive.toggle_wind();
            if (keys.pressed(GLFW_KEY_B))
                responsive.toggle_ball(camera.position(), camera.forward(), scene.field.base_transform[13], time);
            info.wind = responsive.wind_on();
            info.ball = responsive.ball_on();
            shoot = keys.pressed(GLFW_KEY_P) || keys.pressed(GLFW_KEY_F12);
            if (keys.pressed(GLFW_KEY_M)) {
                bool stale = false;
                const int quality = grass.scene.quality();
                if (!window->set_samples(window->samples() > 1 ? 1 : 4, &stale, &error)) {
                    info.status = error;
                } else if (stale && !grass.make(scene, quality, &error)) {
                    return fail(error);
                }
            }
            const double run = keys.down(GLFW_KEY_LEFT_SHIFT) || keys.down(GLFW_KEY_RIGHT_SHIFT) ? 4.0 : 1.0;
            const double forward = double(keys.down(GLFW_KEY_W)) - double(keys.down(GLFW_KEY_S));
            const double right = double(keys.down(GLFW_KEY_D)) - double(keys.down(GLFW_KEY_A));
            const double up = double(keys.down(GLFW_KEY_E)) - double(keys.down(GLFW_KEY_Q));
            // At most a tenth of a second of movement a frame: on a software rasteriser a frame
            // can take seconds, and a short press would otherwise carry the camera the whole
            // frame's time (tens of metres, under the ground).
            const double step = std::min(dt, kMaxMoveSeconds);
            if (forward != 0.0 || right != 0.0 || up != 0.0) camera.move(forward, right, up, step * run);
        }
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window->glfw(), &x, &y);
        const bool drag = glfwGetMouseButton(window->glfw(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS ||
                          glfwGetMouseButton(window->glfw(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        if (drag && looking) camera.turn(x - last_x, y - last_y);
        looking = drag && !io.WantCaptureMouse;
        last_x = x;
        last_y = y;
        if (!io.WantCaptureMouse && io.MouseWheel != 0.0f) camera.scale_speed(io.MouseWheel);

        window->update_size(); // the view's aspect and viewport are the frame's
        grass_view_desc view = grass_default_view_desc();
        const glm::dvec3 p = camera.position();
        for (int c = 0; c < 3; ++c) view.camera_position[c] = p[c];
        const glm::mat4 rotation = camera.view_rotation();
        std::memcpy(view.view, &rotation[0][0], sizeof(view.view));
        const uint32_t w = window->width() ? window->width() : 1, h = window->height() ? window->height() : 1;
        const glm::mat4 projection =
            window->projection(glm::radians(scene.fov_degrees), float(w) / float(h), 0.05f, scene.far_m);
        std::memcpy(view.projection, &projection[0][0], sizeof(view.projection));
        view.viewport[2] = int32_t(w);
        view.viewport[3] = int32_t(h);
        grass_sample::apply_light(scene, &view);
        view.time = time;
        if (responsive.apply(grass.ctx, grass.scene.patch(), time, time - last_time, &error) != GRASS_SUCCESS)
            info.status = error;
        last_time = time;
        if (info.debug_tiers) view.flags |= GRASS_VIEW_FLAG_DEBUG_TIERS;
        if (info.debug_cells) view.flags |= GRASS_VIEW_FLAG_DEBUG_CELLS;

        info.quality = grass_viewer::quality_name(grass.scene.quality());
        info.width = window->width();
        info.height = window->height();
        info.samples = window->samples();
        for (int c = 0; c < 3; ++c) info.camera[c] = p[c];
        info.speed = camera.speed();
        if (overlay) grass_viewer::build_overlay(info);
        ImGui::Render();

        ++frame;
        const bool scripted_shot = o.frames != 0 && frame == o.frames && !o.screenshot.empty();
        grass_host::Image image;
        const grass_result r = window->draw_frame(grass.ctx, view, overlay ? ImGui::GetDrawData() : nullptr,
                                                  shoot || scripted_shot ? &image : nullptr, &error);
        if (r != GRASS_SUCCESS) {
            status = fail(std::string("frame ") + std::to_string(frame) + " failed: " + grass_result_string(r) + " (" +
                          error + ")");
            break;
        }
        grass_get_frame_stats(grass.ctx, &info.stats);
        grass_bool available = 0;
        grass_get_tier_gpu_ms(grass.ctx, info.gpu_ms, &available);
        info.gpu_available = available != 0;
        if (shoot || scripted_shot) {
            const std::string path = scripted_shot ? o.screenshot : "grass-viewer-" + std::to_string(++shots) + ".png";
            if (!grass_host::write_png(path, image, &error)) {
                status = fail(error);
                break;
            }
            info.status = "wrote " + path;
            std::printf("grass-viewer: wrote %s (%ux%u, frame %u, %s, %u samples)\n", path.c_str(), image.width,
                        image.height, frame, grass_sample::backend_name(o.backend), window->samples());
        }
        if (o.exit && o.frames != 0 && frame >= o.frames) break;
    }
    return status; // grass's context, then the window are destroyed
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app("grass-viewer: the sample scenes in a window with the GL 4.5 or the Vulkan backend: a free camera, "
                 "quality presets, debug views, MSAA, an overlay with the frame's figures, screenshots.",
                 "grass-viewer");
    Options o;
    add_options(app, &o);
    const int parsed = grass_sample::parse(app, argc, argv);
    if (parsed >= 0) return parsed;
    grass_sample::Scene scene;
    std::string error;
    if (!load_named_scene(o.scene, &scene, &error)) {
        fail(error);
        return grass_sample::is_gltf_path(o.scene) ? 2 : 1; // a bad glTF file is refused as grass-render does
    }
    if (o.have_camera) std::memcpy(scene.eye, o.camera, sizeof(o.camera));
    if (o.have_target) std::memcpy(scene.target, o.target, sizeof(o.target));
    if (o.fov > 0.0f) scene.fov_degrees = o.fov;
    if (o.far_m > 0.0f) scene.far_m = o.far_m;
    if (o.no_ground) scene.ground = false;
    if (o.width) scene.width = o.width, scene.height = o.height;
    if (o.samples) scene.samples = o.samples;
    if (!o.screenshot.empty() && o.frames == 0) return fail("--screenshot needs --frames N");

    glfwSetErrorCallback(glfw_error);
    if (!glfwInit()) return fail("glfwInit failed (no display? run it under xvfb-run -a without one)");
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    int status = 0;
    grass_viewer::ValidationLog validation;
    try {
        status = run(o, scene, &validation);
    } catch (const std::exception& e) {
        status = fail(e.what());
    }
    if (validation.messages != 0) {
        status = fail(std::to_string(validation.messages) + " validation messages:\n" + validation.text);
    }
    ImGui::DestroyContext();
    glfwTerminate();
    return status;
}
