#include "gl_debug_view.hpp"

#include "gl_instance_input.hpp"
#include "gl_program.hpp"

namespace grass {

namespace {

constexpr GLsizei kBoxVertices = 6; // two triangles, corners from gl_VertexID

} // namespace

grass_result GlDebugView::create(grass_context* ctx, const GlFunctions& gl, const char* function,
                                 GLuint instance_buffer) {
    const grass_result result = create_debug_tiers_program(ctx, gl, function, &program_);
    if (result != GRASS_SUCCESS) return result;

    vertex_array_ = create_instance_vertex_array(gl, instance_buffer);
    return GRASS_SUCCESS;
}

void GlDebugView::destroy(const GlFunctions& gl) {
    if (vertex_array_ != 0) gl.DeleteVertexArrays(1, &vertex_array_);
    if (program_ != 0) gl.DeleteProgram(program_);
    vertex_array_ = 0;
    program_ = 0;
}

void GlDebugView::draw(const GlFunctions& gl, const FramePlan& plan, GLuint uniform_buffer,
                       const Vector<GLintptr>& field_offsets) const {
    gl.UseProgram(program_);
    gl.BindVertexArray(vertex_array_);
    for (size_t i = 0; i < plan.draws.size(); ++i) {
        const TierDraw& draw = plan.draws[i];
        if (draw.instance_count == 0) continue;
        gl.BindBufferRange(GL_UNIFORM_BUFFER, 1, uniform_buffer, field_offsets[i], sizeof(FieldUniforms));
        gl.DrawArraysInstancedBaseInstance(GL_TRIANGLES, 0, kBoxVertices, static_cast<GLsizei>(draw.instance_count),
                                           draw.first_instance);
    }
}

} // namespace grass
