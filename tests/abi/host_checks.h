/*
 * What the C hosts of tests/abi share: CHECK, which counts failed checks, and with
 * GRASS_ABI_TEST_EGL a GL 4.5 core context on EGL's surfaceless platform and grass 0.3's
 * loader type (it returned void*). Includes no grass header: old_header_host.c must see only
 * the frozen 0.3 headers. A host that uses EGL defines _GNU_SOURCE before any include
 * (keep_drivers_resident.h: dl_iterate_phdr, RTLD_NODELETE).
 */
#ifndef GRASS_ABI_HOST_CHECKS_H
#define GRASS_ABI_HOST_CHECKS_H

#include <stdio.h>
#include <string.h>

#ifdef GRASS_ABI_TEST_EGL
#    include "keep_drivers_resident.h"
#    include <EGL/egl.h>
#    include <EGL/eglext.h>
#endif

static int failures = 0;

#define CHECK(condition)                                                                  \
    do {                                                                                  \
        if (!(condition)) {                                                               \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #condition); \
            failures += 1;                                                                \
        }                                                                                 \
    } while (0)

/* main's exit status: 0 when every check passed; else 1, with how many failed. */
static int checks_result(const char* host) {
    if (failures) {
        fprintf(stderr, "%s: %d check(s) failed\n", host, failures);
        return 1;
    }
    printf("%s: all checks passed\n", host);
    return 0;
}

#ifdef GRASS_ABI_TEST_EGL
/* The 0.3 loader type returns void*: copied out of the function pointer (ISO C has no cast
 * between the two; grass.h 0.4's grass_gl_proc ends that). */
static void* load_gl_0_3(void* user_data, const char* name) {
    void (*proc)(void) = eglGetProcAddress(name);
    void* address;
    (void)user_data;
    memcpy(&address, &proc, sizeof(address));
    return address;
}

/* A GL 4.5 core context on EGL's surfaceless platform, current; 0 where there is none. */
static int make_gl_current(EGLDisplay* out_display, EGLContext* out_context) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display;
    EGLDisplay display;
    EGLContext context;
    EGLint major = 0, minor = 0;
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    void (*proc)(void) = eglGetProcAddress("eglGetPlatformDisplayEXT");
    if (!client || !strstr(client, "EGL_MESA_platform_surfaceless") || !proc) return 0;
    memcpy(&get_display, &proc, sizeof(get_display));
    display = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) return 0;
    if (!eglBindAPI(EGL_OPENGL_API)) return 0;
    context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        eglTerminate(display);
        return 0;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        eglTerminate(display);
        return 0;
    }
    keep_drivers_resident();
    *out_display = display;
    *out_context = context;
    return 1;
}

static void release_gl(EGLDisplay display, EGLContext context) {
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    eglTerminate(display);
}
#endif

#endif /* GRASS_ABI_HOST_CHECKS_H */
