#include "shadow_map_copy.hpp"

#include <osg/GLExtensions>

#include <cstring>
#include <sstream>

namespace grass_osg {

namespace {

// The GL names this file uses (OSG's GL header may or may not define them).
constexpr unsigned kTexture2D = 0x0DE1, kTexture2DArray = 0x8C1A, kTextureBinding2DArray = 0x8C1D,
                   kPixelUnpackBufferBinding = 0x88EF, kPixelUnpackBuffer = 0x88EC, kTextureWidth = 0x1000,
                   kTextureHeight = 0x1001, kTextureInternalFormat = 0x1003, kTextureMaxLevel = 0x813D,
                   kDepthComponent = 0x1902, kDepthStencil = 0x84F9, kUnsignedByte = 0x1401, kUnsignedShort = 0x1403,
                   kUnsignedInt = 0x1405, kFloat = 0x1406, kTextureDepthSize = 0x884A, kTextureDepthType = 0x8C16,
                   kUnsignedInt248 = 0x84FA, kFloat32UnsignedInt248Rev = 0x8DAD, kDepth24Stencil8 = 0x88F0,
                   kDepth32FStencil8 = 0x8CAD, kDepth16 = 0x81A5, kDepth24 = 0x81A6, kDepth32 = 0x81A7,
                   kDepth32F = 0x8CAC;

struct Gl {
    void (*GetTextureLevelParameteriv)(unsigned, int, unsigned, int*);
    void (*GetIntegerv)(unsigned, int*);
    void (*CreateTextures)(unsigned, int, unsigned*);
    void (*DeleteTextures)(int, const unsigned*);
    void (*TextureParameteri)(unsigned, unsigned, int);
    void (*BindTexture)(unsigned, unsigned);
    void (*BindBuffer)(unsigned, unsigned);
    void (*TexImage3D)(unsigned, int, int, int, int, int, int, unsigned, unsigned, const void*);
    void (*CopyImageSubData)(unsigned, unsigned, int, int, int, int, unsigned, unsigned, int, int, int, int, int, int,
                             int);
    unsigned (*GetError)();
};

template <typename Fn>
bool load(Fn* fn, const char* name) {
    void* address = osg::getGLExtensionFuncPtr(name);
    std::memcpy(fn, &address, sizeof(*fn));
    return address != nullptr;
}

const Gl* gl() {
    static const Gl* const loaded = [] {
        static Gl g;
        const bool ok = load(&g.GetTextureLevelParameteriv, "glGetTextureLevelParameteriv") &&
                        load(&g.GetIntegerv, "glGetIntegerv") && load(&g.CreateTextures, "glCreateTextures") &&
                        load(&g.DeleteTextures, "glDeleteTextures") &&
                        load(&g.TextureParameteri, "glTextureParameteri") && load(&g.BindTexture, "glBindTexture") &&
                        load(&g.BindBuffer, "glBindBuffer") && load(&g.TexImage3D, "glTexImage3D") &&
                        load(&g.CopyImageSubData, "glCopyImageSubData") && load(&g.GetError, "glGetError");
        return ok ? &g : nullptr;
    }();
    return loaded;
}

bool is_depth_format(int f) {
    return f == int(kDepthComponent) || f == int(kDepth16) || f == int(kDepth24) || f == int(kDepth32) ||
           f == int(kDepth32F) || f == int(kDepth24Stencil8) || f == int(kDepth32FStencil8) || f == int(kDepthStencil);
}

} // namespace

ShadowMapCopy::~ShadowMapCopy() {
    if (array_ && gl()) gl()->DeleteTextures(1, &array_);
}

uint32_t ShadowMapCopy::copy(uint32_t source, std::string* error) {
    const Gl* g = gl();
    if (!g) {
        *error = "grass_osg: the GL context lacks glCopyImageSubData or GL 4.5's direct state access: grass "
                 "cannot read the shadow map";
        return 0;
    }
    for (int k = 0; k < 16 && g->GetError() != 0; ++k) {} // earlier errors are not the copy's
    int width = 0, height = 0, format = 0;
    g->GetTextureLevelParameteriv(source, 0, kTextureWidth, &width);
    g->GetTextureLevelParameteriv(source, 0, kTextureHeight, &height);
    g->GetTextureLevelParameteriv(source, 0, kTextureInternalFormat, &format);
    if (width <= 0 || height <= 0 || !is_depth_format(format)) {
        std::ostringstream s;
        s << "grass_osg: the shadow map (GL texture " << source << ") is " << width << " x " << height
          << " of internal format 0x" << std::hex << format << ", not a depth texture: grass cannot read it";
        *error = s.str();
        return 0;
    }
    if (width != width_ || height != height_ || format != format_) {
        if (array_) g->DeleteTextures(1, &array_);
        array_ = 0;
        unsigned name = 0;
        g->CreateTextures(kTexture2DArray, 1, &name);
        // The source's own internal format (sized or not), so that the copy's formats match.
        // glTexImage3D needs a binding: the unit's array binding and the unpack buffer are
        // put back as they were.
        int bound = 0, unpack = 0;
        g->GetIntegerv(kTextureBinding2DArray, &bound);
        g->GetIntegerv(kPixelUnpackBufferBinding, &unpack);
        if (unpack) g->BindBuffer(kPixelUnpackBuffer, 0);
        g->BindTexture(kTexture2DArray, name);
        const bool stencil =
            format == int(kDepth24Stencil8) || format == int(kDepth32FStencil8) || format == int(kDepthStencil);
        // An unsized format leaves the driver to choose the depth's bits and type, from the
        // pixel type among others: the first type that gives the source's is taken.
        int source_bits = 0, source_type = 0;
        g->GetTextureLevelParameteriv(source, 0, kTextureDepthSize, &source_bits);
        g->GetTextureLevelParameteriv(source, 0, kTextureDepthType, &source_type);
        const unsigned depth_types[] = {kUnsignedInt, kUnsignedShort, kUnsignedByte, kFloat};
        const unsigned stencil_type = format == int(kDepth32FStencil8) ? kFloat32UnsignedInt248Rev : kUnsignedInt248;
        for (const unsigned type : depth_types) {
            g->TexImage3D(kTexture2DArray, 0, format, width, height, 1, 0, stencil ? kDepthStencil : kDepthComponent,
                          stencil ? stencil_type : type, nullptr);
            int bits = 0, depth_type = 0;
            g->GetTextureLevelParameteriv(name, 0, kTextureDepthSize, &bits);
            g->GetTextureLevelParameteriv(name, 0, kTextureDepthType, &depth_type);
            if (stencil || (bits == source_bits && depth_type == source_type)) break;
        }
        int bits = 0, depth_type = 0;
        g->GetTextureLevelParameteriv(name, 0, kTextureDepthSize, &bits);
        g->GetTextureLevelParameteriv(name, 0, kTextureDepthType, &depth_type);
        g->BindTexture(kTexture2DArray, unsigned(bound));
        if (unpack) g->BindBuffer(kPixelUnpackBuffer, unsigned(unpack));
        if (bits != source_bits || depth_type != source_type) {
            g->DeleteTextures(1, &name);
            std::ostringstream e;
            e << "grass_osg: the shadow map (GL texture " << source << ", internal format 0x" << std::hex << format
              << std::dec << ") has " << source_bits << "-bit depth, and the driver made grass's copy of it " << bits
              << "-bit: the copy cannot be made";
            *error = e.str();
            return 0;
        }
        g->TextureParameteri(name, kTextureMaxLevel, 0);
        array_ = name;
        width_ = width;
        height_ = height;
        format_ = format;
    }
    g->CopyImageSubData(source, kTexture2D, 0, 0, 0, 0, array_, kTexture2DArray, 0, 0, 0, 0, width, height, 1);
    if (const unsigned e = g->GetError()) {
        std::ostringstream s;
        s << "grass_osg: copying the shadow map (GL texture " << source << ", " << width << " x " << height
          << ", internal format 0x" << std::hex << format << ") into grass's depth array failed with GL error 0x" << e;
        *error = s.str();
        width_ = height_ = format_ = 0; // made again at the next draw
        return 0;
    }
    return array_;
}

} // namespace grass_osg
