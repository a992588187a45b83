#include "gl_program.hpp"

namespace grass_gl_shaders {
extern const char* const blade_vert;
extern const char* const blade_frag;
extern const char* const debug_tiers_vert;
extern const char* const debug_tiers_frag;
extern const char* const image_vert;
extern const char* const image_frag;
extern const char* const volume_vert;
extern const char* const volume_frag;
} // namespace grass_gl_shaders

namespace grass {

namespace {

// The density map is sampled from texture unit 0 (the unit grass_gl.h documents as
// saved and restored); the shader's binding = 2 is the Vulkan descriptor binding. The
// baked slices use units 3-5, as their bindings say; set here too so that nothing
// depends on the driver honouring layout(binding) on samplers.
struct SamplerUnit {
    const char* name;
    GLint unit;
};
constexpr SamplerUnit kSamplerUnits[] = {
    {"density_map", kDensityMapUnit},
    {"slice_color", kSliceColorUnit},
    {"slice_normal", kSliceNormalUnit},
    {"slice_threshold", kSliceThresholdUnit},
};

// Reads a shader or program info log through the context's allocator.
template <class GetIv, class GetLog>
Vector<char> info_log(grass_context* ctx, GLuint object, GetIv get_iv, GetLog get_log) {
    GLint length = 0;
    get_iv(object, GL_INFO_LOG_LENGTH, &length);
    Vector<char> log(static_cast<size_t>(length > 0 ? length : 0) + 1, '\0', StlAllocator<char>(&ctx->host));
    if (length > 0) get_log(object, length, nullptr, log.data());
    return log;
}

grass_result compile(grass_context* ctx, const GlFunctions& gl, const char* function, GLenum stage,
                     const char* stage_name, const char* source, GLuint* out_shader) {
    const GLuint shader = gl.CreateShader(stage);
    if (shader == 0) {
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                         "%s: glCreateShader(%s) returned 0", function, stage_name);
    }
    gl.ShaderSource(shader, 1, &source, nullptr);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const Vector<char> log = info_log(ctx, shader, gl.GetShaderiv, gl.GetShaderInfoLog);
        gl.DeleteShader(shader);
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                         "%s: the GL driver failed to compile %s: %s", function, stage_name, log.data());
    }
    *out_shader = shader;
    return GRASS_SUCCESS;
}

struct ProgramSource {
    const char* name; // for messages: "the blade program"
    const char* vert_name;
    const char* vert;
    const char* frag_name;
    const char* frag;
};

grass_result create_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                            const ProgramSource& source, GLuint* out_program) {
    GLuint vert = 0;
    GLuint frag = 0;
    grass_result result = compile(ctx, gl, function, GL_VERTEX_SHADER, source.vert_name, source.vert, &vert);
    if (result != GRASS_SUCCESS) return result;
    result = compile(ctx, gl, function, GL_FRAGMENT_SHADER, source.frag_name, source.frag, &frag);
    if (result != GRASS_SUCCESS) {
        gl.DeleteShader(vert);
        return result;
    }

    const GLuint program = gl.CreateProgram();
    if (program == 0) {
        gl.DeleteShader(vert);
        gl.DeleteShader(frag);
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED, "%s: glCreateProgram returned 0",
                         function);
    }
    gl.AttachShader(program, vert);
    gl.AttachShader(program, frag);
    gl.LinkProgram(program);
    gl.DetachShader(program, vert);
    gl.DetachShader(program, frag);
    gl.DeleteShader(vert);
    gl.DeleteShader(frag);

    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const Vector<char> log = info_log(ctx, program, gl.GetProgramiv, gl.GetProgramInfoLog);
        gl.DeleteProgram(program);
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                         "%s: the GL driver failed to link %s: %s", function, source.name, log.data());
    }

    for (const SamplerUnit& sampler : kSamplerUnits) {
        const GLint location = gl.GetUniformLocation(program, sampler.name);
        if (location >= 0) gl.ProgramUniform1i(program, location, sampler.unit);
    }
    *out_program = program;
    return GRASS_SUCCESS;
}

} // namespace

grass_result create_blade_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                  GLuint* out_program) {
    const ProgramSource source = {"the blade program", "blade.vert", grass_gl_shaders::blade_vert, "blade.frag",
                                  grass_gl_shaders::blade_frag};
    return create_program(ctx, gl, function, source, out_program);
}

grass_result create_debug_tiers_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                        GLuint* out_program) {
    const ProgramSource source = {"the debug tiers program", "debug_tiers.vert", grass_gl_shaders::debug_tiers_vert,
                                  "debug_tiers.frag", grass_gl_shaders::debug_tiers_frag};
    return create_program(ctx, gl, function, source, out_program);
}

grass_result create_image_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                  GLuint* out_program) {
    const ProgramSource source = {"the image tier program", "image.vert", grass_gl_shaders::image_vert, "image.frag",
                                  grass_gl_shaders::image_frag};
    return create_program(ctx, gl, function, source, out_program);
}

grass_result create_volume_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                   GLuint* out_program) {
    const ProgramSource source = {"the volume tier program", "volume.vert", grass_gl_shaders::volume_vert,
                                  "volume.frag", grass_gl_shaders::volume_frag};
    return create_program(ctx, gl, function, source, out_program);
}

} // namespace grass
