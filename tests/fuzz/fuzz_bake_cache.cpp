// libFuzzer target: the bake-cache reader (api/src/bake/bake_cache.*). The input is the file
// a context finds in its cache directory. The first input byte says what the target fixes up
// before the reader sees it (a fuzzer cannot find a 64-bit hash by mutation): bit 0 writes
// the expected key into the header, bit 1 then recomputes the header's own hash, so that
// mutations reach the size, layer, mip and length checks and the allocation sized from the
// header. A file the reader accepts must describe a consistent slice set, and storing it
// again must write the same bytes.
//
// `fuzz_bake_cache --write-seeds DIR` writes valid cache files (small bakes of a few
// patches) as seeds for tests/fuzz/corpus/bake_cache.
#include "bake/bake_cache.hpp"
#include "bake/slice_baker.hpp"
#include "patch/patch_generator.hpp"
#include "patch/random.hpp"

#include <dirent.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr uint64_t kKey = 0x0123456789abcdefull;

const std::string& work_dir() {
    static const std::string dir = [] {
        char pattern[] = "/tmp/grass-fuzz-bake-XXXXXX";
        if (!mkdtemp(pattern)) std::abort();
        return std::string(pattern);
    }();
    return dir;
}

std::string cache_file(const std::string& dir, uint64_t key) {
    char name[64];
    std::snprintf(name, sizeof(name), "/grass-slices-%016llx.bin", static_cast<unsigned long long>(key));
    return dir + name;
}

bool write_file(const std::string& path, const uint8_t* data, size_t size) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = (size == 0 || std::fwrite(data, 1, size, f) == size) && std::fflush(f) == 0;
    return std::fclose(f) == 0 && ok;
}

std::vector<uint8_t> read_file(const std::string& path) {
    std::vector<uint8_t> bytes;
    if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
        uint8_t chunk[4096];
        size_t n;
        while ((n = std::fread(chunk, 1, sizeof(chunk), f)) > 0) bytes.insert(bytes.end(), chunk, chunk + n);
        std::fclose(f);
    }
    return bytes;
}

int write_seeds(const char* dir) {
    grass_allocator hooks{};
    grass::HostAllocator host(hooks);
    const uint32_t sizes[][3] = {{0, 4, 4}, {1, 8, 4}, {2, 4, 2}};
    int n = 0;
    for (const auto& s : sizes) {
        grass_patch_desc d = grass_default_patch_desc();
        d.blade_count = 16;
        grass::PatchData patch(&host);
        grass::generate_patch(d, &host, &patch);
        grass::SliceSet set(&host);
        grass::bake_slices(patch, s[0], s[1], s[2], &host, &set);
        const std::string tmp = std::string(dir);
        if (!grass::store_baked(dir, kKey, set)) return 1;
        char name[64];
        std::snprintf(name, sizeof(name), "/seed-%d", n++);
        // The target's control byte: 3 = fix the key and the header hash.
        std::vector<uint8_t> bytes{3};
        const std::vector<uint8_t> file = read_file(cache_file(dir, kKey));
        bytes.insert(bytes.end(), file.begin(), file.end());
        if (!write_file(tmp + name, bytes.data(), bytes.size())) return 1;
        std::remove(cache_file(dir, kKey).c_str());
    }
    return 0;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    for (int i = 1; i + 1 < *argc; ++i) {
        if (std::strcmp((*argv)[i], "--write-seeds") == 0) std::exit(write_seeds((*argv)[i + 1]));
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const uint8_t control = data[0];
    std::vector<uint8_t> file(data + 1, data + size);
    if ((control & 1) && file.size() >= 24) {
        for (int k = 0; k < 8; ++k) file[16 + k] = static_cast<uint8_t>(kKey >> (8 * k));
    }
    if ((control & 2) && file.size() >= 72) {
        const uint64_t h = grass::fnv1a64(file.data(), 64, grass::kFnvOffset);
        for (int k = 0; k < 8; ++k) file[64 + k] = static_cast<uint8_t>(h >> (8 * k));
    }
    const std::string& dir = work_dir();
    const std::string path = cache_file(dir, kKey);
    if (!write_file(path, file.data(), file.size())) std::abort();

    grass_allocator hooks{};
    grass::HostAllocator host(hooks);
    {
        grass::SliceSet set(&host);
        if (grass::load_baked(dir.c_str(), kKey, &host, &set) == grass::CacheMiss::none) {
            // What the reader accepts is a whole slice set...
            const uint64_t texels = set.offset(set.layers, 0);
            if (set.color.size() != texels * 4 || set.normal.size() != texels * 4 ||
                set.threshold.size() != texels * 4 || set.layers == 0 || set.width == 0 || set.height == 0) {
                std::abort();
            }
            // ... that the writer stores as the same bytes.
            std::remove(path.c_str());
            if (!grass::store_baked(dir.c_str(), kKey, set)) std::abort();
            if (read_file(path) != file) std::abort();
        } else if (!set.color.empty() || set.layers != 0) {
            std::abort(); // a refused file leaves the set empty
        }
        // Another key never reads this file.
        grass::SliceSet other(&host);
        if (grass::load_baked(dir.c_str(), kKey + 1, &host, &other) != grass::CacheMiss::missing) std::abort();
    }
    std::remove(path.c_str());
    if (host.allocations() != 0) std::abort();
    return 0;
}
