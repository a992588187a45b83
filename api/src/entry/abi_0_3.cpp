// The 0.3 names of functions renamed in 0.4 (and the 0.4 names of those renamed in 0.5): kept for binaries built against grass.h 0.3,
// and declared by the current headers only to sources that define GRASS_ENABLE_DEPRECATED
// (their "0.3 names" blocks, docs/migrating.md). Each forwards to its new name, which every
// build has (a backend left out of the build keeps its entry points, which say so, in
// context/absent_backends.cpp), so the aliases of the GL and Vulkan calls live here too.
#define GRASS_ENABLE_DEPRECATED 1
#include <grass/grass.h>
#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

extern "C" {

GRASS_API grass_backend grass_context_backend(const grass_context* context) {
    return grass_get_context_backend(context);
}
GRASS_API const char* grass_last_error(const grass_context* context) { return grass_get_last_error(context); }
GRASS_API grass_gl_desc grass_gl_default_desc(void) { return grass_default_gl_desc(); }
GRASS_API grass_vk_desc grass_vk_default_desc(void) { return grass_default_vk_desc(); }
GRASS_API grass_vk_record_desc grass_vk_default_record_desc(void) { return grass_default_vk_record_desc(); }

// Renamed in 0.5 (the headers' "0.4 names" blocks): kept for binaries built against 0.3 and 0.4.
GRASS_API uint32_t grass_library_version(void) { return grass_get_library_version(); }
GRASS_API grass_result grass_vk_prepare_frame(grass_context* context, void* command_buffer) {
    grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
    prepare.command_buffer = command_buffer;
    return grass_vk_prepare(context, &prepare);
}

} // extern "C"
