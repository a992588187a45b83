/* An ISO C99 host hands eglGetProcAddress to grass through a wrapper, with no cast between
 * data and function pointers: grass_gl_get_proc_address_fn returns a function pointer
 * (ctest header_gl_loader_is_iso_c: -std=c99 -pedantic -Wall -Wextra -Werror). */
#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <grass/grass_gl.h>

static grass_gl_proc load_gl(void* user_data, const char* name) {
    (void)user_data;
    return eglGetProcAddress(name);
}

grass_gl_desc make_gl_desc(void);
grass_gl_desc make_gl_desc(void) {
    grass_gl_desc gl = grass_default_gl_desc();
    gl.get_proc_address = load_gl;
    gl.get_proc_address_user_data = NULL;
    return gl;
}
