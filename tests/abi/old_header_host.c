/*
 * A host built against the frozen grass.h 0.3 (tests/abi/grass_0_3.h and its GL and Vulkan
 * companions) and nothing else, run against the current libgrass.so: grass.h's ABI promise.
 * Every getter that fills a struct writes into a heap block of exactly the 0.3 struct's size
 * (AddressSanitizer reports a byte written past it) and into a stack copy followed by a
 * canary. Uses the 0.3 names of functions renamed since. Prints what failed; exit status 0
 * when all is well.
 */
#ifdef GRASS_ABI_TEST_EGL
#    define _GNU_SOURCE 1 /* keep_drivers_resident.h: dl_iterate_phdr, RTLD_NODELETE */
#endif
#include "grass_gl_0_3.h"
#include "grass_vk_0_3.h"

#ifdef GRASS_GRASS_H
#    error "the current grass.h is on this host's include path; it must see only the frozen 0.3 headers"
#endif

#include "host_checks.h"

#include <math.h>
#include <stdlib.h>

/* The 0.3 layouts, as the library records them (api/src/foundation/abi_sizes.cpp). */
typedef char frame_stats_is_152_bytes[sizeof(grass_frame_stats) == 152 ? 1 : -1];
typedef char memory_stats_is_24_bytes[sizeof(grass_memory_stats) == 24 ? 1 : -1];
typedef char patch_info_is_48_bytes[sizeof(grass_patch_info) == 48 ? 1 : -1];

#define CHECK_OK(call)                                                                                      \
    do {                                                                                                    \
        grass_result r_ = (call);                                                                           \
        if (r_ != GRASS_SUCCESS) {                                                                          \
            fprintf(stderr, "%s:%d: %s returned %s\n", __FILE__, __LINE__, #call, grass_result_string(r_)); \
            failures += 1;                                                                                  \
        }                                                                                                   \
    } while (0)

enum { kCanaryBytes = 64, kCanary = 0xc5 };

static void log_message(void* user_data, grass_log_level level, grass_message_id id, const char* message) {
    (void)user_data;
    if (level == GRASS_LOG_ERROR) fprintf(stderr, "grass (message %d): %s\n", (int)id, message);
}

static int canary_intact(const unsigned char* canary) {
    int i;
    for (i = 0; i < kCanaryBytes; ++i) {
        if (canary[i] != kCanary) return 0;
    }
    return 1;
}

/* A camera 2 m before the field's z = 0 edge, 1.7 m up, looking along +z and a little down. */
static grass_view_desc make_view(void) {
    grass_view_desc v = grass_default_view_desc();
    const float pitch = 0.3f, t = 1.0f / (float)tan(0.5236), n = 0.05f, f = 500.0f;
    int k;
    v.camera_position[0] = 4.0;
    v.camera_position[1] = 1.7;
    v.camera_position[2] = -2.0;
    for (k = 0; k < 16; ++k) v.view[k] = 0.0f;
    /* Eye axes in world space: right = -x, up and back = -forward, forward = (0, -sin, cos). */
    v.view[0] = -1.0f;
    v.view[5] = (float)cos(pitch);
    v.view[9] = (float)sin(pitch);
    v.view[6] = (float)sin(pitch);
    v.view[10] = -(float)cos(pitch);
    v.view[15] = 1.0f;
    for (k = 0; k < 16; ++k) v.projection[k] = 0.0f;
    v.projection[0] = t;
    v.projection[5] = t;
    v.projection[10] = (f + n) / (n - f);
    v.projection[11] = -1.0f;
    v.projection[14] = 2.0f * f * n / (n - f);
    v.viewport[2] = 256;
    v.viewport[3] = 256;
    return v;
}

static void check_getters(grass_context* ctx, grass_patch_id patch, uint32_t blade_count, int gpu) {
    grass_frame_stats* fs = (grass_frame_stats*)malloc(sizeof(grass_frame_stats));
    grass_memory_stats* ms = (grass_memory_stats*)malloc(sizeof(grass_memory_stats));
    grass_patch_info* info = (grass_patch_info*)malloc(sizeof(grass_patch_info));
    double* ms_per_kind = (double*)malloc(sizeof(double) * GRASS_TIER_KIND_COUNT);
    grass_bool* available = (grass_bool*)malloc(sizeof(grass_bool));
    struct {
        grass_frame_stats stats;
        unsigned char canary[kCanaryBytes];
    } frame_copy;
    struct {
        grass_memory_stats stats;
        unsigned char canary[kCanaryBytes];
    } memory_copy;
    struct {
        grass_patch_info info;
        unsigned char canary[kCanaryBytes];
    } info_copy;
    struct {
        double ms[GRASS_TIER_KIND_COUNT];
        unsigned char canary[kCanaryBytes];
    } gpu_copy;
    uint64_t instances = 0;
    int k;
    if (!fs || !ms || !info || !ms_per_kind || !available) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }

    CHECK_OK(grass_get_frame_stats(ctx, fs));
    for (k = 0; k < GRASS_TIER_KIND_COUNT; ++k) instances += fs->instances[k];
    CHECK(fs->fields_drawn == 1);
    CHECK(fs->cells_drawn > 0);
    CHECK(instances > 0);
    CHECK(fs->blades_submitted == fs->cells_drawn * blade_count);
    CHECK(fs->nodes_visited > 0);
    CHECK(fs->plan_ms >= 0.0);
    memset(&frame_copy, kCanary, sizeof(frame_copy));
    CHECK_OK(grass_get_frame_stats(ctx, &frame_copy.stats));
    CHECK(canary_intact(frame_copy.canary));
    CHECK(frame_copy.stats.cells_drawn == fs->cells_drawn);

    CHECK_OK(grass_get_memory_stats(ctx, ms));
    CHECK(ms->host_bytes > 0);
    CHECK(ms->host_allocations > 0);
    CHECK(gpu ? ms->gpu_bytes > 0 : ms->gpu_bytes == 0);
    memset(&memory_copy, kCanary, sizeof(memory_copy));
    CHECK_OK(grass_get_memory_stats(ctx, &memory_copy.stats));
    CHECK(canary_intact(memory_copy.canary));
    CHECK(memory_copy.stats.host_allocations == ms->host_allocations);

    CHECK_OK(grass_get_patch_info(ctx, patch, info));
    CHECK(info->blade_count == blade_count);
    CHECK(info->vertex_count > 0);
    CHECK(info->triangle_count > 0);
    CHECK(info->bounds_max[1] > info->bounds_min[1]);
    CHECK(info->content_hash != 0);
    memset(&info_copy, kCanary, sizeof(info_copy));
    CHECK_OK(grass_get_patch_info(ctx, patch, &info_copy.info));
    CHECK(canary_intact(info_copy.canary));
    CHECK(info_copy.info.content_hash == info->content_hash);

    CHECK_OK(grass_get_tier_gpu_ms(ctx, ms_per_kind, available));
    for (k = 0; k < GRASS_TIER_KIND_COUNT; ++k) CHECK(ms_per_kind[k] >= 0.0);
    if (!gpu) CHECK(*available == 0);
    memset(&gpu_copy, kCanary, sizeof(gpu_copy));
    CHECK_OK(grass_get_tier_gpu_ms(ctx, gpu_copy.ms, available));
    CHECK(canary_intact(gpu_copy.canary));

    free(available);
    free(ms_per_kind);
    free(info);
    free(ms);
    free(fs);
}

/* A patch, a density map, a field that uses it, one frame, every getter; then teardown. */
static void run_scene(grass_context* ctx, int gpu) {
    grass_patch_desc pd = grass_default_patch_desc();
    grass_map_desc md = grass_default_map_desc();
    grass_field_desc fd = grass_default_field_desc();
    grass_view_desc view = make_view();
    grass_patch_id patch;
    grass_map_id map;
    grass_field_id field;
    uint8_t density[16 * 16];
    memset(&patch, 0, sizeof(patch));
    memset(&map, 0, sizeof(map));
    memset(&field, 0, sizeof(field));
    memset(density, 200, sizeof(density));

    pd.blade_count = 128;
    CHECK_OK(grass_create_patch(ctx, &pd, &patch));
    md.pixels = density;
    md.width = md.height = 16;
    md.format = GRASS_MAP_FORMAT_R8_UNORM;
    CHECK_OK(grass_create_map(ctx, &md, &map));
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 32;
    fd.maps.density = map;
    CHECK_OK(grass_create_field(ctx, &fd, &field));
    CHECK_OK(grass_begin_frame(ctx, &view));
    CHECK_OK(grass_end_frame(ctx));
    check_getters(ctx, patch, pd.blade_count, gpu);

    /* A refusal through the 0.3 name of grass_get_last_error. */
    CHECK(grass_destroy_patch(ctx, patch) == GRASS_ERROR_IN_USE);
    CHECK(strlen(grass_last_error(ctx)) > 0);
    CHECK_OK(grass_destroy_field(ctx, field));
    CHECK_OK(grass_destroy_map(ctx, map));
    CHECK_OK(grass_destroy_patch(ctx, patch));
}

#ifdef GRASS_ABI_TEST_EGL
static void run_gl(const grass_context_desc* cd) {
    EGLDisplay display;
    EGLContext egl_context;
    grass_gl_desc gl = grass_gl_default_desc();
    grass_context* ctx = NULL;
    if (!make_gl_current(&display, &egl_context)) {
        printf("old_header_host: no GL 4.5 context through EGL; the GL part is skipped\n");
        return;
    }
    CHECK(gl.type == GRASS_STRUCT_TYPE_GL_DESC);
    gl.get_proc_address = load_gl_0_3;
    CHECK_OK(grass_gl_create_context(GRASS_HEADER_VERSION, cd, &gl, &ctx));
    if (ctx) {
        CHECK(grass_context_backend(ctx) == GRASS_BACKEND_GL);
        run_scene(ctx, 1);
        grass_destroy_context(ctx);
    }
    release_gl(display, egl_context);
    printf("old_header_host: GL context checked\n");
}
#endif

int main(void) {
    grass_context_desc cd = grass_default_context_desc();
    grass_context* ctx = NULL;
    const uint32_t library = grass_library_version();
    grass_vk_desc vk = grass_vk_default_desc();
    grass_vk_record_desc record = grass_vk_default_record_desc();
    grass_gl_desc gl = grass_gl_default_desc();

    CHECK(GRASS_HEADER_VERSION == ((0u << 22) | (3u << 12)));
    CHECK(library >> 22 == 0);
    CHECK(((library >> 12) & 0x3ff) >= 3);
    printf("old_header_host: built against grass.h %d.%d.%d, running against libgrass %u.%u.%u\n", GRASS_VERSION_MAJOR,
           GRASS_VERSION_MINOR, GRASS_VERSION_PATCH, (unsigned)(library >> 22), (unsigned)((library >> 12) & 0x3ff),
           (unsigned)(library & 0xfff));

    /* The 0.3 names of the default descs (0.4: grass_default_gl_desc and so on). */
    CHECK(gl.type == GRASS_STRUCT_TYPE_GL_DESC && gl.next == NULL && gl.get_proc_address == NULL);
    CHECK(vk.type == GRASS_STRUCT_TYPE_VK_DESC && vk.frames_in_flight == 2 && vk.sample_count == 1);
    CHECK(record.type == GRASS_STRUCT_TYPE_VK_RECORD_DESC && record.command_buffer == NULL);

    cd.log_fn = log_message;
    CHECK_OK(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx));
    if (!ctx) return 1;
    CHECK(grass_context_backend(ctx) == GRASS_BACKEND_NONE);
    {
        /* grass_vk_prepare_frame (0.5: grass_vk_prepare with a desc) still resolves and
         * refuses a context that is not a Vulkan one, naming the call it forwards to. */
        int not_a_command_buffer = 0;
        CHECK(grass_vk_prepare_frame(ctx, &not_a_command_buffer) == GRASS_ERROR_INVALID_STATE);
        CHECK(strstr(grass_last_error(ctx), "grass_vk_prepare") != NULL);
    }
    run_scene(ctx, 0);
    grass_destroy_context(ctx);

#ifdef GRASS_ABI_TEST_EGL
    run_gl(&cd);
#endif
    return checks_result("old_header_host");
}
