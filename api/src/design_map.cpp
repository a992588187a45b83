#include "design_map.hpp"

#include "validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace grass {

grass_result convert_map(grass_context* ctx, const char* fn, const char* name, const grass_map_desc* desc,
                         Vector<uint16_t>* out) {
    GRASS_TRY(check_desc_header(ctx, fn, name, desc, desc ? raw_enum(desc->type) : int64_t{GRASS_STRUCT_TYPE_MAP_DESC},
                                desc ? desc->next : nullptr, GRASS_STRUCT_TYPE_MAP_DESC, "GRASS_STRUCT_TYPE_MAP_DESC"));
    const grass_map_desc& d = *desc;
    uint32_t texel_bytes = 0;
    const int64_t format = raw_enum(d.format);
    switch (format) {
    case GRASS_MAP_FORMAT_R8_UNORM: texel_bytes = 1; break;
    case GRASS_MAP_FORMAT_R16_UNORM: texel_bytes = 2; break;
    case GRASS_MAP_FORMAT_R32_FLOAT: texel_bytes = 4; break;
    default:
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
                         "%s: %s->format is %lld; it must be a grass_map_format", fn, name, static_cast<long long>(format));
    }
    if (d.width < 1 || d.width > 16384 || d.height < 1 || d.height > 16384) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
                         "%s: %s is %u x %u texels; each side must be 1..16384", fn, name, d.width, d.height);
    }
    const uint64_t row_bytes = static_cast<uint64_t>(d.width) * texel_bytes;
    const uint64_t pitch = d.row_pitch ? d.row_pitch : row_bytes;
    if (pitch < row_bytes || pitch % texel_bytes != 0) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
                         "%s: %s->row_pitch is %u bytes; it must be at least width x texel size (%llu) and a multiple of %u",
                         fn, name, d.row_pitch, static_cast<unsigned long long>(row_bytes), texel_bytes);
    }
    if (!d.pixels) return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: %s->pixels is NULL", fn, name);

    Vector<uint16_t> texels{StlAllocator<uint16_t>(&ctx->host)};
    texels.resize(static_cast<size_t>(d.width) * d.height);
    const auto* base = static_cast<const unsigned char*>(d.pixels);
    for (uint32_t y = 0; y < d.height; ++y) {
        const unsigned char* row = base + pitch * y;
        uint16_t* dst = &texels[static_cast<size_t>(y) * d.width];
        for (uint32_t x = 0; x < d.width; ++x) {
            if (d.format == GRASS_MAP_FORMAT_R8_UNORM) {
                dst[x] = static_cast<uint16_t>(row[x] * 257u);
            } else if (d.format == GRASS_MAP_FORMAT_R16_UNORM) {
                std::memcpy(&dst[x], row + 2 * x, 2);
            } else {
                float v;
                std::memcpy(&v, row + 4 * x, 4);
                if (!(v >= 0.0f && v <= 1.0f)) { // also catches NaN
                    return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
                                     "%s: %s texel (%u, %u) is %g; float maps must hold finite values in [0, 1]", fn,
                                     name, x, y, static_cast<double>(v));
                }
                dst[x] = static_cast<uint16_t>(std::lround(static_cast<double>(v) * 65535.0));
            }
        }
    }
    *out = std::move(texels);
    return GRASS_SUCCESS;
}

float sample_map(const uint16_t* texels, uint32_t width, uint32_t height, double u, double v) {
    const double x = u * width - 0.5, z = v * height - 0.5;
    const double x0f = std::floor(x), z0f = std::floor(z);
    const double fx = x - x0f, fz = z - z0f;
    auto at = [&](double xi, double zi) {
        const auto cx = static_cast<uint32_t>(std::min<double>(std::max(xi, 0.0), width - 1.0));
        const auto cz = static_cast<uint32_t>(std::min<double>(std::max(zi, 0.0), height - 1.0));
        return texels[static_cast<size_t>(cz) * width + cx] / 65535.0;
    };
    const double a = at(x0f, z0f) + fx * (at(x0f + 1, z0f) - at(x0f, z0f));
    const double b = at(x0f, z0f + 1) + fx * (at(x0f + 1, z0f + 1) - at(x0f, z0f + 1));
    return static_cast<float>(a + fz * (b - a));
}

} // namespace grass
