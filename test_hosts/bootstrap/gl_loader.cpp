#include "gl_loader.hpp"

namespace grass_bootstrap {

bool GlFunctions::load(GlProcLoader loader, void* user_data, std::string* error) {
    *this = GlFunctions{};
#define GRASS_BOOTSTRAP_GL_LOAD(type, name)                       \
    name = reinterpret_cast<type>(loader(user_data, "gl" #name)); \
    if (!name) {                                                  \
        *error = "the GL loader has no gl" #name;                 \
        *this = GlFunctions{};                                    \
        return false;                                             \
    }
    GRASS_BOOTSTRAP_GL_FUNCTIONS(GRASS_BOOTSTRAP_GL_LOAD)
#undef GRASS_BOOTSTRAP_GL_LOAD
    return true;
}

bool require_gl45(const GlFunctions& gl, std::string* error) {
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major < 4 || (major == 4 && minor < 5)) {
        *error = "the GL context is " + std::to_string(major) + "." + std::to_string(minor) + "; 4.5 is required";
        return false;
    }
    return true;
}

std::string gl_renderer(const GlFunctions& gl) {
    const auto* renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
    return renderer ? renderer : "unknown GL renderer";
}

namespace {

// Compiles `count` shaders of the given stages and links them into a program.
GLuint link_stages(const GlFunctions& gl, const GLenum* stages, const char* const* sources, int count,
                   const char* label, std::string* error) {
    const GLuint program = gl.CreateProgram();
    for (int k = 0; k < count; ++k) {
        const GLuint shader = gl.CreateShader(stages[k]);
        gl.ShaderSource(shader, 1, &sources[k], nullptr);
        gl.CompileShader(shader);
        GLint ok = 0;
        gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            char log[1024] = {0};
            gl.GetShaderInfoLog(shader, sizeof(log), nullptr, log);
            *error = std::string(label) + " shader: " + log;
            gl.DeleteShader(shader);
            gl.DeleteProgram(program);
            return 0;
        }
        gl.AttachShader(program, shader);
        gl.DeleteShader(shader);
    }
    gl.LinkProgram(program);
    GLint linked = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        char log[1024] = {0};
        gl.GetProgramInfoLog(program, sizeof(log), nullptr, log);
        *error = std::string(label) + " program: " + log;
        gl.DeleteProgram(program);
        return 0;
    }
    return program;
}

} // namespace

GLuint compile_program(const GlFunctions& gl, const char* vertex, const char* fragment, const char* label,
                       std::string* error) {
    const char* sources[2] = {vertex, fragment};
    const GLenum stages[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    return link_stages(gl, stages, sources, 2, label, error);
}

GLuint compile_compute_program(const GlFunctions& gl, const char* compute, const char* label, std::string* error) {
    const GLenum stage = GL_COMPUTE_SHADER;
    return link_stages(gl, &stage, &compute, 1, label, error);
}

} // namespace grass_bootstrap
