#include "gl_program_spy.hpp"

#include <cstring>

namespace grass_test {
namespace {

void APIENTRY seen_use_program(GLuint program) {
    if (program != 0) gl_program_spy().used.insert(program);
    gl_program_spy().use_program(program);
}

GLuint APIENTRY seen_create_program() {
    gl_program_spy().created += 1;
    return gl_program_spy().create_program();
}

} // namespace

GlProgramSpy& gl_program_spy() {
    static GlProgramSpy spy;
    return spy;
}

void (*gl_program_spy_filter(const char* name, void (*real)(void)))(void) {
    if (std::strcmp(name, "glUseProgram") == 0) {
        gl_program_spy().use_program = reinterpret_cast<PFNGLUSEPROGRAMPROC>(real);
        return reinterpret_cast<void (*)(void)>(&seen_use_program);
    }
    if (std::strcmp(name, "glCreateProgram") == 0) {
        gl_program_spy().create_program = reinterpret_cast<PFNGLCREATEPROGRAMPROC>(real);
        return reinterpret_cast<void (*)(void)>(&seen_create_program);
    }
    return real;
}

} // namespace grass_test
