/* An out-of-tree program that uses an installed grass, as a user's would: found by CMake's
 * find_package(grass) or by pkg-config, compiled as ISO C99. It plans one frame of a field
 * on a CPU-only context and checks what the library reports. Exit code 0 on success. */
#include <grass/grass.h>

#include <stdio.h>
#include <string.h>

static int check(grass_result r, const char* call) {
    if (r != GRASS_SUCCESS) {
        fprintf(stderr, "consumer: %s failed: %s\n", call, grass_result_string(r));
        return 1;
    }
    return 0;
}

int main(void) {
    grass_context_desc cd = grass_default_context_desc();
    grass_context* ctx = NULL;
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch;
    grass_field_desc fd = grass_default_field_desc();
    grass_field_id field;
    grass_view_desc view = grass_default_view_desc();
    grass_frame_stats stats;
    int failed = 0;

    if (grass_get_library_version() >> 22 != GRASS_VERSION_MAJOR) {
        fprintf(stderr, "consumer: library version 0x%08x, header major %d\n", (unsigned)grass_get_library_version(),
                GRASS_VERSION_MAJOR);
        return 1;
    }
    if (check(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx), "grass_create_context")) return 1;
    pd.blade_count = 64;
    failed |= check(grass_create_patch(ctx, &pd, &patch), "grass_create_patch");
    fd.patch = patch;
    fd.cells_x = 64;
    fd.cells_z = 64;
    failed |= check(grass_create_field(ctx, &fd, &field), "grass_create_field");
    /* A camera 1.7 m above the middle of the field's near edge, looking along +z (a half
     * turn about y: eye space looks along -z), with a GL perspective of 60 degrees. */
    view.camera_position[0] = 8.0;
    view.camera_position[1] = 1.7;
    view.camera_position[2] = -1.0;
    view.view[0] = -1.0f;
    view.view[10] = -1.0f;
    memset(view.projection, 0, sizeof(view.projection));
    view.projection[0] = 1.7320508f / (320.0f / 180.0f); /* 1 / tan(30 degrees) / aspect */
    view.projection[5] = 1.7320508f;
    view.projection[10] = (1000.0f + 0.1f) / (0.1f - 1000.0f);
    view.projection[11] = -1.0f;
    view.projection[14] = 2.0f * 1000.0f * 0.1f / (0.1f - 1000.0f);
    view.viewport[2] = 320;
    view.viewport[3] = 180;
    failed |= check(grass_begin_frame(ctx, &view), "grass_begin_frame");
    memset(&stats, 0, sizeof(stats));
    failed |= check(grass_get_frame_stats(ctx, &stats), "grass_get_frame_stats");
    failed |= check(grass_end_frame(ctx), "grass_end_frame");
    grass_destroy_context(ctx);
    if (failed) return 1;
    printf("consumer: grass %u.%u.%u, %llu nodes visited, %llu cells drawn as blades\n",
           (unsigned)(grass_get_library_version() >> 22), (unsigned)((grass_get_library_version() >> 12) & 0x3ff),
           (unsigned)(grass_get_library_version() & 0xfff), (unsigned long long)stats.nodes_visited,
           (unsigned long long)stats.cells_drawn);
    if (stats.cells_drawn == 0) {
        fprintf(stderr, "consumer: the camera looks at the field, but the frame plan draws no cell\n");
        return 1;
    }
    return 0;
}
