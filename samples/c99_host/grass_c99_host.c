/*
 * grass_c99_host.c - the shortest complete grass host, in ISO C99.
 *
 * Its own GL 4.5 core context without a window (EGL surfaceless, Mesa), its own framebuffer
 * (an sRGB colour renderbuffer and a depth renderbuffer), one field, one frame, a PNG:
 *
 *   grass-c99-host [out.png]        default out.png: grass-c99-host.png
 *
 * It links libgrass, libEGL and libpng; the GL entry points it calls itself come through
 * eglGetProcAddress, like grass's own. It exits 0 when the image holds grass (at least a
 * tenth of its pixels green-dominant), 1 otherwise. The README's C example is cut from the
 * regions marked [readme:...] below (scripts/readme-example.py), so the two cannot drift.
 */
#include <grass/grass_gl.h>

#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>
#include <png.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { WIDTH = 480, HEIGHT = 270 };

/* The GL entry points the host calls itself. */
static PFNGLCREATERENDERBUFFERSPROC gl_create_renderbuffers;
static PFNGLNAMEDRENDERBUFFERSTORAGEPROC gl_named_renderbuffer_storage;
static PFNGLCREATEFRAMEBUFFERSPROC gl_create_framebuffers;
static PFNGLNAMEDFRAMEBUFFERRENDERBUFFERPROC gl_named_framebuffer_renderbuffer;
static PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC gl_check_named_framebuffer_status;
static PFNGLBINDFRAMEBUFFERPROC gl_bind_framebuffer;
static PFNGLENABLEPROC gl_enable;
static PFNGLDISABLEPROC gl_disable;
static PFNGLCLEARBUFFERFVPROC gl_clear_bufferfv;
static PFNGLREADPIXELSPROC gl_read_pixels;

/* [readme:loader] */
/* grass calls this for every GL entry point it uses. */
static grass_gl_proc GRASS_API_PTR load_gl(void* user_data, const char* name) {
    (void)user_data;
    return eglGetProcAddress(name);
}

/* Every message grass logs: an id and a sentence naming the call, the argument and its value. */
static void GRASS_API_PTR log_message(void* user_data, grass_log_level level, grass_message_id id,
                                      const char* message) {
    (void)user_data;
    fprintf(stderr, "grass %s %d: %s\n", level == GRASS_LOG_ERROR ? "error" : "warning", (int)id, message);
}
/* [readme:end] */

static int ok(grass_result result, const char* call) {
    if (result != GRASS_SUCCESS) fprintf(stderr, "%s failed: %s\n", call, grass_result_string(result));
    return result == GRASS_SUCCESS;
}

/* A GL 4.5 core context on Mesa's surfaceless platform, current on this thread. */
static int create_gl_context(void) {
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLDisplay display;
    EGLContext context;
    if (!get_platform_display) return 0;
    display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) return 0;
    context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) return 0;
    return eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) == EGL_TRUE;
}

static int load_host_gl(void) {
    gl_create_renderbuffers = (PFNGLCREATERENDERBUFFERSPROC)eglGetProcAddress("glCreateRenderbuffers");
    gl_named_renderbuffer_storage = (PFNGLNAMEDRENDERBUFFERSTORAGEPROC)eglGetProcAddress("glNamedRenderbufferStorage");
    gl_create_framebuffers = (PFNGLCREATEFRAMEBUFFERSPROC)eglGetProcAddress("glCreateFramebuffers");
    gl_named_framebuffer_renderbuffer =
        (PFNGLNAMEDFRAMEBUFFERRENDERBUFFERPROC)eglGetProcAddress("glNamedFramebufferRenderbuffer");
    gl_check_named_framebuffer_status =
        (PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC)eglGetProcAddress("glCheckNamedFramebufferStatus");
    gl_bind_framebuffer = (PFNGLBINDFRAMEBUFFERPROC)eglGetProcAddress("glBindFramebuffer");
    gl_enable = (PFNGLENABLEPROC)eglGetProcAddress("glEnable");
    gl_disable = (PFNGLDISABLEPROC)eglGetProcAddress("glDisable");
    gl_clear_bufferfv = (PFNGLCLEARBUFFERFVPROC)eglGetProcAddress("glClearBufferfv");
    gl_read_pixels = (PFNGLREADPIXELSPROC)eglGetProcAddress("glReadPixels");
    return gl_create_renderbuffers && gl_named_renderbuffer_storage && gl_create_framebuffers &&
           gl_named_framebuffer_renderbuffer && gl_check_named_framebuffer_status && gl_bind_framebuffer && gl_enable &&
           gl_disable && gl_clear_bufferfv && gl_read_pixels;
}

/* The target: sRGB colour (grass writes linear RGB; GL encodes it) and 24-bit depth. */
static int create_framebuffer(void) {
    GLuint renderbuffers[2], framebuffer;
    gl_create_renderbuffers(2, renderbuffers);
    gl_named_renderbuffer_storage(renderbuffers[0], GL_SRGB8_ALPHA8, WIDTH, HEIGHT);
    gl_named_renderbuffer_storage(renderbuffers[1], GL_DEPTH_COMPONENT24, WIDTH, HEIGHT);
    gl_create_framebuffers(1, &framebuffer);
    gl_named_framebuffer_renderbuffer(framebuffer, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers[0]);
    gl_named_framebuffer_renderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers[1]);
    if (gl_check_named_framebuffer_status(framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return 0;
    gl_bind_framebuffer(GL_FRAMEBUFFER, framebuffer);
    return 1;
}

/* Column-major matrices, as grass and GL take them. */
static void look_at(const double eye[3], const double target[3], float out[16]) {
    double f[3], s[3], u[3], n;
    int i;
    for (i = 0; i < 3; ++i) f[i] = target[i] - eye[i];
    n = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; ++i) f[i] /= n;
    s[0] = -f[2]; /* f x (0, 1, 0) */
    s[1] = 0.0;
    s[2] = f[0];
    n = sqrt(s[0] * s[0] + s[2] * s[2]);
    s[0] /= n;
    s[2] /= n;
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    memset(out, 0, 16 * sizeof(float));
    for (i = 0; i < 3; ++i) {
        out[i * 4 + 0] = (float)s[i];
        out[i * 4 + 1] = (float)u[i];
        out[i * 4 + 2] = (float)-f[i];
    }
    out[12] = (float)-(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    out[13] = (float)-(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    out[14] = (float)(f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2]);
    out[15] = 1.0f;
}

/* Right-handed, looking down -z, clip z in -1..1 (gluPerspective). */
static void perspective(float fovy, float aspect, float near_m, float far_m, float out[16]) {
    const float f = 1.0f / (float)tan(0.5 * fovy);
    memset(out, 0, 16 * sizeof(float));
    out[0] = f / aspect;
    out[5] = f;
    out[10] = (far_m + near_m) / (near_m - far_m);
    out[11] = -1.0f;
    out[14] = 2.0f * far_m * near_m / (near_m - far_m);
}

/* Reads the target back (GL rows run bottom-up), writes a PNG, counts green-dominant pixels. */
static int write_png(const char* path, long* out_green) {
    unsigned char* pixels = (unsigned char*)malloc((size_t)WIDTH * HEIGHT * 4);
    png_image image;
    long green = 0, i;
    int written;
    if (!pixels) return 0;
    gl_disable(GL_FRAMEBUFFER_SRGB); /* read the stored sRGB bytes as they are */
    gl_read_pixels(0, 0, WIDTH, HEIGHT, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    for (i = 0; i < (long)WIDTH * HEIGHT; ++i) {
        unsigned char* p = pixels + i * 4;
        if (p[1] > p[0] + 8 && p[1] > p[2] + 8) green += 1;
        p[3] = 255; /* the PNG is opaque */
    }
    memset(&image, 0, sizeof(image));
    image.version = PNG_IMAGE_VERSION;
    image.width = WIDTH;
    image.height = HEIGHT;
    image.format = PNG_FORMAT_RGBA;
    /* A negative stride writes the last row first: the image comes out top-down. */
    written = png_image_write_to_file(&image, path, 0, pixels, -WIDTH * 4, NULL);
    free(pixels);
    *out_green = green;
    return written != 0;
}

int main(int argc, char** argv) {
    const char* out_path = argc > 1 ? argv[1] : "grass-c99-host.png";
    const float sky[4] = {0.45f, 0.62f, 0.85f, 1.0f}; /* linear RGB, encoded by GL_FRAMEBUFFER_SRGB */
    const float far_depth = 1.0f;
    const double eye[3] = {8.0, 1.6, -1.0}, target[3] = {8.0, 0.0, 8.0};
    grass_context* ctx = NULL;
    long green = 0;
    int success = 0;

    if (!create_gl_context() || !load_host_gl()) {
        fprintf(stderr, "no GL 4.5 core context through EGL surfaceless (Mesa)\n");
        return 1;
    }
    if (!create_framebuffer()) {
        fprintf(stderr, "the sRGB + depth framebuffer is incomplete\n");
        return 1;
    }
    {
        /* [readme:setup] */
        grass_context_desc cd = grass_default_context_desc();
        grass_gl_desc gl = grass_default_gl_desc();
        grass_patch_desc pd = grass_default_patch_desc(); /* a grass type: blades, shapes, colours */
        grass_field_desc fd = grass_default_field_desc(); /* cells of 0.25 m */
        grass_patch_id patch;
        grass_field_id field;

        cd.log_fn = log_message;
        gl.get_proc_address = load_gl;
        /* The GL context must be current on this thread for every call of a GL grass context. */
        if (!ok(grass_gl_create_context(GRASS_HEADER_VERSION, &cd, &gl, &ctx), "grass_gl_create_context")) goto done;
        if (!ok(grass_create_patch(ctx, &pd, &patch), "grass_create_patch")) goto done;
        fd.patch = patch;
        fd.cells_x = 64; /* 16 m x 16 m */
        fd.cells_z = 64;
        if (!ok(grass_create_field(ctx, &fd, &field), "grass_create_field")) goto done;
        /* [readme:end] */
    }
    {
        /* [readme:frame] */
        /* Every frame, with the host's framebuffer bound and its depth cleared: */
        grass_view_desc view = grass_default_view_desc(); /* the sun and ambient light set */
        grass_frame_stats stats;

        gl_enable(GL_FRAMEBUFFER_SRGB); /* grass writes linear RGB: an sRGB target encodes it */
        gl_clear_bufferfv(GL_COLOR, 0, sky);
        gl_clear_bufferfv(GL_DEPTH, 0, &far_depth);
        memcpy(view.camera_position, eye, sizeof(eye)); /* double: the view's translation */
        look_at(eye, target, view.view);
        perspective(0.9f, (float)WIDTH / HEIGHT, 0.05f, 200.0f, view.projection);
        view.viewport[2] = WIDTH; /* x, y (GL: lower left), width, height */
        view.viewport[3] = HEIGHT;
        if (!ok(grass_begin_frame(ctx, &view), "grass_begin_frame")) goto done;
        if (!ok(grass_gl_render(ctx), "grass_gl_render")) goto done;
        if (!ok(grass_end_frame(ctx), "grass_end_frame")) goto done;
        grass_get_frame_stats(ctx, &stats);
        printf("%lu blades, %lu triangles, %lu draws\n", (unsigned long)stats.blades_drawn,
               (unsigned long)stats.triangles, (unsigned long)stats.draws);
        /* [readme:end] */
    }
    if (!write_png(out_path, &green)) {
        fprintf(stderr, "could not write %s\n", out_path);
        goto done;
    }
    printf("wrote %s: %ld of %d pixels green\n", out_path, green, WIDTH * HEIGHT);
    success = green * 10 >= (long)WIDTH * HEIGHT;
    if (!success) fprintf(stderr, "too few green pixels: the camera sees no grass\n");
done:
    grass_destroy_context(ctx); /* destroys the patch and the field too */
    return success ? 0 : 1;
}
