#include "gl_target.hpp"

#include <cstdio>

namespace grass_bootstrap {

namespace {

bool complete(const GlFunctions& gl, GLuint fbo, const std::string& what, std::string* error) {
    const GLenum status = gl.CheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return true;
    char hex[16];
    std::snprintf(hex, sizeof(hex), "0x%04X", unsigned(status));
    *error = what + " framebuffer is incomplete: status " + hex;
    return false;
}

} // namespace

bool create_render_target(const GlFunctions& gl, GLsizei width, GLsizei height, GLsizei samples, GLenum color_format,
                          const char* label, GlRenderTarget* out, std::string* error) {
    const GLsizei draw_samples = samples > 1 ? samples : 0;
    gl.CreateRenderbuffers(1, &out->color_rb);
    gl.NamedRenderbufferStorageMultisample(out->color_rb, draw_samples, color_format, width, height);
    gl.CreateRenderbuffers(1, &out->depth_rb);
    gl.NamedRenderbufferStorageMultisample(out->depth_rb, draw_samples, GL_DEPTH_COMPONENT32F, width, height);
    gl.CreateFramebuffers(1, &out->draw_fbo);
    gl.NamedFramebufferRenderbuffer(out->draw_fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, out->color_rb);
    gl.NamedFramebufferRenderbuffer(out->draw_fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, out->depth_rb);
    if (!complete(gl, out->draw_fbo, label, error)) return false;
    if (draw_samples == 0) return true;
    gl.CreateRenderbuffers(1, &out->resolve_rb);
    gl.NamedRenderbufferStorageMultisample(out->resolve_rb, 0, color_format, width, height);
    gl.CreateFramebuffers(1, &out->resolve_fbo);
    gl.NamedFramebufferRenderbuffer(out->resolve_fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, out->resolve_rb);
    return complete(gl, out->resolve_fbo, std::string(label) + " resolve", error);
}

void destroy_render_target(const GlFunctions& gl, GlRenderTarget* target) {
    const GLuint framebuffers[] = {target->draw_fbo, target->resolve_fbo};
    const GLuint renderbuffers[] = {target->color_rb, target->depth_rb, target->resolve_rb};
    gl.DeleteFramebuffers(2, framebuffers); // zero names are ignored
    gl.DeleteRenderbuffers(3, renderbuffers);
    *target = GlRenderTarget{};
}

} // namespace grass_bootstrap
