// Argument checks shared by the C entry points. Each check logs a sentence that names the
// function, the argument and the value, and returns the error code (GRASS_SUCCESS if fine).
#pragma once

#include "foundation/log.hpp"
#include "foundation/raw_enum.hpp"

#include <grass/grass.h>

#include <cmath>

namespace grass {

// The type tag and next pointer every desc begins with.
// `actual` is the raw value of desc->type (see raw_enum.hpp).
grass_result check_desc_header(Log* log, const char* function, const char* name, const void* desc, int64_t actual,
                               const void* next, grass_struct_type expected, const char* expected_name);

#define GRASS_CHECK_DESC(log, fn, desc, EXPECTED)                                            \
    ::grass::check_desc_header((log), (fn), #desc, (desc),                                   \
                               (desc) ? ::grass::raw_enum((desc)->type) : int64_t{EXPECTED}, \
                               (desc) ? (desc)->next : nullptr, EXPECTED, #EXPECTED)

grass_result check_not_null(Log* log, const char* function, const char* name, const void* p);
// A grass_bool: 0 or 1 (GRASS_MSG_BAD_ENUM otherwise).
grass_result check_bool(Log* log, const char* function, const char* name, grass_bool b);
grass_result check_finite(Log* log, const char* function, const char* name, double value);
// lo <= value <= hi, and finite.
grass_result check_range(Log* log, const char* function, const char* name, double value, double lo, double hi);
// A float field against a range documented in decimals: float(lo) <= value <= float(hi), and
// finite. The bounds are rounded to the nearest float as C rounds the literal `0.01f`, so the
// documented value as written in C is accepted (0.01f is 0.0099999998, below 0.01).
grass_result check_float_range(Log* log, const char* function, const char* name, float value, double lo, double hi);
// 0 <= lo <= hi <= limit for a min/max pair.
grass_result check_min_max(Log* log, const char* function, const char* name_min, const char* name_max, double lo,
                           double hi, double limit);
// lo < value <= hi, and finite: a range open at its lower end ("> 0 .. 1e4").
grass_result check_range_above(Log* log, const char* function, const char* name, double value, double lo, double hi);
// Finite, and longer than 1e-6 (a direction that must point somewhere).
grass_result check_direction(Log* log, const char* function, const char* name, const float v[3]);
grass_result check_finite_array(Log* log, const char* function, const char* name, const double* v, int n);
grass_result check_finite_array(Log* log, const char* function, const char* name, const float* v, int n);
// A world position: finite, each coordinate within +-1e12 m (beyond, double itself loses the
// millimetre).
grass_result check_world_position(Log* log, const char* function, const char* name, const double p[3]);

// Early return on error: GRASS_TRY(check_...(...));
#define GRASS_TRY(expr)                                         \
    do {                                                        \
        const grass_result grass_try_r_ = (expr);               \
        if (grass_try_r_ != GRASS_SUCCESS) return grass_try_r_; \
    } while (0)

} // namespace grass
