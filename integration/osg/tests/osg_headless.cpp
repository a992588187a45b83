#include "osg_headless.hpp"

#include <gl_loader.hpp>
#include <image_io.hpp>

#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <sys/stat.h>

#include <cstring>

namespace grass_osg_test {

struct GlTarget::Impl : grass_bootstrap::GlFunctions {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
};

namespace {

EGLDisplay open_display(std::string* error) {
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EGLDisplay display = get_platform_display
                             ? get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                             : EGL_NO_DISPLAY;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) {
        *error = "no EGL surfaceless display";
        return EGL_NO_DISPLAY;
    }
    return display;
}

} // namespace

std::unique_ptr<GlTarget> GlTarget::create(const TargetFormat& format, std::string* error) {
    std::unique_ptr<GlTarget> t(new GlTarget);
    t->format_ = format;
    t->impl_.reset(new Impl);
    Impl& g = *t->impl_;
    g.display = open_display(error);
    if (g.display == EGL_NO_DISPLAY) return nullptr;
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    eglChooseConfig(g.display, config_attribs, &config, 1, &count);
    eglBindAPI(EGL_OPENGL_API);
    // Debian's OSG draws with the legacy pipeline: it needs the compatibility profile.
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                      EGL_NONE};
    g.context = eglCreateContext(g.display, count ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attribs);
    if (g.context == EGL_NO_CONTEXT) {
        *error = "no GL 4.5 compatibility context from EGL";
        return nullptr;
    }
    t->make_current();
    const auto loader = [](void*, const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
    if (!g.load(loader, nullptr, error)) return nullptr;
    const GLenum colour = format.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    g.CreateRenderbuffers(3, t->renderbuffers_);
    g.NamedRenderbufferStorageMultisample(t->renderbuffers_[0], GLsizei(format.samples > 1 ? format.samples : 0),
                                          colour, GLsizei(format.width), GLsizei(format.height));
    g.NamedRenderbufferStorageMultisample(t->renderbuffers_[1], GLsizei(format.samples > 1 ? format.samples : 0),
                                          GL_DEPTH24_STENCIL8, GLsizei(format.width), GLsizei(format.height));
    g.NamedRenderbufferStorageMultisample(t->renderbuffers_[2], 0, colour, GLsizei(format.width),
                                          GLsizei(format.height));
    GLuint fbos[2];
    g.CreateFramebuffers(2, fbos);
    t->draw_fbo_ = fbos[0];
    t->resolve_fbo_ = fbos[1];
    g.NamedFramebufferRenderbuffer(fbos[0], GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t->renderbuffers_[0]);
    g.NamedFramebufferRenderbuffer(fbos[0], GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, t->renderbuffers_[1]);
    g.NamedFramebufferRenderbuffer(fbos[1], GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t->renderbuffers_[2]);
    for (GLuint fbo : fbos) {
        if (g.CheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            *error = "the test framebuffer is incomplete";
            return nullptr;
        }
    }
    g.BindFramebuffer(GL_FRAMEBUFFER, t->draw_fbo_);
    // An sRGB target encodes when GL_FRAMEBUFFER_SRGB is on: the test host turns it on once,
    // as many GL engines do, and OSG, which does not know the mode, leaves it on.
    if (format.srgb) g.Enable(GL_FRAMEBUFFER_SRGB);
    return t;
}

GlTarget::~GlTarget() {
    if (!impl_) return;
    Impl& g = *impl_;
    if (g.context != EGL_NO_CONTEXT) {
        make_current();
        if (draw_fbo_) {
            const GLuint fbos[2] = {draw_fbo_, resolve_fbo_};
            g.DeleteFramebuffers(2, fbos);
            g.DeleteRenderbuffers(3, renderbuffers_);
        }
        eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(g.display, g.context);
    }
    // The display stays initialised until the process exits: eglTerminate would unload
    // Mesa's driver, and LeakSanitizer could then no longer name the library of the
    // allocations Mesa keeps until exit (tests/sanitizer/lsan.supp suppresses them by name).
    // Other users of the one surfaceless display (the headless host) may still terminate it;
    // eglInitialize in open_display brings it back.
}

void GlTarget::make_current() { eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context); }

grass_host::Image GlTarget::read() {
    Impl& g = *impl_;
    GLint draw = 0, read_binding = 0;
    g.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    g.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_binding);
    const bool srgb_on = g.IsEnabled(GL_FRAMEBUFFER_SRGB);
    g.Disable(GL_FRAMEBUFFER_SRGB); // copy and read the stored bytes, unconverted
    const GLint w = GLint(format_.width), h = GLint(format_.height);
    g.BlitNamedFramebuffer(draw_fbo_, resolve_fbo_, 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
    g.PixelStorei(GL_PACK_ALIGNMENT, 1);
    grass_host::Image image;
    image.width = format_.width;
    image.height = format_.height;
    std::vector<uint8_t> bottom_up(size_t(w) * h * 4);
    g.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    image.rgba.resize(bottom_up.size());
    for (GLint y = 0; y < h; ++y) {
        std::memcpy(&image.rgba[size_t(y) * w * 4], &bottom_up[size_t(h - 1 - y) * w * 4], size_t(w) * 4);
    }
    g.PixelStorei(GL_PACK_ALIGNMENT, 4);
    if (srgb_on) g.Enable(GL_FRAMEBUFFER_SRGB);
    g.BindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw));
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read_binding));
    return image;
}

void save(const grass_host::Image& image, const std::string& name) {
    mkdir(GRASS_OSG_TEST_OUT, 0755);
    std::string error;
    grass_host::write_png(std::string(GRASS_OSG_TEST_OUT) + "/" + name + ".png", image, &error);
}

} // namespace grass_osg_test
