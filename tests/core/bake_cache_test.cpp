// The bake cache shared by processes: two processes that bake the same patch into one cache
// directory at once never leave a torn file (each writes a temporary file and renames it),
// and a reader running beside them sees either no file or a whole one. (The reasons a file
// is rejected are in slice_baking_test.cpp; the warnings a context logs for them, through the
// API, in tests/render/slice_cache_test.cpp.)
#include "bake/bake_cache.hpp"
#include "bake/slice_baker.hpp"
#include "patch/patch_generator.hpp"

#include <gtest/gtest.h>

#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <cstdlib>
#include <string>

namespace {

using grass::CacheMiss;

int count_files(const std::string& dir, const char* prefix) {
    int n = 0;
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d)) n += std::string(e->d_name).rfind(prefix, 0) == 0;
        closedir(d);
    }
    return n;
}

TEST(BakeCacheProcesses, TwoWritersOfOneKeyNeverLeaveATornFile) {
    char pattern[] = "/tmp/grass-bake-race-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    const std::string dir = pattern;
    grass_allocator hooks{};
    grass::HostAllocator host(hooks);
    grass_patch_desc d = grass_default_patch_desc();
    d.blade_count = 64;
    grass::PatchData patch(&host);
    grass::generate_patch(d, &host, &patch);
    grass::SliceSet set(&host);
    grass::bake_slices(patch, 2, 64, 32, &host, &set); // about 190 KB: many write calls each
    const uint64_t key = grass::bake_key(d, 2, 64, 32);

    constexpr int kWrites = 40;
    pid_t writers[2];
    for (pid_t& pid : writers) {
        pid = fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            bool ok = true;
            for (int k = 0; k < kWrites; ++k) ok = grass::store_baked(dir.c_str(), key, set) && ok;
            _exit(ok ? 0 : 1);
        }
    }
    // Read while they write: every read finds no file yet, or a whole one.
    int whole = 0, reads = 0;
    int status[2] = {0, 0};
    bool done[2] = {false, false};
    for (bool running = true; running; ++reads) {
        grass::SliceSet read(&host);
        const CacheMiss miss = grass::load_baked(dir.c_str(), key, &host, &read);
        ASSERT_TRUE(miss == CacheMiss::none || miss == CacheMiss::missing)
            << "read " << reads << ": the file " << grass::cache_miss_phrase(miss);
        if (miss == CacheMiss::none) {
            whole += 1;
            ASSERT_EQ(read.content_hash, set.content_hash);
        }
        for (int w = 0; w < 2; ++w) done[w] = done[w] || waitpid(writers[w], &status[w], WNOHANG) == writers[w];
        running = !done[0] || !done[1];
    }
    for (int w = 0; w < 2; ++w) {
        EXPECT_TRUE(WIFEXITED(status[w]) && WEXITSTATUS(status[w]) == 0) << "writer " << w << " failed to store";
    }
    std::printf("[ race     ] %d reads beside 2 x %d writes: %d found the whole file, the rest none yet\n", reads,
                kWrites, whole);
    grass::SliceSet last(&host);
    EXPECT_EQ(grass::load_baked(dir.c_str(), key, &host, &last), CacheMiss::none);
    EXPECT_EQ(count_files(dir, "grass-slices-"), 1) << "no temporary file is left behind";
    EXPECT_EQ(std::system(("rm -rf " + dir).c_str()), 0);
}

// A FIFO or a directory under a cache file's name: the load returns at once (a FIFO once
// blocked fopen forever, in grass_create_field), says the name is not a regular file, and
// leaves it alone. Runs in a child process, so that a hang fails the test instead of
// stopping the suite.
TEST(BakeCacheFiles, AFifoOrADirectoryUnderTheNameIsRefusedAtOnce) {
    char pattern[] = "/tmp/grass-bake-special-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    const std::string dir = pattern;
    const uint64_t key = 0x0123456789abcdefull;
    const std::string name = dir + "/grass-slices-0123456789abcdef.bin";
    for (const char* kind : {"fifo", "directory"}) {
        SCOPED_TRACE(kind);
        ASSERT_EQ(std::string(kind) == "fifo" ? mkfifo(name.c_str(), 0600) : mkdir(name.c_str(), 0700), 0);
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            grass_allocator hooks{};
            grass::HostAllocator host(hooks);
            grass::SliceSet set(&host);
            const CacheMiss miss = grass::load_baked(dir.c_str(), key, &host, &set);
            const std::string phrase = grass::cache_miss_phrase(miss);
            _exit(phrase.find("not a regular file") != std::string::npos ? 0 : 1);
        }
        int status = 0;
        bool exited = false;
        for (int wait_ms = 0; wait_ms < 10000 && !exited; wait_ms += 10) {
            exited = waitpid(child, &status, WNOHANG) == child;
            if (!exited) usleep(10000);
        }
        if (!exited) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
        }
        EXPECT_TRUE(exited) << "the load of a " << kind << " did not return within 10 s";
        EXPECT_TRUE(exited && WIFEXITED(status) && WEXITSTATUS(status) == 0)
            << "the load of a " << kind << " did not say the name is not a regular file";
        struct stat st;
        ASSERT_EQ(lstat(name.c_str(), &st), 0) << "it is left alone";
        EXPECT_EQ(std::string(kind) == "fifo" ? S_ISFIFO(st.st_mode) : S_ISDIR(st.st_mode), true);
        ASSERT_EQ(std::string(kind) == "fifo" ? unlink(name.c_str()) : rmdir(name.c_str()), 0);
    }
    EXPECT_EQ(std::system(("rm -rf " + dir).c_str()), 0);
}

} // namespace
