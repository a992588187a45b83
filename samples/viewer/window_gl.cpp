// The GL 4.5 viewer window: a GLFW window with a GL 4.5 core context. The host draws into
// its own sRGB framebuffer (multisampled when asked, resolved like the headless GL host),
// copies it to the window's framebuffer, draws the overlay there, reads it back for a
// screenshot and swaps. grass loads its GL entry points through glfwGetProcAddress.
#include "ground.hpp"
#include "mesh_drawer_gl.hpp"
#include "window.hpp"

#include <grass/grass_gl.h>

#define GL_GLEXT_PROTOTYPES 1
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

namespace grass_host_shaders {
extern const char* const ground_vert;
extern const char* const ground_frag;
} // namespace grass_host_shaders

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

    std::string device_name_;
    bool imgui_ = false;
    GLuint draw_fbo_ = 0, color_rb_ = 0, depth_rb_ = 0; // multisampled when samples_ > 1
    GLuint resolve_fbo_ = 0, resolve_rb_ = 0;           // only when multisampled
    uint32_t target_width_ = 0, target_height_ = 0;     // the size they were made
    GLuint ground_program_ = 0, ground_buffer_ = 0, ground_vao_ = 0;
    std::unique_ptr<grass_host::GlMeshDrawer> meshes_; // the scene's host meshes (glTF)
};

// Loaders return function pointers, as grass_gl_get_proc_address_fn does.
grass_gl_proc load_gl(void*, const char* name) { return glfwGetProcAddress(name); }
// The mesh drawer's loader returns them as void*.
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
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 4 || (major == 4 && minor < 5)) {
        *error = "the GL context is " + std::to_string(major) + "." + std::to_string(minor) + "; 4.5 is required";
        return false;
    }
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    device_name_ = renderer ? renderer : "unknown GL renderer";
    glDebugMessageCallback(&GlWindow::on_debug, desc_.validation_log);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
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
    destroy_target();
    meshes_.reset(); // while the context is current
    if (ground_program_) glDeleteProgram(ground_program_);
    if (ground_buffer_) glDeleteBuffers(1, &ground_buffer_);
    if (ground_vao_) glDeleteVertexArrays(1, &ground_vao_);
    glDebugMessageCallback(nullptr, nullptr);
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
    glCreateRenderbuffers(1, &color_rb_);
    glNamedRenderbufferStorageMultisample(color_rb_, samples, GL_SRGB8_ALPHA8, w, h);
    glCreateRenderbuffers(1, &depth_rb_);
    glNamedRenderbufferStorageMultisample(depth_rb_, samples, GL_DEPTH_COMPONENT32F, w, h);
    glCreateFramebuffers(1, &draw_fbo_);
    glNamedFramebufferRenderbuffer(draw_fbo_, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
    glNamedFramebufferRenderbuffer(draw_fbo_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
    bool complete = glCheckNamedFramebufferStatus(draw_fbo_, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (samples > 0) {
        glCreateRenderbuffers(1, &resolve_rb_);
        glNamedRenderbufferStorageMultisample(resolve_rb_, 0, GL_SRGB8_ALPHA8, w, h);
        glCreateFramebuffers(1, &resolve_fbo_);
        glNamedFramebufferRenderbuffer(resolve_fbo_, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_rb_);
        complete = complete && glCheckNamedFramebufferStatus(resolve_fbo_, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    if (!complete) *error = "the viewer's " + std::to_string(samples_) + "-sample framebuffer is incomplete";
    return complete;
}

void GlWindow::destroy_target() {
    const GLuint framebuffers[] = {draw_fbo_, resolve_fbo_};
    const GLuint renderbuffers[] = {color_rb_, depth_rb_, resolve_rb_};
    glDeleteFramebuffers(2, framebuffers); // zero names are ignored
    glDeleteRenderbuffers(3, renderbuffers);
    draw_fbo_ = resolve_fbo_ = color_rb_ = depth_rb_ = resolve_rb_ = 0;
}

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
    const char* sources[2] = {grass_host_shaders::ground_vert, grass_host_shaders::ground_frag};
    const GLenum stages[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    ground_program_ = glCreateProgram();
    for (int k = 0; k < 2; ++k) {
        const GLuint shader = glCreateShader(stages[k]);
        glShaderSource(shader, 1, &sources[k], nullptr);
        glCompileShader(shader);
        glAttachShader(ground_program_, shader);
        glDeleteShader(shader);
    }
    glLinkProgram(ground_program_);
    GLint linked = 0;
    glGetProgramiv(ground_program_, GL_LINK_STATUS, &linked);
    if (!linked) {
        char log[1024] = {0};
        glGetProgramInfoLog(ground_program_, sizeof(log), nullptr, log);
        *error = std::string("the ground's program: ") + log;
        return false;
    }
    glCreateBuffers(1, &ground_buffer_);
    glNamedBufferData(ground_buffer_, sizeof(grass_host::GroundUniforms), nullptr, GL_DYNAMIC_DRAW);
    glCreateVertexArrays(1, &ground_vao_);
    return true;
}

void GlWindow::draw_ground(const grass_view_desc& view) {
    const grass_host::GroundUniforms u = grass_host::make_ground_uniforms(view, desc_.scene);
    glNamedBufferData(ground_buffer_, sizeof(u), &u, GL_DYNAMIC_DRAW);
    glUseProgram(ground_program_);
    glBindVertexArray(ground_vao_);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, ground_buffer_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(0);
    glUseProgram(0);
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
    glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
    glEnable(GL_FRAMEBUFFER_SRGB); // linear shader output and clear colours are sRGB-encoded
    glViewport(0, 0, w, h);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const float depth = 1.0f;
    glClearBufferfv(GL_COLOR, 0, desc_.scene.clear_color);
    glClearBufferfv(GL_DEPTH, 0, &depth);
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
    GLuint source = draw_fbo_;
    if (resolve_fbo_) {
        glBlitNamedFramebuffer(draw_fbo_, resolve_fbo_, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        source = resolve_fbo_;
    }
    glDisable(GL_FRAMEBUFFER_SRGB);
    // A viewport set on the window's framebuffer: Mesa's software GLX resizes the window's
    // buffers only then (without it, the frames after a resize went to stale, black buffers).
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w, h);
    glBlitNamedFramebuffer(source, 0, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
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
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, GLsizei(width_), GLsizei(height_), GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
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
