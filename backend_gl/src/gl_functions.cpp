#include "gl_functions.hpp"

namespace grass {

const char* GlFunctions::load(grass_gl_get_proc_address_fn loader, void* user_data) {
#define GRASS_GL_LOAD(type, name)                                 \
    name = reinterpret_cast<type>(loader(user_data, "gl" #name)); \
    if (!name) return "gl" #name;
    GRASS_GL_FUNCTIONS(GRASS_GL_LOAD)
#undef GRASS_GL_LOAD
    return nullptr;
}

} // namespace grass
