// GL errors on the draw path, in a debug context (the headless GL host asks EGL for one):
// grass checks glGetError after each grass_gl_render there. A GL error injected into grass's
// own draw call (through the loader the host hands grass) fails the call with
// GRASS_ERROR_BACKEND naming the error; an error the host left pending before the call is
// cleared with a warning and not blamed on grass; without errors the frame succeeds.
#include "render_fixture.hpp"

#include <GL/glcorearb.h>

#include <cstring>

namespace grass_test {
namespace {

PFNGLDRAWELEMENTSINSTANCEDBASEINSTANCEPROC real_draw = nullptr;
PFNGLENABLEPROC real_enable = nullptr;
bool inject = false;

void APIENTRY failing_draw(GLenum mode, GLsizei count, GLenum type, const void* indices, GLsizei instances,
                           GLuint base_instance) {
    real_draw(mode, count, type, indices, instances, base_instance);
    if (inject) real_enable(0x1234); // GL_INVALID_ENUM, as a driver error inside the draw would be
}

void (*filter(const char* name, void (*real)(void)))(void) {
    if (std::strcmp(name, "glEnable") == 0) real_enable = reinterpret_cast<PFNGLENABLEPROC>(real);
    if (std::strcmp(name, "glDrawElementsInstancedBaseInstance") == 0) {
        real_draw = reinterpret_cast<PFNGLDRAWELEMENTSINSTANCEDBASEINSTANCEPROC>(real);
        return reinterpret_cast<void (*)(void)>(&failing_draw);
    }
    return real;
}

TEST(GlDebugErrors, AnErrorInGrasssDrawFailsTheCallAndTheHostsOwnIsNotBlamedOnGrass) {
    grass_host::TargetDesc t;
    t.width = t.height = 64;
    t.gl_proc_filter = &filter;
    std::string error;
    auto host = grass_host::Host::create(GRASS_BACKEND_GL, t, &error);
    ASSERT_TRUE(host) << error;
    GLint flags = 0;
    reinterpret_cast<PFNGLGETINTEGERVPROC>(host->gl_proc_address("glGetIntegerv"))(GL_CONTEXT_FLAGS, &flags);
    if (!(flags & GL_CONTEXT_FLAG_DEBUG_BIT)) GTEST_SKIP() << "the host has no debug context (OSMesa)";
    std::string log;
    grass_context_desc cd = grass_default_context_desc();
    cd.log_user_data = &log;
    cd.log_fn = [](void* user, grass_log_level, grass_message_id, const char* m) {
        *static_cast<std::string*>(user) += std::string(m) + "\n";
    };
    grass_context* ctx = nullptr;
    ASSERT_EQ(host->create_context(cd, &ctx), GRASS_SUCCESS) << log;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 64;
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS) << log;
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 8;
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS) << log;
    const double eye[3] = {1.0, 1.0, -0.5}, look[3] = {1.0, 0.0, 1.0};
    const grass_view_desc v = grass_host::make_view(*host, eye, look, 50.0f);
    grass_host::Image image;
    ASSERT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error << log;
    ASSERT_NE(real_draw, nullptr) << "grass drew through the filtered loader";
    expect_grass(image, t, 0.2, "a frame without errors");

    inject = true;
    EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_ERROR_BACKEND) << log;
    inject = false;
    EXPECT_NE(log.find("GL_INVALID_ENUM"), std::string::npos) << log;
    EXPECT_NE(std::string(grass_get_last_error(ctx)).find("grass_gl_render"), std::string::npos);

    log.clear();
    host->before_grass = [&] { real_enable(0x1234); }; // the host's own mistake
    EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << log;
    EXPECT_NE(log.find("pending before the call"), std::string::npos) << log;
    host->before_grass = nullptr;
    EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << log;
    grass_destroy_context(ctx);
}

} // namespace
} // namespace grass_test
