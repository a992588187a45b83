#include "dynamics/wind.hpp"

#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace grass {

namespace {

constexpr double kMaxPosition = 1e12; // world metres, the camera's bound
constexpr double kMaxTime = 1e9;      // seconds, grass_view_desc.time's bound

double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void normalize3(const float v[3], double out[3]) {
    const double x = v[0], y = v[1], z = v[2];
    const double len = std::sqrt(x * x + y * y + z * z);
    out[0] = x / len;
    out[1] = y / len;
    out[2] = z / len;
}

grass_result validate_source(Log* log, const char* fn, uint32_t i, const grass_wind_source& s) {
    char name[96];
    auto arg = [&](const char* field) {
        std::snprintf(name, sizeof name, "wind->sources[%u].%s", i, field);
        return name;
    };
    const int64_t kind = raw_enum(s.kind);
    if (kind != GRASS_WIND_SOURCE_POINT && kind != GRASS_WIND_SOURCE_CONE && kind != GRASS_WIND_SOURCE_BLAST) {
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: %s is %lld; it must be GRASS_WIND_SOURCE_POINT, _CONE or _BLAST", fn, arg("kind"),
                         static_cast<long long>(kind));
    }
    // Every number finite, used or not (a NaN anywhere is a host's bug); ranges where used.
    GRASS_TRY(check_finite_array(log, fn, arg("position"), s.position, 3));
    for (int c = 0; c < 3; ++c) {
        if (std::fabs(s.position[c]) > kMaxPosition) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: %s[%d] is %g; it must be within +-1e12 m", fn, arg("position"), c, s.position[c]);
        }
    }
    GRASS_TRY(check_finite_array(log, fn, arg("direction"), s.direction, 3));
    GRASS_TRY(check_finite(log, fn, arg("cone_angle"), s.cone_angle));
    GRASS_TRY(check_finite(log, fn, arg("start_time"), s.start_time));
    GRASS_TRY(check_finite(log, fn, arg("duration"), s.duration));
    GRASS_TRY(check_finite(log, fn, arg("front_speed"), s.front_speed));
    GRASS_TRY(check_range(log, fn, arg("speed"), s.speed, 0.0, 1e3));
    GRASS_TRY(check_range(log, fn, arg("radius"), s.radius, 1e-3, 1e6));
    if (kind == GRASS_WIND_SOURCE_CONE) {
        GRASS_TRY(check_direction(log, fn, arg("direction"), s.direction));
        GRASS_TRY(check_range_above(log, fn, arg("cone_angle"), s.cone_angle, 0.0, 1.5707963267948966));
    }
    if (kind == GRASS_WIND_SOURCE_BLAST) {
        GRASS_TRY(check_range(log, fn, arg("start_time"), s.start_time, -kMaxTime, kMaxTime));
        GRASS_TRY(check_range_above(log, fn, arg("duration"), s.duration, 0.0, 1e4));
        GRASS_TRY(check_range_above(log, fn, arg("front_speed"), s.front_speed, 0.0, 1e4));
    }
    return GRASS_SUCCESS;
}

} // namespace

double fract(double x) {
    const double f = x - std::floor(x);
    return f < 1.0 ? f : 0.0;
}

grass_wind_desc default_wind_desc() {
    grass_wind_desc w;
    std::memset(&w, 0, sizeof(w));
    w.type = GRASS_STRUCT_TYPE_WIND_DESC;
    w.direction[0] = 1.0f;
    w.direction[1] = 0.0f;
    w.direction[2] = 0.3f;
    w.speed = 0.0f;
    w.gust_strength = 0.6f;
    w.gust_length = 14.0f;
    w.turbulence = 0.3f;
    std::memcpy(w.gravity, kStandardGravity, sizeof(w.gravity));
    return w;
}

grass_result validate_wind(Log* log, const char* fn, const grass_wind_desc& w) {
    GRASS_TRY(check_direction(log, fn, "wind->direction", w.direction));
    GRASS_TRY(check_range(log, fn, "wind->speed", w.speed, 0.0, 1e3));
    GRASS_TRY(check_range(log, fn, "wind->gust_strength", w.gust_strength, 0.0, 4.0));
    GRASS_TRY(check_range(log, fn, "wind->gust_length", w.gust_length, 0.1, 1e5));
    GRASS_TRY(check_range(log, fn, "wind->turbulence", w.turbulence, 0.0, 1.0));
    static const char* const gravity_names[3] = {"wind->gravity[0]", "wind->gravity[1]", "wind->gravity[2]"};
    for (int c = 0; c < 3; ++c) GRASS_TRY(check_range(log, fn, gravity_names[c], w.gravity[c], -1e3, 1e3));
    GRASS_TRY(check_range(log, fn, "wind->source_count", w.source_count, 0, GRASS_MAX_WIND_SOURCES));
    if (w.source_count > 0) GRASS_TRY(check_not_null(log, fn, "wind->sources", w.sources));
    for (uint32_t i = 0; i < w.source_count; ++i) GRASS_TRY(validate_source(log, fn, i, w.sources[i]));
    return GRASS_SUCCESS;
}

bool wind_is_active(const grass_wind_desc& w) {
    return w.speed > 0.0f || w.source_count > 0 || w.gravity[0] != kStandardGravity[0] ||
           w.gravity[1] != kStandardGravity[1] || w.gravity[2] != kStandardGravity[2];
}

void pack_wind(const grass_wind_desc& w, const double camera[3], double time, const double up[3], FrameUniforms* f) {
    double dir[3];
    normalize3(w.direction, dir);
    const double speed = w.speed;
    for (int c = 0; c < 3; ++c) {
        f->wind[c] = static_cast<float>(dir[c] * speed);
        f->gravity[c] = w.gravity[c] - kStandardGravity[c];
    }
    f->wind[3] = w.gust_strength;
    f->gravity[3] = 0.0f;
    f->wind_shape[0] = 1.0f / w.gust_length;
    f->wind_shape[1] = w.turbulence;
    f->wind_shape[2] = static_cast<float>(w.source_count);
    // The gust waves' phases at the camera, in double: a shader adds dot(p, dir) / lambda_k
    // for a camera-relative p, which stays small wherever the camera is.
    const double along = dot3(camera, dir);
    for (int k = 0; k < 3; ++k) {
        const double lambda = double(w.gust_length) * kGustWavelength[k];
        const double c = speed * kGustSpeed[k];
        f->wind_phase[k] = static_cast<float>(fract(along / lambda - time * c / lambda + kGustOffset[k]));
    }
    // The cross-wind coordinate of the turbulence: along normalize(cross(up, dir)); none
    // when the wind blows along up.
    const double cross[3] = {up[1] * dir[2] - up[2] * dir[1], up[2] * dir[0] - up[0] * dir[2],
                             up[0] * dir[1] - up[1] * dir[0]};
    const double cross_len = std::sqrt(dot3(cross, cross));
    f->wind_phase[3] =
        cross_len > 1e-9 ? static_cast<float>(fract(dot3(camera, cross) / cross_len / (0.5 * w.gust_length))) : 0.0f;

    for (uint32_t i = 0; i < GRASS_MAX_WIND_SOURCES; ++i) {
        float(&out)[4][4] = f->wind_sources[i];
        std::memset(out, 0, sizeof(out));
        if (i >= w.source_count) continue;
        const grass_wind_source& s = w.sources[i];
        for (int c = 0; c < 3; ++c) out[0][c] = static_cast<float>(s.position[c] - camera[c]);
        out[0][3] = static_cast<float>(s.kind);
        if (s.kind == GRASS_WIND_SOURCE_CONE) {
            double axis[3];
            normalize3(s.direction, axis);
            for (int c = 0; c < 3; ++c) out[1][c] = static_cast<float>(axis[c]);
            out[1][3] = static_cast<float>(std::cos(double(s.cone_angle)));
        }
        out[2][0] = s.speed;
        out[2][1] = s.radius;
        if (s.kind == GRASS_WIND_SOURCE_BLAST) {
            out[2][2] = static_cast<float>(time - s.start_time);
            out[2][3] = s.duration;
            out[3][0] = s.front_speed;
        }
    }
}

} // namespace grass
