/*
 * A host's source written against grass.h 0.3, compiled against the CURRENT headers with
 * GRASS_ENABLE_DEPRECATED (docs/migrating.md): every 0.3 name it uses compiles with a
 * deprecation warning and binds to the symbol the library still exports. The one line a
 * 0.3 source changes is the GL loader's: its loader returns void*, as 0.3's type did, and
 * goes to the desc through grass_gl_set_loader_0_3 instead of an assignment (no cast).
 * ctest abi_source_0_3_host runs it; abi_source_0_3_compiles checks that it warns with the
 * macro and is refused without it (tests/abi/source_0_3_compiles.sh). It also uses the two
 * names that 0.3 and 0.4 shared and 0.5 renamed (the headers' "0.4 names" blocks).
 */
#ifdef GRASS_ABI_TEST_EGL
#    define _GNU_SOURCE 1 /* keep_drivers_resident.h: dl_iterate_phdr, RTLD_NODELETE */
#endif
#include "host_checks.h"

#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

/* 0.3: the last refusal's sentence, through grass_last_error (0.4: grass_get_last_error).
 * Used as the only grass string call, as in the report of a host whose implicit
 * declaration truncated the pointer to an int and crashed. */
static void refuse_and_report(grass_context* ctx) {
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch;
    const char* message;
    memset(&patch, 0, sizeof(patch));
    pd.blade_count = 0; /* refused: 1..65536 */
    CHECK(grass_create_patch(ctx, &pd, &patch) == GRASS_ERROR_INVALID_ARGUMENT);
    message = grass_last_error(ctx);
    CHECK(message != NULL && strstr(message, "blade_count") != NULL);
    if (message) printf("source_0_3_host: refused as expected: %s\n", message);
}

#ifdef GRASS_ABI_TEST_EGL
static void run_gl(void) {
    EGLDisplay display;
    EGLContext egl_context;
    grass_context_desc cd = grass_default_context_desc();
    grass_gl_desc gl = grass_gl_default_desc();
    grass_context* ctx = NULL;
    if (!make_gl_current(&display, &egl_context)) {
        printf("source_0_3_host: no GL 4.5 context through EGL; the GL part is skipped\n");
        return;
    }
    CHECK(gl.type == GRASS_STRUCT_TYPE_GL_DESC);
    grass_gl_set_loader_0_3(&gl, load_gl_0_3); /* 0.3: gl.get_proc_address = load_gl_0_3; */
    CHECK(grass_gl_create_context(GRASS_HEADER_VERSION, &cd, &gl, &ctx) == GRASS_SUCCESS);
    if (ctx) {
        CHECK(grass_context_backend(ctx) == GRASS_BACKEND_GL);
        refuse_and_report(ctx);
        grass_destroy_context(ctx);
        printf("source_0_3_host: a GL context made through a 0.3 loader\n");
    } else {
        fprintf(stderr, "source_0_3_host: grass_gl_create_context failed\n");
    }
    release_gl(display, egl_context);
}
#endif

int main(void) {
    grass_context_desc cd = grass_default_context_desc();
    grass_context* ctx = NULL;
    grass_vk_desc vk = grass_vk_default_desc();
    grass_vk_record_desc record = grass_vk_default_record_desc();
    grass_gl_desc gl = grass_gl_default_desc();

    CHECK(gl.type == GRASS_STRUCT_TYPE_GL_DESC && gl.get_proc_address == NULL);
    CHECK(vk.type == GRASS_STRUCT_TYPE_VK_DESC && vk.frames_in_flight == 2);
    CHECK(record.type == GRASS_STRUCT_TYPE_VK_RECORD_DESC && record.command_buffer == NULL);
    CHECK(grass_create_context(GRASS_HEADER_VERSION, &cd, &ctx) == GRASS_SUCCESS);
    if (!ctx) return 1;
    CHECK(grass_context_backend(ctx) == GRASS_BACKEND_NONE);
    /* Renamed in 0.5 (the "0.4 names" blocks): grass_library_version, and
     * grass_vk_prepare_frame, whose command buffer 0.5 passes in a desc. */
    CHECK(grass_library_version() == GRASS_HEADER_VERSION);
    {
        int not_a_command_buffer = 0;
        CHECK(grass_vk_prepare_frame(ctx, &not_a_command_buffer) == GRASS_ERROR_INVALID_STATE);
    }
    refuse_and_report(ctx);
    grass_destroy_context(ctx);
#ifdef GRASS_ABI_TEST_EGL
    run_gl();
#endif
    return checks_result("source_0_3_host");
}
