// The hosts' GL scene target: a framebuffer of a colour and a depth renderbuffer
// (multisampled when samples > 1) and, when multisampled, a single-sample resolve
// framebuffer the scene is blitted into. The headless GL host and the viewer's GL window
// draw into one.
#pragma once

#include "gl_loader.hpp"

#include <string>

namespace grass_bootstrap {

struct GlRenderTarget {
    GLuint draw_fbo = 0, color_rb = 0, depth_rb = 0; // multisampled when samples > 1
    GLuint resolve_fbo = 0, resolve_rb = 0;          // only when multisampled
};

// False and *error ("<label> framebuffer is incomplete: status 0x....") when GL refuses.
bool create_render_target(const GlFunctions& gl, GLsizei width, GLsizei height, GLsizei samples, GLenum color_format,
                          const char* label, GlRenderTarget* out, std::string* error);
void destroy_render_target(const GlFunctions& gl, GlRenderTarget* target);

} // namespace grass_bootstrap
