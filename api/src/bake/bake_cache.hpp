// Disk cache of baked slices (boulanger2006 3.3: "stored on the hard drive"), so that a host
// starts fast the second time. One file per key, "grass-slices-<key as 16 hex digits>.bin",
// in a directory the host chooses: a fixed little-endian header (magic, format version,
// key, sizes, content hash, and a hash of the header itself) and the color, normal and threshold arrays. A load verifies
// everything before it trusts anything; a store writes a temporary file and renames it.
#pragma once

#include "bake/baked_slices.hpp"
#include "foundation/allocator.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// Bump when the baked bytes for the same key would change: the file layout, the baker, the
// mip filters, or the patch generator (the key hashes the desc, not the generated patch).
constexpr uint32_t kBakeFormatVersion = 9; // 4: the threshold channel holds the coverage curve; 5: folded normals;
                                           // 6: partly covered texels keep their colour; 7: the
                                           // horizontal slice's colour and heights seen grazing;
                                           // 8: the image tier's grazing normals per heading;
                                           // 9: the horizontal slice's mips keep the mean opacity

// FNV-1a 64 over the format version, every field of the desc but type and next (by value,
// little-endian, floats by their bits), and the bake parameters (0 sizes replaced by the
// defaults of slice_baker.hpp, so both spellings share a file).
uint64_t bake_key(const grass_patch_desc& desc, uint32_t slices_per_axis, uint32_t width, uint32_t height);

// Why a cache file was not used (load_baked).
enum class CacheMiss {
    none,          // loaded
    missing,       // no file of the key (the first run): not worth a warning
    unreadable,    // it exists but cannot be read
    not_regular,   // a directory, FIFO, socket or device under the name: neither read nor replaced
    truncated,     // shorter or longer than its header says, or empty
    corrupt,       // not a grass cache file, a broken header hash or impossible sizes
    other_version, // written by a grass whose baked bytes differ (kBakeFormatVersion)
    other_patch,   // the file of another key under this name
    content_hash,  // the slices do not match the content hash of the header
};
// A short English phrase for a miss ("is truncated"), for the warning that names the file.
const char* cache_miss_phrase(CacheMiss miss);

// Reads the file of `key` in `directory` into `out`. Returns CacheMiss::none on success;
// otherwise `out` is left empty of data and the result says why: the file is missing,
// unreadable, not a regular file (never read: a FIFO does not block), truncated, too long, or any header field, the key or the recomputed content
// hash does not match. Sizes are checked against the file's length before anything is
// allocated. `path_out` (optional, kCachePathCapacity chars) receives the file's path.
constexpr size_t kCachePathCapacity = 4096;
CacheMiss load_baked(const char* directory, uint64_t key, HostAllocator* host, SliceSet* out, char* path_out = nullptr);

// Writes `set` as the file of `key` in `directory` (which must exist), atomically: a
// temporary file in the same directory renamed over the final name. Returns false on any
// I/O error (and removes the temporary file).
bool store_baked(const char* directory, uint64_t key, const SliceSet& set);

} // namespace grass
