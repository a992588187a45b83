// The one table of GL 4.5 entry points that the hosts call: the headless GL host
// (test_hosts/host_gl.cpp), the GL mesh drawer, the viewer's GL window, the OSG adapter's
// test host and the tests that dispatch a compute program of their own. Like grass, a host links no GL library for these: the table is loaded through
// the context's own loader (eglGetProcAddress, glfwGetProcAddress, OSMesaGetProcAddress).
// The library's own table (backend_gl/src/gl_functions.hpp) stays inside libgrass: hosts
// must not link library internals.
#pragma once

#include <GL/glcorearb.h>

#include <string>

namespace grass_bootstrap {

#define GRASS_BOOTSTRAP_GL_FUNCTIONS(X)                                                  \
    X(PFNGLGETERRORPROC, GetError)                                                       \
    X(PFNGLGETSTRINGPROC, GetString)                                                     \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                 \
    X(PFNGLISENABLEDPROC, IsEnabled)                                                     \
    X(PFNGLENABLEPROC, Enable)                                                           \
    X(PFNGLDISABLEPROC, Disable)                                                         \
    X(PFNGLVIEWPORTPROC, Viewport)                                                       \
    X(PFNGLSCISSORPROC, Scissor)                                                         \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                                     \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                     \
    X(PFNGLCOLORMASKPROC, ColorMask)                                                     \
    X(PFNGLCLIPCONTROLPROC, ClipControl)                                                 \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                 \
    X(PFNGLCREATERENDERBUFFERSPROC, CreateRenderbuffers)                                 \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                                 \
    X(PFNGLNAMEDRENDERBUFFERSTORAGEMULTISAMPLEPROC, NamedRenderbufferStorageMultisample) \
    X(PFNGLCREATEFRAMEBUFFERSPROC, CreateFramebuffers)                                   \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                   \
    X(PFNGLNAMEDFRAMEBUFFERRENDERBUFFERPROC, NamedFramebufferRenderbuffer)               \
    X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, CheckNamedFramebufferStatus)                 \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                         \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                             \
    X(PFNGLBLITNAMEDFRAMEBUFFERPROC, BlitNamedFramebuffer)                               \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                                   \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                                   \
    X(PFNGLDEBUGMESSAGECALLBACKPROC, DebugMessageCallback)                               \
    X(PFNGLDEBUGMESSAGECONTROLPROC, DebugMessageControl)                                 \
    X(PFNGLCREATESHADERPROC, CreateShader)                                               \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                               \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                             \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                 \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                       \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                               \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                             \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                               \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                 \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                               \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                     \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                             \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                   \
    X(PFNGLCREATEBUFFERSPROC, CreateBuffers)                                             \
    X(PFNGLNAMEDBUFFERDATAPROC, NamedBufferData)                                         \
    X(PFNGLNAMEDBUFFERSTORAGEPROC, NamedBufferStorage)                                   \
    X(PFNGLNAMEDBUFFERSUBDATAPROC, NamedBufferSubData)                                   \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                             \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                           \
    X(PFNGLCREATEVERTEXARRAYSPROC, CreateVertexArrays)                                   \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                   \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                         \
    X(PFNGLVERTEXARRAYVERTEXBUFFERPROC, VertexArrayVertexBuffer)                         \
    X(PFNGLVERTEXARRAYELEMENTBUFFERPROC, VertexArrayElementBuffer)                       \
    X(PFNGLENABLEVERTEXARRAYATTRIBPROC, EnableVertexArrayAttrib)                         \
    X(PFNGLVERTEXARRAYATTRIBFORMATPROC, VertexArrayAttribFormat)                         \
    X(PFNGLVERTEXARRAYATTRIBBINDINGPROC, VertexArrayAttribBinding)                       \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                   \
    X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex)                           \
    X(PFNGLGETNAMEDBUFFERSUBDATAPROC, GetNamedBufferSubData)                             \
    X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                                         \
    X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                                             \
    X(PFNGLFINISHPROC, Finish)

// A GL entry point by name, as a data pointer (the host's loader behind it).
using GlProcLoader = void* (*)(void* user_data, const char* name);

struct GlFunctions {
#define GRASS_BOOTSTRAP_GL_DECLARE(type, name) type name = nullptr;
    GRASS_BOOTSTRAP_GL_FUNCTIONS(GRASS_BOOTSTRAP_GL_DECLARE)
#undef GRASS_BOOTSTRAP_GL_DECLARE

    // Loads every entry point with the context current; false and *error ("the GL loader
    // has no glX") at the first one missing.
    bool load(GlProcLoader loader, void* user_data, std::string* error);
    bool loaded() const { return GetError != nullptr; }
};

// False and *error ("the GL context is 3.3; 4.5 is required") below GL 4.5.
bool require_gl45(const GlFunctions& gl, std::string* error);
// GL_RENDERER, or "unknown GL renderer".
std::string gl_renderer(const GlFunctions& gl);

// Compiles a vertex and a fragment shader and links them; 0 and *error ("<label> shader: ..."
// or "<label> program: ...") when GL refuses.
GLuint compile_program(const GlFunctions& gl, const char* vertex, const char* fragment, const char* label,
                       std::string* error);
// Likewise, one compute shader (tests that run grass's shader functions on buffers).
GLuint compile_compute_program(const GlFunctions& gl, const char* compute, const char* label, std::string* error);

} // namespace grass_bootstrap
