#include "gl_instance_input.hpp"

#include "foundation/frame_plan.hpp"

#include <cstddef>

namespace grass {

GLuint create_instance_vertex_array(const GlFunctions& gl, GLuint instance_buffer) {
    GLuint vao = 0;
    gl.CreateVertexArrays(1, &vao);
    if (vao == 0) return 0;
    gl.VertexArrayVertexBuffer(vao, kInstanceBinding, instance_buffer, 0, sizeof(TierInstance));
    gl.VertexArrayBindingDivisor(vao, kInstanceBinding, 1);
    gl.EnableVertexArrayAttrib(vao, 5);
    gl.VertexArrayAttribFormat(vao, 5, 4, GL_FLOAT, GL_FALSE, offsetof(TierInstance, origin));
    gl.VertexArrayAttribBinding(vao, 5, kInstanceBinding);
    gl.EnableVertexArrayAttrib(vao, 6);
    gl.VertexArrayAttribIFormat(vao, 6, 4, GL_UNSIGNED_INT, offsetof(TierInstance, cell));
    gl.VertexArrayAttribBinding(vao, 6, kInstanceBinding);
    gl.EnableVertexArrayAttrib(vao, 7);
    gl.VertexArrayAttribFormat(vao, 7, 4, GL_FLOAT, GL_FALSE, offsetof(TierInstance, terrain));
    gl.VertexArrayAttribBinding(vao, 7, kInstanceBinding);
    return vao;
}

} // namespace grass
