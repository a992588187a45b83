// grass-measure bench's reference cache: reference images (blades everywhere) cost seconds to
// many minutes a frame on a software rasteriser, so each is rendered once and kept on disk,
// keyed by a hash of a text that names everything defining it (reference_key in bench.cpp:
// the scene file's bytes, the bench's part of the field, the patch, the seeds, the camera,
// the size, the samples and supersampling, the backend where it matters, the library version
// and a hash of the sources that draw blades, taken when the build is configured).
//
// One file per reference, <dir>/<hash>.ref: a header line, the key, the RGBA8 pixels; and
// <hash>.png beside it to look at. A file whose key differs from the one asked for (a hash
// collision, or an older format) is a miss.
#pragma once

#include "headless_host.hpp"

#include <string>

namespace grass_measure {
namespace bench {

struct CachedReference {
    grass_host::Image image;
    double frame_ms = 0; // the timed frame (median), where the reference was timed; else 0
    double render_s = 0; // how long rendering it took when it was made (wall time, s)
};

// 16 hex digits: FNV-1a 64 of `key`.
std::string reference_hash(const std::string& key);

// True and *out when <dir>/<hash>.ref holds the reference of exactly `key`.
bool load_reference(const std::string& dir, const std::string& key, CachedReference* out);

// Writes <dir>/<hash>.ref and <hash>.png. False and *error on failure.
bool store_reference(const std::string& dir, const std::string& key, const CachedReference& ref, std::string* error);

} // namespace bench
} // namespace grass_measure
