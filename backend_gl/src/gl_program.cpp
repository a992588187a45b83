#include "gl_program.hpp"

#include "patch/random.hpp"

#include <cstdio>
#include <cstring>

namespace grass_gl_shaders {
extern const char* const blade_vert;
extern const char* const blade_frag;
extern const char* const debug_tiers_vert;
extern const char* const debug_tiers_frag;
extern const char* const image_vert;
extern const char* const image_frag;
extern const char* const volume_vert;
extern const char* const volume_frag;
extern const char* const interaction_comp;
extern const char* const blade_window_comp;
extern const char* const blade_compaction_comp;
} // namespace grass_gl_shaders

namespace grass {

namespace {

// The density map is sampled from texture unit 0 (the unit grass_gl.h documents as
// saved and restored); the shader's binding = 2 is the Vulkan descriptor binding. The
// baked slices use units 3-5 and the other maps 6-9, as their bindings say; set here too
// so that nothing depends on the driver honouring layout(binding) on samplers.
struct SamplerUnit {
    const char* name;
    GLint unit;
};
constexpr SamplerUnit kSamplerUnits[] = {
    {"density_map", kMapUnit[kMapDensity]},
    {"slice_color", kSliceColorUnit},
    {"slice_normal", kSliceNormalUnit},
    {"slice_threshold", kSliceThresholdUnit},
    {"color_map", kMapUnit[kMapColor]},
    {"ambient_map", kMapUnit[kMapAmbient]},
    {"diffuse_map", kMapUnit[kMapDiffuse]},
    {"height_map", kMapUnit[kMapHeight]},
    {"interaction_level0", kInteractionMapUnit[0]},
    {"interaction_level1", kInteractionMapUnit[1]},
    {"wind_map", kWindMapUnit},
    {"host_shadow_map", kShadowMapUnit},
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

// Compiles `source` with the feature mask defined right after its #version line (which
// must come first, so the define cannot precede it).
grass_result compile(grass_context* ctx, const GlFunctions& gl, const char* function, GLenum stage,
                     const char* stage_name, const char* source, uint32_t features, GLuint* out_shader,
                     bool compact = true) {
    const char* newline = std::strchr(source, '\n');
    if (std::strncmp(source, "#version", 8) != 0 || newline == nullptr) {
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                         "%s: %s does not start with a #version line (internal error)", function, stage_name);
    }
    char define[320];
    const bool responsive = (features & kBladeCurveFeatures) != 0;
    // The blade window's variant (kFeatureBladeWindow): the poses read from the window only,
    // one instance per blade the view draws where the backend compacts (`compact`: a driver
    // with GL_ARB_shader_draw_parameters, GlBackend::compacts_blade_window): GRASS_BLADE_COMPACT.
    const bool window = responsive && (features & kFeatureBladeWindow) != 0;
    const bool shadows = (features & kFeatureShadowReceive) != 0;
    const bool motion = (features & kFeatureMotion) != 0;
    const bool lights = (features & kFeatureHostLights) != 0;
    const bool gbuffer = (features & kFeatureGBuffer) != 0;
    std::snprintf(define, sizeof define, "#define GRASS_FEATURES %uu\n%s%s%s%s%s", features,
                  responsive ? (window ? (compact ? "#define GRASS_RESPONSIVE 1\n#define GRASS_BLADE_WINDOW 1\n"
                                                    "#define GRASS_BLADE_COMPACT 1\n"
                                                  : "#define GRASS_RESPONSIVE 1\n#define GRASS_BLADE_WINDOW 1\n")
                                       : "#define GRASS_RESPONSIVE 1\n")
                             : "",
                  shadows ? "#define GRASS_HOST_SHADOWS 1\n" : "", motion ? "#define GRASS_VELOCITY 1\n" : "",
                  lights ? "#define GRASS_HOST_LIGHTS 1\n" : "", gbuffer ? "#define GRASS_GBUFFER 1\n" : "");
    const GLchar* strings[3] = {source, define, newline + 1};
    const GLint lengths[3] = {static_cast<GLint>(newline + 1 - source), -1, -1};

    const GLuint shader = gl.CreateShader(stage);
    if (shader == 0) {
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED, "%s: glCreateShader(%s) returned 0",
                         function, stage_name);
    }
    gl.ShaderSource(shader, 3, strings, lengths);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const Vector<char> log = info_log(ctx, shader, gl.GetShaderiv, gl.GetShaderInfoLog);
        gl.DeleteShader(shader);
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                         "%s: the GL driver failed to compile %s (features 0x%x): %s", function, stage_name, features,
                         log.data());
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

ProgramSource program_source(GlProgramKind kind) {
    switch (kind) {
    case kProgramVolume:
        return {"the volume tier program", "volume.vert", grass_gl_shaders::volume_vert, "volume.frag",
                grass_gl_shaders::volume_frag};
    case kProgramImage:
        return {"the image tier program", "image.vert", grass_gl_shaders::image_vert, "image.frag",
                grass_gl_shaders::image_frag};
    case kProgramDebugTiers:
        return {"the debug tiers program", "debug_tiers.vert", grass_gl_shaders::debug_tiers_vert, "debug_tiers.frag",
                grass_gl_shaders::debug_tiers_frag};
    case kProgramBlades:
    default:
        return {"the blade program", "blade.vert", grass_gl_shaders::blade_vert, "blade.frag",
                grass_gl_shaders::blade_frag};
    }
}

// Links the compiled shaders (deleted here, whatever the outcome) into a program.
grass_result link(grass_context* ctx, const GlFunctions& gl, const char* function, const char* name, uint32_t features,
                  const GLuint* shaders, int shader_count, GLuint* out_program) {
    const GLuint program = gl.CreateProgram();
    if (program == 0) {
        for (int i = 0; i < shader_count; ++i) gl.DeleteShader(shaders[i]);
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED, "%s: glCreateProgram returned 0",
                         function);
    }
    for (int i = 0; i < shader_count; ++i) gl.AttachShader(program, shaders[i]);
    // grass_get_pipeline_cache_data may ask for its binary (gl_program_cache.hpp).
    gl.ProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
    gl.LinkProgram(program);
    for (int i = 0; i < shader_count; ++i) {
        gl.DetachShader(program, shaders[i]);
        gl.DeleteShader(shaders[i]);
    }

    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const Vector<char> log = info_log(ctx, program, gl.GetProgramiv, gl.GetProgramInfoLog);
        gl.DeleteProgram(program);
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                         "%s: the GL driver failed to link %s (features 0x%x): %s", function, name, features,
                         log.data());
    }
    *out_program = program;
    return GRASS_SUCCESS;
}

} // namespace

grass_result create_interaction_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                        GLuint* out_program) {
    GLuint comp = 0;
    const grass_result result =
        compile(ctx, gl, function, GL_COMPUTE_SHADER, "interaction.comp", grass_gl_shaders::interaction_comp, 0, &comp);
    if (result != GRASS_SUCCESS) return result;
    return link(ctx, gl, function, "the interaction pass program", 0, &comp, 1, out_program);
}

namespace {

grass_result create_compute_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                    const char* stage_name, const char* source, const char* name, uint32_t features,
                                    GLuint* out_program) {
    GLuint comp = 0;
    const grass_result result = compile(ctx, gl, function, GL_COMPUTE_SHADER, stage_name, source, features, &comp);
    if (result != GRASS_SUCCESS) return result;
    GLuint program = 0;
    const grass_result linked = link(ctx, gl, function, name, features, &comp, 1, &program);
    if (linked != GRASS_SUCCESS) return linked;
    set_sampler_units(gl, program);
    *out_program = program;
    return GRASS_SUCCESS;
}

} // namespace

grass_result create_blade_window_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                         uint32_t features, GLuint* out_program) {
    return create_compute_program(ctx, gl, function, "blade_window.comp", grass_gl_shaders::blade_window_comp,
                                  "the blade window pass program", features, out_program);
}

grass_result create_blade_compaction_program(grass_context* ctx, const GlFunctions& gl, const char* function,
                                             uint32_t features, GLuint* out_program) {
    return create_compute_program(ctx, gl, function, "blade_compaction.comp", grass_gl_shaders::blade_compaction_comp,
                                  "the blade compaction program", features, out_program);
}

grass_result create_program(grass_context* ctx, const GlFunctions& gl, const char* function, GlProgramKind kind,
                            uint32_t features, bool compact, GLuint* out_program) {
    const ProgramSource source = program_source(kind);
    GLuint shaders[2] = {0, 0};
    grass_result result =
        compile(ctx, gl, function, GL_VERTEX_SHADER, source.vert_name, source.vert, features, &shaders[0], compact);
    if (result != GRASS_SUCCESS) return result;
    result =
        compile(ctx, gl, function, GL_FRAGMENT_SHADER, source.frag_name, source.frag, features, &shaders[1], compact);
    if (result != GRASS_SUCCESS) {
        gl.DeleteShader(shaders[0]);
        return result;
    }
    GLuint program = 0;
    result = link(ctx, gl, function, source.name, features, shaders, 2, &program);
    if (result != GRASS_SUCCESS) return result;

    set_sampler_units(gl, program);
    *out_program = program;
    return GRASS_SUCCESS;
}

void set_sampler_units(const GlFunctions& gl, GLuint program) {
    for (const SamplerUnit& sampler : kSamplerUnits) {
        const GLint location = gl.GetUniformLocation(program, sampler.name);
        if (location >= 0) gl.ProgramUniform1i(program, location, sampler.unit);
    }
}

uint64_t shader_sources_hash() {
    const char* const sources[] = {grass_gl_shaders::blade_vert,       grass_gl_shaders::blade_frag,
                                   grass_gl_shaders::debug_tiers_vert, grass_gl_shaders::debug_tiers_frag,
                                   grass_gl_shaders::image_vert,       grass_gl_shaders::image_frag,
                                   grass_gl_shaders::volume_vert,      grass_gl_shaders::volume_frag,
                                   grass_gl_shaders::interaction_comp, grass_gl_shaders::blade_window_comp};
    uint64_t hash = kFnvOffset;
    for (const char* source : sources) hash = fnv1a64(source, std::strlen(source) + 1, hash);
    return hash;
}

} // namespace grass
