// G-buffer views on GL (GRASS_PASS_GBUFFER; docs/engine-frames.md "Deferred renderers"): the
// check that the host's framebuffer has a draw buffer at every attachment grass writes. The
// fragment shaders write the kGBufferOutput locations (gbuffer.glsl);
// GlDrawStateGuard::begin_gbuffer routes them to the host's draw buffers.
#include "gl_backend.hpp"
#include "gl_program.hpp"

namespace grass {

grass_result GlBackend::check_gbuffer_target(const FramePlan& plan, const char* function) const {
    GLint framebuffer = 0;
    gl_.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    GLint max_draw_buffers = 1;
    gl_.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
    for (uint32_t output = 0; output < kGBufferOutputs; ++output) {
        const uint32_t index = plan.gbuffer_attachment[output];
        if (index == kNoGBufferOutput) continue;
        GLint buffer = GL_NONE;
        if (framebuffer != 0 && index < static_cast<uint32_t>(max_draw_buffers)) {
            gl_.GetIntegerv(static_cast<GLenum>(GL_DRAW_BUFFER0 + index), &buffer);
        }
        if (framebuffer == 0 || buffer == GL_NONE) {
            return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_GBUFFER_TARGET,
                              "%s: the view's grass_view_gbuffer_desc->attachments[%u] is written, but the bound draw "
                              "framebuffer (%d%s) has no draw buffer there (GL_DRAW_BUFFER%u is GL_NONE): bind a "
                              "framebuffer whose glDrawBuffers list has the G-buffer's attachments in its order",
                              function, index, framebuffer, framebuffer == 0 ? ", the default one" : "", index);
        }
    }
    return GRASS_SUCCESS;
}

} // namespace grass
