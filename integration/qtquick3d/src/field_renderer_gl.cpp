// OpenGL: grass draws with Qt's current GL context into the window's default framebuffer.
#include "field_renderer_gl.hpp"

#include <grass/grass_gl.h>

#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QQuickWindow>

namespace grass_qt {

namespace {

grass_gl_proc GRASS_API_PTR get_proc_address(void* user_data, const char* name) {
    return static_cast<QOpenGLContext*>(user_data)->getProcAddress(name);
}

} // namespace

GlFieldRenderer::~GlFieldRenderer() { destroy_context(); } // Qt keeps its context current for the render thread

bool GlFieldRenderer::create_context(const grass_context_desc& desc, QString* error) {
    QOpenGLContext* gl = QOpenGLContext::currentContext();
    if (!gl) {
        *error = QStringLiteral("no current OpenGL context in the window's render thread");
        return false;
    }
    grass_gl_desc gl_desc = grass_default_gl_desc();
    gl_desc.get_proc_address = get_proc_address;
    gl_desc.get_proc_address_user_data = gl;
    if (grass_gl_create_context(GRASS_HEADER_VERSION, &desc, &gl_desc, &context_) != GRASS_SUCCESS) {
        const QSurfaceFormat f = gl->format();
        *error = QStringLiteral("grass_gl_create_context failed on OpenGL %1.%2 (%3 profile); grass needs 4.5: request "
                                "it with QSurfaceFormat::setDefaultFormat before the window is shown")
                     .arg(f.majorVersion())
                     .arg(f.minorVersion())
                     .arg(f.profile() == QSurfaceFormat::CoreProfile ? QStringLiteral("core")
                                                                     : QStringLiteral("compatibility"));
        return false;
    }
    return true;
}

// Qt's GL backend can leave an error pending (llvmpipe: GL_INVALID_ENUM); grass checks
// glGetError after its calls and would report it as its own.
void GlFieldRenderer::clear_host_errors() {
    QOpenGLContext* gl = QOpenGLContext::currentContext();
    if (!gl) return;
    for (int k = 0; k < 16 && gl->functions()->glGetError() != GL_NO_ERROR; ++k) {}
}

grass_result GlFieldRenderer::draw(QString* error) {
    const grass_result r = grass_gl_render(context_);
    if (r != GRASS_SUCCESS) *error = QString::fromUtf8(grass_get_last_error(context_));
    return r;
}

} // namespace grass_qt
