// The baked-slice cache through the API (grass_context_desc.cache_directory): the first
// context writes one file per slice set its fields need, a second context reads them back
// and draws the same picture.
#include "render_fixture.hpp"

#include <dirent.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

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

grass_host::Image render_with_cache(grass_backend backend, const std::string& dir) {
    grass_host::TargetDesc t;
    t.width = t.height = 96;
    std::string error;
    auto host = grass_host::Host::create(backend, t, &error);
    EXPECT_TRUE(host) << error;
    grass_host::Image image;
    if (!host) return image;
    grass_context_desc cd = grass_default_context_desc();
    cd.cache_directory = dir.c_str();
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

INSTANTIATE_TEST_SUITE_P(Backends, SliceCacheTest, ::testing::ValuesIn(enabled_backends()),
                         [](const auto& p) { return backend_name(p.param); });

} // namespace
} // namespace grass_test
