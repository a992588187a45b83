#include "foundation/abi_sizes.hpp"

namespace grass {

namespace {

// Sizes in grass.h 0.3 (tests/abi/grass_0_3.h, the frozen copy; tests/abi/old_header_host.c
// checks them against it). Literal numbers: they must never change.
constexpr size_t kFrameStats03 = 152; // 9 x 8 bytes, 3 arrays of GRASS_TIER_KIND_COUNT uint64, nodes_empty
constexpr size_t kMemoryStats03 = 24; // host_bytes, host_allocations, gpu_bytes
constexpr size_t kPatchInfo03 = 48;   // 3 x uint32, 6 floats, content_hash at offset 40

// Sizes in grass.h 0.4. Literal increments: they must never change.
constexpr size_t kFrameStats04 = kFrameStats03 + 8;   // + draws
constexpr size_t kMemoryStats04 = kMemoryStats03 + 8; // + host_bytes_peak
constexpr size_t kPatchInfo04 = kPatchInfo03;

// Sizes in grass.h 0.5 (the current header).
constexpr size_t kFrameStats05 = kFrameStats04 + 32; // + colliders, colliders_in_map, interaction_texels, time_step
// + dynamics_gpu_bytes; heap_count, heap_budget_known, device_allocations and five arrays of
// GRASS_MAX_MEMORY_HEAPS uint64 (the per-heap device memory)
constexpr size_t kMemoryStats05 = kMemoryStats04 + 8 + 16 + 5 * 16 * 8;
constexpr size_t kPatchInfo05 = kPatchInfo04;

static_assert(GRASS_VERSION_MAJOR == 0 && GRASS_VERSION_MINOR == 5,
              "a new header version: add its sizes to out_struct_size and update these asserts");
static_assert(sizeof(grass_frame_stats) == kFrameStats05, "grass_frame_stats changed: record its new size");
static_assert(sizeof(grass_memory_stats) == kMemoryStats05, "grass_memory_stats changed: record its new size");
static_assert(sizeof(grass_patch_info) == kPatchInfo05, "grass_patch_info changed: record its new size");
static_assert(offsetof(grass_frame_stats, draws) == kFrameStats03, "0.4 fields come after the 0.3 ones");
static_assert(offsetof(grass_memory_stats, host_bytes_peak) == kMemoryStats03, "0.4 fields come after the 0.3 ones");
static_assert(offsetof(grass_frame_stats, colliders) == kFrameStats04, "0.5 fields come after the 0.4 ones");
static_assert(offsetof(grass_memory_stats, dynamics_gpu_bytes) == kMemoryStats04, "0.5 fields come after the 0.4 ones");
static_assert(offsetof(grass_memory_stats, heap_count) == kMemoryStats04 + 8,
              "the heaps come after dynamics_gpu_bytes");
static_assert(GRASS_MAX_MEMORY_HEAPS == 16, "GRASS_MAX_MEMORY_HEAPS is part of the ABI: it never changes");

} // namespace

size_t out_struct_size(OutStruct which, uint32_t header_minor) {
    static constexpr size_t kFrameStats[] = {kFrameStats03, kFrameStats04, kFrameStats05};
    static constexpr size_t kMemoryStats[] = {kMemoryStats03, kMemoryStats04, kMemoryStats05};
    static constexpr size_t kPatchInfo[] = {kPatchInfo03, kPatchInfo04, kPatchInfo05};
    const uint32_t v = header_minor <= 3 ? 0 : header_minor == 4 ? 1 : 2;
    switch (which) {
    case OutStruct::frame_stats:
        return kFrameStats[v];
    case OutStruct::memory_stats:
        return kMemoryStats[v];
    case OutStruct::patch_info:
        return kPatchInfo[v];
    }
    return 0;
}

} // namespace grass
