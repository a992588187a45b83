#include "reference_cache.hpp"

#include "file_bytes.hpp"
#include "image_io.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace grass_measure {
namespace bench {

namespace {
constexpr const char* kMagic = "grass-measure-reference-1";
}

std::string reference_hash(const std::string& key) {
    uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : key) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(h));
    return text;
}

bool load_reference(const std::string& dir, const std::string& key, CachedReference* out) {
    // Read as any file the tools read (grass_sample::read_file_bytes): a FIFO, a directory or
    // a device under the reference's name is a cache miss, never a blocked or endless read.
    std::vector<unsigned char> bytes;
    std::string error;
    if (!grass_sample::read_file_bytes(dir + "/" + reference_hash(key) + ".ref", grass_sample::kMaxFileBytes, &bytes,
                                       &error))
        return false;
    std::istringstream in(std::string(bytes.begin(), bytes.end()));
    std::string magic, stored_key;
    uint32_t w = 0, h = 0;
    double ms = 0, render_s = 0;
    std::string header;
    if (!std::getline(in, header) || !std::getline(in, stored_key)) return false;
    std::istringstream hs(header);
    if (!(hs >> magic >> w >> h >> ms >> render_s) || magic != kMagic || stored_key != key) return false;
    const uint64_t pixels_bytes = uint64_t(w) * h * 4;
    const uint64_t at = static_cast<uint64_t>(in.tellg());
    if (pixels_bytes != bytes.size() - at) return false; // truncated or padded: not this reference
    CachedReference r;
    r.image.width = w;
    r.image.height = h;
    r.image.rgba.assign(bytes.begin() + std::ptrdiff_t(at), bytes.end());
    r.frame_ms = ms;
    r.render_s = render_s;
    *out = std::move(r);
    return true;
}

bool store_reference(const std::string& dir, const std::string& key, const CachedReference& ref, std::string* error) {
    const std::string stem = dir + "/" + reference_hash(key);
    if (key.find('\n') != std::string::npos) {
        *error = "a reference key holds a line break: " + key;
        return false;
    }
    {
        std::ofstream out(stem + ".ref.tmp", std::ios::binary);
        char header[160];
        std::snprintf(header, sizeof(header), "%s %u %u %.6f %.3f\n", kMagic, ref.image.width, ref.image.height,
                      ref.frame_ms, ref.render_s);
        out << header << key << '\n';
        out.write(reinterpret_cast<const char*>(ref.image.rgba.data()), std::streamsize(ref.image.rgba.size()));
        if (!out) {
            *error = "cannot write " + stem + ".ref.tmp";
            return false;
        }
    }
    // Renamed into place only when complete: an interrupted run leaves no half reference.
    if (std::rename((stem + ".ref.tmp").c_str(), (stem + ".ref").c_str()) != 0) {
        *error = "cannot rename " + stem + ".ref.tmp";
        return false;
    }
    return grass_host::write_png(stem + ".png", ref.image, error);
}

} // namespace bench
} // namespace grass_measure
