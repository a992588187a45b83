#include "context/pipeline_blob.hpp"

#include "patch/random.hpp"

#include <cstring>

namespace grass {

namespace {

constexpr char kMagic[8] = {'G', 'R', 'A', 'S', 'S', 'P', 'C', '1'};

struct BlobHeader {
    char magic[8];
    uint32_t header_bytes;
    uint32_t backend;
    uint32_t library_version;
    uint32_t reserved;
    uint64_t payload_bytes;
    uint64_t payload_hash;
    uint64_t identity;
};
static_assert(sizeof(BlobHeader) == kPipelineBlobHeaderBytes, "the blob header is 48 bytes");

} // namespace

void write_pipeline_blob_header(grass_backend backend, uint64_t identity, const void* payload, uint64_t payload_bytes,
                                void* out) {
    BlobHeader h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.header_bytes = static_cast<uint32_t>(kPipelineBlobHeaderBytes);
    h.backend = static_cast<uint32_t>(backend);
    h.library_version = GRASS_HEADER_VERSION;
    h.payload_bytes = payload_bytes;
    h.payload_hash = fnv1a64(payload, payload_bytes, kFnvOffset);
    h.identity = identity;
    std::memcpy(out, &h, sizeof h);
}

const unsigned char* open_pipeline_blob(Log* log, const char* function, grass_backend backend, uint64_t identity,
                                        const void* data, uint64_t size, uint64_t* payload_bytes) {
    const auto ignored = [&](const char* why) -> const unsigned char* {
        log->warn(GRASS_MSG_PIPELINE_CACHE, "%s: desc->cache_data (%llu bytes) is ignored: %s; grass compiles instead",
                  function, static_cast<unsigned long long>(size), why);
        return nullptr;
    };
    BlobHeader h{};
    if (size < sizeof h) return ignored("it is shorter than grass's 48-byte header");
    std::memcpy(&h, data, sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.header_bytes != sizeof h)
        return ignored("it is not a blob of grass_get_pipeline_cache_data");
    if (h.backend != static_cast<uint32_t>(backend)) return ignored("it was saved by a context of another backend");
    if (h.library_version != GRASS_HEADER_VERSION) return ignored("it was saved by another version of grass");
    if (h.identity != identity) return ignored("it was saved on another device, driver or set of shaders");
    if (h.payload_bytes != size - sizeof h) return ignored("its size disagrees with its header (truncated?)");
    const unsigned char* payload = static_cast<const unsigned char*>(data) + sizeof h;
    if (fnv1a64(payload, h.payload_bytes, kFnvOffset) != h.payload_hash)
        return ignored("its contents do not match their hash (corrupt)");
    *payload_bytes = h.payload_bytes;
    return payload;
}

} // namespace grass
