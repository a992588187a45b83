// Motion vectors on GL (grass_view_motion_desc; docs/engine-frames.md "Motion vectors"): the
// velocity target's check and the GrassMotion block. The fragment shaders of a motion view
// write the velocity to output location 1 (motion.glsl); GlDrawStateGuard::begin_motion
// routes that location to the host's draw buffer.
#include "gl_backend.hpp"
#include "gl_program.hpp"

namespace grass {

grass_result GlBackend::check_velocity_target(const FramePlan& plan, const char* function) const {
    GLint framebuffer = 0;
    gl_.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    const uint32_t index = plan.velocity_attachment;
    GLint max_draw_buffers = 1;
    gl_.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
    GLint buffer = GL_NONE;
    if (framebuffer != 0 && index < static_cast<uint32_t>(max_draw_buffers)) {
        gl_.GetIntegerv(static_cast<GLenum>(GL_DRAW_BUFFER0 + index), &buffer);
    }
    if (framebuffer == 0 || buffer == GL_NONE) {
        return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_VELOCITY_TARGET,
                          "%s: the view's grass_view_motion_desc->velocity_attachment is %u, but the bound draw "
                          "framebuffer (%d%s) has no draw buffer there (GL_DRAW_BUFFER%u is GL_NONE): bind a "
                          "framebuffer whose glDrawBuffers list has the velocity target at that index",
                          function, index, framebuffer, framebuffer == 0 ? ", the default one" : "", index);
    }
    return GRASS_SUCCESS;
}

void GlBackend::bind_motion(const FramePlan&) const {
    gl_.BindBufferRange(GL_UNIFORM_BUFFER, kMotionUniformBinding, uniforms_.name(), motion_uniform_offset_,
                        sizeof(MotionUniforms));
}

} // namespace grass
