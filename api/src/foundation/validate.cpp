#include "foundation/validate.hpp"

#include <cmath>

namespace grass {

grass_result check_desc_header(Log* log, const char* function, const char* name, const void* desc, int64_t actual,
                               const void* next, grass_struct_type expected, const char* expected_name) {
    if (!desc)
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: %s is NULL", function, name);
    if (actual != static_cast<int64_t>(expected)) {
        return log->fail(GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                         "%s: %s->type is 0x%08x; expected %s (0x%08x)", function, name, static_cast<unsigned>(actual),
                         expected_name, static_cast<unsigned>(expected));
    }
    if (next)
        return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NEXT_NOT_NULL, "%s: %s->next must be NULL", function,
                         name);
    return GRASS_SUCCESS;
}

grass_result check_not_null(Log* log, const char* function, const char* name, const void* p) {
    if (p) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: %s is NULL", function, name);
}

grass_result check_bool(Log* log, const char* function, const char* name, grass_bool b) {
    if (b == 0 || b == 1) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM, "%s: %s is %u; it must be 0 or 1", function,
                     name, static_cast<unsigned>(b));
}

grass_result check_finite(Log* log, const char* function, const char* name, double value) {
    if (std::isfinite(value)) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NOT_FINITE, "%s: %s is %g; it must be finite", function,
                     name, value);
}

grass_result check_range(Log* log, const char* function, const char* name, double value, double lo, double hi) {
    GRASS_TRY(check_finite(log, function, name, value));
    if (value >= lo && value <= hi) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE, "%s: %s is %g; it must be in [%g, %g]",
                     function, name, value, lo, hi);
}

grass_result check_float_range(Log* log, const char* function, const char* name, float value, double lo, double hi) {
    GRASS_TRY(check_finite(log, function, name, value));
    if (value >= static_cast<float>(lo) && value <= static_cast<float>(hi)) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE, "%s: %s is %.9g; it must be in [%g, %g]",
                     function, name, static_cast<double>(value), lo, hi); // all digits: 0.00999999884 is not 0.01
}

grass_result check_range_above(Log* log, const char* function, const char* name, double value, double lo, double hi) {
    GRASS_TRY(check_finite(log, function, name, value));
    if (value > lo && value <= hi) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE, "%s: %s is %g; it must be in (%g, %g]",
                     function, name, value, lo, hi);
}

grass_result check_direction(Log* log, const char* function, const char* name, const float v[3]) {
    GRASS_TRY(check_finite_array(log, function, name, v, 3));
    const double x = v[0], y = v[1], z = v[2];
    if (x * x + y * y + z * z > 1e-12) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_ZERO_VECTOR,
                     "%s: %s is (%g, %g, %g); it must not be zero (length > 1e-6)", function, name, x, y, z);
}

grass_result check_min_max(Log* log, const char* function, const char* name_min, const char* name_max, double lo,
                           double hi, double limit) {
    GRASS_TRY(check_range(log, function, name_min, lo, 0.0, limit));
    GRASS_TRY(check_range(log, function, name_max, hi, 0.0, limit));
    if (lo <= hi) return GRASS_SUCCESS;
    return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_RANGE_INVERTED, "%s: %s (%g) is greater than %s (%g)",
                     function, name_min, lo, name_max, hi);
}

grass_result check_finite_array(Log* log, const char* function, const char* name, const double* v, int n) {
    for (int i = 0; i < n; ++i) {
        if (!std::isfinite(v[i])) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NOT_FINITE, "%s: %s[%d] is %g; it must be finite",
                             function, name, i, v[i]);
        }
    }
    return GRASS_SUCCESS;
}

grass_result check_finite_array(Log* log, const char* function, const char* name, const float* v, int n) {
    for (int i = 0; i < n; ++i) {
        if (!std::isfinite(v[i])) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NOT_FINITE, "%s: %s[%d] is %g; it must be finite",
                             function, name, i, static_cast<double>(v[i]));
        }
    }
    return GRASS_SUCCESS;
}

grass_result check_world_position(Log* log, const char* function, const char* name, const double p[3]) {
    GRASS_TRY(check_finite_array(log, function, name, p, 3));
    for (int c = 0; c < 3; ++c) {
        if (std::fabs(p[c]) > 1e12) {
            return log->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                             "%s: %s[%d] is %g; it must be within +-1e12 m", function, name, c, p[c]);
        }
    }
    return GRASS_SUCCESS;
}

} // namespace grass
