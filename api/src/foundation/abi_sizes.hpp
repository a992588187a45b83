// The sizes of the structs the library fills, per header version (grass.h, "ABI and
// versions"): a getter writes only the bytes the caller's header declared, so a host built
// against an older, smaller struct gets no bytes past its end.
#pragma once

#include <grass/grass.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace grass {

// The oldest header minor version the library accepts: 0.3 is the first whose layouts it records.
constexpr uint32_t kOldestHeaderMinor = 3;

enum class OutStruct { frame_stats, memory_stats, patch_info };

// Bytes of `which` in grass.h 0.`header_minor` (kOldestHeaderMinor .. GRASS_VERSION_MINOR).
size_t out_struct_size(OutStruct which, uint32_t header_minor);

template <class T>
struct OutStructOf;
template <>
struct OutStructOf<grass_frame_stats> {
    static constexpr OutStruct value = OutStruct::frame_stats;
};
template <>
struct OutStructOf<grass_memory_stats> {
    static constexpr OutStruct value = OutStruct::memory_stats;
};
template <>
struct OutStructOf<grass_patch_info> {
    static constexpr OutStruct value = OutStruct::patch_info;
};

// Copies into `out` the prefix of `full` that grass.h 0.`header_minor` declared (a context's
// header_minor: the header its host was built against).
template <class T>
void write_out_struct(uint32_t header_minor, const T& full, T* out) {
    std::memcpy(out, &full, out_struct_size(OutStructOf<T>::value, header_minor));
}

} // namespace grass
