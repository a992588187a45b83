#include "shadow_cascades_gl.hpp"

#include <GL/glcorearb.h>

#include <cstring>
#include <vector>

namespace grass_host {

#define GRASS_HOST_SHADOW_GL_FUNCTIONS(X)                                  \
    X(PFNGLCREATETEXTURESPROC, CreateTextures)                             \
    X(PFNGLTEXTURESTORAGE3DPROC, TextureStorage3D)                         \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                             \
    X(PFNGLBINDTEXTUREUNITPROC, BindTextureUnit)                           \
    X(PFNGLCREATESAMPLERSPROC, CreateSamplers)                             \
    X(PFNGLSAMPLERPARAMETERIPROC, SamplerParameteri)                       \
    X(PFNGLBINDSAMPLERPROC, BindSampler)                                   \
    X(PFNGLDELETESAMPLERSPROC, DeleteSamplers)                             \
    X(PFNGLCREATEFRAMEBUFFERSPROC, CreateFramebuffers)                     \
    X(PFNGLNAMEDFRAMEBUFFERTEXTURELAYERPROC, NamedFramebufferTextureLayer) \
    X(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERPROC, NamedFramebufferDrawBuffer)     \
    X(PFNGLNAMEDFRAMEBUFFERREADBUFFERPROC, NamedFramebufferReadBuffer)     \
    X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, CheckNamedFramebufferStatus)   \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                     \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                           \
    X(PFNGLVIEWPORTPROC, Viewport)                                         \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                               \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                       \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                       \
    X(PFNGLENABLEPROC, Enable)                                             \
    X(PFNGLDISABLEPROC, Disable)                                           \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                               \
    X(PFNGLCREATEBUFFERSPROC, CreateBuffers)                               \
    X(PFNGLNAMEDBUFFERSTORAGEPROC, NamedBufferStorage)                     \
    X(PFNGLNAMEDBUFFERSUBDATAPROC, NamedBufferSubData)                     \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                             \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)

struct GlShadowCascades::Impl {
#define GRASS_HOST_DECLARE(type, name) type name = nullptr;
    GRASS_HOST_SHADOW_GL_FUNCTIONS(GRASS_HOST_DECLARE)
#undef GRASS_HOST_DECLARE
    GLuint texture = 0, sampler = 0, uniforms = 0;
    std::vector<GLuint> framebuffers;
    GLsizei size = 0;
};

GlShadowCascades::GlShadowCascades() : impl_(std::make_unique<Impl>()) {}

GlShadowCascades::~GlShadowCascades() {
    Impl& g = *impl_;
    if (!g.DeleteBuffers) return; // never loaded
    if (!g.framebuffers.empty()) g.DeleteFramebuffers(GLsizei(g.framebuffers.size()), g.framebuffers.data());
    if (g.texture) g.DeleteTextures(1, &g.texture);
    if (g.sampler) g.DeleteSamplers(1, &g.sampler);
    if (g.uniforms) g.DeleteBuffers(1, &g.uniforms);
}

bool GlShadowCascades::init(ProcLoader loader, void* user_data, const HostShadows& shadows, std::string* error) {
    Impl& g = *impl_;
#define GRASS_HOST_LOAD(type, name)                                                          \
    g.name = reinterpret_cast<type>(loader(user_data, "gl" #name));                          \
    if (!g.name) {                                                                           \
        if (error) *error = "the GL loader has no gl" #name " (the host's shadow cascades)"; \
        return false;                                                                        \
    }
    GRASS_HOST_SHADOW_GL_FUNCTIONS(GRASS_HOST_LOAD)
#undef GRASS_HOST_LOAD
    g.size = GLsizei(shadows.map_size);
    const GLsizei layers = GLsizei(shadows.cascades);
    g.CreateTextures(GL_TEXTURE_2D_ARRAY, 1, &g.texture);
    g.TextureStorage3D(g.texture, 1, GL_DEPTH_COMPONENT32F, g.size, g.size, layers);
    g.framebuffers.assign(size_t(layers), 0);
    g.CreateFramebuffers(layers, g.framebuffers.data());
    for (GLsizei layer = 0; layer < layers; ++layer) {
        const GLuint fbo = g.framebuffers[size_t(layer)];
        g.NamedFramebufferTextureLayer(fbo, GL_DEPTH_ATTACHMENT, g.texture, 0, layer);
        g.NamedFramebufferDrawBuffer(fbo, GL_NONE);
        g.NamedFramebufferReadBuffer(fbo, GL_NONE);
        const GLenum status = g.CheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            if (error) *error = "the shadow cascade framebuffer of layer " + std::to_string(layer) + " is incomplete";
            return false;
        }
    }
    g.CreateSamplers(1, &g.sampler);
    g.SamplerParameteri(g.sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    g.SamplerParameteri(g.sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    g.SamplerParameteri(g.sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    g.SamplerParameteri(g.sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    g.SamplerParameteri(g.sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    g.SamplerParameteri(g.sampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    g.CreateBuffers(1, &g.uniforms);
    g.NamedBufferStorage(g.uniforms, sizeof(HostShadowUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    return true;
}

uint64_t GlShadowCascades::texture() const { return impl_->texture; }

void GlShadowCascades::begin_cascade(uint32_t layer) {
    Impl& g = *impl_;
    g.BindFramebuffer(GL_FRAMEBUFFER, g.framebuffers[layer]);
    g.Viewport(0, 0, g.size, g.size);
    g.DepthMask(GL_TRUE);
    const float far_depth = 1.0f;
    g.ClearBufferfv(GL_DEPTH, 0, &far_depth);
    g.Enable(GL_DEPTH_TEST);
    g.DepthFunc(GL_LESS);
}

void GlShadowCascades::polygon_offset(bool on, float constant, float slope) {
    Impl& g = *impl_;
    if (on) {
        g.Enable(GL_POLYGON_OFFSET_FILL);
        g.PolygonOffset(slope, constant);
    } else {
        g.PolygonOffset(0.0f, 0.0f);
        g.Disable(GL_POLYGON_OFFSET_FILL);
    }
}

void GlShadowCascades::bind_for_receiving(const HostShadowUniforms& uniforms) {
    Impl& g = *impl_;
    g.NamedBufferSubData(g.uniforms, 0, sizeof uniforms, &uniforms);
    g.BindBufferBase(GL_UNIFORM_BUFFER, 3, g.uniforms);
    g.BindTextureUnit(1, g.texture);
    g.BindSampler(1, g.sampler);
}

void GlShadowCascades::unbind() {
    Impl& g = *impl_;
    g.BindBufferBase(GL_UNIFORM_BUFFER, 3, 0);
    g.BindTextureUnit(1, 0);
    g.BindSampler(1, 0);
}

std::string with_define(const char* source, const char* name) {
    std::string s = source;
    const size_t line_end = s.find('\n');
    const std::string define = std::string("#define ") + name + " 1\n";
    if (line_end == std::string::npos) return s + "\n" + define;
    s.insert(line_end + 1, define);
    return s;
}

} // namespace grass_host
