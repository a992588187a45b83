// grass-measure bench's reference cache (tools/measure/reference_cache.cpp): a reference
// stored is loaded back exactly; anything else under its name (a FIFO, a directory, a file
// cut short or grown) is a miss at once, never a blocked or endless read (issue 37).
#include "reference_cache.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using grass_measure::bench::CachedReference;
using grass_measure::bench::load_reference;
using grass_measure::bench::reference_hash;
using grass_measure::bench::store_reference;

std::string scratch_dir() {
    char name[] = "/tmp/grass-reference-cache-XXXXXX";
    const char* made = mkdtemp(name);
    EXPECT_NE(made, nullptr);
    return made ? made : "";
}

CachedReference small_reference() {
    CachedReference r;
    r.image.width = 3;
    r.image.height = 2;
    for (int i = 0; i < 3 * 2 * 4; ++i) r.image.rgba.push_back(static_cast<uint8_t>(i * 7));
    r.frame_ms = 12.5;
    r.render_s = 3.25;
    return r;
}

// load_reference in a child process that must end within `seconds`: true when it returned
// (with `loaded` its result), false when it blocked.
bool loads_in_time(const std::string& dir, const std::string& key, int seconds, bool* loaded) {
    const pid_t child = fork();
    if (child == 0) {
        alarm(static_cast<unsigned>(seconds));
        CachedReference r;
        _exit(load_reference(dir, key, &r) ? 10 : 11);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status)) return false;
    *loaded = WEXITSTATUS(status) == 10;
    return true;
}

TEST(ReferenceCache, AStoredReferenceLoadsBackExactly) {
    const std::string dir = scratch_dir();
    std::string error;
    ASSERT_TRUE(store_reference(dir, "key one", small_reference(), &error)) << error;
    CachedReference back;
    ASSERT_TRUE(load_reference(dir, "key one", &back));
    EXPECT_EQ(back.image.width, 3u);
    EXPECT_EQ(back.image.height, 2u);
    EXPECT_EQ(back.image.rgba, small_reference().image.rgba);
    EXPECT_DOUBLE_EQ(back.frame_ms, 12.5);
    EXPECT_FALSE(load_reference(dir, "key two", &back)) << "another key is a miss";
    std::filesystem::remove_all(dir);
}

TEST(ReferenceCache, AFileCutShortOrGrownIsAMiss) {
    const std::string dir = scratch_dir();
    std::string error;
    ASSERT_TRUE(store_reference(dir, "k", small_reference(), &error)) << error;
    const std::string path = dir + "/" + reference_hash("k") + ".ref";
    { std::ofstream(path, std::ios::binary | std::ios::app) << 'x'; }
    CachedReference back;
    EXPECT_FALSE(load_reference(dir, "k", &back)) << "one byte too many";
    ASSERT_EQ(truncate(path.c_str(), 20), 0);
    EXPECT_FALSE(load_reference(dir, "k", &back)) << "cut short";
    std::filesystem::remove_all(dir);
}

TEST(ReferenceCache, AFifoOrADirectoryUnderTheNameIsAMissAtOnce) {
    const std::string dir = scratch_dir();
    const std::string fifo = dir + "/" + reference_hash("fifo") + ".ref";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    bool loaded = true;
    ASSERT_TRUE(loads_in_time(dir, "fifo", 10, &loaded)) << "load_reference blocked on a FIFO";
    EXPECT_FALSE(loaded);
    ASSERT_EQ(mkdir((dir + "/" + reference_hash("dir") + ".ref").c_str(), 0700), 0);
    loaded = true;
    ASSERT_TRUE(loads_in_time(dir, "dir", 10, &loaded));
    EXPECT_FALSE(loaded);
    std::filesystem::remove_all(dir);
}

} // namespace
