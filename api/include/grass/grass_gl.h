/*
 * grass_gl.h - what an OpenGL 4.5 core host hands over, and the draw call.
 *
 * Includes no GL header. The host creates a GL 4.5 context (core or compatibility),
 * makes it current on the calling thread for every grass call of a GL context (create,
 * destroy, patch, field, render), and gives a proc-address loader. The plugin draws into
 * the framebuffer the host has bound, with the host's depth buffer, and restores every GL
 * state it touches (see grass_gl_render).
 *
 * The GL context must be the very one the grass context was created with (not another
 * one, not even one sharing its objects). Every call that would touch GL (patch, map and
 * field creation and destruction, map updates, wind maps, frames, grass_gl_render,
 * grass_get_tier_gpu_ms) first checks this and refuses otherwise, with
 * GRASS_ERROR_INVALID_STATE and GRASS_MSG_GL_CONTEXT_NOT_CURRENT, before any GL call and
 * leaving no GL error. grass_destroy_context then logs the error and frees its host memory
 * without GL calls (its GL objects go with their GL context). The check costs two GL
 * queries per call (glIsVertexArray and glGetObjectLabel on a vertex array object grass
 * labelled with a process-unique name at creation: vertex arrays are never shared between
 * GL contexts, and with no context current both calls do nothing).
 */
#ifndef GRASS_GRASS_GL_H
#define GRASS_GRASS_GL_H

#include "grass.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A GL entry point as a loader returns it; grass casts it to the entry point's type (whose
 * convention is APIENTRY's: __stdcall on Windows). No convention of its own: it is the type
 * eglGetProcAddress and glfwGetProcAddress return. */
typedef void (*grass_gl_proc)(void);
/* Returns the address of a GL entry point, or NULL: wraps the host's loader, e.g.
 *   static grass_gl_proc GRASS_API_PTR load(void* user_data, const char* name) {
 *       return eglGetProcAddress(name);
 *   }
 * (eglGetProcAddress and glfwGetProcAddress return this very type). grass calls it with
 * GRASS_API_PTR (grass.h; APIENTRY's rule: __stdcall on Windows, nothing elsewhere). */
typedef grass_gl_proc(GRASS_API_PTR* grass_gl_get_proc_address_fn)(void* user_data, const char* name);

typedef struct grass_gl_desc {
    grass_struct_type type;                        /* GRASS_STRUCT_TYPE_GL_DESC */
    const void* next;                              /* NULL */
    grass_gl_get_proc_address_fn get_proc_address; /* required */
    void* get_proc_address_user_data;
} grass_gl_desc;

GRASS_API grass_gl_desc grass_default_gl_desc(void);

/* Creates a context that draws with the current GL context, which must be 4.5 or newer. */
GRASS_API grass_result grass_gl_create_context(uint32_t header_version, const grass_context_desc* desc,
                                               const grass_gl_desc* gl_desc, grass_context** out_context);

/* Draws the begun frame into the currently bound draw framebuffer, to its draw buffer 0.
 * Depth test on (the host's depth buffer is shared), depth writes on, no blending; when the
 * framebuffer is multisampled, the blades use alpha-to-coverage and the volume and image
 * tiers write their coverage as sample masks (the sample count is read from the bound
 * framebuffer). Returns GRASS_ERROR_INVALID_STATE outside grass_begin_frame()/
 * grass_end_frame(). May be called more than once per frame.
 *
 * Set for the draws, then restored as the host left it:
 *   - bindings: program, vertex array, array and element buffers, uniform buffer bindings
 *     0-1 (and the generic uniform buffer binding), texture unit 0 (its 2D texture: the
 *     density map) and its sampler, texture units 3-5 (their 2D array textures) and their
 *     samplers, texture units 6-9 (their 2D textures: the colour, ambient, diffuse and
 *     height maps) and their samplers, active texture;
 *   - responsive grass only (a frame with wind, gravity, colliders or a field's wind map,
 *     grass.h): shader storage buffer bindings 0-7 (and the generic one), the draw
 *     indirect buffer binding, uniform buffer binding 2 (the blade window pass's), image
 *     unit 0,
 *     texture units 10-11 (their 2D textures: the interaction map's levels) and 13 (its 2D
 *     texture: a field's wind map) and their samplers. The
 *     frame's first call runs the interaction pass (a compute dispatch per map level)
 *     before drawing, then glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT |
 *     GL_SHADER_IMAGE_ACCESS_BARRIER_BIT); it runs even when nothing is drawn; then the
 *     blade window pass (docs/responsive.md "The blade window": a compute dispatch per
 *     geometry draw of view 0 with responsive grass) and
 *     glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); and in every call, before the
 *     view's geometry draws, the compaction of its window draws (docs/responsive.md
 *     "Culled blades compacted": a compute dispatch per draw of the view that reads the
 *     window) and glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT),
 *     after which each such draw is one glMultiDrawElementsIndirect;
 *   - viewport 0 (from grass_view_desc.viewport, set with glViewportIndexedf: the host's
 *     other viewports are not touched), depth test/func/mask, cull face (off: no face is
 *     culled, so the front-face winding does not matter), draw buffer 0's blend enable
 *     (off, glDisablei; its blend functions and equations, and those of every other draw
 *     buffer, are not touched), multisample and alpha-to-coverage enables, polygon mode
 *     (fill), draw buffer 0's colour mask (all channels written; alpha holds coverage);
 *   - the colour masks of the other draw buffers the framebuffer has (GL_DRAW_BUFFERi not
 *     GL_NONE, i >= 1): all off while grass draws, so that a G-buffer's other attachments
 *     keep their contents (grass's shaders write draw buffer 0 alone). The draw buffers
 *     themselves are the host's and not touched;
 *   - turned off while grass draws, if the host left them on: stencil test, scissor test
 *     (grass draws the whole viewport; give a split-screen view its own viewport, as on
 *     Vulkan where grass sets the scissor to the viewport), polygon offset (fill), clip
 *     distances 0-7, rasterizer discard, sample mask, sample shading, sample coverage,
 *     alpha-to-one, depth clamp, primitive restart (both kinds), colour logic op. Their
 *     values (stencil func, scissor box, offsets, masks, restart index...) are not touched.
 *   - 0.5: a depth pass (grass_view_pass_desc, GRASS_PASS_DEPTH) also turns draw buffer 0's
 *     colour mask off (every draw buffer's is then off: no colour is written), turns
 *     alpha-to-coverage off, and turns polygon offset (fill) on with
 *     glPolygonOffset(depth_bias_slope, depth_bias_constant); the host's polygon offset
 *     factor and units, and its enable, are restored afterwards.
 *   - 0.5: a view that receives the host's shadows (grass_shadow_receive_desc): texture
 *     unit 14 (its 2D array texture: the host's shadow map, read through grass's own
 *     depth-compare sampler) and its sampler, and uniform buffer binding 2 (grass's block
 *     of the cascades' matrices). The host's map itself (its parameters, contents) is not
 *     touched.
 *   - 0.5: a view with motion vectors (grass_view_motion_desc): the bound framebuffer's
 *     draw buffer list (routed to {the host's draw buffer 0, the host's draw buffer
 *     velocity_attachment} while grass draws, every other one GL_NONE), draw buffer 1's
 *     colour mask (red and green) and blend enable (off), and uniform buffer binding 3
 *     (grass's block of the two frames' matrices).
 *
 * Read as the host's conventions and honoured, never changed:
 *   - the bound draw framebuffer, its draw buffers (but for a motion view, above) and its
 *     sample count;
 *   - glClipControl's depth mode (GL_CLIP_DEPTH_MODE) and viewport 0's glDepthRange: the
 *     volume tier writes gl_FragDepth with them. glClipControl's origin: grass draws
 *     through the host's projection as its scene does, upside down in memory under
 *     GL_UPPER_LEFT as the host's scene is (both origins are tested);
 *   - GL_FRAMEBUFFER_SRGB and the target's format: grass writes linear colour; where the
 *     target does not encode it, set GRASS_VIEW_FLAG_ENCODE_SRGB (grass.h);
 *   - the provoking vertex (grass's flat varyings are the same at every vertex),
 *     GL_DITHER (on by default), the stencil and depth buffers' other state.
 *
 * Debug labels (grass.h, grass_debug_labels_desc; on by default in a debug context): the
 * call is one debug group, "grass render" (glPushDebugGroup / glPopDebugGroup, balanced),
 * with a group per pass and tier kind inside, and grass's GL objects carry glObjectLabel
 * names beginning "grass ". */
GRASS_API grass_result grass_gl_render(grass_context* context);

/* 0.5: Draws view `view` of the begun frame (grass_plan_view's index; grass_gl_render draws
 * view 0), with everything grass_gl_render says: the host's current framebuffer, state
 * restored. The frame's interaction pass runs at its first draw of any view. */
GRASS_API grass_result grass_gl_render_view(grass_context* context, uint32_t view);

/* ---- 0.3 names (begin): see grass.h's block of the same name ----------------------------- */
#if defined(GRASS_RENAMED)
GRASS_RENAMED(grass_gl_default_desc, grass_default_gl_desc, 0.4)
GRASS_API grass_gl_desc grass_gl_default_desc(void);
#endif
#if defined(GRASS_ENABLE_DEPRECATED)
/* The 0.3 loader type: it returned void* (0.4's grass_gl_get_proc_address_fn returns a
 * grass_gl_proc, which eglGetProcAddress, glXGetProcAddress and glfwGetProcAddress return
 * as is). A 0.3 loader is given to a desc with grass_gl_set_loader_0_3, with no cast. */
typedef void*(GRASS_API_PTR* grass_gl_get_proc_address_0_3_fn)(void* user_data, const char* name);
#    if defined(_MSC_VER) && !defined(__cplusplus)
#        define GRASS_GL_INLINE_0_3 static __inline
#    else
#        define GRASS_GL_INLINE_0_3 static inline
#    endif
/* Sets desc->get_proc_address to a 0.3 loader. grass calls it as a grass_gl_proc loader:
 * both return one pointer in the same register on every platform grass supports, as for
 * programs built against grass.h 0.3. */
GRASS_DEPRECATED("a loader returning void* is grass 0.3's type: return grass_gl_proc and assign "
                 "grass_gl_desc.get_proc_address (docs/migrating.md)")
GRASS_GL_INLINE_0_3 void grass_gl_set_loader_0_3(grass_gl_desc* desc, grass_gl_get_proc_address_0_3_fn loader) {
    /* Through void (*)(void), the type that converts to and from every function pointer
     * without -Wcast-function-type's warning. */
#    if defined(__cplusplus)
    desc->get_proc_address = reinterpret_cast<grass_gl_get_proc_address_fn>(reinterpret_cast<void (*)(void)>(loader));
#    else
    desc->get_proc_address = (grass_gl_get_proc_address_fn)(void (*)(void))loader;
#    endif
}
#endif
/* ---- 0.3 names (end) -------------------------------------------------------------------- */

#ifdef __cplusplus
}
#endif

#endif /* GRASS_GRASS_GL_H */
