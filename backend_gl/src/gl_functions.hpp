// The GL entry points the backend calls, loaded per context from the host's loader. No
// GL library is linked and nothing is global: each context holds its own table.
#pragma once

#include <grass/grass_gl.h>

#include <GL/glcorearb.h>

// X(PFN type, name without the gl prefix)
#define GRASS_GL_FUNCTIONS(X)                                                        \
    /* queries and global state */                                                   \
    X(PFNGLGETERRORPROC, GetError)                                                   \
    X(PFNGLGETSTRINGPROC, GetString)                                                 \
    X(PFNGLGETSTRINGIPROC, GetStringi)                                               \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                             \
    X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                                         \
    X(PFNGLGETINTEGER64I_VPROC, GetInteger64i_v)                                     \
    X(PFNGLGETBOOLEANVPROC, GetBooleanv)                                             \
    X(PFNGLGETBOOLEANI_VPROC, GetBooleani_v)                                         \
    X(PFNGLCOLORMASKIPROC, ColorMaski)                                               \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                             \
    X(PFNGLISENABLEDPROC, IsEnabled)                                                 \
    X(PFNGLENABLEPROC, Enable)                                                       \
    X(PFNGLDISABLEPROC, Disable)                                                     \
    X(PFNGLISENABLEDIPROC, IsEnabledi)                                               \
    X(PFNGLENABLEIPROC, Enablei)                                                     \
    X(PFNGLDISABLEIPROC, Disablei)                                                   \
    X(PFNGLGETFLOATI_VPROC, GetFloati_v)                                             \
    X(PFNGLVIEWPORTINDEXEDFPROC, ViewportIndexedf)                                   \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                 \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                                 \
    X(PFNGLPOLYGONMODEPROC, PolygonMode)                                             \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                                         \
    X(PFNGLGETFLOATVPROC, GetFloatv)                                                 \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                             \
    /* shaders and programs */                                                       \
    X(PFNGLCREATESHADERPROC, CreateShader)                                           \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                           \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                         \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                             \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                   \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                           \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                         \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                           \
    X(PFNGLDETACHSHADERPROC, DetachShader)                                           \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                             \
    X(PFNGLPROGRAMBINARYPROC, ProgramBinary)                                         \
    X(PFNGLGETPROGRAMBINARYPROC, GetProgramBinary)                                   \
    X(PFNGLPROGRAMPARAMETERIPROC, ProgramParameteri)                                 \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                           \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                 \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                               \
    X(PFNGLPROGRAMUNIFORM1IPROC, ProgramUniform1i)                                   \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                         \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                               \
    /* buffers */                                                                    \
    X(PFNGLCREATEBUFFERSPROC, CreateBuffers)                                         \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                         \
    X(PFNGLNAMEDBUFFERSTORAGEPROC, NamedBufferStorage)                               \
    X(PFNGLNAMEDBUFFERDATAPROC, NamedBufferData)                                     \
    X(PFNGLNAMEDBUFFERSUBDATAPROC, NamedBufferSubData)                               \
    X(PFNGLCOPYNAMEDBUFFERSUBDATAPROC, CopyNamedBufferSubData)                       \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                               \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                       \
    X(PFNGLBINDBUFFERRANGEPROC, BindBufferRange)                                     \
    /* vertex arrays */                                                              \
    X(PFNGLCREATEVERTEXARRAYSPROC, CreateVertexArrays)                               \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                               \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                     \
    X(PFNGLVERTEXARRAYVERTEXBUFFERPROC, VertexArrayVertexBuffer)                     \
    X(PFNGLVERTEXARRAYELEMENTBUFFERPROC, VertexArrayElementBuffer)                   \
    X(PFNGLVERTEXARRAYATTRIBFORMATPROC, VertexArrayAttribFormat)                     \
    X(PFNGLVERTEXARRAYATTRIBIFORMATPROC, VertexArrayAttribIFormat)                   \
    X(PFNGLVERTEXARRAYATTRIBBINDINGPROC, VertexArrayAttribBinding)                   \
    X(PFNGLENABLEVERTEXARRAYATTRIBPROC, EnableVertexArrayAttrib)                     \
    X(PFNGLVERTEXARRAYBINDINGDIVISORPROC, VertexArrayBindingDivisor)                 \
    /* textures and samplers */                                                      \
    X(PFNGLCREATETEXTURESPROC, CreateTextures)                                       \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                       \
    X(PFNGLTEXTURESTORAGE2DPROC, TextureStorage2D)                                   \
    X(PFNGLTEXTURESUBIMAGE2DPROC, TextureSubImage2D)                                 \
    X(PFNGLTEXTURESTORAGE3DPROC, TextureStorage3D)                                   \
    X(PFNGLTEXTURESUBIMAGE3DPROC, TextureSubImage3D)                                 \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                         \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                             \
    X(PFNGLCREATESAMPLERSPROC, CreateSamplers)                                       \
    X(PFNGLDELETESAMPLERSPROC, DeleteSamplers)                                       \
    X(PFNGLSAMPLERPARAMETERIPROC, SamplerParameteri)                                 \
    X(PFNGLBINDSAMPLERPROC, BindSampler)                                             \
    /* drawing */                                                                    \
    X(PFNGLDRAWARRAYSINSTANCEDBASEINSTANCEPROC, DrawArraysInstancedBaseInstance)     \
    X(PFNGLDRAWELEMENTSINSTANCEDBASEINSTANCEPROC, DrawElementsInstancedBaseInstance) \
    X(PFNGLMULTIDRAWELEMENTSINDIRECTPROC, MultiDrawElementsIndirect)                 \
    /* responsive grass: the interaction pass (gl_dynamics.cpp) */                   \
    X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                                     \
    X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                                         \
    X(PFNGLBINDIMAGETEXTUREPROC, BindImageTexture)                                   \
    X(PFNGLCLEARTEXIMAGEPROC, ClearTexImage)                                         \
    X(PFNGLTEXTUREPARAMETERIPROC, TextureParameteri)                                 \
    /* timer queries (grass_get_tier_gpu_ms) */                                      \
    X(PFNGLGETQUERYIVPROC, GetQueryiv)                                               \
    X(PFNGLCREATEQUERIESPROC, CreateQueries)                                         \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                                         \
    X(PFNGLQUERYCOUNTERPROC, QueryCounter)                                           \
    X(PFNGLGETQUERYOBJECTIVPROC, GetQueryObjectiv)                                   \
    X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)                             \
    /* the current-context check (gl_current.cpp) */                                 \
    X(PFNGLISVERTEXARRAYPROC, IsVertexArray)                                         \
    X(PFNGLOBJECTLABELPROC, ObjectLabel)                                             \
    X(PFNGLGETOBJECTLABELPROC, GetObjectLabel)                                       \
    /* debug labels (grass_debug_labels): KHR_debug, GL 4.3 core */                  \
    X(PFNGLPUSHDEBUGGROUPPROC, PushDebugGroup)                                       \
    X(PFNGLPOPDEBUGGROUPPROC, PopDebugGroup)

namespace grass {

struct GlFunctions {
#define GRASS_GL_DECLARE(type, name) type name = nullptr;
    GRASS_GL_FUNCTIONS(GRASS_GL_DECLARE)
#undef GRASS_GL_DECLARE

    // Loads every entry point. Returns nullptr on success, or the GL name ("glFoo") of
    // the first one the loader did not give.
    const char* load(grass_gl_get_proc_address_fn loader, void* user_data);
};

} // namespace grass
