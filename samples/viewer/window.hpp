// A viewer window: a GLFW window and the backend's device around it (a GL 4.5 context, or
// a Vulkan instance, device and swapchain), the frame the host draws into it (sky, ground,
// the scene's host meshes, grass, the overlay) and the read-back of the presented image. One
// per backend: window_gl.cpp and window_vk.cpp.
#pragma once

#include <grass/grass.h>

#include "headless_host.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>

struct GLFWwindow;
struct ImDrawData;

namespace grass_viewer {

// Validation messages: Vulkan's layers' warnings and errors, GL's debug-output errors. The
// caller keeps it, so that the messages of the window's destruction count too.
struct ValidationLog {
    uint32_t messages = 0;
    std::string text;
    void add(const std::string& line) {
        ++messages;
        text += line + "\n";
    }
};

struct WindowDesc {
    uint32_t width = 640, height = 360; // framebuffer pixels
    uint32_t samples = 4;               // 1 or 4
    bool vsync = true;
    bool validation = true;                  // Vulkan: the validation layers when installed
    ValidationLog* validation_log = nullptr; // required
    // The host's scene: sky colour, ground and host meshes (the headless hosts' TargetDesc
    // fields; the meshes drawn with their mesh drawers).
    grass_host::TargetDesc scene;
};

class Window {
public:
    // nullptr and *error when the window or the device cannot be had.
    static std::unique_ptr<Window> create(grass_backend backend, const WindowDesc& desc, std::string* error);
    virtual ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* glfw() const { return window_; }
    virtual grass_backend backend() const = 0;
    virtual std::string device_name() const = 0;
    // Reads the window's framebuffer size (call it before making the frame's view: the next
    // draw_frame makes its targets that size).
    void update_size();
    // The framebuffer's size at the last update_size (it follows the window).
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    uint32_t samples() const { return samples_; }

    // A grass context on this window's device, for its current sample count.
    virtual grass_result create_context(const grass_context_desc& desc, grass_context** out) = 0;
    // The projection for this backend's clip convention (GL: z -1..1, y up; Vulkan: z 0..1,
    // y down), as the headless hosts make it.
    virtual glm::mat4 projection(float fovy_radians, float aspect, float near_m, float far_m) const = 0;
    // Changes the sample count (1 or 4). True when grass contexts made for the old count
    // must be made again (Vulkan: the render pass changed); *error on failure.
    virtual bool set_samples(uint32_t samples, bool* contexts_stale, std::string* error) = 0;

    // Waits until the device has finished every frame submitted (Vulkan); grass objects may
    // be destroyed only then (docs/api.md). GL: nothing to wait for.
    virtual void wait_idle() {}

    // Starts the overlay's frame (ImGui's backends) before ImGui::NewFrame.
    virtual void overlay_new_frame() = 0;

    // Draws and presents one frame: sky, ground, host meshes, grass (grass_begin_frame ..
    // grass_end_frame with `view`), the overlay when `overlay` is not null. With `screenshot` the presented
    // image is read back (sRGB RGBA8, top row first) before it is presented. Returns the
    // first failing grass call's result, or GRASS_ERROR_BACKEND with *error for the host's.
    virtual grass_result draw_frame(grass_context* ctx, const grass_view_desc& view, ImDrawData* overlay,
                                    grass_host::Image* screenshot, std::string* error) = 0;

protected:
    explicit Window(const WindowDesc& desc)
        : desc_(desc), width_(desc.width), height_(desc.height), samples_(desc.samples) {}
    // Opens the GLFW window (after the backend's hints) and follows its framebuffer size.
    bool open(const char* title, std::string* error);

    WindowDesc desc_;
    GLFWwindow* window_ = nullptr;
    uint32_t width_, height_, samples_;
};

std::unique_ptr<Window> create_gl_window(const WindowDesc& desc, std::string* error);
std::unique_ptr<Window> create_vk_window(const WindowDesc& desc, std::string* error);

} // namespace grass_viewer
