// The GL host's cascaded sun shadow map (TargetDesc::host_shadows): a GL_TEXTURE_2D_ARRAY of
// GL_DEPTH_COMPONENT32F, a layer per cascade, a depth-only framebuffer per layer, a compare
// sampler and the uniform block (light_cascades.hpp) the host's receiving shaders read.
// Its calls go through the host's loader, as the mesh drawer's do.
#pragma once

#include "light_cascades.hpp"

#include <memory>
#include <string>

namespace grass_host {

class GlShadowCascades {
public:
    using ProcLoader = void* (*)(void* user_data, const char* name);

    GlShadowCascades();
    ~GlShadowCascades(); // the context that init used must be current
    GlShadowCascades(const GlShadowCascades&) = delete;
    GlShadowCascades& operator=(const GlShadowCascades&) = delete;

    // Makes the map of `shadows` (cascades layers of map_size texels); false and *error.
    bool init(ProcLoader loader, void* user_data, const HostShadows& shadows, std::string* error);

    // The map's texture name (for grass_shadow_receive_desc.shadow_map).
    uint64_t texture() const;
    // Binds cascade `layer`'s framebuffer and viewport, clears its depth to 1 and turns the
    // depth test (GL_LESS) and writes on.
    void begin_cascade(uint32_t layer);
    // glPolygonOffset(slope, constant) with GL_POLYGON_OFFSET_FILL on; off with on = false.
    void polygon_offset(bool on, float constant, float slope);
    // Binds the map and its compare sampler at unit 1 and `uniforms` at uniform binding 3
    // (shaders/cascade_shadows.glsl) for the ground's and meshes' receiving programs.
    void bind_for_receiving(const HostShadowUniforms& uniforms);
    // Unbinds what bind_for_receiving bound.
    void unbind();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// `source` (a shader beginning with its #version line) with `#define <name> 1` after that line.
std::string with_define(const char* source, const char* name);

} // namespace grass_host
