// The headless GL host: a GL 4.5 core context without a window (EGL surfaceless, or
// OSMesa when EGL cannot give one or GRASS_HOST_GL=osmesa), an offscreen sRGB colour +
// depth target, and the frame around grass_gl_render. Like grass, it links no GL
// library: its own GL calls go through a table loaded from the context's proc loader.
//
// GRASS_HOST_GL: unset = EGL, then OSMesa; "egl" = EGL only; "osmesa" = OSMesa only.
#include "driver_residency.hpp"
#include "gl_loader.hpp"
#include "gl_target.hpp"
#include "ground.hpp"
#include "host_factories.hpp"
#include "host_shaders.hpp"
#include "mesh_drawer_gl.hpp"
#include "shadow_cascades_gl.hpp"

#include <grass/grass_gl.h>

#define EGL_NO_X11 1 // keep Xlib's macros (None, Bool, Status) out
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#include <dlfcn.h>
#include <link.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace grass_host {

namespace {

// OSMesa, loaded at run time (osmesa.h would pull in the legacy gl.h).
using OSMesaContext = void*;
using OsMesaProc = void (*)();
using OsMesaCreateContextAttribsFn = OSMesaContext (*)(const int* attributes, OSMesaContext share);
using OsMesaMakeCurrentFn = unsigned char (*)(OSMesaContext, void* buffer, GLenum type, GLsizei width, GLsizei height);
using OsMesaDestroyContextFn = void (*)(OSMesaContext);
using OsMesaGetProcAddressFn = OsMesaProc (*)(const char* name);
constexpr int kOsMesaFormat = 0x22;
constexpr int kOsMesaRgba = 0x1908; // GL_RGBA
constexpr int kOsMesaDepthBits = 0x30;
constexpr int kOsMesaStencilBits = 0x31;
constexpr int kOsMesaAccumBits = 0x32;
constexpr int kOsMesaProfile = 0x33;
constexpr int kOsMesaCoreProfile = 0x34;
constexpr int kOsMesaContextMajorVersion = 0x36;
constexpr int kOsMesaContextMinorVersion = 0x37;
constexpr GLsizei kOsMesaDummySize = 16; // OSMesa needs a buffer to make current; we draw to FBOs

std::string hex(unsigned value) {
    char text[16];
    std::snprintf(text, sizeof(text), "0x%04X", value);
    return text;
}

class GlHost final : public Host {
public:
    explicit GlHost(const TargetDesc& target) : Host(target) {}
    ~GlHost() override;
    GlHost(const GlHost&) = delete;
    GlHost& operator=(const GlHost&) = delete;

    bool init(std::string* error);

    grass_backend backend() const override { return GRASS_BACKEND_GL; }
    grass_result create_context(const grass_context_desc& desc, grass_context** out) override;
    void projection(float fovy_radians, float aspect, float near_m, float far_m, float out[16]) const override;
    grass_result render(grass_context* context, const grass_view_desc& view, const Occluder* occluder, Image* out,
                        std::string* error) override;
    void* gl_proc_address(const char* name) const override;

private:
    enum class Path { none, egl, osmesa };

    bool init_egl(std::string* error);
    void release_egl();
    bool init_osmesa(std::string* error);
    grass_gl_proc proc(const char* name) const;
    static grass_gl_proc GRASS_API_PTR load_proc(void* user_data, const char* name);
    bool load_functions(std::string* error);
    bool create_target(std::string* error);
    void clear_rect(const float color[4], float depth, const int32_t rect[4]);
    bool create_ground(std::string* error);
    void draw_ground(const grass_view_desc& view, bool receive_shadows);
    bool create_shadows(std::string* error);
    // TargetDesc::host_shadows: the frame's grass views planned (main, then the cascades'),
    // the cascades drawn (the meshes' depth, grass's depth views), the main framebuffer bound.
    grass_result draw_shadow_cascades(grass_context* context, const ShadowFrameViews& views,
                                      const LightCascades& cascades);
    GLuint ground_program_ = 0, ground_receiving_program_ = 0, ground_buffer_ = 0, ground_vao_ = 0;
    std::unique_ptr<GlMeshDrawer> meshes_;      // target.meshes
    std::unique_ptr<GlShadowCascades> shadows_; // target.host_shadows
    uint32_t count_gl_errors(const char* where);
    static void APIENTRY debug_callback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                        const GLchar* message, const void* user_param);

    Path path_ = Path::none;
    EGLDisplay egl_display_ = EGL_NO_DISPLAY;
    EGLContext egl_context_ = EGL_NO_CONTEXT;
    void* osmesa_library_ = nullptr;
    OSMesaContext osmesa_context_ = nullptr;
    OsMesaMakeCurrentFn osmesa_make_current_ = nullptr;
    OsMesaDestroyContextFn osmesa_destroy_context_ = nullptr;
    OsMesaGetProcAddressFn osmesa_get_proc_address_ = nullptr;
    std::vector<uint8_t> osmesa_buffer_;

    grass_bootstrap::GlFunctions gl_;
    bool gl_loaded_ = false;
    bool debug_output_ = false;
    grass_bootstrap::GlRenderTarget fb_; // multisampled when target.samples > 1
    std::vector<uint8_t> readback_;
    uint32_t debug_errors_ = 0;         // errors seen by debug_callback
    uint32_t debug_errors_counted_ = 0; // debug_errors_ at the last count_gl_errors
};

bool GlHost::init(std::string* error) {
    const char* choice = std::getenv("GRASS_HOST_GL");
    const std::string which = choice ? choice : "";
    if (!which.empty() && which != "egl" && which != "osmesa") {
        *error = "GRASS_HOST_GL is '" + which + "'; expected 'egl' or 'osmesa' (or unset)";
        return false;
    }
    std::string egl_error, osmesa_error;
    if (which != "osmesa") {
        if (init_egl(&egl_error)) {
            path_ = Path::egl;
        } else {
            release_egl();
        }
    }
    if (path_ == Path::none && which != "egl" && init_osmesa(&osmesa_error)) path_ = Path::osmesa;
    if (path_ == Path::none) {
        *error = "no GL 4.5 core context:";
        if (!egl_error.empty()) *error += " EGL surfaceless: " + egl_error + ";";
        if (!osmesa_error.empty()) *error += " OSMesa: " + osmesa_error;
        return false;
    }
    if (!load_functions(error)) return false;

    if (!grass_bootstrap::require_gl45(gl_, error)) return false;
    device_name_ = grass_bootstrap::gl_renderer(gl_) + (path_ == Path::egl ? " (EGL surfaceless)" : " (OSMesa)");

    // KHR_debug is core in 4.3; a debug context reports everything, others at least errors.
    gl_.DebugMessageCallback(&GlHost::debug_callback, this);
    gl_.DebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    gl_.Enable(GL_DEBUG_OUTPUT);
    gl_.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    debug_output_ = true;

    if (!check_host_shadows(target_, error)) return false;
    if (!create_target(error)) return false;
    if (target_.ground && !create_ground(error)) return false;
    if (!target_.meshes.empty()) {
        meshes_ = std::make_unique<GlMeshDrawer>();
        movable_meshes_ = meshes_.get();
        auto loader = [](void* self, const char* name) { return static_cast<GlHost*>(self)->gl_proc_address(name); };
        if (!meshes_->init(loader, this, target_.meshes, error)) return false;
    }
    if (target_.host_shadows.cascades > 0 && !create_shadows(error)) return false;
    count_gl_errors("host initialisation");
    return true;
}

bool GlHost::init_egl(std::string* error) {
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client_extensions || !std::strstr(client_extensions, "EGL_MESA_platform_surfaceless")) {
        *error = "the EGL client does not offer EGL_MESA_platform_surfaceless";
        return false;
    }
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_platform_display) {
        *error = "eglGetPlatformDisplayEXT is not available";
        return false;
    }
    egl_display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (egl_display_ == EGL_NO_DISPLAY) {
        *error = "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA) failed with " + hex(eglGetError());
        return false;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(egl_display_, &major, &minor)) {
        *error = "eglInitialize failed with " + hex(eglGetError());
        egl_display_ = EGL_NO_DISPLAY;
        return false;
    }
    const char* extensions = eglQueryString(egl_display_, EGL_EXTENSIONS);
    const bool configless = extensions && (std::strstr(extensions, "EGL_KHR_no_config_context") ||
                                           std::strstr(extensions, "EGL_MESA_configless_context"));
    const bool surfaceless = extensions && std::strstr(extensions, "EGL_KHR_surfaceless_context");
    if (!configless || !surfaceless || !eglBindAPI(EGL_OPENGL_API)) {
        *error = "the EGL display lacks EGL_KHR_no_config_context, EGL_KHR_surfaceless_context or desktop GL";
        return false;
    }
    EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,
        4,
        EGL_CONTEXT_MINOR_VERSION,
        5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_CONTEXT_OPENGL_DEBUG,
        EGL_TRUE,
        EGL_NONE,
    };
    egl_context_ = eglCreateContext(egl_display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (egl_context_ == EGL_NO_CONTEXT) {
        attributes[6] = EGL_NONE; // retry without the debug flag
        egl_context_ = eglCreateContext(egl_display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    }
    if (egl_context_ == EGL_NO_CONTEXT) {
        *error = "eglCreateContext(GL 4.5 core) failed with " + hex(eglGetError());
        return false;
    }
    if (!eglMakeCurrent(egl_display_, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_context_)) {
        *error = "eglMakeCurrent(EGL_NO_SURFACE) failed with " + hex(eglGetError());
        return false;
    }
    static const char* const kDrivers[] = {"_dri.so", "libgallium", nullptr};
    keep_drivers_resident(kDrivers);
    return true;
}

bool GlHost::init_osmesa(std::string* error) {
    osmesa_library_ = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (!osmesa_library_) {
        const char* why = dlerror();
        *error = std::string("dlopen(libOSMesa.so.8) failed: ") + (why ? why : "unknown reason");
        return false;
    }
    auto create = reinterpret_cast<OsMesaCreateContextAttribsFn>(dlsym(osmesa_library_, "OSMesaCreateContextAttribs"));
    osmesa_make_current_ = reinterpret_cast<OsMesaMakeCurrentFn>(dlsym(osmesa_library_, "OSMesaMakeCurrent"));
    osmesa_destroy_context_ = reinterpret_cast<OsMesaDestroyContextFn>(dlsym(osmesa_library_, "OSMesaDestroyContext"));
    osmesa_get_proc_address_ = reinterpret_cast<OsMesaGetProcAddressFn>(dlsym(osmesa_library_, "OSMesaGetProcAddress"));
    if (!create || !osmesa_make_current_ || !osmesa_destroy_context_ || !osmesa_get_proc_address_) {
        *error = "libOSMesa.so.8 lacks OSMesaCreateContextAttribs, OSMesaMakeCurrent, OSMesaDestroyContext or "
                 "OSMesaGetProcAddress";
        return false;
    }
    const int attributes[] = {
        kOsMesaFormat,
        kOsMesaRgba,
        kOsMesaDepthBits,
        0,
        kOsMesaStencilBits,
        0,
        kOsMesaAccumBits,
        0,
        kOsMesaProfile,
        kOsMesaCoreProfile,
        kOsMesaContextMajorVersion,
        4,
        kOsMesaContextMinorVersion,
        5,
        0,
    };
    osmesa_context_ = create(attributes, nullptr);
    if (!osmesa_context_) {
        *error = "OSMesaCreateContextAttribs(GL 4.5 core) failed";
        return false;
    }
    osmesa_buffer_.assign(size_t(kOsMesaDummySize) * kOsMesaDummySize * 4, 0);
    if (!osmesa_make_current_(osmesa_context_, osmesa_buffer_.data(), GL_UNSIGNED_BYTE, kOsMesaDummySize,
                              kOsMesaDummySize)) {
        *error = "OSMesaMakeCurrent failed";
        return false;
    }
    return true;
}

// Loaders return function pointers, as grass_gl_get_proc_address_fn does: no cast.
grass_gl_proc GlHost::proc(const char* name) const {
    if (path_ == Path::egl) return eglGetProcAddress(name);
    if (path_ == Path::osmesa) return osmesa_get_proc_address_(name);
    return nullptr;
}

void* GlHost::gl_proc_address(const char* name) const { return reinterpret_cast<void*>(proc(name)); }

grass_gl_proc GRASS_API_PTR GlHost::load_proc(void* user_data, const char* name) {
    const auto* host = static_cast<const GlHost*>(user_data);
    const grass_gl_proc real = host->proc(name);
    return host->target_.gl_proc_filter ? host->target_.gl_proc_filter(name, real) : real;
}

bool GlHost::load_functions(std::string* error) {
    const auto loader = [](void* host, const char* name) {
        return static_cast<const GlHost*>(host)->gl_proc_address(name);
    };
    gl_loaded_ = gl_.load(loader, this, error);
    return gl_loaded_;
}

bool GlHost::create_target(std::string* error) {
    const TargetDesc& t = target_;
    GLint max_size = 0, max_samples = 0;
    gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    gl_.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (t.width == 0 || t.height == 0 || t.width > uint32_t(max_size) || t.height > uint32_t(max_size)) {
        *error = "target size " + std::to_string(t.width) + "x" + std::to_string(t.height) + " is outside 1.." +
                 std::to_string(max_size);
        return false;
    }
    if (t.samples == 0 || t.samples > uint32_t(max_samples)) {
        *error = "target.samples is " + std::to_string(t.samples) + "; this device supports 1.." +
                 std::to_string(max_samples);
        return false;
    }
    const GLsizei w = GLsizei(t.width), h = GLsizei(t.height);
    const GLsizei samples = t.samples > 1 ? GLsizei(t.samples) : 0;
    const GLenum color_format = t.float_color ? GL_RGBA32F : t.unorm_color ? GL_RGBA8 : GL_SRGB8_ALPHA8;
    return grass_bootstrap::create_render_target(gl_, w, h, samples, color_format, "the offscreen", &fb_, error);
}

GlHost::~GlHost() {
    if (gl_loaded_) {
        grass_bootstrap::destroy_render_target(gl_, &fb_);
        if (ground_program_) gl_.DeleteProgram(ground_program_);
        if (ground_receiving_program_) gl_.DeleteProgram(ground_receiving_program_);
        shadows_.reset();
        if (ground_buffer_) gl_.DeleteBuffers(1, &ground_buffer_);
        if (ground_vao_) gl_.DeleteVertexArrays(1, &ground_vao_);
        movable_meshes_ = nullptr;
        meshes_.reset();
        if (debug_output_) gl_.DebugMessageCallback(nullptr, nullptr);
    }
    release_egl();
    if (osmesa_context_) {
        osmesa_make_current_(nullptr, nullptr, 0, 0, 0);
        osmesa_destroy_context_(osmesa_context_);
    }
    if (osmesa_library_) dlclose(osmesa_library_);
}

void GlHost::release_egl() {
    if (egl_display_ == EGL_NO_DISPLAY) return;
    eglMakeCurrent(egl_display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (egl_context_ != EGL_NO_CONTEXT) eglDestroyContext(egl_display_, egl_context_);
    eglTerminate(egl_display_);
    eglReleaseThread();
    egl_display_ = EGL_NO_DISPLAY;
    egl_context_ = EGL_NO_CONTEXT;
}

grass_result GlHost::create_context(const grass_context_desc& desc, grass_context** out) {
    grass_gl_desc gl_desc = grass_default_gl_desc();
    gl_desc.get_proc_address = &GlHost::load_proc;
    gl_desc.get_proc_address_user_data = this;
    return grass_gl_create_context(GRASS_HEADER_VERSION, &desc, &gl_desc, out);
}

// Right-handed, looking down -z, clip z in -1..1 (gluPerspective), or in 0..1 with
// gl_clip_zero_to_one; reversed_z maps the near plane to the top of the range.
void GlHost::projection(float fovy_radians, float aspect, float near_m, float far_m, float out[16]) const {
    const float f = 1.0f / std::tan(0.5f * fovy_radians);
    for (int i = 0; i < 16; ++i) out[i] = 0.0f;
    out[0] = f / aspect;
    out[5] = f;
    out[11] = -1.0f;
    if (target_.gl_clip_zero_to_one) {
        out[10] = far_m / (near_m - far_m);
        out[14] = far_m * near_m / (near_m - far_m);
        if (target_.reversed_z) { // z' = w - z: depth 1 - d
            out[10] = -1.0f - out[10];
            out[14] = -out[14];
        }
    } else {
        out[10] = (far_m + near_m) / (near_m - far_m);
        out[14] = 2.0f * far_m * near_m / (near_m - far_m);
        if (target_.reversed_z) { // z' = -z: depth 1 - d
            out[10] = -out[10];
            out[14] = -out[14];
        }
    }
}

// Clears colour and depth inside `rect` (x, y, width, height; GL bottom-left origin).
void GlHost::clear_rect(const float color[4], float depth, const int32_t rect[4]) {
    gl_.Enable(GL_SCISSOR_TEST);
    gl_.Scissor(rect[0], rect[1], rect[2], rect[3]);
    gl_.ClearBufferfv(GL_COLOR, 0, color);
    gl_.ClearBufferfv(GL_DEPTH, 0, &depth);
    gl_.Disable(GL_SCISSOR_TEST);
}

// The host's terrain stand-in: a camera-relative ground square (shaders/ground.*).
bool GlHost::create_ground(std::string* error) {
    std::string ignored;
    ground_program_ = grass_bootstrap::compile_program(
        gl_, grass_host_shaders::ground_vert, grass_host_shaders::ground_frag, "ground", error ? error : &ignored);
    if (!ground_program_) return false;
    gl_.CreateBuffers(1, &ground_buffer_);
    gl_.NamedBufferData(ground_buffer_, sizeof(GroundUniforms), nullptr, GL_DYNAMIC_DRAW);
    gl_.CreateVertexArrays(1, &ground_vao_);
    return true;
}

// The cascades' map and framebuffers, and the ground's and meshes' programs that read it.
bool GlHost::create_shadows(std::string* error) {
    shadows_ = std::make_unique<GlShadowCascades>();
    auto loader = [](void* self, const char* name) { return static_cast<GlHost*>(self)->gl_proc_address(name); };
    if (!shadows_->init(loader, this, target_.host_shadows, error)) return false;
    if (meshes_ && !meshes_->init_receiving(error)) return false;
    if (target_.ground) {
        const std::string vert = with_define(grass_host_shaders::ground_vert, "HOST_SHADOWS");
        const std::string frag = with_define(grass_host_shaders::ground_frag, "HOST_SHADOWS");
        ground_receiving_program_ =
            grass_bootstrap::compile_program(gl_, vert.c_str(), frag.c_str(), "ground (shadows)", error);
        if (!ground_receiving_program_) return false;
    }
    return true;
}

grass_result GlHost::draw_shadow_cascades(grass_context* context, const ShadowFrameViews& views,
                                          const LightCascades& cascades) {
    const HostShadows& hs = target_.host_shadows;
    grass_result result = plan_shadow_frame(context, views, cascades.count, shadow_parts.grass_casts);
    for (uint32_t i = 0; i < cascades.count && result == GRASS_SUCCESS; ++i) {
        shadows_->begin_cascade(i);
        if (meshes_ && shadow_parts.host_casts) {
            shadows_->polygon_offset(true, hs.mesh_bias_constant, hs.mesh_bias_slope);
            meshes_->draw(cascades.light_view[i], false, false);
            shadows_->polygon_offset(false, 0.0f, 0.0f);
        }
        if (shadow_parts.grass_casts) result = grass_gl_render_view(context, 1 + i);
    }
    gl_.Disable(GL_DEPTH_TEST);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fb_.draw_fbo);
    gl_.Viewport(0, 0, GLsizei(target_.width), GLsizei(target_.height));
    return result;
}

void GlHost::draw_ground(const grass_view_desc& view, bool receive_shadows) {
    const GroundUniforms u = make_ground_uniforms(view, target_);
    gl_.NamedBufferData(ground_buffer_, sizeof(u), &u, GL_DYNAMIC_DRAW);
    gl_.UseProgram(receive_shadows ? ground_receiving_program_ : ground_program_);
    gl_.BindVertexArray(ground_vao_);
    gl_.BindBufferBase(GL_UNIFORM_BUFFER, 0, ground_buffer_);
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(target_.reversed_z ? GL_GREATER : GL_LESS);
    gl_.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(kGroundVertexCount));
    gl_.Disable(GL_DEPTH_TEST);
    gl_.BindVertexArray(0);
    gl_.UseProgram(0);
}

grass_result GlHost::render(grass_context* context, const grass_view_desc& view, const Occluder* occluder, Image* out,
                            std::string* error) {
    const int32_t w = int32_t(target_.width), h = int32_t(target_.height);
    // TargetDesc::host_shadows: grass's frame begins first (the main view receiving, the
    // cascades' depth views) and the cascades are drawn before the main view's scene.
    const bool shadowed = shadows_ && shadow_parts.any();
    LightCascades cascades;
    ShadowFrameViews shadow_views;
    grass_result shadow_result = GRASS_SUCCESS;
    if (shadowed) {
        cascades = fit_light_cascades(view, target_.host_shadows, false);
        make_shadow_frame_views(view, cascades, target_.host_shadows, shadows_->texture(), 0,
                                shadow_parts.grass_receives, &shadow_views);
        shadow_result = draw_shadow_cascades(context, shadow_views, cascades);
    }
    const bool host_receives = shadowed && shadow_parts.host_receives;
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fb_.draw_fbo);
    gl_.Enable(GL_FRAMEBUFFER_SRGB); // linear shader output and clear colours are sRGB-encoded
    gl_.Viewport(0, 0, w, h);
    gl_.DepthMask(GL_TRUE);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (target_.gl_clip_zero_to_one) gl_.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    const int32_t whole[4] = {0, 0, w, h};
    float clear_color[4];
    stored_clear_color(target_, clear_color);
    clear_rect(clear_color, target_.reversed_z ? 0.0f : 1.0f, whole);

    if (host_receives) shadows_->bind_for_receiving(cascades.uniforms);
    if (target_.ground) draw_ground(view, host_receives);
    if (meshes_) meshes_->draw(view, target_.reversed_z, target_.unorm_color, host_receives);
    if (host_receives) shadows_->unbind();

    if (occluder) {
        // The window depth of a camera-facing plane at view-space z = -distance.
        const float* p = view.projection;
        const float z = -occluder->distance;
        const float clip_z = p[10] * z + p[14];
        const float clip_w = p[11] * z + p[15];
        const float ndc_z = clip_z / clip_w;
        const float depth = target_.gl_clip_zero_to_one ? ndc_z : 0.5f * ndc_z + 0.5f;
        const int32_t x0 = std::max(occluder->x0, 0), x1 = std::min(occluder->x1, w);
        const int32_t y0 = std::max(occluder->y0, 0), y1 = std::min(occluder->y1, h);
        if (x1 > x0 && y1 > y0) {
            float color[4] = {occluder->color[0], occluder->color[1], occluder->color[2], 1.0f};
            if (target_.unorm_color) {
                for (int c = 0; c < 3; ++c) color[c] = linear_to_srgb(color[c]);
            }
            const int32_t rect[4] = {x0, h - y1, x1 - x0, y1 - y0}; // top-left -> bottom-left origin
            clear_rect(color, depth, rect);
        }
    }

    if (before_grass) before_grass();
    grass_result result = GRASS_SUCCESS;
    if (shadowed) { // the frame began in draw_shadow_cascades; view 0 is the main view
        result = shadow_result;
        if (result == GRASS_SUCCESS) result = grass_gl_render_view(context, 0);
        const grass_result end = grass_end_frame(context);
        if (result == GRASS_SUCCESS) result = end;
    } else {
        result = begin_grass_frame ? begin_grass_frame(context) : grass_begin_frame(context, &view);
        if (result == GRASS_SUCCESS) {
            result = draw_grass ? draw_grass(context, nullptr) : grass_gl_render(context);
            const grass_result end = grass_end_frame(context);
            if (result == GRASS_SUCCESS) result = end;
        }
    }
    if (after_grass) after_grass();
    if (target_.gl_clip_zero_to_one) gl_.ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    if (result != GRASS_SUCCESS) {
        if (error) *error = grass_get_last_error(context);
        gl_.Disable(GL_FRAMEBUFFER_SRGB);
        return result;
    }

    GLuint read_fbo = fb_.draw_fbo;
    if (fb_.resolve_fbo != 0) {
        gl_.BlitNamedFramebuffer(fb_.draw_fbo, fb_.resolve_fbo, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT,
                                 GL_NEAREST);
        read_fbo = fb_.resolve_fbo;
    }
    gl_.Disable(GL_FRAMEBUFFER_SRGB); // read the stored sRGB bytes, unconverted
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    const size_t texel = target_.float_color ? 4 * sizeof(float) : 4;
    const size_t row = size_t(w) * texel;
    readback_.resize(row * size_t(h));
    gl_.ReadPixels(0, 0, w, h, GL_RGBA, target_.float_color ? GL_FLOAT : GL_UNSIGNED_BYTE, readback_.data());
    if (target_.read_depth) {
        std::vector<float> depth(size_t(w) * size_t(h));
        gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, fb_.draw_fbo);
        gl_.ReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
        out->depth.resize(depth.size());
        for (int32_t y = 0; y < h; ++y) { // bottom-up rows
            std::memcpy(&out->depth[size_t(y) * w], &depth[size_t(h - 1 - y) * w], size_t(w) * sizeof(float));
        }
    }
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fb_.draw_fbo); // stays bound, as a host's scene target would

    out->width = target_.width;
    out->height = target_.height;
    uint8_t* rows = nullptr;
    if (target_.float_color) {
        out->rgba_f32.resize(size_t(w) * size_t(h) * 4);
        rows = reinterpret_cast<uint8_t*>(out->rgba_f32.data());
    } else {
        out->rgba.resize(readback_.size());
        rows = out->rgba.data();
    }
    for (int32_t y = 0; y < h; ++y) { // GL rows run bottom-up
        std::memcpy(rows + size_t(y) * row, &readback_[size_t(h - 1 - y) * row], row);
    }
    if (target_.float_color) encode_float_image(out);
    if (count_gl_errors("the frame") != 0 && error) *error = log_;
    return GRASS_SUCCESS;
}

// Drains glGetError. With debug output on, GL errors also arrive as debug messages; the
// flags then count only when debug output missed them, so no error is counted twice.
uint32_t GlHost::count_gl_errors(const char* where) {
    const bool debug_reported = debug_errors_ != debug_errors_counted_;
    debug_errors_counted_ = debug_errors_;
    uint32_t errors = 0;
    for (int i = 0; i < 64; ++i) {
        const GLenum e = gl_.GetError();
        if (e == GL_NO_ERROR) break;
        ++errors;
        if (!debug_reported) {
            ++messages_;
            log_ += "glGetError: " + hex(e) + " after " + where + "\n";
        }
    }
    return errors;
}

void APIENTRY GlHost::debug_callback(GLenum, GLenum type, GLuint id, GLenum, GLsizei length, const GLchar* message,
                                     const void* user_param) {
    if (type != GL_DEBUG_TYPE_ERROR) return;
    auto* host = static_cast<GlHost*>(const_cast<void*>(user_param));
    ++host->debug_errors_;
    ++host->messages_;
    host->log_ += "GL debug error " + std::to_string(id) + ": ";
    host->log_.append(message, length >= 0 ? size_t(length) : std::strlen(message));
    host->log_ += "\n";
}

} // namespace

std::unique_ptr<Host> create_gl_host(const TargetDesc& target, std::string* error) {
    auto host = std::make_unique<GlHost>(target);
    std::string why;
    if (!host->init(&why)) {
        if (error) *error = "GL headless host: " + why;
        return nullptr;
    }
    return host;
}

} // namespace grass_host
