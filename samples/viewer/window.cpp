#include "window.hpp"

#include <GLFW/glfw3.h>

namespace grass_viewer {

std::unique_ptr<Window> Window::create(grass_backend backend, const WindowDesc& desc, std::string* error) {
#ifdef GRASS_VIEWER_GL
    if (backend == GRASS_BACKEND_GL) return create_gl_window(desc, error);
#endif
#ifdef GRASS_VIEWER_VK
    if (backend == GRASS_BACKEND_VULKAN) return create_vk_window(desc, error);
#endif
    *error = std::string("this build has no ") + (backend == GRASS_BACKEND_VULKAN ? "Vulkan" : "GL") + " backend";
    return nullptr;
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
}

bool Window::open(const char* title, std::string* error) {
    window_ = glfwCreateWindow(int(width_), int(height_), title, nullptr, nullptr);
    if (!window_) {
        const char* why = nullptr;
        glfwGetError(&why);
        *error = std::string("glfwCreateWindow failed: ") + (why ? why : "unknown reason");
        return false;
    }
    update_size();
    return true;
}

void Window::update_size() {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    width_ = uint32_t(w > 0 ? w : 0);
    height_ = uint32_t(h > 0 ? h : 0);
}

} // namespace grass_viewer
