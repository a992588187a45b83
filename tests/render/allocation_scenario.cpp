#include "allocation_scenario.hpp"

#include <stdlib.h>

#include <filesystem>
#include <vector>

namespace grass_test {
namespace {

// The bake cache every run of the process shares (removed at exit): the first run bakes the
// volume and image slices on the CPU, the others read them back. The bake allocates no GPU
// memory, so the runs make the same GPU allocations either way; it was most of grass's own
// work in each run (13% of the Vulkan tests' CPU time in the plain build, 7-10% under ASan:
// docs/records/testing.md).
struct ScenarioBakeCache {
    std::string path;
    ScenarioBakeCache() {
        std::string pattern = (std::filesystem::temp_directory_path() / "grass-allocation-scenario-XXXXXX").string();
        if (mkdtemp(pattern.data())) path = pattern;
    }
    ~ScenarioBakeCache() {
        std::error_code ignored;
        if (!path.empty()) std::filesystem::remove_all(path, ignored);
    }
};

const char* scenario_bake_cache() {
    static ScenarioBakeCache cache;
    return cache.path.empty() ? nullptr : cache.path.c_str();
}

} // namespace

grass_context_desc logged_desc(FailureLog* log) {
    grass_context_desc cd = grass_default_context_desc();
    cd.log_user_data = log;
    cd.log_fn = [](void* user, grass_log_level level, grass_message_id id, const char* message) {
        auto* l = static_cast<FailureLog*>(user);
        if (level == GRASS_LOG_ERROR) l->last_error = id;
        if (level != GRASS_LOG_INFO) l->text += std::string(message) + "\n";
    };
    return cd;
}

ScenarioResult run_allocation_scenario(grass_host::Host& host, const AllocationProbe& probe, int fail_at,
                                       bool responsive) {
    ScenarioResult out;
    const int injected_before = probe.failures_injected();
    const int64_t made_before = probe.allocations_made();
    out.log = std::make_unique<FailureLog>();
    FailureLog& log = *out.log;
    std::string error;
    auto call = [&](const char* what, const std::function<grass_result()>& f) {
        const bool failed_before = probe.failures_injected() > injected_before;
        grass_result r = f();
        if (r == GRASS_SUCCESS) return true;
        out.failed_call = what;
        if (probe.after_failure) probe.after_failure(out.context, what);
        EXPECT_EQ(r, GRASS_ERROR_OUT_OF_MEMORY) << what << " (allocation " << fail_at << "): " << log.text << error;
        EXPECT_FALSE(failed_before) << what << " failed after the injected failure: " << log.text << error;
        EXPECT_TRUE(probe.failures_injected() > injected_before) << what << " failed without an injected failure";
        EXPECT_EQ(log.last_error, GRASS_MSG_OUT_OF_MEMORY) << log.text;
        r = f();
        EXPECT_EQ(r, GRASS_SUCCESS) << what << " repeated: " << log.text << error;
        return r == GRASS_SUCCESS;
    };
    grass_context_desc cd = logged_desc(&log);
    cd.cache_directory = scenario_bake_cache();
    if (!call(probe.create_function, [&] { return host.create_context(cd, &out.context); })) return out;
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 128;
    grass_patch_id patch{};
    if (!call("grass_create_patch", [&] { return grass_create_patch(out.context, &pd, &patch); })) return out;
    std::vector<uint8_t> texels(16 * 16, 200);
    grass_map_desc md = grass_default_map_desc();
    md.pixels = texels.data();
    md.width = md.height = 16;
    grass_map_id density{};
    if (!call("grass_create_map", [&] { return grass_create_map(out.context, &md, &density); })) return out;
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 64;
    fd.maps.density = density;
    grass_field_id field{};
    if (!call("grass_create_field", [&] { return grass_create_field(out.context, &fd, &field); })) return out;
    if (responsive) {
        grass_wind_desc wind = grass_default_wind_desc();
        wind.speed = 4.0f;
        EXPECT_EQ(grass_set_wind(out.context, &wind), GRASS_SUCCESS) << log.text;
        grass_collider ball{};
        ball.radius = 0.4f;
        ball.center[0] = 8.0;
        ball.center[1] = 0.2;
        ball.center[2] = 3.0;
        EXPECT_EQ(grass_set_colliders(out.context, &ball, 1), GRASS_SUCCESS) << log.text;
    }
    out.setup_allocations = static_cast<int>(probe.allocations_made() - made_before);
    const double eye[3] = {8.0, 2.0, -1.0}, look[3] = {8.0, 0.0, 10.0};
    const grass_view_desc v = grass_host::make_view(host, eye, look, 50.0f, 0.05f, 200.0f);
    grass_host::Image image;
    for (int frame = 0; frame < 2; ++frame) {
        if (!call("a frame", [&] { return host.render(out.context, v, nullptr, &image, &error); })) return out;
    }
    expect_grass(image, host.target(), 0.2, "the last frame");
    if (fail_at > 0) {
        EXPECT_EQ(probe.failures_injected(), injected_before + 1) << "allocation " << fail_at;
    }
    out.allocations = static_cast<int>(probe.allocations_made() - made_before);
    return out;
}

} // namespace grass_test
