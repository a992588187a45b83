// grass-deferred: a small deferred renderer with grass in its G-buffer (docs/engine-frames.md,
// "Deferred renderers"). Headless GL 4.5 (the test hosts' EGL context), one frame, a PNG:
//
//   grass-deferred [--backend gl|vk] [out.png]        default: gl, grass-deferred.png
//   grass-deferred [--backend gl|vk] --velocity-output FILE.png
//
// --backend vk: the same scene with Vulkan (vk_deferred.cpp): the same G-buffer and lighting
// passes in a Vulkan deferred host (vk_deferred_host.hpp). The scene: scene.hpp. Both halves
// draw with the same shaders (shaders/: the ground, the lighting).
// 1. The G-buffer: base colour (RGBA16F, linear), normal (RGBA8, n * 0.5 + 0.5), material
//    (RGBA8: roughness, translucency, ambient occlusion), velocity (RGBA16F) and depth. The
//    host draws its ground into it, then grass draws a GRASS_PASS_GBUFFER view into the same
//    attachments.
// 2. The lighting pass (shaders/lighting.frag): one full-screen triangle reads the G-buffer
//    and lights every pixel, ground and grass alike, with a low sun, an ambient term and three point lights (glTF's
//    falloff, as grass_light's), into an sRGB target that becomes the PNG.
// Exits 0 when the picture holds lit grass (at least a tenth of its pixels green-dominant,
// and the point lights brightening over 2000 pixels by more than 40 levels against the sun
// alone), 1 otherwise.
// --velocity-output FILE.png: instead of the lit picture, two frames with a previous camera (a
// pan) and a gust of wind, grass writing its velocity into the G-buffer's velocity attachment,
// checked and drawn as a picture (velocity.hpp); exits 0 when the checks hold.
#include "gl_loader.hpp"
#include "headless_host.hpp"
#include "host_factories.hpp"
#include "image_io.hpp"
#include "scene.hpp"
#include "velocity.hpp"

#include <grass/grass_gl.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace deferred_glsl { // shaders/, embedded as text by the build (Vulkan's SPIR-V: vk_deferred_passes.cpp)
extern const char* const gbuffer_ground_vert; // the ground's quad into the G-buffer
extern const char* const gbuffer_ground_frag;
extern const char* const lighting_vert; // the full-screen lighting pass
extern const char* const lighting_frag;
} // namespace deferred_glsl

namespace {

using namespace deferred;

// GL entry points beyond the bootstrap's table.
struct Textures {
    PFNGLCREATETEXTURESPROC CreateTextures = nullptr;
    PFNGLTEXTURESTORAGE2DPROC TextureStorage2D = nullptr;
    PFNGLNAMEDFRAMEBUFFERTEXTUREPROC NamedFramebufferTexture = nullptr;
    PFNGLNAMEDFRAMEBUFFERDRAWBUFFERSPROC NamedFramebufferDrawBuffers = nullptr;
    PFNGLBINDTEXTUREUNITPROC BindTextureUnit = nullptr;
    PFNGLUNIFORMMATRIX4FVPROC UniformMatrix4fv = nullptr;
    PFNGLUNIFORM2FPROC Uniform2f = nullptr;
    PFNGLUNIFORM3FVPROC Uniform3fv = nullptr;
    PFNGLUNIFORM4FVPROC Uniform4fv = nullptr;
};

void* load_proc(void* host, const char* name) { return static_cast<grass_host::Host*>(host)->gl_proc_address(name); }

void log_message(void*, grass_log_level level, grass_message_id id, const char* message) {
    std::fprintf(stderr, "grass %s %d: %s\n", level == GRASS_LOG_ERROR ? "error" : "warning", int(id), message);
}

bool ok(grass_result r, const char* call) {
    if (r != GRASS_SUCCESS) std::fprintf(stderr, "%s failed: %s\n", call, grass_result_string(r));
    return r == GRASS_SUCCESS;
}

} // namespace

int main(int argc, char** argv) {
    bool vulkan = false;
    std::string out_path = "grass-deferred.png", velocity_path;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--backend" && i + 1 < argc &&
            (std::string(argv[i + 1]) == "gl" || std::string(argv[i + 1]) == "vk")) {
            vulkan = std::string(argv[++i]) == "vk";
        } else if (arg == "--velocity-output" && i + 1 < argc) {
            velocity_path = argv[++i];
        } else if (arg.rfind("--", 0) == 0) {
            std::fprintf(stderr,
                         "grass-deferred: unknown option %s (usage: grass-deferred [--backend gl|vk] "
                         "[--velocity-output FILE.png] [out.png])\n",
                         arg.c_str());
            return 2;
        } else {
            out_path = arg;
        }
    }
#ifdef GRASS_HOST_HAS_VULKAN
    if (vulkan) return run_vulkan(out_path, velocity_path);
#else
    if (vulkan) {
        std::fprintf(stderr, "grass-deferred: this build has no Vulkan backend\n");
        return 2;
    }
#endif
    grass_host::TargetDesc target;
    target.width = kWidth;
    target.height = kHeight;
    std::string error;
    std::unique_ptr<grass_host::Host> host = grass_host::create_gl_host(target, &error);
    grass_bootstrap::GlFunctions gl;
    Textures tx;
    if (!host || !gl.load(&load_proc, host.get(), &error)) {
        std::fprintf(stderr, "no GL 4.5 context: %s\n", error.c_str());
        return 1;
    }
#define LOAD(name) tx.name = reinterpret_cast<decltype(tx.name)>(host->gl_proc_address("gl" #name))
    LOAD(CreateTextures);
    LOAD(TextureStorage2D);
    LOAD(NamedFramebufferTexture);
    LOAD(NamedFramebufferDrawBuffers);
    LOAD(BindTextureUnit);
    LOAD(UniformMatrix4fv);
    LOAD(Uniform2f);
    LOAD(Uniform3fv);
    LOAD(Uniform4fv);
#undef LOAD

    // The G-buffer (albedo, normal, material, depth, velocity) and the lit target.
    GLuint textures[6], gbuffer = 0, lit = 0;
    const GLenum formats[6] = {GL_RGBA16F, GL_RGBA8, GL_RGBA8, GL_DEPTH_COMPONENT32F, GL_SRGB8_ALPHA8, GL_RGBA16F};
    tx.CreateTextures(GL_TEXTURE_2D, 6, textures);
    for (int i = 0; i < 6; ++i) tx.TextureStorage2D(textures[i], 1, formats[i], kWidth, kHeight);
    gl.CreateFramebuffers(1, &gbuffer);
    gl.CreateFramebuffers(1, &lit);
    const GLenum buffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    for (int i = 0; i < 3; ++i) tx.NamedFramebufferTexture(gbuffer, buffers[i], textures[i], 0);
    tx.NamedFramebufferTexture(gbuffer, buffers[3], textures[5], 0);
    tx.NamedFramebufferTexture(gbuffer, GL_DEPTH_ATTACHMENT, textures[3], 0);
    tx.NamedFramebufferDrawBuffers(gbuffer, 4, buffers);
    tx.NamedFramebufferTexture(lit, GL_COLOR_ATTACHMENT0, textures[4], 0);
    const GLuint ground = grass_bootstrap::compile_program(gl, deferred_glsl::gbuffer_ground_vert,
                                                           deferred_glsl::gbuffer_ground_frag, "ground", &error);
    const GLuint lighting = grass_bootstrap::compile_program(gl, deferred_glsl::lighting_vert,
                                                             deferred_glsl::lighting_frag, "lighting", &error);
    if (!ground || !lighting) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
    }
    GLuint vertex_array = 0;
    gl.CreateVertexArrays(1, &vertex_array);

    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = log_message;
    grass_context* ctx = nullptr;
    grass_patch_id patch{};
    grass_field_id field{};
    grass_patch_desc pd = grass_default_patch_desc();
    grass_field_desc fd = grass_default_field_desc();
    if (!ok(host->create_context(cd, &ctx), "grass_gl_create_context")) return 1;
    bool success = ok(grass_create_patch(ctx, &pd, &patch), "grass_create_patch");
    fd.patch = patch;
    fd.cells_x = fd.cells_z = kCells;
    success = success && ok(grass_create_field(ctx, &fd, &field), "grass_create_field");

    const double* eye = kEye;
    grass_view_desc view = grass_host::make_view(*host, kEye, kAt, kFovy, kNear, kFar);
    view.viewport[2] = kWidth;
    view.viewport[3] = kHeight;
    float vp[16]; // camera-relative world -> clip
    view_projection(view, vp);
    const bool velocity = !velocity_path.empty();
    grass_view_gbuffer_desc layout = gbuffer_layout(velocity);
    grass_view_pass_desc pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = &layout;
    view.next = &pass;
    grass_view_motion_desc motion = pan_motion(*host, false);
    if (velocity) {
        view.time = kTime;
        motion.next = &pass;
        view.next = &motion;
        const grass_wind_desc wind = gust_wind();
        success = success && ok(grass_set_wind(ctx, &wind), "grass_set_wind");
    }
    // The ground, then grass into the same G-buffer: albedo, normal, material (with its ambient
    // occlusion) and, for the velocity frames, velocity.
    const auto draw_gbuffer = [&]() {
        const float far_depth = 1.0f, zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        gl.BindFramebuffer(GL_FRAMEBUFFER, gbuffer);
        gl.Viewport(0, 0, kWidth, kHeight);
        for (int i = 0; i < 4; ++i) gl.ClearBufferfv(GL_COLOR, i, zero);
        gl.ClearBufferfv(GL_DEPTH, 0, &far_depth);
        gl.Enable(GL_DEPTH_TEST);
        gl.DepthFunc(GL_LEQUAL);
        gl.UseProgram(ground);
        gl.BindVertexArray(vertex_array);
        float world_to_clip[16], world_to_previous_clip[16];
        ground_matrices(view, world_to_clip, world_to_previous_clip);
        tx.UniformMatrix4fv(0, 1, GL_FALSE, world_to_clip);
        tx.UniformMatrix4fv(1, 1, GL_FALSE, world_to_previous_clip);
        gl.DrawArrays(GL_TRIANGLES, 0, 6);
        return ok(grass_begin_frame(ctx, &view), "grass_begin_frame") && ok(grass_gl_render(ctx), "grass_gl_render") &&
               ok(grass_end_frame(ctx), "grass_end_frame");
    };
    if (velocity) {
        // The velocity attachment of a frame without the wind's motion and of one with it,
        // read back top row first (GL's rows run bottom-up).
        const auto read_velocity = [&](bool wind_moves, VelocityImage* out) {
            motion = pan_motion(*host, wind_moves);
            motion.next = &pass;
            if (!draw_gbuffer()) return false;
            std::vector<float> rows(size_t(kWidth) * kHeight * 4);
            out->rgba.resize(rows.size());
            gl.ReadBuffer(GL_COLOR_ATTACHMENT3);
            gl.ReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, rows.data());
            const size_t row = size_t(kWidth) * 4;
            for (uint32_t y = 0; y < kHeight; ++y)
                std::memcpy(&out->rgba[y * row], &rows[(kHeight - 1 - y) * row], row * sizeof(float));
            return true;
        };
        VelocityImage still, gust;
        success = success && read_velocity(false, &still) && read_velocity(true, &gust);
        const int checked = success ? check_and_write_velocity(view, still, gust, velocity_path) : 1;
        grass_destroy_context(ctx);
        return checked;
    }
    success = success && draw_gbuffer();

    // The lighting pass into the sRGB target.
    float lamp_positions[3][4];
    for (int i = 0; i < 3; ++i) {
        for (int c = 0; c < 3; ++c) lamp_positions[i][c] = float(kLamps[i][c] - eye[c]);
        lamp_positions[i][3] = kLampRange;
    }
    // Lights the G-buffer into the sRGB target and reads it back, top row first; `with_lamps`
    // false: the sun and the ambient light alone (what the lamps add is checked below).
    const auto light_and_read = [&](bool with_lamps) {
        const float none[3][4] = {};
        gl.BindFramebuffer(GL_FRAMEBUFFER, lit);
        gl.Disable(GL_DEPTH_TEST);
        gl.Enable(GL_FRAMEBUFFER_SRGB);
        gl.UseProgram(lighting);
        for (int i = 0; i < 4; ++i) tx.BindTextureUnit(GLuint(i), textures[i]);
        tx.UniformMatrix4fv(0, 1, GL_FALSE, vp);
        tx.Uniform2f(1, float(kWidth), float(kHeight));
        tx.Uniform3fv(2, 1, kSunDirection);
        tx.Uniform3fv(3, 1, kSunColor);
        tx.Uniform3fv(4, 1, kAmbient);
        tx.Uniform4fv(5, 3, &lamp_positions[0][0]);
        tx.Uniform4fv(8, 3, with_lamps ? &kLampColors[0][0] : &none[0][0]);
        gl.DrawArrays(GL_TRIANGLES, 0, 3);
        std::vector<uint8_t> rows(size_t(kWidth) * kHeight * 4), top_first(rows.size());
        gl.Disable(GL_FRAMEBUFFER_SRGB); // the stored sRGB bytes as they are
        gl.ReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
        const size_t row = size_t(kWidth) * 4;
        for (uint32_t y = 0; y < kHeight; ++y) std::memcpy(&top_first[y * row], &rows[(kHeight - 1 - y) * row], row);
        return top_first;
    };
    const std::vector<uint8_t> sun_only = light_and_read(false);
    success = holds_lit_grass(light_and_read(true), sun_only, out_path) && success;
    grass_destroy_context(ctx);
    return success ? 0 : 1;
}
