/*
 * A host built against the current headers, in ISO C99 (-Wpedantic -Werror): the fields
 * grown in grass.h 0.4 are filled (grass_frame_stats.draws,
 * grass_memory_stats.host_bytes_peak), the 0.4 names answer and the id helpers are exported.
 * Exit status 0 when all is well.
 */
#include "host_checks.h"

#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

#define CHECK_OK(call) CHECK((call) == GRASS_SUCCESS)

int main(void) {
    grass_context_desc cd = grass_default_context_desc();
    grass_patch_desc pd = grass_default_patch_desc();
    grass_field_desc fd = grass_default_field_desc();
    grass_view_desc view = grass_default_view_desc();
    grass_context* ctx = NULL;
    grass_patch_id patch, null_patch;
    grass_field_id field;
    grass_frame_stats fs;
    grass_memory_stats ms;
    grass_view_gbuffer_desc gbuffer;
    grass_view_pass_desc pass;
    const uint64_t unwritten = 0xababababababababull;
    int k;

    CHECK(grass_get_library_version() == GRASS_HEADER_VERSION);
    CHECK(grass_default_gl_desc().type == GRASS_STRUCT_TYPE_GL_DESC);
    CHECK(grass_default_mesh_field_desc().type == GRASS_STRUCT_TYPE_MESH_FIELD_DESC);
    CHECK(grass_default_vk_desc().type == GRASS_STRUCT_TYPE_VK_DESC);
    CHECK(grass_default_vk_host_objects_desc().type == GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC);
    CHECK(grass_default_vk_host_objects_desc().allocation_callbacks == NULL);
    CHECK(grass_default_vk_multiview_desc().type == GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC);
    CHECK(grass_default_vk_multiview_desc().view_mask == 0);
    CHECK(grass_default_vk_depth_pass_desc().type == GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC);
    CHECK(grass_default_vk_depth_pass_desc().render_pass == 0 && grass_default_vk_depth_pass_desc().sample_count == 1);
    CHECK(grass_default_vk_velocity_target_desc().type == GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC);
    CHECK(grass_default_vk_velocity_target_desc().color_attachment_count == 2 &&
          grass_default_vk_velocity_target_desc().velocity_attachment == 1);
    CHECK(grass_default_vk_gbuffer_target_desc().type == GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC);
    CHECK(grass_default_vk_gbuffer_target_desc().color_attachment_count == 4);
    CHECK(grass_default_vk_record_desc().type == GRASS_STRUCT_TYPE_VK_RECORD_DESC);
    CHECK_OK(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx));
    if (!ctx) return 1;
    CHECK(grass_get_context_backend(ctx) == GRASS_BACKEND_NONE);

    memset(&patch, 0, sizeof(patch));
    memset(&null_patch, 0, sizeof(null_patch));
    memset(&field, 0, sizeof(field));
    CHECK_OK(grass_create_patch(ctx, &pd, &patch));
    CHECK(!grass_patch_id_is_null(patch));
    CHECK(grass_patch_id_is_null(null_patch));
    CHECK(grass_patch_id_equal(patch, patch));
    CHECK(!grass_patch_id_equal(patch, null_patch));
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 32;
    CHECK_OK(grass_create_field(ctx, &fd, &field));
    CHECK(grass_field_id_equal(field, field) && !grass_field_id_is_null(field));

    /* Above the field's middle, looking straight down (view: world y -> eye -z). */
    view.camera_position[0] = view.camera_position[2] = 4.0;
    view.camera_position[1] = 3.0;
    for (k = 0; k < 16; ++k) view.view[k] = view.projection[k] = 0.0f;
    view.view[0] = 1.0f;
    view.view[9] = -1.0f;
    view.view[6] = 1.0f;
    view.view[15] = 1.0f;
    view.projection[0] = view.projection[5] = 1.0f;
    view.projection[10] = -1.0002f;
    view.projection[11] = -1.0f;
    view.projection[14] = -0.020002f;
    view.viewport[2] = view.viewport[3] = 256;
    CHECK_OK(grass_begin_frame(ctx, &view));
    CHECK_OK(grass_end_frame(ctx));
    /* 0.5's G-buffer view: a layout chained after its pass, planned without a GPU. */
    gbuffer = grass_default_view_gbuffer_desc();
    CHECK(gbuffer.type == GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC && gbuffer.attachment_count == 1);
    gbuffer.attachment_count = 2;
    gbuffer.attachments[0].semantic = GRASS_GBUFFER_ALBEDO;
    gbuffer.attachments[1].semantic = GRASS_GBUFFER_NORMAL;
    gbuffer.attachments[1].format = GRASS_GBUFFER_FORMAT_SNORM;
    pass = grass_default_view_pass_desc();
    pass.pass = GRASS_PASS_GBUFFER;
    pass.next = &gbuffer;
    view.next = &pass;
    CHECK_OK(grass_begin_frame(ctx, &view));
    CHECK_OK(grass_end_frame(ctx));
    view.next = NULL;

    memset(&fs, 0xab, sizeof(fs));
    CHECK_OK(grass_get_frame_stats(ctx, &fs));
    CHECK(fs.fields_drawn == 1);
    CHECK(fs.draws != unwritten);
    CHECK(fs.draws >= 1 && fs.draws <= GRASS_DEFAULT_TIER_COUNT);
    memset(&ms, 0xab, sizeof(ms));
    CHECK_OK(grass_get_memory_stats(ctx, &ms));
    CHECK(ms.host_bytes_peak != unwritten);
    CHECK(ms.host_bytes > 0 && ms.host_bytes_peak >= ms.host_bytes);
    /* 0.5's device heaps: written, and none without a GPU backend. */
    CHECK(ms.heap_count == 0 && ms.device_allocations == 0);
    CHECK(ms.heap_size[0] == 0 && ms.heap_usage[GRASS_MAX_MEMORY_HEAPS - 1] == 0);
    printf("current_header_host: %llu draws, host bytes %llu (peak %llu)\n", (unsigned long long)fs.draws,
           (unsigned long long)ms.host_bytes, (unsigned long long)ms.host_bytes_peak);

    CHECK(grass_destroy_patch(ctx, patch) == GRASS_ERROR_IN_USE);
    CHECK(strlen(grass_get_last_error(ctx)) > 0);
    CHECK_OK(grass_destroy_field(ctx, field));
    CHECK_OK(grass_destroy_patch(ctx, patch));
    grass_destroy_context(ctx);
    return checks_result("current_header_host");
}
