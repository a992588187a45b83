// The GL 4.5 viewer window: a GLFW window with a GL 4.5 core context. The host draws into
// its own sRGB framebuffer (multisampled when asked, resolved like the headless GL host),
// copies it to the window's framebuffer, draws the overlay there, reads it back for a
// screenshot and swaps. grass loads its GL entry points through glfwGetProcAddress.
#include "gl_loader.hpp"
#include "gl_target.hpp"
#include "ground.hpp"
#include "host_shaders.hpp"
#include "mesh_drawer_gl.hpp"
#include "window.hpp"

#include <grass/grass_gl.h>

#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>

namespace grass_viewer {

namespace {

class GlWindow final : public Window {
public:
    explicit GlWindow(const WindowDesc& desc) : Window(desc) {}
    ~GlWindow() override;
    bool init(std::string* error);

    grass_backend backend() const override { return GRASS_BACKEND_GL; }
    std::string device_name() const override { return device_name_; }
    grass_result create_context(const grass_context_desc& desc, grass_context** out) override;
    glm::mat4 projection(float fovy, float aspect, float near_m, float far_m) const override {
        return glm::perspectiveRH_NO(fovy, aspect, near_m, far_m);
    }
    bool set_samples(uint32_t samples, bool* contexts_stale, std::string* error) override;
    void overlay_new_frame() override { ImGui_ImplOpenGL3_NewFrame(); }
    grass_result draw_frame(grass_context* ctx, const grass_view_desc& view, ImDrawData* overlay,
                            grass_host::Image* screenshot, std::string* error) override;

private:
    bool create_target(std::string* error);
    void destroy_target();
    bool create_ground(std::string* error);
    void draw_ground(const grass_view_desc& view);
    void read_back(grass_host::Image* out);
    static void APIENTRY on_debug(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                  const GLchar* message, const void* user);

    grass_bootstrap::GlFunctions gl_; // the host's GL calls, loaded through GLFW
    std::string device_name_;
    bool imgui_ = false;
    grass_bootstrap::GlRenderTarget fb_;            // the scene's: multisampled when samples_ > 1
    uint32_t target_width_ = 0, target_height_ = 0; // the size they were made
    GLuint ground_program_ = 0, ground_buffer_ = 0, ground_vao_ = 0;
    std::unique_ptr<grass_host::GlMeshDrawer> meshes_; // the scene's host meshes (glTF)
};

// Loaders return function pointers, as grass_gl_get_proc_address_fn does.
grass_gl_proc GRASS_API_PTR load_gl(void*, const char* name) { return glfwGetProcAddress(name); }
// The mesh drawer's and the host's table's loader returns them as void*.
void* load_gl_for_meshes(void*, const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

bool GlWindow::init(std::string* error) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 0); // the host's scene target has the depth buffer
    glfwWindowHint(GLFW_SAMPLES, 0);
    if (!open("grass-viewer (GL 4.5)", error)) return false;
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(desc_.vsync ? 1 : 0);
    if (!gl_.load(&load_gl_for_meshes, nullptr, error)) return false;
    if (!grass_bootstrap::require_gl45(gl_, error)) return false;
    device_name_ = grass_bootstrap::gl_renderer(gl_);
    gl_.DebugMessageCallback(&GlWindow::on_debug, desc_.validation_log);
    gl_.DebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    gl_.Enable(GL_DEBUG_OUTPUT);
    gl_.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    if (!create_target(error) || !create_ground(error)) return false;
    if (!desc_.scene.meshes.empty()) {
        meshes_ = std::make_unique<grass_host::GlMeshDrawer>();
        if (!meshes_->init(&load_gl_for_meshes, nullptr, desc_.scene.meshes, error)) return false;
    }
    imgui_ = ImGui_ImplGlfw_InitForOpenGL(window_, true) && ImGui_ImplOpenGL3_Init("#version 450");
    if (!imgui_) {
        *error = "the overlay (ImGui's GLFW and OpenGL3 backends) cannot start";
        return false;
    }
    return true;
}

GlWindow::~GlWindow() {
    if (!window_) return;
    glfwMakeContextCurrent(window_);
    if (imgui_) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
    }
    if (!gl_.loaded()) return;
    destroy_target();
    meshes_.reset(); // while the context is current
    if (ground_program_) gl_.DeleteProgram(ground_program_);
    if (ground_buffer_) gl_.DeleteBuffers(1, &ground_buffer_);
    if (ground_vao_) gl_.DeleteVertexArrays(1, &ground_vao_);
    gl_.DebugMessageCallback(nullptr, nullptr);
}

void APIENTRY GlWindow::on_debug(GLenum, GLenum type, GLuint id, GLenum, GLsizei length, const GLchar* message,
                                 const void* user) {
    if (type != GL_DEBUG_TYPE_ERROR) return;
    auto* log = static_cast<ValidationLog*>(const_cast<void*>(user));
    log->add("GL debug error " + std::to_string(id) + ": " +
             std::string(message, length >= 0 ? size_t(length) : std::strlen(message)));
}

grass_result GlWindow::create_context(const grass_context_desc& desc, grass_context** out) {
    grass_gl_desc gl = grass_default_gl_desc();
    gl.get_proc_address = &load_gl;
    return grass_gl_create_context(GRASS_HEADER_VERSION, &desc, &gl, out);
}

// The scene's target: sRGB colour and 32-bit float depth, as the headless GL host's.
bool GlWindow::create_target(std::string* error) {
    const GLsizei w = GLsizei(width_ ? width_ : 1), h = GLsizei(height_ ? height_ : 1);
    const GLsizei samples = samples_ > 1 ? GLsizei(samples_) : 0;
    target_width_ = uint32_t(w);
    target_height_ = uint32_t(h);
    const std::string label = "the viewer's " + std::to_string(samples_) + "-sample";
    return grass_bootstrap::create_render_target(gl_, w, h, samples, GL_SRGB8_ALPHA8, label.c_str(), &fb_, error);
}

void GlWindow::destroy_target() { grass_bootstrap::destroy_render_target(gl_, &fb_); }

bool GlWindow::set_samples(uint32_t samples, bool* contexts_stale, std::string* error) {
    *contexts_stale = false; // a GL grass context draws into any bound framebuffer
    const uint32_t old = samples_;
    destroy_target();
    samples_ = samples;
    if (create_target(error)) return true;
    destroy_target();
    samples_ = old;
    std::string ignored;
    create_target(&ignored);
    return false;
}

// The headless hosts' ground (test_hosts/shaders/ground.*), compiled for GL.
bool GlWindow::create_ground(std::string* error) {
    ground_program_ = grass_bootstrap::compile_program(gl_, grass_host_shaders::ground_vert,
                                                       grass_host_shaders::ground_frag, "the ground's", error);
    if (!ground_program_) return false;
    gl_.CreateBuffers(1, &ground_buffer_);
    gl_.NamedBufferData(ground_buffer_, sizeof(grass_host::GroundUniforms), nullptr, GL_DYNAMIC_DRAW);
    gl_.CreateVertexArrays(1, &ground_vao_);
    return true;
}

void GlWindow::draw_ground(const grass_view_desc& view) {
    const grass_host::GroundUniforms u = grass_host::make_ground_uniforms(view, desc_.scene);
    gl_.NamedBufferData(ground_buffer_, sizeof(u), &u, GL_DYNAMIC_DRAW);
    gl_.UseProgram(ground_program_);
    gl_.BindVertexArray(ground_vao_);
    gl_.BindBufferBase(GL_UNIFORM_BUFFER, 0, ground_buffer_);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(grass_host::kGroundVertexCount));
    gl_.Disable(GL_DEPTH_TEST);
    gl_.BindVertexArray(0);
    gl_.UseProgram(0);
}

grass_result GlWindow::draw_frame(grass_context* ctx, const grass_view_desc& view, ImDrawData* overlay,
                                  grass_host::Image* screenshot, std::string* error) {
    if ((width_ != target_width_ || height_ != target_height_) && width_ > 0 && height_ > 0) {
        destroy_target();
        if (!create_target(error)) return GRASS_ERROR_BACKEND;
    }
    if (width_ == 0 || height_ == 0) { // minimised: nothing to draw
        glfwSwapBuffers(window_);
        return GRASS_SUCCESS;
    }
    const GLint w = GLint(width_), h = GLint(height_);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fb_.draw_fbo);
    gl_.Enable(GL_FRAMEBUFFER_SRGB); // linear shader output and clear colours are sRGB-encoded
    gl_.Viewport(0, 0, w, h);
    gl_.DepthMask(GL_TRUE);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const float depth = 1.0f;
    gl_.ClearBufferfv(GL_COLOR, 0, desc_.scene.clear_color);
    gl_.ClearBufferfv(GL_DEPTH, 0, &depth);
    if (desc_.scene.ground) draw_ground(view);
    if (meshes_) meshes_->draw(view, false, false); // into the depth grass shares
    grass_result result = grass_begin_frame(ctx, &view);
    if (result == GRASS_SUCCESS) {
        result = grass_gl_render(ctx);
        const grass_result end = grass_end_frame(ctx);
        if (result == GRASS_SUCCESS) result = end;
    }
    // Resolve as the headless host does (sRGB conversion on), then copy the stored bytes to
    // the window's framebuffer unconverted.
    GLuint source = fb_.draw_fbo;
    if (fb_.resolve_fbo) {
        gl_.BlitNamedFramebuffer(fb_.draw_fbo, fb_.resolve_fbo, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT,
                                 GL_NEAREST);
        source = fb_.resolve_fbo;
    }
    gl_.Disable(GL_FRAMEBUFFER_SRGB);
    // A viewport set on the window's framebuffer: Mesa's software GLX resizes the window's
    // buffers only then (without it, the frames after a resize went to stale, black buffers).
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_.Viewport(0, 0, w, h);
    gl_.BlitNamedFramebuffer(source, 0, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (overlay) ImGui_ImplOpenGL3_RenderDrawData(overlay);
    if (screenshot) read_back(screenshot);
    glfwSwapBuffers(window_);
    if (result != GRASS_SUCCESS) *error = grass_get_last_error(ctx);
    return result;
}

// The window's back buffer as it will be presented: RGBA8, rows flipped to top-down.
void GlWindow::read_back(grass_host::Image* out) {
    const size_t row = size_t(width_) * 4;
    std::vector<uint8_t> rows(row * height_);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl_.ReadBuffer(GL_BACK);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, GLsizei(width_), GLsizei(height_), GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    out->width = width_;
    out->height = height_;
    out->rgba.resize(rows.size());
    for (uint32_t y = 0; y < height_; ++y) {
        std::memcpy(&out->rgba[size_t(y) * row], &rows[size_t(height_ - 1 - y) * row], row);
        for (size_t x = 0; x < width_; ++x) out->rgba[size_t(y) * row + 4 * x + 3] = 255; // opaque, as presented
    }
}

} // namespace

std::unique_ptr<Window> create_gl_window(const WindowDesc& desc, std::string* error) {
    auto window = std::make_unique<GlWindow>(desc);
    if (!window->init(error)) return nullptr;
    return window;
}

} // namespace grass_viewer
