// The adapter's GL_TEXTURE_2D_ARRAY copy of a host's GL_TEXTURE_2D depth map: grass reads a
// shadow map as a depth array (grass_shadow_receive_desc.shadow_map), OSG's shadow
// techniques draw GL_TEXTURE_2D maps. One per grass context, in its GL context. Private to
// the adapter.
#pragma once

#include <cstdint>
#include <string>

namespace grass_osg {

class ShadowMapCopy {
public:
    ShadowMapCopy() = default;
    // The GL context must be current.
    ~ShadowMapCopy();
    ShadowMapCopy(const ShadowMapCopy&) = delete;
    ShadowMapCopy& operator=(const ShadowMapCopy&) = delete;

    // Copies level 0 of the 2D depth texture `source` into layer 0 of the array (made, or
    // made again, with the source's size and internal format), glCopyImageSubData: no GL
    // state changes but the array's own. The array's name, or 0 and *error.
    uint32_t copy(uint32_t source, std::string* error);

private:
    uint32_t array_ = 0;
    int width_ = 0, height_ = 0, format_ = 0;
};

} // namespace grass_osg
