#include "maps/design_map.hpp"

#include "foundation/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace grass {

namespace {

uint32_t component_bytes(int64_t format) {
    switch (format) {
    case GRASS_MAP_FORMAT_R8_UNORM:
    case GRASS_MAP_FORMAT_RGBA8_UNORM:
        return 1;
    case GRASS_MAP_FORMAT_R16_UNORM:
    case GRASS_MAP_FORMAT_RGBA16_UNORM:
        return 2;
    case GRASS_MAP_FORMAT_R32_FLOAT:
    case GRASS_MAP_FORMAT_RGBA32_FLOAT:
        return 4;
    default:
        return 0;
    }
}

// sRGB-encoded 0..1 to linear 0..1 (the colour map's rgb; its alpha stays linear).
double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

} // namespace

uint32_t map_format_channels(int64_t format) {
    switch (format) {
    case GRASS_MAP_FORMAT_R8_UNORM:
    case GRASS_MAP_FORMAT_R16_UNORM:
    case GRASS_MAP_FORMAT_R32_FLOAT:
        return 1;
    case GRASS_MAP_FORMAT_RGBA8_UNORM:
    case GRASS_MAP_FORMAT_RGBA16_UNORM:
    case GRASS_MAP_FORMAT_RGBA32_FLOAT:
        return 4;
    default:
        return 0;
    }
}

grass_result convert_map(Log* log, const char* fn, const char* name, const grass_map_desc* desc, uint32_t max_width,
                         uint32_t max_height, Vector<uint16_t>* out) {
    GRASS_TRY(check_desc_header(log, fn, name, desc, desc ? raw_enum(desc->type) : int64_t{GRASS_STRUCT_TYPE_MAP_DESC},
                                desc ? desc->next : nullptr, GRASS_STRUCT_TYPE_MAP_DESC, "GRASS_STRUCT_TYPE_MAP_DESC"));
    const grass_map_desc& d = *desc;
    const int64_t format = raw_enum(d.format);
    const uint32_t channels = map_format_channels(format);
    const uint32_t bytes = component_bytes(format);
    if (channels == 0) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
                         "%s: %s->format is %lld; it must be a grass_map_format", fn, name,
                         static_cast<long long>(format));
    }
    if (d.width < 1 || d.width > max_width || d.height < 1 || d.height > max_height) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
                         "%s: %s is %u x %u texels; it must be 1..%u wide and 1..%u high", fn, name, d.width, d.height,
                         max_width, max_height);
    }
    const uint32_t texel_bytes = channels * bytes;
    const uint64_t row_bytes = static_cast<uint64_t>(d.width) * texel_bytes;
    const uint64_t pitch = d.row_pitch ? d.row_pitch : row_bytes;
    if (pitch < row_bytes || pitch % bytes != 0) {
        return log->fail(
            GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
            "%s: %s->row_pitch is %u bytes; it must be at least width x texel size (%llu) and a multiple of %u", fn,
            name, d.row_pitch, static_cast<unsigned long long>(row_bytes), bytes);
    }
    if (!d.pixels)
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: %s->pixels is NULL", fn, name);

    Vector<uint16_t> texels{out->get_allocator()}; // the context's host memory, as *out
    texels.resize(static_cast<size_t>(d.width) * d.height * channels);
    const auto* base = static_cast<const unsigned char*>(d.pixels);
    for (uint32_t y = 0; y < d.height; ++y) {
        const unsigned char* row = base + pitch * y;
        uint16_t* dst = &texels[static_cast<size_t>(y) * d.width * channels];
        for (uint32_t i = 0; i < d.width * channels; ++i) {
            double v;
            if (bytes == 1) {
                v = row[i] / 255.0;
            } else if (bytes == 2) {
                uint16_t u;
                std::memcpy(&u, row + 2 * i, 2);
                v = u / 65535.0;
            } else {
                float f;
                std::memcpy(&f, row + 4 * i, 4);
                if (!(f >= 0.0f && f <= 1.0f)) { // also catches NaN
                    return log->fail(
                        GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_MAP,
                        "%s: %s texel (%u, %u) channel %u is %g; float maps must hold finite values in [0, 1]", fn,
                        name, i / channels, y, i % channels, static_cast<double>(f));
                }
                v = f;
            }
            const bool color = channels == 4 && i % 4 != 3;
            if (color) v = srgb_to_linear(v);
            dst[i] = static_cast<uint16_t>(std::lround(v * 65535.0));
        }
    }
    *out = std::move(texels);
    return GRASS_SUCCESS;
}

float sample_map(const uint16_t* texels, uint32_t width, uint32_t height, uint32_t channels, double u, double v) {
    const double x = u * width - 0.5, z = v * height - 0.5;
    const double x0f = std::floor(x), z0f = std::floor(z);
    const double fx = x - x0f, fz = z - z0f;
    auto at = [&](double xi, double zi) {
        const auto cx = static_cast<uint32_t>(std::min<double>(std::max(xi, 0.0), width - 1.0));
        const auto cz = static_cast<uint32_t>(std::min<double>(std::max(zi, 0.0), height - 1.0));
        return texels[(static_cast<size_t>(cz) * width + cx) * channels] / 65535.0;
    };
    const double a = at(x0f, z0f) + fx * (at(x0f + 1, z0f) - at(x0f, z0f));
    const double b = at(x0f, z0f + 1) + fx * (at(x0f + 1, z0f + 1) - at(x0f, z0f + 1));
    return static_cast<float>(a + fz * (b - a));
}

} // namespace grass
