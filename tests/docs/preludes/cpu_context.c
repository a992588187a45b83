/* doc-test prelude (tests/docs/run_doc_examples.py): a C fragment of the docs that works on
 * a host's context, runs here on a CPU-only one (it plans frames and draws nothing). The
 * names the guides' fragments take as given: ctx, cd, patch, field, fd (the field's desc),
 * density (a 256 x 256 R16 density map, as the height map of design-maps.md), view, t, tests/test_count (the default lod setup),
 * the pixels heights, mown and draught, the host's own helicopter and ball, and a host frame's
 * engine_frame, engine_finished, seconds, main_camera and cascade_view[3]. Any message
 * grass logs at error level fails the block: a fragment must be right as written. */
#include <grass/grass.h>

#include <stdio.h>
#include <string.h>

static int errors = 0;

static void log_message(void* user_data, grass_log_level level, grass_message_id id, const char* message) {
    (void)user_data;
    if (level == GRASS_LOG_ERROR) {
        fprintf(stderr, "grass error %d: %s\n", (int)id, message);
        errors += 1;
    }
}

static void helicopter_position(double t, double out[3]) {
    out[0] = 8.0 + t;
    out[1] = 6.0;
    out[2] = 8.0;
}
static void ball_position(double t, double out[3]) {
    out[0] = 4.0 + t;
    out[1] = 0.3;
    out[2] = 4.0;
}
static void ball_velocity(double t, float out[3]) {
    (void)t;
    out[0] = 1.0f;
    out[1] = 0.0f;
    out[2] = 0.0f;
}

static uint16_t heights[256 * 256];
static uint16_t mown[16 * 16];
static uint8_t draught[64 * 64 * 4];
static uint16_t density_pixels[256 * 256];

int main(void) {
    grass_context_desc cd = grass_default_context_desc();
    grass_context* ctx = NULL;
    grass_patch_desc patch_desc = grass_default_patch_desc();
    grass_map_desc density_desc = grass_default_map_desc();
    grass_field_desc fd = grass_default_field_desc();
    grass_view_desc view = grass_default_view_desc();
    grass_tier_desc default_tiers[GRASS_MAX_TIERS];
    grass_lod_test tests[GRASS_MAX_LOD_TESTS];
    uint32_t tier_count = 0, test_count = 0;
    grass_patch_id patch;
    grass_field_id field;
    grass_map_id density;
    double t = 0.5;
    size_t k;

    for (k = 0; k < sizeof(density_pixels) / sizeof(density_pixels[0]); ++k) density_pixels[k] = 50000;
    for (k = 0; k < sizeof(heights) / sizeof(heights[0]); ++k) heights[k] = (uint16_t)(k % 256 * 100);
    memset(draught, 128, sizeof(draught));
    cd.log_fn = log_message;
    if (grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) != GRASS_SUCCESS) return 1;
    grass_create_patch(ctx, &patch_desc, &patch);
    density_desc.pixels = density_pixels;
    density_desc.width = density_desc.height = 256;
    density_desc.format = GRASS_MAP_FORMAT_R16_UNORM;
    grass_create_map(ctx, &density_desc, &density);
    grass_default_lod_setup(0.25, default_tiers, tests);
    tier_count = GRASS_DEFAULT_TIER_COUNT;
    test_count = GRASS_DEFAULT_LOD_TEST_COUNT;
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 64;
    grass_create_field(ctx, &fd, &field);
    view.camera_position[0] = 8.0;
    view.camera_position[1] = 1.7;
    view.camera_position[2] = -2.0;
    view.viewport[2] = 640;
    view.viewport[3] = 360;
    grass_view_desc main_camera = view, cascade_view[3];
    uint64_t engine_frame = 1, engine_finished = 0;
    double seconds = t;
    for (k = 0; k < 3; ++k) cascade_view[k] = view;
    (void)main_camera;
    (void)engine_frame;
    (void)engine_finished;
    (void)seconds;
    if (errors) {
        fprintf(stderr, "doc-test prelude: the context's setup failed\n");
        return 1;
    }
    /* clang-format off */
    {
        /* doc-test block */
    }
    /* clang-format on */
    grass_destroy_context(ctx);
    if (errors) {
        fprintf(stderr, "doc-test: the block made %d error(s)\n", errors);
        return 1;
    }
    return 0;
}
