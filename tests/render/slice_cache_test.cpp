// The baked-slice cache through the API (grass_context_desc.cache_directory): the first
// context writes one file per slice set its fields need, a second context reads them back
// and draws the same picture.
#include "render_fixture.hpp"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace grass_test {
namespace {

int count_cache_files(const std::string& dir) {
    int n = 0;
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d)) n += std::string(e->d_name).rfind("grass-slices-", 0) == 0;
        closedir(d);
    }
    return n;
}

struct CacheWarnings {
    int count = 0;
    std::string text;
};

grass_host::Image render_with_cache(grass_backend backend, const std::string& dir, CacheWarnings* warnings = nullptr) {
    grass_host::TargetDesc t;
    t.width = t.height = 96;
    std::string error;
    auto host = grass_host::Host::create(backend, t, &error);
    EXPECT_TRUE(host) << error;
    grass_host::Image image;
    if (!host) return image;
    grass_context_desc cd = grass_default_context_desc();
    cd.cache_directory = dir.c_str();
    if (warnings) {
        cd.log_user_data = warnings;
        cd.log_fn = [](void* user, grass_log_level level, grass_message_id id, const char* message) {
            auto* w = static_cast<CacheWarnings*>(user);
            if (level == GRASS_LOG_WARNING && id == GRASS_MSG_BAKE_CACHE) {
                w->count += 1;
                w->text += std::string(message) + "\n";
            }
        };
    }
    grass_context* ctx = nullptr;
    EXPECT_EQ(host->create_context(cd, &ctx), GRASS_SUCCESS);
    const grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    EXPECT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS);
    grass_field_desc fd = grass_default_field_desc(); // Lemme's tiers: volume 8, 2, 1 and image
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 64;
    grass_field_id field{};
    EXPECT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS) << grass_get_last_error(ctx);
    const double eye[3] = {8.0, 2.0, -1.0}, look[3] = {8.0, 0.0, 10.0};
    const grass_view_desc v = grass_host::make_view(*host, eye, look, 50.0f, 0.05f, 200.0f);
    EXPECT_EQ(host->render(ctx, v, nullptr, &image, &error), GRASS_SUCCESS) << error;
    grass_destroy_context(ctx);
    EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
    return image;
}

class SliceCacheTest : public ::testing::TestWithParam<grass_backend> {};

TEST_P(SliceCacheTest, AContextWritesTheCacheAndTheNextOneReadsItBack) {
    char pattern[] = "/tmp/grass-cache-test-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    const std::string dir = pattern;
    const auto first = render_with_cache(GetParam(), dir);
    EXPECT_EQ(count_cache_files(dir), 4) << "volume 8, 2, 1 slices and the horizontal slice";
    const auto second = render_with_cache(GetParam(), dir);
    EXPECT_EQ(count_cache_files(dir), 4);
    EXPECT_EQ(mean_difference(first, second), 0.0);
    EXPECT_EQ(std::system(("rm -rf " + dir).c_str()), 0);
}

std::vector<std::string> cache_files(const std::string& dir) {
    std::vector<std::string> files;
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d)) {
            if (std::string(e->d_name).rfind("grass-slices-", 0) == 0) files.push_back(dir + "/" + e->d_name);
        }
        closedir(d);
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<char> file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void put_file(const std::string& path, const std::vector<char>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A fresh cache directory (*dir) and the first picture drawn with it, which must show grass:
// comparisons of all-sky pictures prove nothing.
grass_host::Image first_cached_picture(grass_backend backend, std::string* dir) {
    char pattern[] = "/tmp/grass-cache-test-XXXXXX";
    EXPECT_NE(mkdtemp(pattern), nullptr);
    *dir = pattern;
    const auto image = render_with_cache(backend, *dir);
    grass_host::TargetDesc t;
    t.width = t.height = 96;
    expect_grass(image, t, 0.1, "the first picture");
    return image;
}

// Damaged files (truncated, empty, a flipped byte, another patch's file under the name) are
// baked again with one warning each, naming the file and the damage, and rewritten whole:
// the picture does not change and the next context reads every file without a word.
TEST_P(SliceCacheTest, DamagedFilesAreBakedAgainWithAWarningAndRewritten) {
    std::string dir;
    const auto first = first_cached_picture(GetParam(), &dir);
    const std::vector<std::string> files = cache_files(dir);
    ASSERT_EQ(files.size(), 4u);
    std::vector<std::vector<char>> good;
    for (const auto& f : files) good.push_back(file_bytes(f));
    std::vector<char> bytes = good[0];
    bytes.resize(bytes.size() / 2);
    put_file(files[0], bytes); // truncated
    put_file(files[1], {});    // zero length
    bytes = good[2];
    bytes[bytes.size() / 2] ^= 0x20; // a flipped bit in the texels
    put_file(files[2], bytes);
    put_file(files[3], good[0]); // another slice set's file under this name
    CacheWarnings w;
    const auto second = render_with_cache(GetParam(), dir, &w);
    EXPECT_EQ(w.count, 4) << w.text;
    for (const char* phrase : {"is truncated", "holds slices that do not match", "holds the slices of another patch"}) {
        EXPECT_NE(w.text.find(phrase), std::string::npos) << phrase << " in\n" << w.text;
    }
    EXPECT_NE(w.text.find(files[1]), std::string::npos) << "the warning names the file:\n" << w.text;
    EXPECT_EQ(mean_difference(first, second), 0.0);
    for (size_t k = 0; k < files.size(); ++k) EXPECT_EQ(file_bytes(files[k]), good[k]) << files[k] << " rewritten";
    CacheWarnings again;
    render_with_cache(GetParam(), dir, &again);
    EXPECT_EQ(again.count, 0) << again.text;
    EXPECT_EQ(std::system(("rm -rf " + dir).c_str()), 0);
}

// A cache directory that cannot be written (missing, or a file) costs one warning per
// context, not one per slice set, and the picture is the same as without a cache.
TEST_P(SliceCacheTest, AnUnwritableDirectoryWarnsOnceAndDrawsTheSame) {
    std::string dir;
    const auto cached = first_cached_picture(GetParam(), &dir);
    put_file(dir + "/a-file", {'x'});
    for (const std::string& bad : {dir + "/missing", dir + "/a-file"}) {
        CacheWarnings w;
        const auto image = render_with_cache(GetParam(), bad, &w);
        EXPECT_EQ(w.count, 1) << bad << ":\n" << w.text;
        EXPECT_NE(w.text.find("cannot write to the cache directory " + bad), std::string::npos) << w.text;
        EXPECT_EQ(mean_difference(cached, image), 0.0) << bad;
    }
    EXPECT_EQ(std::system(("rm -rf " + dir).c_str()), 0);
}

// A directory or a FIFO under a cache file's name (a FIFO once blocked grass_create_field
// for ever): one warning each, naming the path; the field is made, draws the same picture,
// and the names are left alone.
TEST_P(SliceCacheTest, ADirectoryOrAFifoUnderAFileNameWarnsOnceAndDrawsTheSame) {
    std::string dir;
    const auto first = first_cached_picture(GetParam(), &dir);
    const std::vector<std::string> files = cache_files(dir);
    ASSERT_EQ(files.size(), 4u);
    ASSERT_EQ(std::remove(files[0].c_str()), 0);
    ASSERT_EQ(mkdir(files[0].c_str(), 0700), 0);
    ASSERT_EQ(std::remove(files[1].c_str()), 0);
    ASSERT_EQ(mkfifo(files[1].c_str(), 0600), 0);
    CacheWarnings w;
    const auto second = render_with_cache(GetParam(), dir, &w);
    EXPECT_EQ(w.count, 2) << w.text;
    for (int k = 0; k < 2; ++k) {
        EXPECT_NE(w.text.find(files[k] + " is not a regular file"), std::string::npos) << files[k] << "\n" << w.text;
    }
    EXPECT_EQ(mean_difference(first, second), 0.0);
    struct stat st;
    ASSERT_EQ(lstat(files[0].c_str(), &st), 0);
    EXPECT_TRUE(S_ISDIR(st.st_mode));
    ASSERT_EQ(lstat(files[1].c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
    EXPECT_EQ(std::system(("rm -rf " + dir).c_str()), 0);
}

INSTANTIATE_TEST_SUITE_P(Backends, SliceCacheTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
