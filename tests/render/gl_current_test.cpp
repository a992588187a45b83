// The GL context of a grass context must be current for every call that makes GL calls
// (grass_gl.h): with no GL context current, or with another one current, each such call is
// refused with GRASS_MSG_GL_CONTEXT_NOT_CURRENT, makes no GL call (no error is left in the
// other context), and once the right context is current again everything works. (Before,
// the calls succeeded: with no context the field drew nothing, and with another context
// the patch and map were made in it and the next grass_gl_render crashed in the driver.)
// EGL hosts only: the test switches contexts with eglMakeCurrent.
#include "render_fixture.hpp"

#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <GL/glcorearb.h>

namespace grass_test {
namespace {

const std::string kNotCurrent = std::to_string(int(GRASS_MSG_GL_CONTEXT_NOT_CURRENT)) + ":";

class GlCurrentTest : public RenderTest {
protected:
    void SetUp() override {
        RenderTest::SetUp();
        display_ = eglGetCurrentDisplay();
        mine_ = eglGetCurrentContext();
        if (mine_ == EGL_NO_CONTEXT) GTEST_SKIP() << "the GL host is not on EGL (OSMesa)";
        draw_ = eglGetCurrentSurface(EGL_DRAW);
        read_ = eglGetCurrentSurface(EGL_READ);
        const EGLint attributes[] = {
            EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        other_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
        ASSERT_NE(other_, EGL_NO_CONTEXT) << "a second GL context";
        get_error_ = reinterpret_cast<PFNGLGETERRORPROC>(eglGetProcAddress("glGetError"));
        gen_vertex_arrays_ = reinterpret_cast<PFNGLGENVERTEXARRAYSPROC>(eglGetProcAddress("glGenVertexArrays"));
        bind_vertex_array_ = reinterpret_cast<PFNGLBINDVERTEXARRAYPROC>(eglGetProcAddress("glBindVertexArray"));
        ASSERT_TRUE(get_error_ && gen_vertex_arrays_ && bind_vertex_array_);
    }
    void TearDown() override {
        if (mine_ != EGL_NO_CONTEXT) make_mine_current();
        if (other_ != EGL_NO_CONTEXT) eglDestroyContext(display_, other_);
        RenderTest::TearDown();
    }
    void make_mine_current() { ASSERT_TRUE(eglMakeCurrent(display_, draw_, read_, mine_)); }
    // None: no GL context current. Other: a second context, holding vertex arrays of the
    // same names as grass's in its own (so that a name check alone would be fooled).
    void make_current(bool other) {
        if (!other) {
            ASSERT_TRUE(eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
            return;
        }
        ASSERT_TRUE(eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, other_));
        GLuint names[32];
        gen_vertex_arrays_(32, names);
        for (GLuint n : names) bind_vertex_array_(n); // a VAO exists once bound
        bind_vertex_array_(0);
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext mine_ = EGL_NO_CONTEXT, other_ = EGL_NO_CONTEXT;
    EGLSurface draw_ = EGL_NO_SURFACE, read_ = EGL_NO_SURFACE;
    PFNGLGETERRORPROC get_error_ = nullptr;
    PFNGLGENVERTEXARRAYSPROC gen_vertex_arrays_ = nullptr;
    PFNGLBINDVERTEXARRAYPROC bind_vertex_array_ = nullptr;
};

TEST_P(GlCurrentTest, EveryGlCallIsRefusedWithoutItsContextAndWorksAgainAfter) {
    const double eye[3] = {0.5, 2.0, 0.5}, target[3] = {0.5, 0.0, 0.5001};
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    const grass_field_id field = make_field(field_desc(4));
    const unsigned char texels[4] = {255, 255, 255, 255};
    grass_map_desc md = grass_default_map_desc();
    md.width = md.height = 2;
    md.row_pitch = 2;
    md.pixels = texels;
    grass_map_id map{};
    ASSERT_EQ(grass_create_map(ctx, &md, &map), GRASS_SUCCESS) << log;
    const grass_view_desc v = view(eye, target);
    for (bool other : {false, true}) {
        SCOPED_TRACE(other ? "another GL context current" : "no GL context current");
        make_current(other);
        if (other) {
            ASSERT_EQ(get_error_(), static_cast<GLenum>(GL_NO_ERROR));
        }
        const grass_patch_desc pd = grass_default_patch_desc();
        grass_patch_id new_patch{};
        grass_map_id new_map{};
        grass_field_id new_field{};
        grass_field_desc fd = field_desc(4);
        double ms[GRASS_TIER_KIND_COUNT];
        grass_bool available = 0;
        const struct {
            const char* call;
            grass_result result;
        } calls[] = {
            {"grass_create_patch", grass_create_patch(ctx, &pd, &new_patch)},
            {"grass_create_map", grass_create_map(ctx, &md, &new_map)},
            {"grass_update_map", grass_update_map(ctx, map, 0, 0, &md)},
            {"grass_create_field", grass_create_field(ctx, &fd, &new_field)},
            {"grass_begin_frame", grass_begin_frame(ctx, &v)},
            {"grass_gl_render", grass_gl_render(ctx)},
            {"grass_get_tier_gpu_ms", grass_get_tier_gpu_ms(ctx, ms, &available)},
            {"grass_destroy_field", grass_destroy_field(ctx, field)},
            {"grass_destroy_map", grass_destroy_map(ctx, map)},
            {"grass_destroy_patch", grass_destroy_patch(ctx, patch)},
        };
        size_t refusals = 0;
        for (size_t pos = log.find(kNotCurrent); pos != std::string::npos; pos = log.find(kNotCurrent, pos + 1)) {
            refusals += 1;
        }
        EXPECT_EQ(refusals, sizeof(calls) / sizeof(calls[0])) << log;
        for (const auto& c : calls) {
            EXPECT_EQ(c.result, GRASS_ERROR_INVALID_STATE) << c.call;
            EXPECT_NE(log.find(std::string(c.call) + ": the GL context"), std::string::npos) << c.call << "\n" << log;
        }
        EXPECT_EQ(new_patch.index + new_map.index + new_field.index, 0u) << "nothing was made";
        if (other) {
            EXPECT_EQ(get_error_(), static_cast<GLenum>(GL_NO_ERROR)) << "no GL error left in the other context";
        }
        log.clear();
        make_mine_current();
        // Back in its own context, the same field, map and patch work and draw.
        EXPECT_EQ(grass_update_map(ctx, map, 0, 0, &md), GRASS_SUCCESS) << log;
        const auto image = render(v);
        EXPECT_GT(grass_share(image, sky, 0, 0, image.width, image.height), 0.1);
    }
    EXPECT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS) << log;
    EXPECT_EQ(grass_destroy_map(ctx, map), GRASS_SUCCESS) << log;
}

// A context destroyed while its GL context is not current says so, makes no GL call, and
// frees its host memory (ASan's leak check); the GL objects go with their GL context.
TEST_P(GlCurrentTest, DestroyingAContextWithoutItsGlContextFreesItsHostMemoryOnly) {
    for (bool other : {false, true}) {
        SCOPED_TRACE(other ? "another GL context current" : "no GL context current");
        grass_context_desc d = grass_default_context_desc();
        std::string second_log;
        d.log_user_data = &second_log;
        d.log_fn = [](void* user, grass_log_level, grass_message_id id, const char* message) {
            *static_cast<std::string*>(user) += std::to_string(int(id)) + ": " + message + "\n";
        };
        grass_context* second = nullptr;
        ASSERT_EQ(host->create_context(d, &second), GRASS_SUCCESS) << second_log;
        grass_field_id f{};
        grass_patch_id p{};
        const grass_patch_desc pd = grass_default_patch_desc();
        ASSERT_EQ(grass_create_patch(second, &pd, &p), GRASS_SUCCESS) << second_log;
        ASSERT_EQ(create_blade_field(second, p, 4, &f), GRASS_SUCCESS) << second_log;
        make_current(other);
        grass_destroy_context(second);
        EXPECT_NE(second_log.find(kNotCurrent + " grass_destroy_context"), std::string::npos) << second_log;
        if (other) {
            EXPECT_EQ(get_error_(), static_cast<GLenum>(GL_NO_ERROR));
        }
        make_mine_current();
    }
    const double eye[3] = {0.5, 2.0, 0.5}, target[3] = {0.5, 0.0, 0.5001};
    make_field(field_desc(4));
    uint8_t sky[3];
    expected_sky(host->target(), sky);
    const auto image = render(view(eye, target));
    EXPECT_GT(grass_share(image, sky, 0, 0, image.width, image.height), 0.1) << "the first context still draws";
}

INSTANTIATE_TEST_SUITE_P(Backends, GlCurrentTest, ::testing::Values(GRASS_BACKEND_GL),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
