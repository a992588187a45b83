// The GL entry points the render tests that draw into a framebuffer of their own call
// (MotionVectorsTest, GBufferTest): loaded through the host's loader (grass_host::Host::
// gl_proc_address), one table for all of them.
#pragma once

#include "headless_host.hpp"

#include <grass/grass_gl.h>

#include <GL/glcorearb.h>
#include <gtest/gtest.h>

#include <string>

namespace grass_test {

#define GRASS_TEST_GL_FUNCTIONS(X)                                       \
    X(PFNGLCREATEFRAMEBUFFERSPROC, CreateFramebuffers)                   \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                   \
    X(PFNGLNAMEDFRAMEBUFFERTEXTUREPROC, NamedFramebufferTexture)         \
    X(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERSPROC, NamedFramebufferDrawBuffers) \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                         \
    X(PFNGLCLEARNAMEDFRAMEBUFFERFVPROC, ClearNamedFramebufferfv)         \
    X(PFNGLCREATETEXTURESPROC, CreateTextures)                           \
    X(PFNGLTEXTURESTORAGE2DPROC, TextureStorage2D)                       \
    X(PFNGLTEXTURESTORAGE2DMULTISAMPLEPROC, TextureStorage2DMultisample) \
    X(PFNGLNAMEDFRAMEBUFFERREADBUFFERPROC, NamedFramebufferReadBuffer)   \
    X(PFNGLBLITNAMEDFRAMEBUFFERPROC, BlitNamedFramebuffer)               \
    X(PFNGLTEXTURESUBIMAGE2DPROC, TextureSubImage2D)                     \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                           \
    X(PFNGLGETTEXTUREIMAGEPROC, GetTextureImage)                         \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                 \
    X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                             \
    X(PFNGLGETBOOLEANI_VPROC, GetBooleani_v)                             \
    X(PFNGLISENABLEDIPROC, IsEnabledi)                                   \
    X(PFNGLENABLEIPROC, Enablei)                                         \
    X(PFNGLDISABLEIPROC, Disablei)                                       \
    X(PFNGLCOLORMASKIPROC, ColorMaski)                                   \
    X(PFNGLCREATEBUFFERSPROC, CreateBuffers)                             \
    X(PFNGLNAMEDBUFFERDATAPROC, NamedBufferData)                         \
    X(PFNGLBINDBUFFERRANGEPROC, BindBufferRange)                         \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                             \
    X(PFNGLGETUNIFORMBLOCKINDEXPROC, GetUniformBlockIndex)               \
    X(PFNGLCREATEQUERIESPROC, CreateQueries)                             \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                             \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                                   \
    X(PFNGLENDQUERYPROC, EndQuery)                                       \
    X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)

struct GlTestFunctions {
#define GRASS_TEST_GL_DECLARE(type, name) type name = nullptr;
    GRASS_TEST_GL_FUNCTIONS(GRASS_TEST_GL_DECLARE)
#undef GRASS_TEST_GL_DECLARE
};

// Loads every entry point; a missing one fails the calling test, naming it.
inline void load_gl_test_functions(const grass_host::Host& host, GlTestFunctions* gl) {
#define GRASS_TEST_GL_LOAD(type, name)                                   \
    gl->name = reinterpret_cast<type>(host.gl_proc_address("gl" #name)); \
    EXPECT_NE(gl->name, nullptr) << "gl" #name;
    GRASS_TEST_GL_FUNCTIONS(GRASS_TEST_GL_LOAD)
#undef GRASS_TEST_GL_LOAD
}

// A frame of `v` drawn over the whole of the bound `size` x `size` framebuffer; `log` the
// context's messages, for a failure to show.
inline void draw_whole_view(grass_context* ctx, const grass_view_desc& v, int size, const std::string& log) {
    grass_view_desc d = v;
    d.viewport[0] = d.viewport[1] = 0;
    d.viewport[2] = d.viewport[3] = size;
    EXPECT_EQ(grass_begin_frame(ctx, &d), GRASS_SUCCESS) << log;
    EXPECT_EQ(grass_gl_render(ctx), GRASS_SUCCESS) << log;
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS) << log;
}

} // namespace grass_test
