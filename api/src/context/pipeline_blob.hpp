// The blob of grass_get_pipeline_cache_data (grass.h "Pipelines before the first frame"):
// grass's header, then the backend's payload (Vulkan: vkGetPipelineCacheData's bytes; GL:
// the program binaries, gl_program_cache.hpp). The header carries a magic, the backend, the
// library version, the payload's size and FNV-1a 64 hash, and the backend's identity of the
// device and shaders the payload was made with; a blob that fails any of them is ignored
// with a GRASS_MSG_PIPELINE_CACHE warning, never read further.
#pragma once

#include "foundation/log.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

constexpr uint64_t kPipelineBlobHeaderBytes = 48;

// Writes the header of a blob holding `payload` into `out` (kPipelineBlobHeaderBytes).
void write_pipeline_blob_header(grass_backend backend, uint64_t identity, const void* payload, uint64_t payload_bytes,
                                void* out);

// The payload of blob `data` (`size` bytes), or nullptr after a warning through `log` that
// names `function` and what is wrong (too short, not grass's, another backend, version,
// device or shaders, truncated, corrupt). *payload_bytes: its size.
const unsigned char* open_pipeline_blob(Log* log, const char* function, grass_backend backend, uint64_t identity,
                                        const void* data, uint64_t size, uint64_t* payload_bytes);

} // namespace grass
