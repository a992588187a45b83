// C entry points for design maps: images a field's map stack references (lemme2012 6.4).
#include "entry/api_map.hpp"
#include "context/context.hpp"
#include "context/id_checks.hpp"
#include "foundation/validate.hpp"
#include "maps/design_map.hpp"

#include <algorithm>
#include <cstring>

namespace grass {

namespace {

MapTexels texels_of(const DesignMap& m) {
    MapTexels t;
    t.texels = m.texels.data();
    t.width = m.width;
    t.height = m.height;
    t.channels = m.channels;
    return t;
}

} // namespace

grass_result make_map(grass_context* ctx, const char* fn, const char* name, const grass_map_desc* desc,
                      bool field_private, uint32_t* out_slot) {
    constexpr uint32_t kMaxSide = 16384;
    Vector<uint16_t> texels{StlAllocator<uint16_t>(&ctx->host)};
    GRASS_TRY(convert_map(ctx, fn, name, desc, kMaxSide, kMaxSide, &texels));
    DesignMap* map = ctx->host.create<DesignMap>(&ctx->host);
    map->texels = std::move(texels);
    map->width = desc->width;
    map->height = desc->height;
    map->channels = map_format_channels(raw_enum(desc->format));
    map->format = desc->format;
    map->field_private = field_private;
    if (map->channels == 1) {
        try {
            map->pyramid.build(map->texels.data(), map->width, map->height);
        } catch (...) {
            ctx->host.destroy(map);
            throw;
        }
    }
    const uint32_t slot = ctx->maps.insert(map);
    const grass_result r = ctx->backend->upload_map(slot, texels_of(*map));
    if (r != GRASS_SUCCESS) {
        ctx->backend->release_map(slot);
        ctx->maps.erase(slot);
        return r;
    }
    *out_slot = slot;
    return GRASS_SUCCESS;
}

void release_map(grass_context* ctx, uint32_t slot) {
    ctx->backend->release_map(slot);
    ctx->maps.erase(slot);
}

namespace {

grass_result update_map(grass_context* ctx, grass_map_id id, uint32_t x, uint32_t y, const grass_map_desc* region) {
    const char* fn = "grass_update_map";
    GRASS_TRY(check_map_id(ctx, fn, "map", id));
    if (ctx->in_frame) {
        return ctx->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_FRAME_ALREADY_BEGUN,
                         "%s: cannot update a map between grass_begin_frame and grass_end_frame", fn);
    }
    const uint32_t slot = id.index - 1;
    DesignMap& map = *ctx->maps.get(slot);
    if (x >= map.width || y >= map.height) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_REGION,
                         "%s: the region starts at texel (%u, %u), outside the %u x %u map", fn, x, y, map.width,
                         map.height);
    }
    GRASS_TRY(check_not_null(ctx, fn, "region", region));
    if (raw_enum(region->format) != raw_enum(map.format)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_MAP_REGION,
                         "%s: region->format is %lld; it must be the map's format (%lld)", fn,
                         static_cast<long long>(raw_enum(region->format)),
                         static_cast<long long>(raw_enum(map.format)));
    }
    Vector<uint16_t> texels{StlAllocator<uint16_t>(&ctx->host)};
    GRASS_TRY(convert_map(ctx, fn, "region", region, map.width - x, map.height - y, &texels));
    const uint32_t c = map.channels, w = region->width, h = region->height;
    Vector<uint16_t> before{StlAllocator<uint16_t>(&ctx->host)}; // the old region, restored on a backend failure
    before.resize(texels.size());
    auto swap_rows = [&](Vector<uint16_t>* into, const Vector<uint16_t>& from) {
        for (uint32_t row = 0; row < h; ++row) {
            uint16_t* m = &map.texels[(static_cast<size_t>(y + row) * map.width + x) * c];
            const size_t o = static_cast<size_t>(row) * w * c;
            if (into) std::memcpy(&(*into)[o], m, sizeof(uint16_t) * w * c);
            std::memcpy(m, &from[o], sizeof(uint16_t) * w * c);
        }
    };
    swap_rows(&before, texels);
    MapRegion r;
    r.x = x;
    r.y = y;
    r.width = w;
    r.height = h;
    const grass_result result = ctx->backend->update_map(slot, texels_of(map), r);
    if (result != GRASS_SUCCESS) {
        swap_rows(nullptr, before);
        return result;
    }
    if (c == 1) map.pyramid.update(map.texels.data(), x, y, w, h);
    return GRASS_SUCCESS;
}

} // namespace
} // namespace grass

using grass::guarded;

extern "C" {

GRASS_API grass_map_desc grass_default_map_desc(void) {
    grass_map_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_MAP_DESC;
    d.format = GRASS_MAP_FORMAT_R8_UNORM;
    return d;
}

GRASS_API grass_result grass_create_map(grass_context* context, const grass_map_desc* desc, grass_map_id* out_map) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_create_map", [&] {
        const char* fn = "grass_create_map";
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(grass::check_not_null(context, fn, "out_map", out_map));
        uint32_t slot = 0;
        GRASS_TRY(grass::make_map(context, fn, "desc", desc, false, &slot));
        out_map->index = slot + 1;
        out_map->generation = context->maps.generation(slot);
        out_map->owner = context->owner;
        return GRASS_SUCCESS;
    });
}

GRASS_API grass_result grass_update_map(grass_context* context, grass_map_id map, uint32_t x, uint32_t y,
                                        const grass_map_desc* region) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_update_map", [&] {
        GRASS_TRY(grass::check_gpu_current(context, "grass_update_map"));
        return grass::update_map(context, map, x, y, region);
    });
}

GRASS_API grass_result grass_destroy_map(grass_context* context, grass_map_id map) {
    if (!context) return GRASS_ERROR_INVALID_ARGUMENT;
    return guarded(context, "grass_destroy_map", [&] {
        const char* fn = "grass_destroy_map";
        GRASS_TRY(grass::check_gpu_current(context, fn));
        GRASS_TRY(grass::check_map_id(context, fn, "map", map));
        const uint32_t slot = map.index - 1;
        const uint32_t users = context->maps.get(slot)->field_users;
        if (users > 0) {
            return context->fail(GRASS_ERROR_IN_USE, GRASS_MSG_MAP_IN_USE,
                                 "%s: map (index %u) is still used by %u field(s); destroy them first", fn, map.index,
                                 users);
        }
        grass::release_map(context, slot);
        return GRASS_SUCCESS;
    });
}

} // extern "C"
