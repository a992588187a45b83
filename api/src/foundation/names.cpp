#include "foundation/names.hpp"

namespace grass {

const char* tier_kind_name(grass_tier_kind kind) {
    switch (kind) {
    case GRASS_TIER_GEOMETRY:
        return "geometry";
    case GRASS_TIER_VOLUME:
        return "volume";
    case GRASS_TIER_IMAGE:
        return "image";
    default:
        return "unknown";
    }
}

const char* backend_creator(grass_backend backend) {
    switch (backend) {
    case GRASS_BACKEND_NONE:
        return "grass_create_context";
    case GRASS_BACKEND_GL:
        return "grass_gl_create_context";
    case GRASS_BACKEND_VULKAN:
        return "grass_vk_create_context";
    }
    return "an unknown backend";
}

} // namespace grass
