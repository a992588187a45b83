// Values a fuzz target feeds the C API: mostly sane, often at or past the documented edges
// (NaN, infinities, negative, zero, huge), decoded from the fuzzer's bytes.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <limits>

namespace grass_fuzz {

inline double hostile_double(FuzzedDataProvider& in, double lo, double hi) {
    switch (in.ConsumeIntegralInRange<int>(0, 11)) {
    case 0:
        return std::numeric_limits<double>::quiet_NaN();
    case 1:
        return std::numeric_limits<double>::infinity();
    case 2:
        return -std::numeric_limits<double>::infinity();
    case 3:
        return -1.0;
    case 4:
        return 0.0;
    case 5:
        return 1e30;
    case 6:
        return -1e30;
    case 7:
        return std::numeric_limits<double>::denorm_min();
    case 8:
        return in.ConsumeFloatingPoint<double>(); // anything at all
    default:
        return in.ConsumeFloatingPointInRange<double>(lo, hi); // within the sane range
    }
}

inline float hostile_float(FuzzedDataProvider& in, double lo, double hi) {
    return static_cast<float>(hostile_double(in, lo, hi));
}

inline uint32_t hostile_u32(FuzzedDataProvider& in, uint32_t lo, uint32_t hi) {
    switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 0:
        return 0;
    case 1:
        return 0xffffffffu;
    case 2:
        return 0x80000000u;
    case 3:
        return in.ConsumeIntegral<uint32_t>();
    default:
        return in.ConsumeIntegralInRange<uint32_t>(lo, hi);
    }
}

} // namespace grass_fuzz
