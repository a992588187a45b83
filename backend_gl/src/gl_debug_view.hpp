// The debug view (GRASS_VIEW_FLAG_DEBUG_CELLS): every planned instance of every tier kind
// as a flat box coloured by its kind, drawn instead of the grass. Needs no patch: the six
// corners come from the vertex index, the instances from the frame's instance buffer.
#pragma once

#include "gl_functions.hpp"

#include <context.hpp>
#include <frame_plan.hpp>

namespace grass {

class GlDebugView {
public:
    // Builds the program and a vertex array reading `instance_buffer` (binding 1, locations
    // 5-6). On failure the context holds the message and nothing is left behind.
    grass_result create(grass_context* ctx, const GlFunctions& gl, const char* function, GLuint instance_buffer);
    void destroy(const GlFunctions& gl);

    // One draw per plan draw, all kinds. The caller has set the draw state, bound the Frame
    // block and uploaded the plan; field_offsets[i] is draw i's Field block in uniform_buffer.
    void draw(const GlFunctions& gl, const FramePlan& plan, GLuint uniform_buffer,
              const Vector<GLintptr>& field_offsets) const;

private:
    GLuint program_ = 0;
    GLuint vertex_array_ = 0;
};

} // namespace grass
