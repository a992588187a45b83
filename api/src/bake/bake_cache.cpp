#include "bake/bake_cache.hpp"

#include "bake/slice_baker.hpp"
#include "bake/slice_mips.hpp"
#include "bake/slice_set_hash.hpp"
#include "patch/random.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <random>
#include <type_traits>

#ifndef _WIN32
#    include <fcntl.h>
#    include <sys/stat.h>
#    include <unistd.h>
#endif

namespace grass {

namespace {

constexpr char kMagic[8] = {'G', 'R', 'S', 'L', 'I', 'C', 'E', 'S'};
constexpr size_t kHeaderBytes = 72;  // the last 8: FNV-1a 64 of the first 64
constexpr uint32_t kMaxSize = 16384; // texels along s or t
constexpr uint32_t kMaxSlicesPerAxis = 1024;
constexpr size_t kMaxPath = kCachePathCapacity;

struct Header {
    uint32_t version = 0;
    uint64_t key = 0;
    uint32_t slices_per_axis = 0, layers = 0, width = 0, height = 0, mip_levels = 0;
    float height_patch_units = 0;
    uint64_t texels = 0;
    uint64_t content_hash = 0;
};

void put32(uint8_t* p, uint32_t v) {
    for (int k = 0; k < 4; ++k) p[k] = static_cast<uint8_t>(v >> (8 * k));
}
void put64(uint8_t* p, uint64_t v) {
    for (int k = 0; k < 8; ++k) p[k] = static_cast<uint8_t>(v >> (8 * k));
}
uint32_t get32(const uint8_t* p) {
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= static_cast<uint32_t>(p[k]) << (8 * k);
    return v;
}
uint64_t get64(const uint8_t* p) {
    uint64_t v = 0;
    for (int k = 0; k < 8; ++k) v |= static_cast<uint64_t>(p[k]) << (8 * k);
    return v;
}
uint32_t float_bits(float f) {
    uint32_t v;
    std::memcpy(&v, &f, 4);
    return v;
}
float bits_float(uint32_t v) {
    float f;
    std::memcpy(&f, &v, 4);
    return f;
}

void encode_header(const Header& h, uint8_t* p) {
    std::memset(p, 0, kHeaderBytes);
    std::memcpy(p, kMagic, 8);
    put32(p + 8, h.version);
    put32(p + 12, static_cast<uint32_t>(kHeaderBytes));
    put64(p + 16, h.key);
    put32(p + 24, h.slices_per_axis);
    put32(p + 28, h.layers);
    put32(p + 32, h.width);
    put32(p + 36, h.height);
    put32(p + 40, h.mip_levels);
    put32(p + 44, float_bits(h.height_patch_units));
    put64(p + 48, h.texels);
    put64(p + 56, h.content_hash);
    put64(p + 64, fnv1a64(p, 64, kFnvOffset));
}

bool decode_header(const uint8_t* p, Header* h) {
    if (std::memcmp(p, kMagic, 8) != 0 || get32(p + 12) != kHeaderBytes) return false;
    if (get64(p + 64) != fnv1a64(p, 64, kFnvOffset)) return false;
    h->version = get32(p + 8);
    h->key = get64(p + 16);
    h->slices_per_axis = get32(p + 24);
    h->layers = get32(p + 28);
    h->width = get32(p + 32);
    h->height = get32(p + 36);
    h->mip_levels = get32(p + 40);
    h->height_patch_units = bits_float(get32(p + 44));
    h->texels = get64(p + 48);
    h->content_hash = get64(p + 56);
    return true;
}

// "<directory>/grass-slices-<key>.bin" plus `suffix`; false when it does not fit.
bool file_path(const char* directory, uint64_t key, const char* suffix, char* out, size_t capacity) {
    if (!directory) return false;
    const size_t len = std::strlen(directory);
    const char* sep = (len == 0 || directory[len - 1] == '/' || directory[len - 1] == '\\') ? "" : "/";
    const int n = std::snprintf(out, capacity, "%s%sgrass-slices-%016llx.bin%s", len ? directory : ".", len ? sep : "/",
                                static_cast<unsigned long long>(key), suffix);
    return n > 0 && static_cast<size_t>(n) < capacity;
}

template <class T>
void hash_value(uint64_t* h, T value) {
    uint8_t bytes[8];
    uint64_t v = 0;
    if constexpr (sizeof(T) == 4 && std::is_floating_point<T>::value) {
        v = float_bits(value);
    } else {
        v = static_cast<uint64_t>(value);
    }
    put64(bytes, v);
    *h = fnv1a64(bytes, sizeof(T) <= 4 ? 4 : 8, *h);
}

// Opens `path` for reading if it is a regular file. A FIFO under the name would block a
// plain fopen until a writer comes (forever): it is opened non-blocking, and the opened
// descriptor is checked (fstat, no race with a rename). *miss says why on failure.
std::FILE* open_regular(const char* path, CacheMiss* miss) {
#ifndef _WIN32
    const int fd = ::open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        *miss = errno == ENOENT || errno == ENOTDIR ? CacheMiss::missing : CacheMiss::unreadable;
        return nullptr;
    }
    struct stat st;
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        *miss = CacheMiss::not_regular;
        ::close(fd);
        return nullptr;
    }
    std::FILE* f = ::fdopen(fd, "rb");
    if (!f) {
        *miss = CacheMiss::unreadable;
        ::close(fd);
    }
    return f;
#else
    std::FILE* f = std::fopen(path, "rb");
    if (!f) *miss = errno == ENOENT || errno == ENOTDIR ? CacheMiss::missing : CacheMiss::unreadable;
    return f;
#endif
}

bool read_exact(std::FILE* f, void* data, size_t bytes) { return bytes == 0 || std::fread(data, 1, bytes, f) == bytes; }
bool write_exact(std::FILE* f, const void* data, size_t bytes) {
    return bytes == 0 || std::fwrite(data, 1, bytes, f) == bytes;
}

void clear_set(SliceSet* out) {
    out->slices_per_axis = out->layers = out->width = out->height = out->mip_levels = 0;
    out->height_patch_units = 0;
    out->color.clear();
    out->normal.clear();
    out->threshold.clear();
    out->content_hash = 0;
}

} // namespace

uint64_t bake_key(const grass_patch_desc& d, uint32_t slices_per_axis, uint32_t width, uint32_t height) {
    if (width == 0) width = slices_per_axis ? kDefaultVerticalSliceWidth : kDefaultHorizontalSliceSize;
    if (height == 0) height = slices_per_axis ? kDefaultVerticalSliceHeight : kDefaultHorizontalSliceSize;
    uint64_t h = kFnvOffset;
    const char tag[] = "grass-baked-slices";
    h = fnv1a64(tag, sizeof(tag) - 1, h);
    hash_value(&h, kBakeFormatVersion);
    hash_value(&h, d.blade_count);
    hash_value(&h, d.subdivisions);
    hash_value(&h, d.length_min);
    hash_value(&h, d.length_max);
    hash_value(&h, d.width_min);
    hash_value(&h, d.width_max);
    hash_value(&h, d.tilt_min);
    hash_value(&h, d.tilt_max);
    hash_value(&h, d.bend_min);
    hash_value(&h, d.bend_max);
    for (int c = 0; c < 3; ++c) hash_value(&h, d.root_color[c]);
    for (int c = 0; c < 3; ++c) hash_value(&h, d.tip_color[c]);
    hash_value(&h, d.blade_color_variation);
    hash_value(&h, d.vertex_color_variation);
    hash_value(&h, static_cast<uint32_t>(d.threshold_mode));
    hash_value(&h, d.cluster_sigma);
    hash_value(&h, d.cluster_frequency);
    hash_value(&h, d.ao_impact);
    hash_value(&h, d.ao_height);
    hash_value(&h, d.seed);
    hash_value(&h, slices_per_axis);
    hash_value(&h, width);
    hash_value(&h, height);
    return h;
}

const char* cache_miss_phrase(CacheMiss miss) {
    switch (miss) {
    case CacheMiss::none:
        return "was read";
    case CacheMiss::missing:
        return "is missing";
    case CacheMiss::unreadable:
        return "cannot be read";
    case CacheMiss::not_regular:
        return "is not a regular file (a directory, pipe or device) and is left alone";
    case CacheMiss::truncated:
        return "is truncated (or longer than its header says)";
    case CacheMiss::corrupt:
        return "is corrupt (not a grass cache file, or its header is damaged)";
    case CacheMiss::other_version:
        return "was written by another version of grass";
    case CacheMiss::other_patch:
        return "holds the slices of another patch";
    case CacheMiss::content_hash:
        return "holds slices that do not match their content hash";
    }
    return "cannot be used";
}

CacheMiss load_baked(const char* directory, uint64_t key, HostAllocator* host, SliceSet* out, char* path_out) {
    clear_set(out);
    char path[kMaxPath];
    if (!file_path(directory, key, "", path, sizeof(path))) return CacheMiss::missing;
    if (path_out) std::memcpy(path_out, path, sizeof(path));
    CacheMiss miss = CacheMiss::none;
    std::FILE* f = open_regular(path, &miss);
    if (!f) return miss;
    do {
        if (std::fseek(f, 0, SEEK_END) != 0) {
            miss = CacheMiss::unreadable;
            break;
        }
        const long length = std::ftell(f);
        if (length < 0 || std::fseek(f, 0, SEEK_SET) != 0) {
            miss = CacheMiss::unreadable;
            break;
        }
        miss = CacheMiss::truncated;
        if (length < static_cast<long>(kHeaderBytes)) break;
        uint8_t bytes[kHeaderBytes];
        Header h;
        if (!read_exact(f, bytes, kHeaderBytes)) break;
        miss = CacheMiss::corrupt;
        if (!decode_header(bytes, &h)) break;
        miss = CacheMiss::other_version;
        if (h.version != kBakeFormatVersion) break;
        miss = CacheMiss::other_patch;
        if (h.key != key) break;
        miss = CacheMiss::corrupt;
        if (h.slices_per_axis > kMaxSlicesPerAxis || h.width == 0 || h.height == 0 || h.width > kMaxSize ||
            h.height > kMaxSize) {
            break;
        }
        if (h.layers != slice_layer_count(h.slices_per_axis)) break;
        if (h.mip_levels != full_mip_count(h.width, h.height)) break;
        if (!(h.height_patch_units > 0.0f) || !std::isfinite(h.height_patch_units)) break;
        // Bounded above: at most 1024 * 2 + 1 layers of 16384^2 * 4 / 3 texels, no overflow.
        const uint64_t texels = h.layers * slice_layer_texels(h.width, h.height, h.mip_levels);
        if (h.texels != texels) break;
        miss = CacheMiss::truncated;
        if (static_cast<uint64_t>(length) != kHeaderBytes + texels * 16) break; // checked before allocating
        SliceSet set(host);
        set.color.resize(texels * 4);
        set.normal.resize(texels * 4);
        set.threshold.resize(texels * 4);
        const uint64_t values = texels * 4; // threshold + coverage curve per texel
        if (!read_exact(f, set.color.data(), set.color.size()) ||
            !read_exact(f, set.normal.data(), set.normal.size())) {
            break;
        }
        bool read_ok = true;
        uint8_t chunk[4096];
        for (uint64_t i = 0; i < values && read_ok;) {
            const uint64_t n = std::min<uint64_t>(sizeof(chunk) / 2, values - i);
            read_ok = read_exact(f, chunk, n * 2);
            for (uint64_t k = 0; k < n && read_ok; ++k) {
                set.threshold[i + k] = static_cast<uint16_t>(chunk[2 * k] | (chunk[2 * k + 1] << 8));
            }
            i += n;
        }
        if (!read_ok) break;
        set.slices_per_axis = h.slices_per_axis;
        set.layers = h.layers;
        set.width = h.width;
        set.height = h.height;
        set.mip_levels = h.mip_levels;
        set.height_patch_units = h.height_patch_units;
        set.content_hash = slice_content_hash(set);
        miss = CacheMiss::content_hash;
        if (set.content_hash != h.content_hash) break;
        out->slices_per_axis = set.slices_per_axis;
        out->layers = set.layers;
        out->width = set.width;
        out->height = set.height;
        out->mip_levels = set.mip_levels;
        out->height_patch_units = set.height_patch_units;
        out->content_hash = set.content_hash;
        out->color = std::move(set.color);
        out->normal = std::move(set.normal);
        out->threshold = std::move(set.threshold);
        set_alpha_test_scales(out, host);
        miss = CacheMiss::none;
    } while (false);
    std::fclose(f);
    return miss;
}

bool store_baked(const char* directory, uint64_t key, const SliceSet& set) {
    const uint64_t texels = set.offset(set.layers, 0);
    if (set.color.size() != texels * 4 || set.normal.size() != texels * 4 || set.threshold.size() != texels * 4) {
        return false;
    }
    char path[kMaxPath], temp[kMaxPath], suffix[64];
    // A name no other writer uses at the same time (a process-wide counter, a stack address,
    // the clock and the system's entropy: processes forked from one parent share the first
    // three, and two such writers once picked the same name and one failed to store); two
    // writers of one key write the same bytes anyway.
    static std::atomic<uint64_t> counter{0};
    uint64_t entropy = 0;
    try {
        std::random_device device;
        entropy = (static_cast<uint64_t>(device()) << 32) ^ device();
    } catch (...) {
        entropy = 0; // no entropy source: the other parts still separate threads and runs
    }
    const uint64_t unique = (counter.fetch_add(1) + 1) * 0x9e3779b97f4a7c15ull ^
                            static_cast<uint64_t>(reinterpret_cast<uintptr_t>(&path)) ^
                            static_cast<uint64_t>(std::time(nullptr)) * 0xc2b2ae3d27d4eb4full ^
                            static_cast<uint64_t>(std::clock()) ^ entropy * 0x94d049bb133111ebull;
    std::snprintf(suffix, sizeof(suffix), ".tmp-%016llx", static_cast<unsigned long long>(unique));
    if (!file_path(directory, key, "", path, sizeof(path)) || !file_path(directory, key, suffix, temp, sizeof(temp))) {
        return false;
    }
    std::FILE* f = std::fopen(temp, "wb");
    if (!f) return false;
    Header h;
    h.version = kBakeFormatVersion;
    h.key = key;
    h.slices_per_axis = set.slices_per_axis;
    h.layers = set.layers;
    h.width = set.width;
    h.height = set.height;
    h.mip_levels = set.mip_levels;
    h.height_patch_units = set.height_patch_units;
    h.texels = texels;
    h.content_hash = slice_content_hash(set);
    uint8_t bytes[kHeaderBytes];
    encode_header(h, bytes);
    bool ok = write_exact(f, bytes, kHeaderBytes) && write_exact(f, set.color.data(), set.color.size()) &&
              write_exact(f, set.normal.data(), set.normal.size());
    uint8_t chunk[4096];
    const uint64_t values = texels * 4;
    for (uint64_t i = 0; i < values && ok;) {
        const uint64_t n = std::min<uint64_t>(sizeof(chunk) / 2, values - i);
        for (uint64_t k = 0; k < n; ++k) {
            chunk[2 * k] = static_cast<uint8_t>(set.threshold[i + k]);
            chunk[2 * k + 1] = static_cast<uint8_t>(set.threshold[i + k] >> 8);
        }
        ok = write_exact(f, chunk, n * 2);
        i += n;
    }
    ok = (std::fflush(f) == 0) && ok;
    ok = (std::fclose(f) == 0) && ok;
    if (ok) ok = std::rename(temp, path) == 0;
    if (!ok) std::remove(temp);
    return ok;
}

} // namespace grass
