// Enums that arrive from C hosts may hold any integer. Loading an out-of-range value as a
// C++ enum is undefined behaviour, so every host enum is read as its raw integer first and
// validated as an integer.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace grass {

template <class E>
int64_t raw_enum(const E& value) {
    static_assert(std::is_enum<E>::value, "raw_enum reads enums");
    std::underlying_type_t<E> raw;
    std::memcpy(&raw, &value, sizeof(raw));
    return static_cast<int64_t>(raw);
}

} // namespace grass
