/* doc-test prelude (tests/docs/run_doc_examples.py): a GL loader wrapper of the docs, as an
 * ISO C99 host writes it, handed to a grass_gl_desc. Compiled only (no GL context here). */
/* doc-test flags: -lEGL */
#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <grass/grass_gl.h>

#include <stdio.h>

/* doc-test block */

int main(void) {
    grass_gl_desc gl = grass_default_gl_desc();
    gl.get_proc_address = load_gl;
    printf("doc-test: the loader is %s\n", gl.get_proc_address ? "set" : "NULL");
    return gl.get_proc_address != NULL ? 0 : 1;
}
