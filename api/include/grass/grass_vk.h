/*
 * grass_vk.h - what a Vulkan host hands over, and the recording calls.
 *
 * Includes no Vulkan header: dispatchable handles (VkInstance, VkPhysicalDevice,
 * VkDevice, VkCommandBuffer) travel as void*, non-dispatchable ones (VkRenderPass) as
 * uint64_t, formats and sample counts as their VkFormat / VkSampleCountFlagBits values.
 *
 * The host owns the instance, device, queues, command buffers and render targets. The
 * plugin owns its pipelines, buffers, images and descriptor pools, records into the
 * host's command buffers and never submits, waits on a queue, or presents.
 *
 * Per frame:
 *   grass_begin_frame(ctx, &view);            plan (CPU only)
 *   grass_vk_prepare(ctx, &prepare);          outside a render pass: uploads + barriers
 *   ... host begins its render pass ...
 *   grass_vk_record(ctx, &record);            inside the pass, in its first subpass
 *   ... host ends the pass, submits ...
 *   grass_end_frame(ctx);
 *
 * Debug labels (grass.h, grass_debug_labels_desc): where the host enabled VK_EXT_debug_utils
 * on its instance, grass names its objects and labels its passes in the host's command
 * buffers (vkCmdBeginDebugUtilsLabelEXT / vkCmdEndDebugUtilsLabelEXT, balanced within each
 * call).
 *
 * Frames in flight: the plugin keeps frames_in_flight copies of its per-frame buffers and
 * uses them in turn, one per grass_begin_frame(). The host must have waited for the GPU
 * to finish frame N - frames_in_flight before it calls grass_begin_frame() for frame N,
 * as it does for its own per-frame resources.
 *
 * Threads and secondary command buffers:
 *   - Every call may run on any thread. A context is externally synchronized (grass.h,
 *     "Thread safety"): its calls must not overlap, and a context moves between threads
 *     only where the host orders the calls (a join, a mutex). Separate contexts on one
 *     VkDevice share no grass object and may run at the same time, each on its thread:
 *     one context per view records a main view and shadow cascades on four threads.
 *   - grass_vk_record records into a primary command buffer inside the pass, or into a
 *     secondary one that the host began with VK_COMMAND_BUFFER_USAGE_RENDER_PASS_CONTINUE_BIT
 *     and the pass's inheritance (the render pass and subpass of grass_vk_desc, or, for
 *     dynamic rendering, VkCommandBufferInheritanceRenderingInfo with its colour and depth
 *     formats and sample count) and executes in the pass
 *     (VK_SUBPASS_CONTENTS_SECONDARY_COMMAND_BUFFERS or
 *     VK_RENDERING_CONTENTS_SECONDARY_COMMAND_BUFFERS_BIT). It inherits no state: it binds
 *     and sets all it draws with, viewport and scissor included. grass_vk_prepare records
 *     into a primary outside any pass (a worker's own, submitted before the pass).
 *   - The command buffers, their pools and the queue are the host's to synchronize: grass
 *     records into the buffer it is given (on the calling thread) and touches no pool and
 *     no queue. It creates and frees its own Vulkan objects on the calling thread, which
 *     Vulkan allows on one device from several threads at once.
 */
#ifndef GRASS_GRASS_VK_H
#define GRASS_GRASS_VK_H

#include "grass.h"

#ifdef __cplusplus
extern "C" {
#endif

/* VKAPI_PTR (vk_platform.h), spelled here so that no Vulkan header is needed: the calling
 * convention of Vulkan's entry points. */
#if defined(_WIN32)
#    define GRASS_VKAPI_PTR __stdcall
#elif defined(__ANDROID__) && defined(__ARM_ARCH) && __ARM_ARCH >= 7 && defined(__ARM_32BIT_STATE)
#    define GRASS_VKAPI_PTR __attribute__((pcs("aapcs-vfp")))
#else
#    define GRASS_VKAPI_PTR
#endif

/* VkInstance is `struct VkInstance_T*` (VK_DEFINE_HANDLE); declaring the struct includes no
 * Vulkan header. */
struct VkInstance_T;
/* PFN_vkVoidFunction. */
typedef void(GRASS_VKAPI_PTR* grass_vk_void_function)(void);
/* PFN_vkGetInstanceProcAddr, its very type: `vk_desc.get_instance_proc_addr =
 * vkGetInstanceProcAddr;` needs no cast, in C and C++. Before 0.5 it took a void* instance
 * and needed a cast; a cast to it still compiles (docs/migrating.md). */
typedef grass_vk_void_function(GRASS_VKAPI_PTR* grass_vk_get_instance_proc_addr_fn)(struct VkInstance_T* instance,
                                                                                    const char* name);

typedef struct grass_vk_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_DESC */
    /* NULL, or a chain of extensions (0.5): a grass_vk_host_objects_desc, a
     * grass_vk_multiview_desc, a grass_vk_depth_pass_desc, a grass_vk_velocity_target_desc,
     * a grass_vk_gbuffer_target_desc, each at most once, in any order */
    const void* next;
    grass_vk_get_instance_proc_addr_fn get_instance_proc_addr; /* required */
    void* instance;                                            /* VkInstance, required */
    void* physical_device;                                     /* VkPhysicalDevice, required */
    void* device;                                              /* VkDevice, required; Vulkan 1.1 or newer */
    uint32_t queue_family; /* the family of the queue the host submits grass work on */
    /* Either a render pass (the plugin draws in its subpass `subpass`) ... */
    uint64_t render_pass; /* VkRenderPass, or 0 for dynamic rendering */
    uint32_t subpass;     /* default 0 */
    /* ... or dynamic rendering (render_pass = 0; the host enabled dynamicRendering). */
    uint32_t color_format;     /* VkFormat of the single colour attachment */
    uint32_t depth_format;     /* VkFormat of the depth attachment, required */
    uint32_t sample_count;     /* VkSampleCountFlagBits of the pass: 1, 2, 4, 8...; default 1 */
    uint32_t frames_in_flight; /* 1..8; default 2 */
} grass_vk_desc;

GRASS_API grass_vk_desc grass_default_vk_desc(void);

/* 0.5: what else the host lends grass, chained through grass_vk_desc.next (the desc itself
 * never changes layout: grass.h, "ABI and versions"). Both default to grass's own. */
typedef struct grass_vk_host_objects_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC */
    const void* next;       /* NULL, or a further extension of grass_vk_desc */
    /* The host's host-memory allocator for Vulkan objects: a const VkAllocationCallbacks*,
     * or NULL (default: the driver's). grass copies the struct; its pUserData must stay valid
     * until the context is destroyed. Every vkCreate*, vkDestroy*, vkAllocateMemory and
     * vkFreeMemory grass makes passes it (each object is destroyed with the callbacks it was
     * made with). pfnAllocation, pfnReallocation and pfnFree are required, and
     * pfnInternalAllocation and pfnInternalFree are both set or both NULL (Vulkan's rule);
     * otherwise GRASS_ERROR_INVALID_ARGUMENT. Device memory itself is grass's own: a few
     * blocks per memory type (docs/integration.md, "Memory"). */
    const void* allocation_callbacks;
    /* VkPipelineCache of the host, or 0 (the default): grass makes its own, which
     * grass_get_pipeline_cache_data saves and grass_pipeline_desc.cache_data seeds. When
     * given, every pipeline grass makes goes through it (vkCreate*Pipelines only: grass never
     * merges into it nor reads it back); the host keeps it alive until the context is
     * destroyed, and made it without VK_PIPELINE_CACHE_CREATE_EXTERNALLY_SYNCHRONIZED_BIT if
     * other threads use it meanwhile. */
    uint64_t pipeline_cache;
} grass_vk_host_objects_desc;

/* 0.5 */
GRASS_API grass_vk_host_objects_desc grass_default_vk_host_objects_desc(void);

/* 0.5: Stereo (grass_stereo_view_desc; docs/integration.md, "Stereo: multiview"), chained
 * through grass_vk_desc.next. */
typedef struct grass_vk_multiview_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC */
    const void* next;       /* NULL, or a further extension of grass_vk_desc */
    /* The view mask of the pass grass draws in. 0 (the default): a mono pass, as without
     * this struct. 0x3: a multiview pass of two views, view 0 the first eye and view 1 the
     * second, into 2-layer attachments; every frame of the context is then a stereo frame.
     * Dynamic rendering: the host begins its rendering with VkRenderingInfo::viewMask 0x3; a
     * render pass: its subpass has view mask 0x3 (VkRenderPassMultiviewCreateInfo). The host
     * enabled the multiview feature (VkPhysicalDeviceMultiviewFeatures, or
     * Vulkan11Features.multiview); a device without it is refused (GRASS_ERROR_UNSUPPORTED).
     * Its pipelines run the multiview shader variant; a context without stereo has exactly
     * the pipelines, shaders and memory of before. */
    uint32_t view_mask;
} grass_vk_multiview_desc;

/* 0.5 */
GRASS_API grass_vk_multiview_desc grass_default_vk_multiview_desc(void);

/* 0.5: Depth-only passes (grass_view_pass_desc, GRASS_PASS_DEPTH; docs/engine-frames.md,
 * "Shadows: grass in the host's shadow maps"), chained through grass_vk_desc.next: the
 * host's depth-only target that grass draws its depth views in (a shadow map's pass, which
 * has no colour attachment). Its fields follow grass_vk_desc's. grass makes depth-only
 * pipelines against it on the first depth view that draws each tier and feature mask: no
 * colour attachment, no colour writes, no alpha to coverage, the view's depth bias as
 * dynamic state (vkCmdSetDepthBias). Without this struct a context refuses a depth view
 * (GRASS_ERROR_INVALID_STATE); a context that never draws one holds nothing for it. Not with
 * grass_vk_multiview_desc.view_mask 0x3 (GRASS_ERROR_INVALID_ARGUMENT). */
typedef struct grass_vk_depth_pass_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC */
    const void* next;       /* NULL, or a further extension of grass_vk_desc */
    /* Either a render pass whose subpass `subpass` has a depth attachment and no colour
     * attachment ... */
    uint64_t render_pass; /* VkRenderPass, or 0 (the default) for dynamic rendering */
    uint32_t subpass;     /* default 0 */
    /* ... or dynamic rendering (render_pass = 0): a depth attachment alone. */
    uint32_t depth_format; /* VkFormat of the depth attachment, required */
    uint32_t sample_count; /* VkSampleCountFlagBits of the pass: 1, 2, 4...; default 1 */
} grass_vk_depth_pass_desc;

/* 0.5 */
GRASS_API grass_vk_depth_pass_desc grass_default_vk_depth_pass_desc(void);

/* 0.5: Motion vectors (grass_view_motion_desc; docs/engine-frames.md, "Motion vectors"),
 * chained through grass_vk_desc.next: the colour attachments of the pass grass draws in
 * (grass_vk_desc's render pass subpass, or its dynamic rendering) when that pass also holds
 * a velocity target. grass makes its motion pipelines against it on the first motion view
 * that draws each tier and feature mask: colour attachment 0 the lit colour as without it,
 * attachment velocity_attachment written .rg unblended (.ba masked off), every other colour
 * attachment's write mask 0; the GrassMotion block per view slot in the view's descriptor
 * set of grass's own (shared with a receiving view's shadow map, so one view may both
 * receive shadows and write motion vectors). A motion view's
 * grass_view_motion_desc.velocity_attachment must equal
 * velocity_attachment. Without this struct a context refuses a motion view
 * (GRASS_ERROR_INVALID_STATE); a context that never draws one holds nothing for it. Not with
 * grass_vk_multiview_desc.view_mask 0x3 (GRASS_ERROR_INVALID_ARGUMENT). The velocity is in
 * viewport units with Vulkan's clip y: +y is down the framebuffer (GL's encoding is y up). */
typedef struct grass_vk_velocity_target_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC */
    const void* next;       /* NULL, or a further extension of grass_vk_desc */
    /* How many colour attachments the pass has: 2 to 8 (attachment 0 is the lit colour,
     * grass_vk_desc.color_format under dynamic rendering). Default 2. */
    uint32_t color_attachment_count;
    /* The index of the velocity target among them: 1 to color_attachment_count - 1. Default 1. */
    uint32_t velocity_attachment;
    /* Dynamic rendering (grass_vk_desc.render_pass 0): the VkFormat of every colour
     * attachment other than 0, in order (index i - 1 for attachment i; the velocity's a
     * float format with R and G, e.g. VK_FORMAT_R16G16_SFLOAT), each not
     * VK_FORMAT_UNDEFINED. A render pass: ignored. */
    uint32_t color_formats[7];
} grass_vk_velocity_target_desc;

/* 0.5 */
GRASS_API grass_vk_velocity_target_desc grass_default_vk_velocity_target_desc(void);

/* 0.5: G-buffer views (grass_view_pass_desc GRASS_PASS_GBUFFER, grass_view_gbuffer_desc;
 * docs/engine-frames.md, "Deferred renderers"), chained through grass_vk_desc.next: the colour
 * attachments of the pass grass draws in (grass_vk_desc's render pass subpass, or its dynamic
 * rendering) when the host draws G-buffer views in it. A G-buffer view's
 * grass_view_gbuffer_desc.attachment_count must equal color_attachment_count; attachment i
 * of its layout is colour attachment i of the pass. grass makes a G-buffer view's pipelines
 * on the first view that draws each layout (the semantic and write mask of every attachment),
 * tier and feature mask: each semantic's output goes to its attachment, unblended, with the
 * attachment's write mask (a NONE attachment's is 0), and grass's other outputs are left out
 * of the module; depth tested and written as a colour view's; no alpha to coverage. The
 * GrassGBuffer block lives per view slot in the view's descriptor set of grass's own (with a
 * motion view's GrassMotion block: a G-buffer view may write velocity). The device needs
 * independentBlend when the pass has more than one colour attachment. Without this struct a
 * context refuses a G-buffer view (GRASS_ERROR_INVALID_STATE); a context that never draws one
 * holds nothing for it. Mono only: not with grass_vk_multiview_desc.view_mask 0x3
 * (GRASS_ERROR_INVALID_ARGUMENT). With a grass_vk_velocity_target_desc besides, both describe
 * the same pass: their color_attachment_count must agree. Every pipeline of the context (its
 * colour views' too) then has a blend state per attachment; a colour view writes attachment 0
 * alone. Sample count: grass_vk_desc.sample_count, for every attachment. */
typedef struct grass_vk_gbuffer_target_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC */
    const void* next;       /* NULL, or a further extension of grass_vk_desc */
    /* How many colour attachments the pass has: 1 to 8. Default 4. */
    uint32_t color_attachment_count;
    /* Dynamic rendering (grass_vk_desc.render_pass 0): the VkFormat of every colour
     * attachment after the first, at its index (color_formats[i] for attachment i), each not
     * VK_FORMAT_UNDEFINED; color_formats[0] is ignored (attachment 0's is
     * grass_vk_desc.color_format). A render pass: ignored. */
    uint32_t color_formats[8];
} grass_vk_gbuffer_target_desc;

/* 0.5 */
GRASS_API grass_vk_gbuffer_target_desc grass_default_vk_gbuffer_target_desc(void);

GRASS_API grass_result grass_vk_create_context(uint32_t header_version, const grass_context_desc* desc,
                                               const grass_vk_desc* vk_desc, grass_context** out_context);

/* Records pending uploads (patches, maps) and the barriers that make them visible to the
 * vertex and fragment stages, and the responsive grass's interaction pass. Call between
 * grass_begin_frame() and the render pass that grass_vk_record() draws in, every frame (a
 * frame of several views: once, after grass_plan_view of view 0, before any view's pass); it
 * records nothing when nothing is pending and the frame has no pass (still grass, or no
 * colliders and no trail to age). grass_vk_record() refuses a frame whose pass was not
 * recorded (GRASS_MSG_UPLOAD_NOT_RECORDED).
 *
 * The interaction pass (responsive grass, docs/responsive.md): the interaction map is one
 * RGBA32F image per level, N x N texels, shared by every frame in flight (it persists from
 * frame to frame), always in VK_IMAGE_LAYOUT_GENERAL. For a frame with colliders or a trail
 * grass_vk_prepare records, after the uploads:
 *   1. Only the first time after the map is made (or remade by grass_set_interaction): a
 *      barrier UNDEFINED -> GENERAL (TOP_OF_PIPE -> TRANSFER, access 0 -> TRANSFER_WRITE)
 *      and vkCmdClearColorImage of each level to the cleared texel.
 *   2. One image barrier per level, GENERAL -> GENERAL:
 *      src stages VERTEX_SHADER | FRAGMENT_SHADER | COMPUTE_SHADER | TRANSFER,
 *      src access SHADER_WRITE | TRANSFER_WRITE  ->  dst stage COMPUTE_SHADER,
 *      dst access SHADER_READ | SHADER_WRITE.
 *      It orders this frame's pass after every earlier submitted use of the map: the draws
 *      of earlier frames that read it (write-after-read, which frames in flight make
 *      possible), the previous pass and the clear (read/write-after-write).
 *   3. vkCmdBindPipeline (compute) and, per level, vkCmdBindDescriptorSets (compute) and
 *      vkCmdDispatch(ceil(N / 8), ceil(N / 8), 1).
 *   4. One image barrier per level, GENERAL -> GENERAL: src COMPUTE_SHADER / SHADER_WRITE ->
 *      dst VERTEX_SHADER | FRAGMENT_SHADER / SHADER_READ (this frame's draws texelFetch it).
 * The blade window pass (responsive grass, docs/responsive.md "The blade window"): each
 * blade's per-blade state stepped and its pose computed once per frame for the geometry
 * draws of view 0 that the core gives the window, into one device-local storage buffer (the
 * records) shared by every frame in flight, read by every view's draws of the window variant
 * in the vertex shader. For a frame with wind or colliders grass_vk_prepare records, after
 * the interaction pass:
 *   4b. Only on a frame whose window grew: a memory barrier src COMPUTE_SHADER / SHADER_WRITE
 *      -> dst TRANSFER / TRANSFER_READ, then vkCmdCopyBuffer of the old records into the new
 *      buffer (the blades the window keeps keep their state); step 5 orders the pass after it.
 *   5. One memory barrier: src stages TRANSFER | VERTEX_SHADER | COMPUTE_SHADER, src access
 *      SHADER_WRITE | TRANSFER_WRITE  ->  dst stage COMPUTE_SHADER, dst access SHADER_READ |
 *      SHADER_WRITE. It orders the pass after the earlier frames' draws that read the poses
 *      (write-after-read: frames in flight share them), after the previous pass (write-after-
 *      write), and after what it reads: this frame's interaction pass and uploads.
 *   6. Per draw: vkCmdBindPipeline (compute), vkCmdBindDescriptorSets (compute, sets 0-2: the
 *      draw's, its work items, the colliders) and vkCmdDispatch(ceil(blades / 64), work items,
 *      1); with push constants where the device reads the blocks at an index (lavapipe).
 *   7. One buffer barrier on the poses: src COMPUTE_SHADER / SHADER_WRITE -> dst VERTEX_SHADER /
 *      SHADER_READ (this frame's draws read them).
 * Still grass records none of it and holds no window.
 * The host's compute pipeline binding is changed (it rebinds its own after). These barriers
 * order work within one queue in submission order, so submit every frame's grass work to the
 * queue of vk_desc.queue_family, in frame order. The device needs nothing beyond Vulkan 1.1
 * core for it (storage images of a declared format, storage buffers in the vertex stage
 * read only); the blade window needs 8 storage buffers in the compute stage
 * (maxPerStageDescriptorStorageBuffers), and a device with fewer poses every blade per vertex,
 * statelessly. */
typedef struct grass_vk_prepare_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_PREPARE_DESC */
    const void* next;       /* NULL */
    void* command_buffer;   /* VkCommandBuffer outside any render pass */
} grass_vk_prepare_desc;

/* 0.5 */
GRASS_API grass_vk_prepare_desc grass_default_vk_prepare_desc(void);

/* 0.5: replaces grass_vk_prepare_frame(context, command_buffer) (docs/migrating.md). */
GRASS_API grass_result grass_vk_prepare(grass_context* context, const grass_vk_prepare_desc* prepare);

typedef struct grass_vk_record_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VK_RECORD_DESC */
    const void* next;       /* NULL */
    void* command_buffer;   /* VkCommandBuffer inside the host's render pass: a primary, or a
                               secondary that inherits the pass (see "Threads" above) */
} grass_vk_record_desc;

GRASS_API grass_vk_record_desc grass_default_vk_record_desc(void);

/* Records the draws of the begun frame. Binds its own pipeline and descriptor sets, may
 * set push constants of its own pipeline layout, and sets viewport and scissor from the
 * view; the host must rebind its own state after. A stereo context (grass_vk_multiview_desc.view_mask 0x3) records
 * each draw once; the pass's multiview runs it for both eyes (one viewport for both). */
GRASS_API grass_result grass_vk_record(grass_context* context, const grass_vk_record_desc* record);

/* 0.5: Records view `view` of the begun frame (grass_plan_view's index; grass_vk_record
 * records view 0), as grass_vk_record does. Each view has its own per-frame buffers and
 * descriptor sets: recording one never disturbs another's recorded commands. */
GRASS_API grass_result grass_vk_record_view(grass_context* context, uint32_t view, const grass_vk_record_desc* record);

/* ---- 0.3 names (begin): see grass.h's block of the same name ----------------------------- */
#if defined(GRASS_RENAMED)
GRASS_RENAMED(grass_vk_default_desc, grass_default_vk_desc, 0.4)
GRASS_API grass_vk_desc grass_vk_default_desc(void);
GRASS_RENAMED(grass_vk_default_record_desc, grass_default_vk_record_desc, 0.4)
GRASS_API grass_vk_record_desc grass_vk_default_record_desc(void);
#endif
/* ---- 0.3 names (end) -------------------------------------------------------------------- */

/* ---- 0.4 names (begin): see grass.h's block of the same name ----------------------------- */
#if defined(GRASS_RENAMED)
GRASS_RENAMED(grass_vk_prepare_frame, grass_vk_prepare, 0.5)
GRASS_API grass_result grass_vk_prepare_frame(grass_context* context, void* command_buffer);
#endif
/* ---- 0.4 names (end) -------------------------------------------------------------------- */

#ifdef __cplusplus
}
#endif

#endif /* GRASS_GRASS_VK_H */
