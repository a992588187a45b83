// The soak: a long run of frames the way a game drives grass. A camera circles a field
// (one lap every --period frames), a design map is painted every frame, a second field is
// created every 100 frames and destroyed 50 frames later. At the same point of every lap after the first,
// everything grass holds must be what it held at the end of the first lap: host memory and
// allocations (grass_get_memory_stats), GPU memory, the process's resident memory (within
// --rss-slack-kb), GL object names / Vulkan objects; and the GL debug output (KHR_debug) or
// the Vulkan validation layers (with synchronization validation) stay silent.
//
//   grass_soak --backend none|gl|vk --frames 10000 --period 1000
// Prints one line per lap; exits 1 on the first broken promise. ctest runs a short form.
#include "gl_names.hpp"
#include "headless_host.hpp"
#if GRASS_HOST_HAS_VULKAN
#    include "vk_intercept.hpp"
#endif

#include <grass/grass.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Options {
    grass_backend backend = GRASS_BACKEND_NONE;
    int frames = 400;
    int period = 200;
    long rss_slack_kb = 4096;
};

bool parse(int argc, char** argv, Options* o) {
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--backend") {
            if (value == "none")
                o->backend = GRASS_BACKEND_NONE;
            else if (value == "gl")
                o->backend = GRASS_BACKEND_GL;
            else if (value == "vk")
                o->backend = GRASS_BACKEND_VULKAN;
            else
                return false;
        } else if (key == "--frames") {
            o->frames = std::atoi(value.c_str());
        } else if (key == "--period") {
            o->period = std::atoi(value.c_str());
        } else if (key == "--rss-slack-kb") {
            o->rss_slack_kb = std::atol(value.c_str());
        } else {
            return false;
        }
    }
    return o->frames > 0 && o->period >= 100 && o->period % 100 == 0 && o->frames % o->period == 0;
}

long resident_kb() {
    long pages = 0, resident = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return resident * 4;
}

struct Snapshot {
    grass_memory_stats memory{};
    long rss_kb = 0;
    long gl_names = 0;
    long vk_objects = 0; // Vulkan objects grass made and has not destroyed
};

} // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parse(argc, argv, &o)) {
        std::fprintf(stderr, "usage: grass_soak --backend none|gl|vk --frames N --period P (P a multiple of 100, N of "
                             "P) [--rss-slack-kb K]\n");
        return 2;
    }
    // Vulkan: the validation layer's synchronization validation on, besides the defaults.
    setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 0);
    std::unique_ptr<grass_host::Host> host;
    grass_context* ctx = nullptr;
    const grass_context_desc cd = grass_default_context_desc();
    if (o.backend != GRASS_BACKEND_NONE) {
        grass_host::TargetDesc t;
        t.width = t.height = 64; // small: llvmpipe and lavapipe draw every frame
        t.ground = true;
#if GRASS_HOST_HAS_VULKAN
        t.vk_get_instance_proc_addr = grass_test::vk_intercept::get_instance_proc_addr(); // counts grass's objects
#endif
        std::string error;
        host = grass_host::Host::create(o.backend, t, &error);
        if (!host) {
            std::fprintf(stderr, "no host: %s\n", error.c_str());
            return 1;
        }
        if (host->create_context(cd, &ctx) != GRASS_SUCCESS) return 1;
    } else if (grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) != GRASS_SUCCESS) {
        return 1;
    }
    auto fail = [&](const char* what) {
        std::fprintf(stderr, "soak: %s: %s\n", what, grass_get_last_error(ctx));
        grass_destroy_context(ctx);
        return 1;
    };

    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 128;
    grass_patch_id patch{};
    if (grass_create_patch(ctx, &pd, &patch) != GRASS_SUCCESS) return fail("grass_create_patch");
    std::vector<uint8_t> texels(64 * 64, 220);
    grass_map_desc md = grass_default_map_desc();
    md.pixels = texels.data();
    md.width = md.height = 64;
    grass_map_id density{};
    if (grass_create_map(ctx, &md, &density) != GRASS_SUCCESS) return fail("grass_create_map");
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 96;
    fd.maps.density = density;
    grass_field_id field{}, visitor{};
    if (grass_create_field(ctx, &fd, &field) != GRASS_SUCCESS) return fail("grass_create_field");
    grass_field_desc vd = fd; // the field that comes and goes, beside the first
    vd.cells_x = vd.cells_z = 16;
    vd.base_transform[12] = 24.0;

    const double centre = 0.5 * fd.cells_x * fd.cell_size;
    Snapshot first;
    for (int frame = 0; frame < o.frames; ++frame) {
        // Paint a stripe of the density map (a mower's path).
        uint8_t stripe[16];
        for (int k = 0; k < 16; ++k) stripe[k] = static_cast<uint8_t>((frame * 7 + k * 16) & 0xff);
        grass_map_desc region = grass_default_map_desc();
        region.pixels = stripe;
        region.width = 16;
        region.height = 1;
        if (grass_update_map(ctx, density, static_cast<uint32_t>((frame * 3) % 48), static_cast<uint32_t>(frame % 64),
                             &region) != GRASS_SUCCESS)
            return fail("grass_update_map");
        // The visitor field is made every 100 frames and destroyed 50 frames later.
        if (frame % 100 == 0 && grass_create_field(ctx, &vd, &visitor) != GRASS_SUCCESS) {
            return fail("grass_create_field");
        }
        if (frame % 100 == 50 && grass_destroy_field(ctx, visitor) != GRASS_SUCCESS) return fail("grass_destroy_field");
        const double angle = 6.283185307179586 * (frame % o.period) / o.period;
        const double eye[3] = {centre + 9.0 * std::cos(angle), 1.8, centre + 9.0 * std::sin(angle)};
        const double look[3] = {centre, 0.0, centre};
        grass_result r;
        if (host) {
            const grass_view_desc v = grass_host::make_view(*host, eye, look, 55.0f);
            grass_host::Image image;
            std::string error;
            r = host->render(ctx, v, nullptr, &image, &error);
            if (r != GRASS_SUCCESS) std::fprintf(stderr, "%s\n", error.c_str());
        } else {
            grass_view_desc v = grass_default_view_desc();
            std::memcpy(v.camera_position, eye, sizeof(eye));
            const double f[3] = {look[0] - eye[0], look[1] - eye[1], look[2] - eye[2]};
            const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
            const double fz[3] = {f[0] / fl, f[1] / fl, f[2] / fl};
            const double rx[3] = {-fz[2], 0.0, fz[0]}; // f x up, unnormalised
            const double rl = std::sqrt(rx[0] * rx[0] + rx[2] * rx[2]);
            const double rn[3] = {rx[0] / rl, 0.0, rx[2] / rl};
            const double u[3] = {rn[1] * fz[2] - rn[2] * fz[1], rn[2] * fz[0] - rn[0] * fz[2],
                                 rn[0] * fz[1] - rn[1] * fz[0]};
            for (int c = 0; c < 3; ++c) {
                v.view[4 * c + 0] = static_cast<float>(rn[c]);
                v.view[4 * c + 1] = static_cast<float>(u[c]);
                v.view[4 * c + 2] = static_cast<float>(-fz[c]);
            }
            v.view[15] = 1.0f;
            const float proj[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.0002f, -1, 0, 0, -0.20002f, 0};
            std::memcpy(v.projection, proj, sizeof(proj));
            v.viewport[2] = v.viewport[3] = 64;
            r = grass_begin_frame(ctx, &v);
            if (r == GRASS_SUCCESS) r = grass_end_frame(ctx);
        }
        if (r != GRASS_SUCCESS) return fail("a frame");

        if ((frame + 1) % o.period == 0) {
            Snapshot now;
            grass_get_memory_stats(ctx, &now.memory);
            now.rss_kb = resident_kb();
            if (host && o.backend == GRASS_BACKEND_GL) now.gl_names = grass_test::gl_live_names(*host);
#if GRASS_HOST_HAS_VULKAN
            if (o.backend == GRASS_BACKEND_VULKAN)
                now.vk_objects = static_cast<long>(grass_test::vk_intercept::live().total());
#endif
            const uint32_t messages = host ? host->validation_messages() : 0;
            std::printf("frame %6d: host %llu bytes in %llu allocations (peak %llu), gpu %llu bytes, rss %ld kB, GL "
                        "names %ld, Vulkan objects %ld, validation messages %u\n",
                        frame + 1, (unsigned long long)now.memory.host_bytes,
                        (unsigned long long)now.memory.host_allocations, (unsigned long long)now.memory.host_bytes_peak,
                        (unsigned long long)now.memory.gpu_bytes, now.rss_kb, now.gl_names, now.vk_objects, messages);
            std::fflush(stdout);
            if (messages != 0) {
                std::fprintf(stderr, "soak: the %s reported:\n%s\n",
                             o.backend == GRASS_BACKEND_GL ? "GL debug output" : "Vulkan validation layers",
                             host->validation_log().c_str());
                return fail("validation");
            }
            if (frame + 1 == o.period) {
                first = now;
            } else {
                const bool flat = now.memory.host_bytes == first.memory.host_bytes &&
                                  now.memory.host_allocations == first.memory.host_allocations &&
                                  now.memory.host_bytes_peak == first.memory.host_bytes_peak &&
                                  now.memory.gpu_bytes == first.memory.gpu_bytes && now.gl_names == first.gl_names &&
                                  now.vk_objects == first.vk_objects && now.rss_kb - first.rss_kb <= o.rss_slack_kb;
                if (!flat) {
                    std::fprintf(stderr, "soak: not flat since frame %d (rss slack %ld kB)\n", o.period,
                                 o.rss_slack_kb);
                    return fail("memory");
                }
            }
        }
    }
    grass_destroy_context(ctx);
    if (host && host->validation_messages() != 0) {
        std::fprintf(stderr, "soak: after destroy: %s\n", host->validation_log().c_str());
        return 1;
    }
    std::printf("soak: %d frames, flat\n", o.frames);
    return 0;
}
