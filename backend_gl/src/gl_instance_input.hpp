// The vertex input of the programs that read only instances (debug boxes, the volume and
// image tiers): their corners come from the vertex index.
#pragma once

#include "gl_functions.hpp"

namespace grass {

// The binding the instance buffer is read from, in every vertex array of the backend.
constexpr GLuint kInstanceBinding = 1;

// A vertex array reading TierInstance records from `instance_buffer` on kInstanceBinding:
// location 5 vec4 origin, location 6 uvec4 cell and size (integer), location 7 vec4 terrain
// height range. 0 on failure.
GLuint create_instance_vertex_array(const GlFunctions& gl, GLuint instance_buffer);

} // namespace grass
