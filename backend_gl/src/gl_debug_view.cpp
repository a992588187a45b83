#include "gl_debug_view.hpp"

#include "gl_program.hpp"

#include <cstddef>

namespace grass {

namespace {

constexpr GLuint kInstanceBinding = 1; // as in the blade vertex arrays
constexpr GLsizei kBoxVertices = 6;    // two triangles, corners from gl_VertexID

} // namespace

grass_result GlDebugView::create(grass_context* ctx, const GlFunctions& gl, const char* function,
                                 GLuint instance_buffer) {
    const grass_result result = create_debug_tiers_program(ctx, gl, function, &program_);
    if (result != GRASS_SUCCESS) return result;

    gl.CreateVertexArrays(1, &vertex_array_);
    gl.VertexArrayVertexBuffer(vertex_array_, kInstanceBinding, instance_buffer, 0, sizeof(TierInstance));
    gl.VertexArrayBindingDivisor(vertex_array_, kInstanceBinding, 1);
    // Location 5: vec4 origin; location 6: uvec4 cell and size (integer).
    gl.EnableVertexArrayAttrib(vertex_array_, 5);
    gl.VertexArrayAttribFormat(vertex_array_, 5, 4, GL_FLOAT, GL_FALSE, offsetof(TierInstance, origin));
    gl.VertexArrayAttribBinding(vertex_array_, 5, kInstanceBinding);
    gl.EnableVertexArrayAttrib(vertex_array_, 6);
    gl.VertexArrayAttribIFormat(vertex_array_, 6, 4, GL_UNSIGNED_INT, offsetof(TierInstance, cell));
    gl.VertexArrayAttribBinding(vertex_array_, 6, kInstanceBinding);
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
