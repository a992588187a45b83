// The check that the host's GL context of a grass context is current on the calling thread
// (grass_gl.h), made before every call that would make GL calls. Core GL has no "current
// context" query and hosts load GL through EGL, GLX, OSMesa, Qt or OSG, so the check asks GL
// itself: a vertex array object (never shared between GL contexts) that grass made at
// creation carries a label unique in the process. In the right context the name is a vertex
// array with that label; in another context it is no vertex array, or one with another
// label; with no context current, GL's no-op dispatch answers 0 and writes nothing. Neither
// call raises a GL error. Cost: two GL queries per checked call.
#include "gl_backend.hpp"

#include <atomic>
#include <cstdio>
#include <cstring>

namespace grass {

void GlBackend::label_context() {
    static std::atomic<uint64_t> contexts{0}; // process-wide: no two grass contexts share a label
    const int n = std::snprintf(context_label_, sizeof(context_label_), "grass context %llu",
                                static_cast<unsigned long long>(contexts.fetch_add(1) + 1));
    context_label_length_ = static_cast<GLsizei>(n);
    gl_.ObjectLabel(GL_VERTEX_ARRAY, tier_vertex_array_, context_label_length_, context_label_);
}

grass_result GlBackend::check_current(const char* function) {
    bool current = tier_vertex_array_ != 0 && gl_.IsVertexArray(tier_vertex_array_) == GL_TRUE;
    if (current) {
        char label[sizeof(context_label_)] = {};
        GLsizei length = 0;
        gl_.GetObjectLabel(GL_VERTEX_ARRAY, tier_vertex_array_, sizeof(label), &length, label);
        current = length == context_label_length_ && std::memcmp(label, context_label_, sizeof(label)) == 0;
    }
    if (current) return GRASS_SUCCESS;
    return ctx_->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_GL_CONTEXT_NOT_CURRENT,
                      "%s: the GL context this grass context was created with is not current on this thread (no "
                      "GL context is, or another one is); make it current first",
                      function);
}

} // namespace grass
