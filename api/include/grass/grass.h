/*
 * grass.h - the stable C interface of the grass renderer.
 *
 * One generated grass patch is tiled over the cells of a field, each cell randomly
 * mirrored; per-blade density thresholds against a density map thin the grass. The host
 * owns the GPU device, the frame and the rest of the scene; this library owns grass.
 *
 * This header is backend-neutral: it includes no GL or Vulkan header. The calls that
 * hand over a GL context or a Vulkan device, and that draw, are in grass_gl.h and
 * grass_vk.h.
 *
 * Conventions
 *   - C99; every type and function is prefixed grass_, every macro and enum GRASS_.
 *   - Objects made from a context are small id structs with a generation: a stale id (its
 *     object was destroyed), a foreign id (made by another context) or the zero id is
 *     refused with GRASS_ERROR_INVALID_HANDLE, never dereferenced.
 *   - Every create call takes a *_desc struct that begins with its type tag and a next
 *     pointer (reserved for extensions; must be NULL today). Fill a desc with its
 *     grass_default_*_desc() and change what you need.
 *   - Calls that can fail return grass_result. Bad input is refused with an error, a log
 *     message names the argument and its value, and the earlier state stays intact.
 *   - Units: metres, seconds, radians, linear RGB. Patch geometry is in *patch units*:
 *     the ground square of a patch is 1 x 1 and a field scales it to its cell size.
 *
 * ABI and versions
 *   A program built against this header runs against any later library of the same major
 *   version. Within a major version:
 *   - Structs the caller fills (every *_desc, grass_allocator, grass_map_stack,
 *     grass_tier_desc, grass_lod_test, grass_quality_desc, the id structs: whatever the
 *     library reads, whatever a grass_default_*() or grass_quality_preset() returns by
 *     value, every element of an array) never change layout. Values returned by value and
 *     arrays with a stride cannot be grown safely, so new inputs come as extension structs
 *     chained through a desc's next pointer, each with its own type tag.
 *   - Structs the library fills (grass_frame_stats, grass_memory_stats, grass_patch_info)
 *     only grow at the end. Each context keeps the GRASS_HEADER_VERSION given to the call
 *     that created it, and every getter writes only the bytes the struct had in that
 *     header version: an older program gets the fields it knows of and nothing past them.
 *     grass_lod_node, which the library fills for a lod test callback, also only grows at
 *     the end: a callback reads the fields it knows of.
 *   - The array lengths the library writes to (GRASS_TIER_KIND_COUNT, GRASS_MAX_TIERS,
 *     GRASS_MAX_LOD_TESTS, GRASS_DEFAULT_TIER_COUNT, GRASS_DEFAULT_LOD_TEST_COUNT) do not
 *     change.
 *   - Functions are only added; a renamed function keeps its old symbol for programs
 *     built against the older header, and this header declares its old name only to
 *     sources that define GRASS_ENABLE_DEPRECATED ("Renamed names" below); a renamed
 *     field keeps its place, and its old name is an alias for those sources.
 *   - The numeric values of enums, struct type tags and message ids never change.
 *
 * Thread safety
 *   A context is externally synchronized: calls on one context must not overlap. Separate
 *   contexts share nothing and may be used from separate threads. The library's only
 *   global state is thread-safe: the registry of live contexts' owner tags (see "Ids"
 *   below) and counters that make names unique. Allocation and log callbacks are per context and are called on the
 *   thread that made the call that triggered them.
 *
 * Re-entrancy
 *   While a callback of a context runs (a GRASS_LOD_TEST_CALLBACK during grass_begin_frame,
 *   the log callback, an allocator hook), every call on that same context is refused with
 *   GRASS_ERROR_INVALID_STATE and GRASS_MSG_REENTRANT_CALL and changes nothing
 *   (grass_destroy_context logs the refusal and destroys nothing). Allowed are the calls
 *   that take no context (grass_result_string, grass_default_*, the id tests, ...) and the
 *   two getters grass_get_last_error and grass_get_context_backend. A refusal made inside
 *   the log callback is kept as the last error but not logged again (no recursion); one
 *   made inside another callback is logged. Calls on other contexts are allowed.
 *
 * Ids
 *   An id's owner tag is unique among the live contexts of the process: a process-wide
 *   counter hands tags out in turn and skips those still live, so the tag of a destroyed
 *   context comes back only after 65,534 more contexts were made. A slot whose generation
 *   would wrap is retired, never reused. So an id is refused as stale for the whole life
 *   of its context once its object is destroyed, and as foreign by every other context,
 *   unless 65,534 contexts were made after its own was destroyed.
 *
 * Ownership
 *   Pointers passed in descs are read during the call only and never kept (map pixels are
 *   copied). Strings passed to callbacks live until the callback returns.
 */
#ifndef GRASS_GRASS_H
#define GRASS_GRASS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Version ---------------------------------------------------------------------- */

/* The one version number of grass: the build reads it from here (CMakeLists.txt). */
#define GRASS_VERSION_MAJOR 0
#define GRASS_VERSION_MINOR 5
#define GRASS_VERSION_PATCH 0
/* The version this header declares. Pass it to the create-context calls: the library
 * refuses a header whose major version differs from its own, whose minor is newer than its
 * own, or whose minor is older than 3 (0.3 is the oldest header whose struct layouts the
 * library knows); see "ABI and versions" above. */
#define GRASS_HEADER_VERSION \
    ((uint32_t)((GRASS_VERSION_MAJOR << 22) | (GRASS_VERSION_MINOR << 12) | GRASS_VERSION_PATCH))

#if defined(_WIN32) && defined(GRASS_SHARED)
#    ifdef GRASS_BUILDING
#        define GRASS_API __declspec(dllexport)
#    else
#        define GRASS_API __declspec(dllimport)
#    endif
#elif defined(__GNUC__)
#    define GRASS_API __attribute__((visibility("default")))
#else
#    define GRASS_API
#endif

/* The calling convention of every callback grass calls (log, allocation, LOD tests, the GL
 * loader): VKAPI_PTR's rule (vk_platform.h), __stdcall on Windows (which 64-bit Windows
 * ignores: it has one convention), nothing elsewhere. Define a callback with it between the
 * return type and the name, as Vulkan's VKAPI_CALL:
 *   static void GRASS_API_PTR on_log(void* user_data, grass_log_level level,
 *                                    grass_message_id id, const char* message) { ... }
 * Where it is empty (every platform but 32-bit Windows) a callback without it converts as
 * before. Vulkan's own entry point (grass_vk_get_instance_proc_addr_fn) follows VKAPI_PTR
 * exactly (GRASS_VKAPI_PTR, grass_vk.h). */
#if defined(_WIN32)
#    define GRASS_API_PTR __stdcall
#else
#    define GRASS_API_PTR
#endif

/* ---- Renamed names -----------------------------------------------------------------------
 * A name renamed since 0.3 stays declared for source code that defines
 * GRASS_ENABLE_DEPRECATED before including grass: each use then compiles with a deprecation
 * warning that names the new name (functions: the "0.3 names" and "0.4 names" blocks at the
 * ends of the headers; fields: an alias in the struct). Without the macro a use of an old
 * function name is a compile error that says so (GCC 12+, Clang), never an implicit
 * declaration (whose int result would truncate grass_last_error's pointer).
 * docs/migrating.md lists every rename. */
#if defined(_MSC_VER)
#    define GRASS_DEPRECATED(msg) __declspec(deprecated(msg))
#elif defined(__GNUC__) || defined(__clang__)
#    define GRASS_DEPRECATED(msg) __attribute__((deprecated(msg)))
#elif defined(__cplusplus) && __cplusplus >= 201402L
#    define GRASS_DEPRECATED(msg) [[deprecated(msg)]]
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 202311L
#    define GRASS_DEPRECATED(msg) [[deprecated(msg)]]
#else
#    define GRASS_DEPRECATED(msg)
#endif

/* GRASS_RENAMED(old_name, new_name, version): the attribute of a name renamed in `version`. */
#if defined(GRASS_ENABLE_DEPRECATED)
#    define GRASS_RENAMED(old_name, new_name, version) \
        GRASS_DEPRECATED(#old_name " was renamed " #new_name " in grass " #version " (docs/migrating.md)")
#elif defined(__has_attribute)
#    if __has_attribute(unavailable)
#        define GRASS_RENAMED(old_name, new_name, version)                                                \
            __attribute__((unavailable(#old_name " was renamed " #new_name " in grass " #version          \
                                                 "; define GRASS_ENABLE_DEPRECATED to keep the old name " \
                                                 "(docs/migrating.md)")))
#    endif
#endif

/* A renamed struct field keeps its old name as a second member of an anonymous union, so
 * layout and size do not change. Only with GRASS_ENABLE_DEPRECATED, and only where anonymous
 * unions are standard (C11 and later, C++): in C99 an old field name is not declared. */
#if defined(GRASS_ENABLE_DEPRECATED) && \
    (defined(__cplusplus) || (defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L))
#    define GRASS_FIELD_ALIASES 1
#endif

/* The version of the library that is linked (same encoding as GRASS_HEADER_VERSION). */
GRASS_API uint32_t grass_get_library_version(void);

/* ---- Results ---------------------------------------------------------------------- */

typedef enum grass_result {
    GRASS_SUCCESS = 0,
    GRASS_ERROR_INVALID_ARGUMENT = -1,  /* a value is out of range, NaN, infinite or NULL */
    GRASS_ERROR_INVALID_HANDLE = -2,    /* a stale, foreign or zero id */
    GRASS_ERROR_WRONG_STRUCT_TYPE = -3, /* a desc whose type tag is not the one expected */
    GRASS_ERROR_INVALID_STATE = -4,     /* a call in the wrong order (e.g. drawing outside a frame) */
    GRASS_ERROR_OUT_OF_MEMORY = -5,     /* host or GPU memory could not be allocated */
    GRASS_ERROR_VERSION_MISMATCH = -6,  /* the header and the library do not match */
    GRASS_ERROR_BACKEND = -7,           /* the GPU API failed; the log says which call */
    GRASS_ERROR_UNSUPPORTED = -8,       /* the device or the build lacks what is needed */
    GRASS_ERROR_IN_USE = -9             /* the object is still used by another object */
} grass_result;

/* A static English name for a result code, e.g. "GRASS_ERROR_INVALID_HANDLE". */
GRASS_API const char* grass_result_string(grass_result result);

typedef uint32_t grass_bool; /* 0 = false, anything else = true */

/* ---- Struct type tags ------------------------------------------------------------- */

typedef enum grass_struct_type {
    GRASS_STRUCT_TYPE_CONTEXT_DESC = 0x67720001,
    GRASS_STRUCT_TYPE_PATCH_DESC = 0x67720002,
    GRASS_STRUCT_TYPE_FIELD_DESC = 0x67720003,
    GRASS_STRUCT_TYPE_MAP_DESC = 0x67720004,
    GRASS_STRUCT_TYPE_VIEW_DESC = 0x67720005,
    GRASS_STRUCT_TYPE_GRASS_TYPE_DESC = 0x67720006,
    GRASS_STRUCT_TYPE_QUALITY_DESC = 0x67720007,
    GRASS_STRUCT_TYPE_GL_DESC = 0x67720101,
    GRASS_STRUCT_TYPE_VK_DESC = 0x67720201,
    GRASS_STRUCT_TYPE_VK_RECORD_DESC = 0x67720202,
    GRASS_STRUCT_TYPE_VK_PREPARE_DESC = 0x67720203,         /* 0.5 */
    GRASS_STRUCT_TYPE_VK_HOST_OBJECTS_DESC = 0x67720204,    /* 0.5 */
    GRASS_STRUCT_TYPE_VK_MULTIVIEW_DESC = 0x67720205,       /* 0.5 */
    GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC = 0x67720206,      /* 0.5: depth-only passes on Vulkan */
    GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC = 0x67720207, /* 0.5: motion vectors on Vulkan */
    GRASS_STRUCT_TYPE_VK_GBUFFER_TARGET_DESC = 0x67720208,  /* 0.5: G-buffer views on Vulkan */
    /* 0.5: responsive grass */
    GRASS_STRUCT_TYPE_BLADE_MECHANICS = 0x67720008,
    GRASS_STRUCT_TYPE_WIND_DESC = 0x67720009,
    GRASS_STRUCT_TYPE_INTERACTION_DESC = 0x6772000A,
    GRASS_STRUCT_TYPE_WIND_MAP_DESC = 0x6772000B,
    GRASS_STRUCT_TYPE_BLADE_CULLING_DESC = 0x6772000C,
    GRASS_STRUCT_TYPE_PIPELINE_DESC = 0x6772000D,           /* 0.5 */
    GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC = 0x6772000E,       /* 0.5 */
    GRASS_STRUCT_TYPE_STEREO_VIEW_DESC = 0x6772000F,        /* 0.5: stereo */
    GRASS_STRUCT_TYPE_LOD_ORIGIN_DESC = 0x67720010,         /* 0.5 */
    GRASS_STRUCT_TYPE_FRAME_DESC = 0x67720011,              /* 0.5: frames and views */
    GRASS_STRUCT_TYPE_VIEW_PASS_DESC = 0x67720012,          /* 0.5: depth-only passes (shadows) */
    GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC = 0x67720013,     /* 0.5: the host's shadow maps, received */
    GRASS_STRUCT_TYPE_VIEW_MOTION_DESC = 0x67720014,        /* 0.5: motion vectors */
    GRASS_STRUCT_TYPE_VIEW_LIGHTS_DESC = 0x67720015,        /* 0.5: the host's lights */
    GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC = 0x67720016,       /* 0.5: G-buffer passes (deferred hosts) */
    GRASS_STRUCT_TYPE_BLADE_TESSELLATION_DESC = 0x67720017, /* 0.5: dynamic tessellation of the blades */
    GRASS_STRUCT_TYPE_MESH_FIELD_DESC = 0x67720018          /* 0.5: grass on a host's triangle mesh */
} grass_struct_type;

/* ---- Logging ---------------------------------------------------------------------- */

typedef enum grass_log_level {
    GRASS_LOG_ERROR = 0,   /* a call was refused or failed */
    GRASS_LOG_WARNING = 1, /* a call succeeded but something looks wrong */
    GRASS_LOG_INFO = 2     /* lifetime events (context, device, patch baked) */
} grass_log_level;

/* Numbered message ids: stable across versions, so hosts and tests can match them. */
typedef enum grass_message_id {
    GRASS_MSG_NONE = 0,
    /* 1xx: arguments */
    GRASS_MSG_NULL_ARGUMENT = 100,
    GRASS_MSG_WRONG_STRUCT_TYPE = 101,
    GRASS_MSG_NEXT_NOT_NULL = 102,
    GRASS_MSG_NOT_FINITE = 103,     /* NaN or infinity in a number */
    GRASS_MSG_OUT_OF_RANGE = 104,   /* a number outside its documented range */
    GRASS_MSG_RANGE_INVERTED = 105, /* a min greater than its max */
    GRASS_MSG_ZERO_CELLS = 106,
    /* a matrix the call cannot use: a field's base_transform that is not a proper rotation
     * (orthonormal within 1e-5, no mirroring) plus translation with last row (0, 0, 0, 1);
     * a singular view rotation; an all-zero projection; a singular maps.cell_to_map */
    GRASS_MSG_BAD_TRANSFORM = 107,
    GRASS_MSG_BAD_MAP = 108, /* a design map of bad size, pitch or format */
    GRASS_MSG_BAD_ENUM = 109,
    GRASS_MSG_ZERO_VECTOR = 110,
    GRASS_MSG_MAP_ROLE = 111,      /* a map whose format does not fit its role in a map stack */
    GRASS_MSG_MAP_REGION = 112,    /* a map update outside the map or of another format */
    GRASS_MSG_IN_GRASS_TYPE = 113, /* warning after an error: which grass type of a desc->next chain it is in */
    /* 2xx: handles and lifetime */
    GRASS_MSG_STALE_HANDLE = 200,
    GRASS_MSG_FOREIGN_HANDLE = 201,
    GRASS_MSG_NULL_HANDLE = 202,
    GRASS_MSG_PATCH_IN_USE = 203, /* a patch still used by a field (before 0.5 also a map) */
    GRASS_MSG_TOO_MANY_OBJECTS = 204,
    GRASS_MSG_MAP_IN_USE = 205, /* 0.5: a map still used by a field */
    /* 3xx: call order */
    GRASS_MSG_FRAME_NOT_BEGUN = 300,
    GRASS_MSG_FRAME_ALREADY_BEGUN = 301,
    GRASS_MSG_WRONG_BACKEND = 302,
    GRASS_MSG_UPLOAD_NOT_RECORDED = 303,
    /* 0.5: a call made from inside a callback of the same context (a lod test callback, the
     * log callback, an allocator hook), refused with GRASS_ERROR_INVALID_STATE; see
     * "Re-entrancy" above. */
    GRASS_MSG_REENTRANT_CALL = 304,
    /* 4xx: version and environment */
    GRASS_MSG_VERSION_MISMATCH = 400,
    GRASS_MSG_DEVICE_UNSUPPORTED = 401,
    GRASS_MSG_BACKEND_CALL_FAILED = 402,
    GRASS_MSG_OUT_OF_MEMORY = 403,
    GRASS_MSG_INTERNAL_ERROR = 404, /* a broken internal invariant (a bug in grass, not the host's): the frame
                                       * plan, a field's maps or a baked slice set disagree with what the core
                                       * uploaded. Returned as GRASS_ERROR_INVALID_STATE: the context's state
                                       * cannot serve the call; the same in every backend. Please report it. */
    /* 0.4: warning: a file of the bake cache (grass_context_desc.cache_directory) was truncated,
     * corrupt, of another grass version or of another patch, and was baked again and
     * rewritten; or the cache directory cannot be written (missing, read-only, full): said
     * once per context, which then bakes without the cache. */
    GRASS_MSG_BAKE_CACHE = 405,
    /* 0.4: the GPU device was lost (Vulkan VK_ERROR_DEVICE_LOST), returned as
     * GRASS_ERROR_BACKEND: the context cannot draw again; destroy it (that stays safe) and
     * make a new one on a new device. */
    GRASS_MSG_DEVICE_LOST = 406,
    /* 0.5: warning: grass_view_desc.time went backwards (a host restarted its clock): the
     * responsive grass state keeps going with a time step of 0 for that frame. */
    GRASS_MSG_TIME_BACKWARDS = 407,
    /* 0.5: a call of a GL context (grass_gl_create_context) made while the GL context it was
     * created with is not current on the calling thread (none is, or another one is):
     * refused with GRASS_ERROR_INVALID_STATE before any GL call (grass_gl.h). */
    GRASS_MSG_GL_CONTEXT_NOT_CURRENT = 408,
    /* 0.5: warning: a pipeline cache blob (grass_pipeline_desc.cache_data) was ignored: too
     * short, not grass's, of another backend, grass version, device, driver or shader set,
     * truncated or corrupt; or the driver refused a program binary in it. grass compiles
     * what it needs instead, so the call still succeeds. */
    GRASS_MSG_PIPELINE_CACHE = 409,
    /* 0.5: warning: GRASS_DEBUG_LABELS_ON was asked for, and the API cannot label (Vulkan
     * without VK_EXT_debug_utils on the instance): the context works, unlabelled. */
    GRASS_MSG_DEBUG_LABELS_UNAVAILABLE = 410,
    /* 0.5: a frame was refused because the context's per-frame resources are all held by
     * unfinished frames (grass_frame_desc.completed_frame_index; Vulkan: frames_in_flight). */
    GRASS_MSG_FRAMES_IN_FLIGHT = 411,
    /* 0.5: a view with a grass_view_motion_desc was drawn where its velocity cannot go (GL: the
     * bound draw framebuffer is the default one, or its draw buffer velocity_attachment is
     * GL_NONE), refused with GRASS_ERROR_INVALID_STATE before anything is drawn. */
    GRASS_MSG_VELOCITY_TARGET = 412,
    /* 0.5: warning: more colliders than GRASS_MAX_COLLIDERS_PER_TILE (1024) reached one tile of the
     * interaction map (docs/responsive.md): the tile keeps those reaching lowest, the others
     * press nothing there. Said once per context; the frame goes on. */
    GRASS_MSG_COLLIDER_TILE_CAP = 413,
    /* 0.5: a G-buffer view (GRASS_PASS_GBUFFER) was drawn where its attachments cannot go (GL:
     * the bound draw framebuffer is the default one, or the draw buffer of an attachment that
     * grass writes is GL_NONE; Vulkan: the context has no grass_vk_gbuffer_target_desc, or
     * the view's attachment count is not its), refused before anything is drawn. */
    GRASS_MSG_GBUFFER_TARGET = 414,
    /* 0.5: a call that applies to a grid field only (its wind map, per-blade culling) was
     * given a mesh field (grass_create_mesh_field), refused with GRASS_ERROR_INVALID_ARGUMENT.
     * Also a warning: grass_create_mesh_field skipped degenerate triangles (zero area), the
     * field made without them; or it made a mesh field on a GL or Vulkan context, whose
     * backend does not draw mesh fields yet (docs/mesh-fields.md). */
    GRASS_MSG_MESH_FIELD = 415,
    /* 5xx: information */
    GRASS_MSG_CONTEXT_CREATED = 500,
    GRASS_MSG_PATCH_GENERATED = 501
} grass_message_id;

/* Called for every message the context emits. `message` is one English sentence that
 * names the call, the argument and the value. */
typedef void(GRASS_API_PTR* grass_log_fn)(void* user_data, grass_log_level level, grass_message_id id,
                                          const char* message);

/* ---- Allocation ------------------------------------------------------------------- */

/* Host-memory hooks. All three are set or all are NULL (then malloc/free are used).
 * `alignment` is a power of two no larger than 64. free_fn is never given NULL. */
typedef struct grass_allocator {
    void*(GRASS_API_PTR* alloc_fn)(void* user_data, size_t size, size_t alignment);
    void(GRASS_API_PTR* free_fn)(void* user_data, void* ptr);
    void* user_data;
} grass_allocator;

/* ---- Context ---------------------------------------------------------------------- */

typedef struct grass_context grass_context; /* opaque */

typedef enum grass_depth_mode {
    GRASS_DEPTH_LESS = 0,   /* depth 0 is near: classic, the default */
    GRASS_DEPTH_GREATER = 1 /* depth 1 is near: reversed-Z hosts */
} grass_depth_mode;

typedef struct grass_context_desc {
    grass_struct_type type;    /* GRASS_STRUCT_TYPE_CONTEXT_DESC */
    const void* next;          /* NULL, or a chain of extensions: a grass_debug_labels_desc (0.5) */
    grass_allocator allocator; /* default: all NULL = malloc/free */
    grass_log_fn log_fn;       /* default NULL: messages are dropped */
    void* log_user_data;
    grass_log_level log_level;   /* highest level passed to log_fn; default GRASS_LOG_WARNING */
    grass_depth_mode depth_mode; /* the host's depth convention; default GRASS_DEPTH_LESS */
    /* A directory where baked slices (the volume and image tiers' textures) are cached,
     * keyed by a hash of the patch desc, so a host starts fast the second time. NULL (the
     * default): bake every time. The directory must exist; the string is copied. */
    const char* cache_directory;
} grass_context_desc;

GRASS_API grass_context_desc grass_default_context_desc(void);

/* 0.5: debug labels and object names, for frame debuggers (RenderDoc, Nsight) and
 * validation messages (docs/integration.md, "Frame debuggers and calling
 * conventions"). With them on, every object
 * grass creates carries a name beginning "grass " (buffers, images, views, samplers,
 * pipelines, layouts, descriptor pools and set layouts, memory, query pools; GL: buffers,
 * textures, samplers, programs, vertex arrays, queries) and grass's work in a command
 * buffer or GL frame is grouped under labels: "grass uploads" and "grass interaction pass"
 * (grass_vk_prepare; GL: inside "grass render"), and "grass draw" (GL: "grass render") with
 * one label inside per tier kind drawn ("grass blades", "grass volumes", "grass images").
 *   Vulkan: grass calls VK_EXT_debug_utils, which the host enables on its instance (grass
 *   cannot): it is there when the host's vkGetInstanceProcAddr returns
 *   vkSetDebugUtilsObjectNameEXT and vkCmdBeginDebugUtilsLabelEXT.
 *   GL: KHR_debug (GL 4.3 core): glObjectLabel, glPushDebugGroup / glPopDebugGroup.
 * Off, it costs one branch per object created and per label, and builds no string. */
typedef enum grass_debug_labels {
    /* The default: on in a GL debug context (GL_CONTEXT_FLAG_DEBUG_BIT), and on Vulkan when
     * the host enabled VK_EXT_debug_utils on its instance; off otherwise. */
    GRASS_DEBUG_LABELS_AUTO = 0,
    /* Never: grass names nothing (but the vertex array of grass_gl.h's current-context
     * check, labelled "grass context N" always) and pushes no label. */
    GRASS_DEBUG_LABELS_OFF = 1,
    /* Always on GL; on Vulkan whenever VK_EXT_debug_utils is enabled (without it grass
     * cannot label, and says so in a warning, GRASS_MSG_DEBUG_LABELS_UNAVAILABLE). */
    GRASS_DEBUG_LABELS_ON = 2
} grass_debug_labels;

/* Chained through grass_context_desc.next (any backend; the null backend has nothing to
 * label). */
typedef struct grass_debug_labels_desc {
    grass_struct_type type;    /* GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC */
    const void* next;          /* NULL, or a further extension of grass_context_desc */
    grass_debug_labels labels; /* default GRASS_DEBUG_LABELS_AUTO */
} grass_debug_labels_desc;

/* 0.5 */
GRASS_API grass_debug_labels_desc grass_default_debug_labels_desc(void);

/* A context with no GPU backend: it generates patches, plans frames and reports stats,
 * and draws nothing. For tools, tests and servers. The GPU contexts are made by
 * grass_gl_create_context() and grass_vk_create_context(). */
GRASS_API grass_result grass_create_context(uint32_t header_version, const grass_context_desc* desc,
                                            grass_context** out_context);

/* Destroys every object of the context and the context. NULL is accepted. For a GPU
 * context the host's device must be idle with respect to grass work (Vulkan) or its GL
 * context current (GL). */
GRASS_API void grass_destroy_context(grass_context* context);

typedef enum grass_backend { GRASS_BACKEND_NONE = 0, GRASS_BACKEND_GL = 1, GRASS_BACKEND_VULKAN = 2 } grass_backend;

GRASS_API grass_backend grass_get_context_backend(const grass_context* context);

/* The message of the last error this context reported, or "" if none. Valid until the
 * next call on the context. */
GRASS_API const char* grass_get_last_error(const grass_context* context);

/* The most memory heaps a device reports (Vulkan's VK_MAX_MEMORY_HEAPS). */
#define GRASS_MAX_MEMORY_HEAPS 16

typedef struct grass_memory_stats {
    uint64_t host_bytes;       /* host memory the context holds now, through its allocator */
    uint64_t host_allocations; /* live host allocations */
    uint64_t gpu_bytes;        /* GPU memory the backend holds (buffers + textures) */
    /* 0.4: */
    uint64_t host_bytes_peak; /* the highest host_bytes since the context was created */
    /* 0.5: */
    /* GPU memory of the responsive grass (included in gpu_bytes): the interaction map and
     * each patch's blade control points, made at the first frame that needs them. 0 for a
     * context that never had wind or colliders. Bounded by grass_interaction_desc: it does
     * not grow with the fields, the time or the number of colliders. */
    uint64_t dynamics_gpu_bytes;
    /* 0.5, the device memory per heap (Vulkan). gpu_bytes above is what grass's resources
     * take; grass allocates device memory in blocks per memory type (docs/integration.md,
     * "Memory"), so a heap's heap_allocated is at least its heap_in_use. Heap h is the
     * device's VkPhysicalDeviceMemoryProperties::memoryHeaps[h]; entries from heap_count on
     * are 0. GL reports no heap (heap_count 0, every entry 0): OpenGL has no portable
     * query of device memory, and Mesa's llvmpipe has none at all; gpu_bytes stays what grass's
     * buffers and textures take. */
    uint32_t heap_count;                             /* the device's memory heaps; 0 on GL and without a GPU */
    uint32_t heap_budget_known;                      /* 1: heap_budget and heap_usage are filled */
    uint64_t device_allocations;                     /* live vkAllocateMemory of grass (blocks + dedicated) */
    uint64_t heap_size[GRASS_MAX_MEMORY_HEAPS];      /* bytes of each heap */
    uint64_t heap_allocated[GRASS_MAX_MEMORY_HEAPS]; /* device memory grass allocated on the heap */
    uint64_t heap_in_use[GRASS_MAX_MEMORY_HEAPS];    /* of it, bytes bound to grass's resources */
    /* Where the device has VK_EXT_memory_budget (heap_budget_known 1), read at this call
     * (grass queries it on the physical device; the host need not enable the extension):
     * heap_budget: what the whole process can allocate on the heap without degrading;
     * heap_usage: what the whole process, not only grass, has allocated there. Else 0. */
    uint64_t heap_budget[GRASS_MAX_MEMORY_HEAPS];
    uint64_t heap_usage[GRASS_MAX_MEMORY_HEAPS];
} grass_memory_stats;

GRASS_API grass_result grass_get_memory_stats(const grass_context* context, grass_memory_stats* out_stats);

/* ---- Handles ---------------------------------------------------------------------- */

/* A zero-initialised id is the null id. Compare ids with grass_*_id_equal() and test them
 * with grass_*_id_is_null() (below). */
typedef struct grass_patch_id {
    uint32_t index;      /* slot + 1; 0 = null */
    uint16_t generation; /* bumped when the slot is reused */
    uint16_t owner;      /* tag of the context that made it */
} grass_patch_id;

typedef struct grass_field_id {
    uint32_t index;
    uint16_t generation;
    uint16_t owner;
} grass_field_id;

typedef struct grass_map_id {
    uint32_t index;
    uint16_t generation;
    uint16_t owner;
} grass_map_id;

/* 1 when both ids name the same object of the same context (or both are null), else 0. */
GRASS_API grass_bool grass_patch_id_equal(grass_patch_id a, grass_patch_id b);
GRASS_API grass_bool grass_field_id_equal(grass_field_id a, grass_field_id b);
GRASS_API grass_bool grass_map_id_equal(grass_map_id a, grass_map_id b);
/* 1 for the null id (all zero), else 0. A non-null id may still be stale. */
GRASS_API grass_bool grass_patch_id_is_null(grass_patch_id id);
GRASS_API grass_bool grass_field_id_is_null(grass_field_id id);
GRASS_API grass_bool grass_map_id_is_null(grass_map_id id);

/* ---- Patch: a grass type ---------------------------------------------------------- */

typedef enum grass_threshold_mode {
    /* Density thresholds spread at random over the patch: thinning keeps isolated blades. */
    GRASS_THRESHOLD_UNIFORM = 0,
    /* Thresholds follow equalised Perlin noise plus a Gaussian of width cluster_sigma
     * (lemme2012 4.1.3): thin grass grows in clumps. */
    GRASS_THRESHOLD_CLUSTERED = 1
} grass_threshold_mode;

/* One grass type. The generated blades are rooted on the unit ground square of the
 * patch; tips may reach outside it. All lengths are in patch units (cell edge = 1).
 * Every min/max pair must satisfy 0 <= min <= max. */
typedef struct grass_patch_desc {
    grass_struct_type type;       /* GRASS_STRUCT_TYPE_PATCH_DESC */
    const void* next;             /* NULL */
    uint32_t blade_count;         /* blades per patch, 1..65536; default 384 */
    uint32_t subdivisions;        /* quads along a blade, 1..32; default 4 */
    float length_min, length_max; /* blade arc length; default 0.45 .. 0.85 */
    float width_min, width_max;   /* blade width at the root; default 0.018 .. 0.032 */
    float tilt_min, tilt_max;     /* radians from vertical at the root, 0..1.5; default 0.05 .. 0.55 */
    float bend_min, bend_max;     /* gravity pull on the trajectory, relative to length, 0..2; default 0.2 .. 0.7 */
    float root_color[3];          /* linear RGB at the root; default (0.05, 0.12, 0.02) */
    float tip_color[3];           /* linear RGB at the tip; default (0.28, 0.45, 0.09) */
    float blade_color_variation;  /* 0..1: per-blade darkening and hue shift; default 0.35 */
    float vertex_color_variation; /* 0..1: per-vertex modulation; default 0.08 */
    grass_threshold_mode threshold_mode; /* default GRASS_THRESHOLD_CLUSTERED */
    float cluster_sigma;                 /* clustered mode: Gaussian width, 0..1; default 0.12 */
    uint32_t cluster_frequency;          /* clustered mode: noise periods per patch, 1..64; default 3 */
    float ao_impact;                     /* B_impact of lemme eq. 6.11, 0..1; default 0.65 */
    float ao_height;                     /* B_height of eq. 6.11 in patch units, > 0; default 0.55 */
    uint64_t seed;                       /* default 1; the same desc and seed give identical blades */
} grass_patch_desc;

GRASS_API grass_patch_desc grass_default_patch_desc(void);

/* Generates the patch. GPU contexts upload it at once (GL: the host's GL context must be
 * current; Vulkan: it is copied to the device by the next grass_vk_prepare()). */
GRASS_API grass_result grass_create_patch(grass_context* context, const grass_patch_desc* desc,
                                          grass_patch_id* out_patch);

/* Fails with GRASS_ERROR_IN_USE while a field uses the patch. */
GRASS_API grass_result grass_destroy_patch(grass_context* context, grass_patch_id patch);

typedef struct grass_patch_info {
    uint32_t blade_count;
    uint32_t vertex_count;
    uint32_t triangle_count; /* per patch instance, all blades drawn */
    float bounds_min[3];     /* patch units; tips may leave the unit square */
    float bounds_max[3];
    uint64_t content_hash; /* FNV-1a 64 of the generated blade data: pins determinism */
} grass_patch_info;

GRASS_API grass_result grass_get_patch_info(const grass_context* context, grass_patch_id patch,
                                            grass_patch_info* out_info);

/* Reads the generated per-blade density thresholds, in blade order (for tools and tests).
 * `capacity` is the number of floats `out_thresholds` holds; at least blade_count. */
GRASS_API grass_result grass_get_patch_thresholds(const grass_context* context, grass_patch_id patch,
                                                  float* out_thresholds, uint32_t capacity);

/* ---- Design maps (lemme2012 6.4, boulanger2006 3.4-3.5) ---------------------------- */

typedef enum grass_map_format {
    GRASS_MAP_FORMAT_R8_UNORM = 1,     /* uint8, 0..255 -> 0..1 */
    GRASS_MAP_FORMAT_R16_UNORM = 2,    /* uint16, 0..65535 -> 0..1 */
    GRASS_MAP_FORMAT_R32_FLOAT = 3,    /* float, finite, 0..1 */
    GRASS_MAP_FORMAT_RGBA8_UNORM = 4,  /* 4 x uint8 (colour maps) */
    GRASS_MAP_FORMAT_RGBA16_UNORM = 5, /* 4 x uint16 (colour maps) */
    GRASS_MAP_FORMAT_RGBA32_FLOAT = 6  /* 4 x float, finite, 0..1 (colour maps) */
} grass_map_format;

/* An image in host memory, copied by the call that takes it. Maps are projected along the
 * field's up axis: texel (0, 0) is at map uv (0, 0) and rows run along +v. Sampled
 * bilinearly with edge clamping; every value, whatever the format, means 0..1. */
typedef struct grass_map_desc {
    grass_struct_type type;  /* GRASS_STRUCT_TYPE_MAP_DESC */
    const void* next;        /* NULL */
    const void* pixels;      /* row 0 first; rows run along +v (field +z), texels along +u (+x) */
    uint32_t width, height;  /* 1..16384 */
    uint32_t row_pitch;      /* bytes between rows; 0 = tightly packed */
    grass_map_format format; /* default GRASS_MAP_FORMAT_R8_UNORM */
} grass_map_desc;

GRASS_API grass_map_desc grass_default_map_desc(void);

/* A design map on its own, which fields reference through their grass_map_stack; several
 * fields may share one (GPU contexts upload it once). The core keeps a min/max pyramid of
 * it, so the quadtree knows each node's terrain height range and whether it holds grass. */
GRASS_API grass_result grass_create_map(grass_context* context, const grass_map_desc* desc, grass_map_id* out_map);

/* Replaces the texels of the rectangle whose first texel is (x, y) and whose size is
 * region->width x region->height, with region->pixels (same format as the map; its
 * row_pitch applies). Paint or mow grass at run time: the next frame plans and draws with
 * the new texels; nothing outside the rectangle changes. Not between grass_begin_frame and
 * grass_end_frame. GL: the host's GL context must be current. Vulkan: the copy is recorded
 * by the next grass_vk_prepare(). */
GRASS_API grass_result grass_update_map(grass_context* context, grass_map_id map, uint32_t x, uint32_t y,
                                        const grass_map_desc* region);

/* Fails with GRASS_ERROR_IN_USE while a field uses the map. */
GRASS_API grass_result grass_destroy_map(grass_context* context, grass_map_id map);

/* The design maps of a field (lemme figure 6.7). Every map is optional: a null id (all
 * zero) means the field does without it, and its shaders do not sample it. */
typedef struct grass_map_stack {
    /* Single-channel: multiplies grass_field_desc.density. Blades whose density threshold
     * lies above the local density are not drawn (bilinear, lemme 6.4.1); a quadtree node
     * whose density is zero everywhere is discarded with its subtree. */
    grass_map_id density;
    /* RGBA: colour modulation C = A_c C_c + (1 - A_c) C_blade (lemme eq. 6.8); a high alpha
     * paints field marks, a low alpha varies the lawn subtly. sRGB-encoded rgb, linear alpha. */
    grass_map_id color;
    /* Single-channel: the ambient light, with the scene's ambient occlusion already in it;
     * multiplies grass_view_desc.ambient_color (lemme eq. 6.9-6.10; boulanger 3.5). */
    grass_map_id ambient;
    /* Single-channel: the diffuse (sun) light the scenery lets through: shadows cast by the
     * host's buildings and trees; multiplies grass_view_desc.sun_color (lemme figure 7.8). */
    grass_map_id diffuse;
    /* Single-channel: the terrain height along the field's up axis, times height_scale
     * metres (lemme 6.4.4). Every tier is displaced by it. */
    grass_map_id height;
    float height_scale; /* metres for a height-map value of 1; finite, 0..1e5; default 1 */
    /* Cell space to map space (lemme's configTf): map (u, v) = (m[0] x + m[2] z + m[4],
     * m[1] x + m[3] z + m[5]) for a point (x, z) of the field in cells. All zero (the
     * default): the maps span the whole field, u = x / cells_x, v = z / cells_z. Another
     * transform lets several fields share one map stack, or maps a region in finer detail. */
    double cell_to_map[6];
} grass_map_stack;

/* ---- Tiers and lod tests (lemme2012 6.1.2-6.1.3, 6.2) ------------------------------ */

/* How a tier draws its instances. */
typedef enum grass_tier_kind {
    GRASS_TIER_GEOMETRY = 0, /* blades as geometry; cells only, never macro-cells */
    GRASS_TIER_VOLUME = 1,   /* a ray-cast volume of vertical slices */
    GRASS_TIER_IMAGE = 2     /* one horizontal slice */
} grass_tier_kind;
/* The length of the per-tier-kind arrays of grass_frame_stats and grass_get_tier_gpu_ms:
 * fixed within a major version. */
#define GRASS_TIER_KIND_COUNT 3
#define GRASS_MAX_TIERS 8
#define GRASS_MAX_LOD_TESTS 32

typedef struct grass_tier_desc {
    grass_tier_kind kind;
    uint32_t slices; /* volume tiers: vertical slices per axis, 1..64; 0 for the others */
} grass_tier_desc;

/* What a lod test answers for a quadtree node. */
typedef enum grass_lod_answer {
    GRASS_LOD_DISCARD = 0, /* the node and its subtree are not drawn by this test's tier */
    GRASS_LOD_SPLIT = 1,   /* ask again for the node's children (a cell is drawn instead) */
    GRASS_LOD_DRAW = 2     /* draw the node whole (a macro-cell unless it is one cell) */
} grass_lod_answer;

/* A quadtree node as a lod test sees it. Level 0 nodes are cells; a node of level k spans
 * up to 2^k x 2^k cells (fewer at the field's far edges). */
typedef struct grass_lod_node {
    uint32_t level;
    uint32_t cell_x, cell_z;   /* its first cell */
    uint32_t cells_x, cells_z; /* cells it spans */
    uint32_t tier;             /* index of the tier the asking test feeds */
    double center[3];          /* world-space bounding sphere of its box */
    double radius;
    double distance_min; /* metres from the camera to the nearest point of its box */
    double distance_max; /* ... and to the farthest */
    double height_min;   /* metres: the lowest terrain height under the node (0 without a height map) */
    double height_max;   /* ... and the highest */
} grass_lod_node;

typedef grass_lod_answer(GRASS_API_PTR* grass_lod_test_fn)(void* user_data, const grass_lod_node* node);

typedef enum grass_lod_test_kind {
    /* Draws the tier between begin and end metres from the camera: discards a node entirely
     * outside, draws one entirely inside, splits one across an edge (see edge_ratio).
     * transition_in and transition_out are the widths of its fade-in after begin and
     * fade-out before end, where it shares cells with the neighbouring tier. */
    GRASS_LOD_TEST_DISTANCE_BAND = 1,
    /* Splits until a node spans at most max_macro_cells cells each way, then draws it whole. */
    GRASS_LOD_TEST_MACRO_CELL = 2,
    /* Asks the host's callback. */
    GRASS_LOD_TEST_CALLBACK = 3,
    /* Terrain unplanarity (lemme 6.4.4): splits a node whose terrain height range (highest
     * minus lowest height of the height map over it, metres) exceeds max_unplanarity +
     * unplanarity_ratio x its distance from the camera, and draws it otherwise. Keeps
     * macro-cells on hills small enough that their flat slices follow the ground. */
    GRASS_LOD_TEST_UNPLANARITY = 4,
    /* Hilltop silhouettes (lemme 6.4.6, after Boulanger): discards the nodes whose bounding
     * box lies entirely below the camera and draws the others (bound their size with a
     * MACRO_CELL or UNPLANARITY test of the same tier). A tier with this test is an
     * *overlay*: it draws every blade the density passes, on top of the tiers the distance
     * bands share out, and takes no share itself. Give it a volume tier and a DISTANCE_BAND
     * where the image tier draws, so that distant hilltops keep their blades against the sky. */
    GRASS_LOD_TEST_HILLTOP = 5
} grass_lod_test_kind;

/* One lod test. All tests of a tier must answer draw for the tier to draw a node; any
 * discard drops the node's subtree for that tier; otherwise the node is split. A node
 * drawn or discarded by a tier is not asked again for that tier below it (the skip flags of
 * lemme figure 6.3). A geometry tier draws cells only: it splits a larger node. */
typedef struct grass_lod_test {
    grass_lod_test_kind kind;
    uint32_t tier;        /* index into grass_field_desc.tiers */
    float begin, end;     /* DISTANCE_BAND: metres, 0 <= begin < end; end may be INFINITY */
    float transition_in;  /* DISTANCE_BAND: metres, >= 0 */
    float transition_out; /* DISTANCE_BAND: metres, >= 0 */
    /* DISTANCE_BAND: a node that crosses begin or end is drawn whole (instead of split
     * down to cells) once its side is at most edge_ratio times its distance from the
     * camera: 0 = exact edges, more = fewer nodes and instances for some drawing beyond the
     * band (where the tier's blades are faded out). 0..1. */
    float edge_ratio;
    uint32_t max_macro_cells;   /* MACRO_CELL: cells, >= 1 */
    grass_lod_test_fn callback; /* CALLBACK: required; called during grass_begin_frame */
    void* user_data;            /* CALLBACK */
    float max_unplanarity;      /* UNPLANARITY: metres, >= 0 */
    float unplanarity_ratio;    /* UNPLANARITY: metres of height range allowed per metre of distance, 0..1 */
} grass_lod_test;

#define GRASS_DEFAULT_TIER_COUNT 5
#define GRASS_DEFAULT_LOD_TEST_COUNT 9

/* Lemme's football-field setup (lemme2012 chapter 7). His distances are in cells (his cell
 * is the unit patch), so they scale with cell_size: metres = value x cell_size.
 *   tier 0 geometry           0 .. 20 cells
 *   tier 1 volume, 8 slices   5 .. 80 cells, macro-cells up to 40 cells a side
 *   tier 2 volume, 2 slices  50 .. 160 cells, macro-cells up to 40
 *   tier 3 volume, 1 slice  100 .. 300 cells, macro-cells up to 40
 *   tier 4 image            200 cells .. infinity, macro-cells up to 500
 * Each overlap is the transition zone of the two tiers that share it; volume and image
 * bands have an edge_ratio of 0.25. A field that leaves its lod tests NULL and has a
 * height map also gets an UNPLANARITY test on its volume and image tiers (half a cell plus
 * 2% of the distance). Fills
 * GRASS_DEFAULT_TIER_COUNT tiers and GRASS_DEFAULT_LOD_TEST_COUNT tests. */
GRASS_API void grass_default_lod_setup(double cell_size, grass_tier_desc* out_tiers, grass_lod_test* out_tests);

/* ---- Quality: the speed/accuracy trade (docs/quality.md measures it) -------------- */

typedef enum grass_quality_level {
    GRASS_QUALITY_REFERENCE = 0, /* blades at every distance, 8 subdivisions, 4x MSAA: the ground truth */
    GRASS_QUALITY_HIGH = 1,      /* Lemme's table twice as far, twice the slices */
    GRASS_QUALITY_DEFAULT = 2,   /* Lemme's football table (grass_default_lod_setup), 4x MSAA */
    GRASS_QUALITY_LOW = 3,       /* tiers nearer, larger macro-cells, fewer blades, no MSAA */
    GRASS_QUALITY_FASTEST = 4    /* the cheapest setup that still looks like a lawn */
} grass_quality_level;
#define GRASS_QUALITY_LEVEL_COUNT 5

/* The knobs behind the presets. Each one trades speed for accuracy (docs/quality.md). */
typedef struct grass_quality_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_QUALITY_DESC */
    const void* next;       /* NULL */
    /* Blades at every distance (one geometry tier): the reference; the knobs below that
     * shape the other tiers are then unused. */
    grass_bool blades_everywhere;
    float distance_scale;   /* multiplies the default table's tier distances, 0.1..16; default 1 */
    float transition_scale; /* multiplies its transition widths (after distance_scale), 0..1.2; default 1 */
    float slice_scale;      /* multiplies its slices per axis (8, 2, 1), rounded, at least 1, at most 64; 0.125..8 */
    float macro_cell_scale; /* multiplies its macro-cell limits (40, 500), rounded, at least 1; 0.025..4 */
    uint32_t blade_subdivisions; /* quads along a blade, 1..32; default 4 */
    float blade_fraction;        /* of the patch's blade_count kept (at least 1 blade), (0, 1]; default 1 */
    uint32_t msaa_samples;       /* the sample count the preset is meant for (the host owns the target): 1, 2, 4 or 8 */
} grass_quality_desc;

/* The knobs of a preset. */
GRASS_API grass_quality_desc grass_quality_preset(grass_quality_level level);

/* Applies `quality` to a patch desc (blade count, subdivisions) and writes the lod setup for
 * fields of `cell_size` metres: up to GRASS_MAX_TIERS tiers and GRASS_MAX_LOD_TESTS tests,
 * their counts in *out_tier_count and *out_test_count. Refuses out-of-range knobs with an
 * error naming them (through the context's log), writing nothing. */
GRASS_API grass_result grass_apply_quality(grass_context* context, const grass_quality_desc* quality, double cell_size,
                                           grass_patch_desc* inout_patch, grass_tier_desc* out_tiers,
                                           uint32_t* out_tier_count, grass_lod_test* out_tests,
                                           uint32_t* out_test_count);

/* ---- Field: a grid of cells covered by one patch ---------------------------------- */

/* Field space: cell (i, j) covers [i, i+1] x [j, j+1] cell edges along x and z, y up.
 * base_transform maps field space scaled by cell_size (metres) to world space. */
typedef struct grass_field_desc {
    grass_struct_type type;    /* GRASS_STRUCT_TYPE_FIELD_DESC */
    const void* next;          /* NULL, or a chain of grass_grass_type_desc: more grass types */
    grass_patch_id patch;      /* required */
    uint32_t cells_x, cells_z; /* 1 .. 2^30 each; no default (0 is refused) */
    double cell_size;          /* metres per cell edge, 1e-4 .. 1e4; default 0.25 */
    double base_transform[16]; /* column-major, rotation + translation only, the translation
                                    within +-1e12 m (as the camera); default identity */
    float density;             /* uniform density 0..1 where no map is given, or the map's
                                    multiplier; default 1 */
    /* Optional, NULL = uniform density: a single-channel density map copied into this field
     * alone and spanning it (the shortcut for maps.density, which is refused with it). */
    const grass_map_desc* density_map;
    grass_bool mirror_tiling; /* mirror each cell along x and/or z at random; default 1 */
    uint32_t mirror_seed;     /* selects the mirror pattern; default 0 */
    /* The tiers and the lod tests that choose them per quadtree node. Both NULL (counts 0):
     * grass_default_lod_setup(cell_size). Copied at creation. */
    const grass_tier_desc* tiers;
    uint32_t tier_count; /* 1..GRASS_MAX_TIERS */
    const grass_lod_test* lod_tests;
    uint32_t lod_test_count; /* 1..GRASS_MAX_LOD_TESTS; every tier needs at least one */
    /* Where two tiers share a transition zone each blade is drawn by one of them; a blade
     * crossing over fades out of one tier as it fades into the other over this half-width,
     * in density-threshold units (lemme2012 eq. 5.26). Needs a multisampled target to show
     * (alpha-to-coverage for blades, sample masks for the slices); without one the
     * crossover is exact. 0..0.25; default 0.05. */
    float transition_window;
    /* The design maps: density (multiplying the density above and density_map), colour,
     * ambient, diffuse light and height. Default: none. */
    grass_map_stack maps;
} grass_field_desc;

GRASS_API grass_field_desc grass_default_field_desc(void);

#define GRASS_MAX_GRASS_TYPES 8

/* Another grass type on the same field (lemme 6.4.5): its own patch, density (and density
 * map) and tiers with lod tests, so types grow in their own places and change tier at
 * their own distances; it shares the field's cells, transform, mirroring and every other
 * map (colour, ambient, diffuse, height). Chain them from grass_field_desc.next (each
 * one's next points to the following type, the last one's is NULL): the field's own desc
 * is the first type, up to GRASS_MAX_GRASS_TYPES in all. The field id stands for all of
 * them; grass_destroy_field destroys them together. Frame stats count each type as a field. */
typedef struct grass_grass_type_desc {
    grass_struct_type type;       /* GRASS_STRUCT_TYPE_GRASS_TYPE_DESC */
    const void* next;             /* the next grass_grass_type_desc, or NULL */
    grass_patch_id patch;         /* required */
    float density;                /* 0..1, as grass_field_desc.density; default 1 */
    grass_map_id density_map;     /* single-channel, as grass_map_stack.density; default none */
    const grass_tier_desc* tiers; /* as in grass_field_desc; both NULL: the default setup */
    uint32_t tier_count;
    const grass_lod_test* lod_tests;
    uint32_t lod_test_count;
} grass_grass_type_desc;

GRASS_API grass_grass_type_desc grass_default_grass_type_desc(void);

GRASS_API grass_result grass_create_field(grass_context* context, const grass_field_desc* desc,
                                          grass_field_id* out_field);
GRASS_API grass_result grass_destroy_field(grass_context* context, grass_field_id field);

/* ---- Mesh field: grass on a host's triangle mesh (jahrmann2017 4) ------------------ */

/* 0.5: where a mesh field's density comes from (docs/mesh-fields.md). */
typedef enum grass_mesh_density_source {
    GRASS_MESH_DENSITY_UNIFORM = 0,    /* grass_mesh_field_desc.density everywhere */
    GRASS_MESH_DENSITY_PER_VERTEX = 1, /* vertex_density, 0..1 per vertex, interpolated, times density */
    GRASS_MESH_DENSITY_MAP = 2         /* maps.density sampled at the mesh's UVs, times density */
} grass_mesh_density_source;

/* 0.5: how blades are seeded on the mesh (jahrmann2017 4). */
typedef enum grass_mesh_seeding {
    GRASS_MESH_SEEDING_SINGLE_BLADES = 0, /* uniformly at random by area */
    GRASS_MESH_SEEDING_TUFTS = 1          /* Poisson-disk tuft centres, blades around each */
} grass_mesh_seeding;

/* 0.5: grass on any triangle mesh: a planet, a cliff, an overhang's underside, a roof. The
 * mesh's arrays are copied at creation (the host may free them after the call). Each blade
 * grows along the normal interpolated at its root, with the shape of a blade of `patch`.
 * The field id works where field ids do (grass_destroy_field destroys it); the calls of
 * grid fields only (grass_set_field_wind_map, grass_set_blade_culling) refuse it with
 * GRASS_MSG_MESH_FIELD. A triangle of zero area is skipped (not an error). Limits, costs and
 * the update design (deforming meshes): docs/mesh-fields.md. */
typedef struct grass_mesh_field_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_MESH_FIELD_DESC */
    const void* next;       /* NULL */
    grass_patch_id patch;   /* required: the blades' shape and colour */
    float patch_scale;      /* metres per patch unit (a blade's size), 1e-4..1e4; default 0.25 */
    /* The mesh. Strides in bytes between consecutive vertices' values, 0 = tightly packed
     * (12 for positions and normals, 8 for UVs, 4 for vertex_density); otherwise at least that
     * and a multiple of 4. Positions and normals in mesh space, normals not zero. */
    const float* positions;
    uint32_t position_stride;
    const float* normals;
    uint32_t normal_stride;
    const float* uvs; /* NULL: a mesh without UVs (no design maps then) */
    uint32_t uv_stride;
    uint64_t vertex_count;   /* 1 .. 2^31 - 1 */
    const uint32_t* indices; /* triangles, each below vertex_count */
    uint64_t index_count;    /* a multiple of 3, 3 .. 2^31 - 3 */
    /* Mesh space to world, column-major, affine and invertible (scale included: the density
     * counts blades per square metre of the transformed surface); the translation within
     * +-1e12 m. Default identity. */
    double transform[16];
    float density;                            /* blades per square metre, (0, 1e5]; default 100 */
    grass_mesh_density_source density_source; /* default GRASS_MESH_DENSITY_UNIFORM */
    const float* vertex_density;              /* PER_VERTEX: one value 0..1 per vertex */
    uint32_t vertex_density_stride;
    /* The design maps sampled at the mesh's UVs (needs uvs): density (with
     * GRASS_MESH_DENSITY_MAP) and colour; the other roles and cell_to_map are not used by
     * mesh fields and must be none/zero. */
    grass_map_stack maps;
    grass_mesh_seeding seeding; /* default single blades */
    float tuft_min_distance;    /* TUFTS: metres between tuft centres, (0, 1e4]; default 0.2 */
    float tuft_radius;          /* TUFTS: metres from a tuft's centre to its blades, [0, 1e4]; default 0.05 */
    uint32_t blades_per_tuft;   /* TUFTS: 1..4096; default 8 */
    uint32_t patch_blades;      /* blades per culling patch, 64..16384; default 1024 */
    uint32_t seed;              /* the scatter's seed: same seed and mesh, same blades; default 1 */
} grass_mesh_field_desc;

GRASS_API grass_mesh_field_desc grass_default_mesh_field_desc(void);

/* 0.5: scatters blades on the mesh and makes a field of them. Refused, naming the argument
 * and its value and leaving the context as it was: a NULL array, counts out of range, an
 * index not below vertex_count (named with its position), a NaN or infinite position,
 * normal, UV or vertex density, a zero normal, a transform that is not affine or not
 * invertible, a mesh whose triangles are all degenerate, more than 2^26 blades, maps that do
 * not fit. Between grass_begin_frame and grass_end_frame: GRASS_ERROR_INVALID_STATE. */
GRASS_API grass_result grass_create_mesh_field(grass_context* context, const grass_mesh_field_desc* desc,
                                               grass_field_id* out_field);

/* ---- Frames ----------------------------------------------------------------------- */

typedef enum grass_view_flags {
    GRASS_VIEW_FLAG_NONE = 0,
    /* Debugging: draw without the depth test (grass is drawn over the host's scene). Vulkan
     * draws it with pipelines of their own: grass_prepare_pipelines compiles them with
     * GRASS_PIPELINE_FEATURE_DEBUG_VIEWS; without that, the first frame that sets this flag
     * compiles those it draws with. GL toggles the test: nothing to compile. */
    GRASS_VIEW_FLAG_NO_DEPTH_TEST = 1u << 0,
    /* Debugging: tint each tier's grass: red geometry, yellow volume, blue image
     * (boulanger2006 figure 12, lemme2012 figure 7.1); the transition zones show both.
     * This flag and DEBUG_THRESHOLDS draw with shader variants of their own, compiled by the
     * first frame that sets one of them; frames without them run none of their code. */
    GRASS_VIEW_FLAG_DEBUG_TIERS = 1u << 1,
    /* Debugging: instead of grass, draw every planned instance as a flat box on the ground
     * in its tier's colour, the size of its cell or macro-cell. */
    GRASS_VIEW_FLAG_DEBUG_CELLS = 1u << 2,
    /* Debugging and tests: every tier writes, instead of its colour, the density threshold
     * of the blade it draws (16 bits: red = high byte, green = low byte, written so that an
     * 8-bit sRGB target stores those bytes exactly) and its tier kind in blue (0 geometry,
     * 128 volume, 255 image). Use a single-sampled target. */
    GRASS_VIEW_FLAG_DEBUG_THRESHOLDS = 1u << 3,
    /* 0.4: Colour output. Grass writes linear RGB, for a target that encodes it to sRGB as it
     * stores it (an sRGB format: GL_SRGB8_ALPHA8 with GL_FRAMEBUFFER_SRGB enabled,
     * VK_FORMAT_*_SRGB) or keeps it linear (a float HDR target the host tone-maps later).
     * A target that stores what the shader writes without conversion (a UNORM format, or GL
     * with GL_FRAMEBUFFER_SRGB disabled) shows that linear colour about 3.5 times too dark
     * in the mid tones: set this flag and grass encodes its colour to sRGB in the shader
     * instead. Multisampled, such a target then averages encoded samples at blade edges
     * (as it does for everything the host draws into it). The DEBUG_THRESHOLDS view keeps
     * its exact bytes with this flag on a UNORM target. */
    GRASS_VIEW_FLAG_ENCODE_SRGB = 1u << 4
} grass_view_flags;

/* The camera and lights of one frame. */
typedef struct grass_view_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VIEW_DESC */
    /* NULL, or a chain of the view's extensions (0.5), each at most once, in any order:
     * grass_stereo_view_desc (the second eye of a multiview pass), grass_lod_origin_desc,
     * grass_view_pass_desc, grass_shadow_receive_desc and grass_view_motion_desc. */
    const void* next;
    double camera_position[3]; /* world space, metres, within +-1e12 m each */
    /* World-to-eye matrix, column-major. Only its rotation is used: translation comes
     * from camera_position, so a host may pass a view built at the origin. */
    float view[16];
    /* Eye-to-clip matrix, column-major: exactly the projection the host renders its own
     * scene with in this frame and this viewport, the one its depth buffer was written with,
     * including its depth convention (reversed Z goes with GRASS_DEPTH_GREATER) and any
     * sub-pixel jitter (TAA); not a culling, shadow, LOD or un-jittered projection. Of an
     * engine's several projection matrices pass the one its render system draws with (the
     * API's clip z range and y direction, the depth range adjusted; docs/api.md names
     * Ogre's), in column-major order. GL: clip z in -1..1, or in 0..1 when the host sets
     * glClipControl(..., GL_ZERO_TO_ONE) (read at each grass_gl_render), y up. Vulkan: clip
     * z in 0..1 and y down (put the flip in the matrix: a negative viewport height is
     * refused). grass culls with it and takes every fragment's depth from it. Any invertible
     * matrix: perspective, orthographic, off-centre (its centre of projection may lie off
     * camera_position), infinite far, warped (a light-space perspective shadow map). */
    float projection[16];
    /* x, y, width, height in pixels of the host's target: the viewport the host draws its
     * scene with; width and height > 0. The origin follows the API, as the host's own
     * viewport call does: GL: (x, y) is the lower-left corner, y up from the bottom row
     * (glViewport); Vulkan: the upper-left corner, y down from the top row (VkViewport;
     * grass also sets the scissor to this rectangle). An engine with a top-left origin on GL
     * passes y = target height - top - height. x and y may be negative or reach past the
     * target; grass does not know the target's size and draws nothing where the rectangle
     * misses it, silently. */
    int32_t viewport[4];
    float sun_direction[3]; /* world-space direction towards the sun; not zero;
                                    default (0.35, 0.8, 0.25) */
    float sun_color[3];     /* linear RGB irradiance; default (1.0, 0.95, 0.85) */
    float ambient_color[3]; /* linear RGB; default (0.30, 0.36, 0.45) */
    /* Seconds, any origin: drives the wind, and the difference to the previous frame's time
     * is the time step of the responsive grass (collider trails recover with it). The first
     * frame of a context steps 0; a time earlier than the previous frame's steps 0 and warns
     * (GRASS_MSG_TIME_BACKWARDS). Within +-1e9 s; default 0. */
    double time;
    uint32_t flags; /* grass_view_flags; default 0 */
} grass_view_desc;

GRASS_API grass_view_desc grass_default_view_desc(void);

/* 0.5: Stereo (docs/integration.md, "Stereo: multiview"). Chained on grass_view_desc.next,
 * it makes the frame a stereo frame: grass_view_desc is the first eye (view 0 of the host's
 * multiview pass, layer 0 of its attachments) and this struct the second (view 1). Both eyes
 * are drawn by one grass_vk_record into a pass whose view mask is 0b11 (grass_vk_multiview_desc's
 * view_mask; the context must have been created for it). Both eyes share one plan: grass
 * culls against the union of the two frusta and measures the lod distances (and sorts the
 * blades) from one origin, the eyes' midpoint unless a grass_lod_origin_desc is chained too,
 * so both eyes draw the same blades, tiers and transitions. The eyes share the viewport,
 * sun, time and flags of grass_view_desc. A context without a backend plans it; GL
 * contexts refuse it (GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED: the GL backend
 * has no GL_OVR_multiview path, which Mesa's llvmpipe lacks). A Vulkan context made with a
 * view mask refuses a frame without it, and one made without refuses a frame with it. */
typedef struct grass_stereo_view_desc {
    grass_struct_type type;    /* GRASS_STRUCT_TYPE_STEREO_VIEW_DESC */
    const void* next;          /* the view's next extension, or NULL */
    double camera_position[3]; /* the second eye, world space, metres, as grass_view_desc's */
    float view[16];            /* its world-to-eye matrix, as grass_view_desc.view */
    float projection[16];      /* its eye-to-clip matrix, as grass_view_desc.projection */
} grass_stereo_view_desc;

/* Default: the identity view and projection at the world origin (set all three). */
GRASS_API grass_stereo_view_desc grass_default_stereo_view_desc(void);

/* 0.5: Chained on grass_view_desc.next: the point the lod tests measure their distances
 * from, the tiers' transitions and per-blade distance culling fade by, and the geometry
 * tier sorts its instances by (front to back), instead of the camera (mono) or the eyes'
 * midpoint (stereo). Positions and culling stay the camera's. A host draws a mono view with
 * the plan of a stereo frame by giving it the stereo frame's lod origin (the tests do); a
 * shadow or reflection view may give the main camera's. An orthographic view (projection[3],
 * [7] and [11] zero: a shadow cascade, a top-down map) has no eye to measure from: give it
 * the main camera's position or the point where its axis meets the ground. */
typedef struct grass_lod_origin_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_LOD_ORIGIN_DESC */
    const void* next;       /* the view's next extension, or NULL */
    double position[3];     /* world space, metres, within +-1e12 m each; default 0 */
} grass_lod_origin_desc;

GRASS_API grass_lod_origin_desc grass_default_lod_origin_desc(void);

/* 0.5: What a G-buffer view writes into one of the host's attachments
 * (grass_view_gbuffer_attachment). */
typedef enum grass_gbuffer_semantic {
    GRASS_GBUFFER_NONE = 0,   /* grass writes nothing there */
    GRASS_GBUFFER_ALBEDO = 1, /* the linear base colour, rgb (design maps applied, unlit) */
    GRASS_GBUFFER_NORMAL = 2, /* the world normal of the side facing the camera, xyz */
    /* r: roughness, 1 (grass's own lighting is Lambert's, two-sided, without specular);
     * g: translucency, 0.25 (the share of the light on a blade's back that its front lets
     * through, for a host that lights it); b (not in the default mask): the ambient occlusion
     * grass scales its ambient light by (the blades' own, eq. 6.11, times the ambient map). */
    GRASS_GBUFFER_MATERIAL = 3,
    /* rg: the velocity, as grass_view_motion_desc's encoding; needs a grass_view_motion_desc
     * on the view (else GRASS_ERROR_INVALID_ARGUMENT), whose velocity_attachment it ignores. */
    GRASS_GBUFFER_VELOCITY = 4
} grass_gbuffer_semantic;

/* How an attachment stores values: a normal is written n * 0.5 + 0.5 to a UNORM
 * attachment, as the signed vector to SNORM and FLOAT ones; the other semantics write their
 * values as they are (a UNORM attachment clamps velocity to 0..1: give it a FLOAT one). */
typedef enum grass_gbuffer_format {
    GRASS_GBUFFER_FORMAT_UNORM = 0, /* GL_RGBA8, GL_RGB10_A2, GL_SRGB8_ALPHA8 ... */
    GRASS_GBUFFER_FORMAT_SNORM = 1, /* GL_RGBA8_SNORM ... */
    GRASS_GBUFFER_FORMAT_FLOAT = 2  /* GL_RGBA16F, GL_RG16F, GL_R11F_G11F_B10F ... */
} grass_gbuffer_format;

#define GRASS_MAX_GBUFFER_ATTACHMENTS 8

/* One attachment of a G-buffer. */
typedef struct grass_gbuffer_attachment {
    grass_gbuffer_semantic semantic; /* default GRASS_GBUFFER_NONE; each other semantic once */
    grass_gbuffer_format format;     /* default GRASS_GBUFFER_FORMAT_UNORM */
    /* The channels grass writes: bit 1 r, 2 g, 4 b, 8 a; 0 to 15. The others keep what the
     * host had there. 0 (the default) takes the semantic's own: 7 (rgb) for ALBEDO and
     * NORMAL, 3 (rg) for MATERIAL and VELOCITY. */
    uint32_t write_mask;
} grass_gbuffer_attachment;

/* 0.5: Chained on grass_view_desc.next with a grass_view_pass_desc of GRASS_PASS_GBUFFER:
 * the host's G-buffer layout. GL: attachment i is the bound framebuffer's draw buffer i
 * (glDrawBuffers' list, GL_DRAW_BUFFERi); grass routes its outputs there for its draws and
 * restores the host's draw buffers and colour masks after. Vulkan: attachment i is colour
 * attachment i of the pass (grass_vk_gbuffer_target_desc; attachment_count must equal its
 * color_attachment_count, else GRASS_ERROR_INVALID_ARGUMENT); formats are the pass's. A
 * colour or depth view ignores it. A frame without a G-buffer view compiles, creates and
 * holds nothing for it. */
typedef struct grass_view_gbuffer_desc {
    grass_struct_type type;    /* GRASS_STRUCT_TYPE_VIEW_GBUFFER_DESC */
    const void* next;          /* the view's next extension, or NULL */
    uint32_t attachment_count; /* 1 to GRASS_MAX_GBUFFER_ATTACHMENTS; default 1 */
    grass_gbuffer_attachment attachments[GRASS_MAX_GBUFFER_ATTACHMENTS];
} grass_view_gbuffer_desc;

/* Default: one attachment, of semantic NONE (set the semantics). */
GRASS_API grass_view_gbuffer_desc grass_default_view_gbuffer_desc(void);

/* 0.5: What a view's pass writes (docs/engine-frames.md, "Shadows: grass in the host's shadow
 * maps"). */
typedef enum grass_pass_kind {
    GRASS_PASS_COLOR = 0, /* colour and depth, lit (the default) */
    /* Depth alone, for the host's shadow maps: every tier draws its alpha-tested coverage
     * (the blades as they are, the volume tier's ray to the depth the colour pass gives it,
     * the image tier's slice where its coverage passes) with a shader variant of its own that
     * does no lighting, and writes no colour (GL: every draw buffer's colour mask is off while
     * grass draws it; Vulkan: into the depth-only target of grass_vk_depth_pass_desc, which a
     * Vulkan context needs for it: without one it refuses a depth view, GRASS_ERROR_INVALID_STATE). */
    GRASS_PASS_DEPTH = 1,
    /* 0.5: A G-buffer, for deferred hosts (docs/engine-frames.md, "Deferred renderers"): every
     * tier writes its depth and the surface its lighting uses (base colour, normal, roughness
     * and translucency, velocity) into the host's attachments that a grass_view_gbuffer_desc
     * on the view describes (required: without one the view is refused,
     * GRASS_ERROR_INVALID_ARGUMENT), and nothing else: no lit colour, nothing in an attachment
     * of semantic NONE nor in a channel its write mask leaves off. Coverage is alpha-tested as
     * the depth pass's (no blending, no alpha to coverage). Vulkan: into the host's pass that
     * a grass_vk_gbuffer_target_desc describes, which a Vulkan context needs for it (without
     * one it refuses a G-buffer view, GRASS_ERROR_INVALID_STATE). */
    GRASS_PASS_GBUFFER = 2
} grass_pass_kind;

/* 0.5: Chained on grass_view_desc.next: the pass the view draws. Without it a view is a
 * GRASS_PASS_COLOR view. A depth pass takes none of the debug view flags or
 * GRASS_VIEW_FLAG_NO_DEPTH_TEST (GRASS_ERROR_INVALID_ARGUMENT). A frame without a depth view
 * compiles, creates and holds nothing for it. */
typedef struct grass_view_pass_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VIEW_PASS_DESC */
    const void* next;       /* the view's next extension, or NULL */
    grass_pass_kind pass;   /* default GRASS_PASS_COLOR */
    /* The depth bias of a depth pass, as the host's own shadow casters take it: GL
     * glPolygonOffset(depth_bias_slope, depth_bias_constant) while grass draws (restored
     * after; the volume tier, which writes its own depth, adds the bias its carrier box
     * got; Vulkan: vkCmdSetDepthBias(constant, 0, slope), dynamic state of grass's depth-only
     * pipelines). Added to the depth in the host's convention: positive pushes grass away from a
     * GRASS_DEPTH_LESS light, negative from a GRASS_DEPTH_GREATER (reversed) one. constant
     * within +-65536 units of the depth's resolution, slope within +-64; 0 and 0 (the
     * default) bias nothing. Ignored by a colour pass. */
    float depth_bias_constant;
    float depth_bias_slope;
} grass_view_pass_desc;

/* Default: GRASS_PASS_COLOR, no bias. */
GRASS_API grass_view_pass_desc grass_default_view_pass_desc(void);

/* 0.5: How a shadow map's stored depth compares with a point's (grass_shadow_receive_desc). */
typedef enum grass_shadow_compare {
    /* Lit where the point's depth <= the stored depth (standard depth: 0 near the light). */
    GRASS_SHADOW_COMPARE_LESS_EQUAL = 0,
    /* Lit where the point's depth >= the stored depth (reversed Z: 1 near the light). */
    GRASS_SHADOW_COMPARE_GREATER_EQUAL = 1
} grass_shadow_compare;

#define GRASS_MAX_SHADOW_CASCADES 4

/* 0.5: Chained on grass_view_desc.next: the view receives the host's sun shadows
 * (docs/engine-frames.md, "Receiving the host's shadows"). Every tier darkens the sun term of
 * its lighting (grass_view_desc.sun_color) by the share of the sun the map says reaches the
 * point (the blades at each fragment, the volume tier at each point its ray composites, the
 * image tier at its point); the ambient term stays. A view without it draws with the same
 * programs and memory as before. A depth pass (GRASS_PASS_DEPTH) ignores it (it writes no
 * lighting). Vulkan: mono contexts only (a multiview context refuses it,
 * GRASS_ERROR_UNSUPPORTED). The host keeps the map alive and unchanged (GL: its name valid,
 * its contents as drawn; Vulkan: the image and view, until the frame has finished on the
 * GPU) until grass has drawn the view. */
typedef struct grass_shadow_receive_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_SHADOW_RECEIVE_DESC */
    const void* next;       /* the view's next extension, or NULL */
    /* GL: the name of a GL_TEXTURE_2D_ARRAY depth texture (GL_DEPTH_COMPONENT*), layer i the
     * map of cascade i; grass reads its level 0 through a sampler of its own (linear, depth
     * compare), whatever the texture's own parameters. Vulkan: a VkImageView, of type
     * VK_IMAGE_VIEW_TYPE_2D_ARRAY, of the depth aspect of a depth image (D16, D32, D24S8 or
     * D32S8; sampled, with linear filtering), layer i the map of cascade i, read through
     * grass's own compare sampler. Not 0. */
    uint64_t shadow_map;
    /* Vulkan: the VkImageLayout the map is in while grass's pass runs:
     * VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, DEPTH_READ_ONLY_OPTIMAL,
     * SHADER_READ_ONLY_OPTIMAL, READ_ONLY_OPTIMAL or GENERAL (any other is refused). The host
     * has finished writing the map and made it visible to fragment-shader reads in that
     * layout before the pass grass records in. GL: ignored. Default 0 (refused on Vulkan). */
    uint32_t vk_image_layout;
    /* Cascades in shadow_map and the arrays below: 1 to GRASS_MAX_SHADOW_CASCADES. Default 1. */
    uint32_t cascade_count;
    /* Per cascade, column-major: a world position (metres, as camera_position) to (u, v,
     * depth as stored in the map) in x, y, z of the product (w divides: 1 for an orthographic
     * cascade), u and v in 0..1 over the cascade's layer. The host bakes its clip-to-texture
     * bias (and an atlas rectangle if it has one) into it, as Unity's WorldToShadow is. A
     * point outside 0..1 in u or v is lit. Default: identity. */
    float world_to_shadow[GRASS_MAX_SHADOW_CASCADES][16];
    /* Where cascade i ends: metres along the camera's view axis from the camera, ascending,
     * > 0; a point closer than cascade_end[i] and not closer than cascade_end[i-1] reads
     * cascade i, a point beyond cascade_end[cascade_count - 1] is lit. Entries past
     * cascade_count are ignored. Default 1e30 for each. */
    float cascade_end[GRASS_MAX_SHADOW_CASCADES];
    grass_shadow_compare compare; /* default GRASS_SHADOW_COMPARE_LESS_EQUAL */
    /* Moved towards the light before the comparison, in the units of the stored depth (0..1
     * for a normalised depth texture): against self-shadowing (acne) where grass also casts
     * into the map. 0 to 1; 0 biases nothing. Default 0.0005. */
    float depth_bias;
    /* The filter's radius in texels of the map: 0 reads one hardware-filtered tap (2x2 PCF);
     * above 0 a 3x3 grid of such taps that far apart, a soft edge about 2 x radius texels
     * wide. 0 to 16. Default 1. */
    float filter_radius;
} grass_shadow_receive_desc;

/* Default: as each field says (the identity matrices and no map: set shadow_map, the
 * matrices and the cascades). */
GRASS_API grass_shadow_receive_desc grass_default_shadow_receive_desc(void);

/* 0.5: Chained on grass_view_desc.next: every tier also writes the screen-space velocity of
 * its grass to an extra colour target (docs/engine-frames.md, "Motion vectors"), for temporal
 * antialiasing, motion blur and upscalers. The velocity covers the camera's motion (the
 * previous camera and matrices below) and the wind's motion of the blades and of the
 * volume and image tiers' bend (their pose at `time` minus their pose at previous_time).
 * The colliders' trails are in it as they stand up again (their pose at the trail's age then);
 * the frame a collider first presses grass gives that press no velocity (the interaction map
 * keeps no earlier contact). A view without it draws with the same programs and memory as
 * before. A depth pass (GRASS_PASS_DEPTH) ignores it. Vulkan: the context was made with a
 * grass_vk_velocity_target_desc (else GRASS_ERROR_INVALID_STATE).
 *
 * Encoding: per pixel, the grass's position in this frame minus its position in the
 * previous frame, both without their jitter, in viewport units: NDC x 0.5 (a whole
 * viewport's width is 1), x to the right, y up in NDC on GL (GL's window y; the host flips
 * it where its convention is y down), y down on Vulkan (Vulkan's clip y). Written to .r and .g of the velocity attachment as
 * floats (a GL_RG16F or GL_RGBA16F target, a VK_FORMAT_R16G16_SFLOAT one...); .b and .a are
 * masked off, untouched. Where no
 * grass covers a pixel nothing is written (the host clears it or draws its own first).
 * Subtracting it from a pixel's viewport coordinate (window xy / viewport size) gives
 * where that grass was in the previous frame. */
typedef struct grass_view_motion_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_VIEW_MOTION_DESC */
    const void* next;       /* the view's next extension, or NULL */
    /* The previous frame's camera, as its grass_view_desc had them: camera_position (world
     * metres, within +-1e12 m), view (only its rotation is used, as grass_view_desc.view)
     * and projection (with its jitter). Default: the identity and the origin. */
    double previous_camera_position[3];
    float previous_view[16];
    float previous_projection[16];
    /* The jitter (NDC offsets, x and y) that this view's projection and the previous one
     * contain, taken out of the velocity: a projection jittered by (jx, jy) moves every point
     * by (jx, jy) in NDC (a perspective projection has them in its third column, an
     * orthographic one in its fourth). Each within +-2. Default 0. */
    float jitter[2];
    float previous_jitter[2];
    /* The previous frame's time (s; grass_view_desc.time, or grass_frame_desc.time of a
     * frame of views): the wind's motion is the pose at this frame's time minus the pose at
     * previous_time. Finite; equal to this frame's time: no wind motion. Default 0. */
    double previous_time;
    /* Where the velocity goes. GL: the index of the draw buffer (glDrawBuffers' list of the
     * bound framebuffer) that holds the velocity target, 1 to 7 (0 is the lit colour).
     * Vulkan: the colour attachment's index in the pass, equal to the context's
     * grass_vk_velocity_target_desc.velocity_attachment. Default 1. */
    uint32_t velocity_attachment;
} grass_view_motion_desc;

/* Default: as each field says (set the previous camera, matrices and time). */
GRASS_API grass_view_motion_desc grass_default_view_motion_desc(void);

/* 0.5: The host's lights (docs/engine-frames.md, "The host's lights"). */
typedef enum grass_light_kind {
    GRASS_LIGHT_DIRECTIONAL = 0, /* parallel light from `direction` (a second sun, a moon) */
    GRASS_LIGHT_POINT = 1,       /* from `position` in every direction */
    GRASS_LIGHT_SPOT = 2         /* from `position` along `direction`, within a cone */
} grass_light_kind;

#define GRASS_MAX_VIEW_LIGHTS 8

/* One light, in the conventions of glTF's KHR_lights_punctual: a point or spot light's
 * irradiance at distance d is color * intensity / d^2, faded to 0 at `range` by
 * (1 - (d / range)^4)^2 (clamped to 0..1); a directional light's is color * intensity. A
 * spot's cone fades smoothly from inner_cone_angle to outer_cone_angle off its axis. */
typedef struct grass_light {
    grass_light_kind kind; /* default GRASS_LIGHT_POINT */
    /* Point and spot: world position, metres, within +-1e12 m each (as camera_position).
     * Directional: ignored. Default 0. */
    double position[3];
    /* Directional: the world direction towards the light (as grass_view_desc.sun_direction).
     * Spot: the direction the light shines in (from the light outwards). Point: ignored. Not
     * zero where used. Default (0, -1, 0). */
    float direction[3];
    float color[3];  /* linear RGB, each 0 or more; default (1, 1, 1) */
    float intensity; /* 0 or more (point and spot: candela-like, times 1/d^2); default 1 */
    /* Point and spot: the distance (m) at which the light has faded to 0, > 0; default 10.
     * Directional: ignored. */
    float range;
    /* Spot: the cone's half angles in radians, 0 <= inner < outer <= pi / 2. Defaults 0
     * and pi / 4. Others: ignored. */
    float inner_cone_angle;
    float outer_cone_angle;
} grass_light;

/* Default: a white point light of intensity 1 and range 10 m at the origin. */
GRASS_API grass_light grass_default_light(void);

/* Chained on grass_view_desc.next: the host's lights light grass in every tier, besides the
 * view's sun (grass_view_desc.sun_*), which stays the one light that the host's shadow map
 * (grass_shadow_receive_desc) and the diffuse light map shade. The host's lights cast no
 * shadows on grass. Optionally also: Kajiya-Kay anisotropic specular (bakay2003 3.3.2) on
 * the blades and its equivalent on the volume and image tiers, for the sun and every light;
 * and the ambient light as second-order spherical harmonics instead of
 * grass_view_desc.ambient_color. A view without it draws with the same programs and memory
 * as before. A depth pass (GRASS_PASS_DEPTH) ignores it. GL and Vulkan; Vulkan: mono contexts
 * only (a multiview context refuses it, GRASS_ERROR_UNSUPPORTED). Cost: each light adds to
 * every tier's fragment work (the volume tier's most: it lights every point its rays
 * composite); docs/records/host-lights.md has the figures. */
typedef struct grass_view_lights_desc {
    grass_struct_type type;    /* GRASS_STRUCT_TYPE_VIEW_LIGHTS_DESC */
    const void* next;          /* the view's next extension, or NULL */
    uint32_t light_count;      /* 0 to GRASS_MAX_VIEW_LIGHTS; default 0 */
    const grass_light* lights; /* light_count lights; may be NULL when light_count is 0 */
    /* Kajiya-Kay specular: its strength (0: none, 0 to 1) and exponent (1 to 1024).
     * Defaults 0 and 32. */
    float specular_strength;
    float specular_exponent;
    /* 1: the ambient light is a function of the normal, A(n) = sum over k of
     * ambient_sh[k] * Y_k(n), in place of grass_view_desc.ambient_color (linear RGB, as it):
     * the nine real spherical harmonics of orders 0-2 over world directions n = (x, y, z),
     * in the order Y_00 = 0.282095, Y_1-1 = 0.488603 y, Y_10 = 0.488603 z, Y_11 = 0.488603 x,
     * Y_2-2 = 1.092548 xy, Y_2-1 = 1.092548 yz, Y_20 = 0.315392 (3z^2 - 1), Y_21 = 1.092548
     * xz, Y_22 = 0.546274 (x^2 - y^2). A constant ambient colour a is ambient_sh[0] = a /
     * 0.282095 and the rest 0; a host with a probe's radiance coefficients L_k gives
     * L_k * A_l / pi, A_l = pi, 2 pi / 3, pi / 4 for orders 0, 1, 2 (Ramamoorthi and Hanrahan
     * 2001). Each coefficient finite. 0: ambient_color as before. Default 0. */
    uint32_t ambient_sh_enabled;
    float ambient_sh[9][3];
} grass_view_lights_desc;

/* Default: as each field says (no lights, no specular, the view's ambient colour). */
GRASS_API grass_view_lights_desc grass_default_view_lights_desc(void);

/* Starts a frame of one view: validates the view and plans what every field draws. Then
 * draw with grass_gl_render() or grass_vk_record(), and close with grass_end_frame().
 * It is grass_begin_host_frame() with the next frame index and the promise that the frame
 * frames_in_flight before it has finished (Vulkan; GL needs none), then grass_plan_view():
 * the view is view 0 of the frame, and view->time is the frame's time. */
GRASS_API grass_result grass_begin_frame(grass_context* context, const grass_view_desc* view);
/* Ends the frame begun by grass_begin_frame() or grass_begin_host_frame(). */
GRASS_API grass_result grass_end_frame(grass_context* context);

/* ---- 0.5: Frames and views (docs/integration.md, "Frames and views") ----------------- */
/*
 * An engine draws several views in one of its frames: the main camera, shadow cascades,
 * reflections, split screen. grass_begin_host_frame() begins the host's frame once; each
 * grass_plan_view() then plans one view of it, numbered 0, 1, ... in the order planned, up
 * to GRASS_MAX_VIEWS_PER_FRAME; draw view k with grass_gl_render_view(context, k) or
 * grass_vk_record_view(context, k, ...), in any order, as often as the host needs, until
 * grass_end_frame(). Planning a view never changes another's plan or what was recorded for
 * it, and each view keeps its GPU data until the host reports its frame finished.
 *
 * What a view shares with the others of its frame: the time (grass_frame_desc.time: the
 * wind, and the responsive grass's one step per frame) and the interaction map, which view
 * 0 moves with its camera and every view reads. What it has of its own: camera, projection
 * (perspective or orthographic), viewport, sun, flags and extensions (a grass_lod_origin_desc
 * makes a shadow view choose its blades and tiers as the main camera does).
 * GPU timings (grass_get_tier_gpu_ms) add up the views of a frame; grass_get_frame_stats
 * reports the last planned view.
 *
 * Resource reuse follows the host's frame indices: the GPU data of frame N is rewritten by a
 * later frame only once the host reports N finished (completed_frame_index >= N). Vulkan: at
 * most frames_in_flight (grass_vk_desc) frames may be unfinished, the one begun included; a
 * frame that would need more is refused (GRASS_ERROR_INVALID_STATE) and nothing changes.
 */
#define GRASS_MAX_VIEWS_PER_FRAME 16

typedef struct grass_frame_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_FRAME_DESC */
    const void* next;       /* NULL */
    /* The host's frame number: greater than every earlier frame's of this context (gaps are
     * allowed), and at least 1. */
    uint64_t frame_index;
    /* The newest frame whose GPU work the host knows has finished (its fence signalled), or
     * 0 when none has; less than frame_index, and never less than an earlier frame's value.
     * GL: ignored beyond these checks (the GL driver orders its own buffer reuse). */
    uint64_t completed_frame_index;
    /* Seconds, any origin: as grass_view_desc.time (the wind; the responsive grass steps the
     * difference to the previous frame's time). grass_plan_view ignores view->time. */
    double time;
} grass_frame_desc;

/* Default: frame_index 1, completed_frame_index 0, time 0. */
GRASS_API grass_frame_desc grass_default_frame_desc(void);

/* Begins the host's frame (no view planned yet). Refused inside a frame. */
GRASS_API grass_result grass_begin_host_frame(grass_context* context, const grass_frame_desc* frame);

/* Plans one more view of the begun frame: validates it as grass_begin_frame does and plans
 * what every field draws for it; *out_view is its index (0 for the first). On failure the
 * frame's earlier views are untouched and *out_view is not written. */
GRASS_API grass_result grass_plan_view(grass_context* context, const grass_view_desc* view, uint32_t* out_view);

typedef struct grass_frame_stats {
    uint64_t fields_drawn;
    uint64_t nodes_visited;    /* quadtree nodes the traversal reached */
    uint64_t cells_drawn;      /* geometry-tier patch instances (cells) */
    uint64_t blades_submitted; /* cells_drawn x blades per patch; plus the mesh fields' planned blades */
    uint64_t blades_drawn;     /* blades the geometry tier draws, from the density and the
                                    tier transitions at each cell's center: exact without a map
                                    and away from transition zones, an estimate elsewhere */
    uint64_t triangles;        /* triangles of the drawn blades */
    double plan_ms;            /* CPU time of the frame plan */
    uint64_t lod_test_calls;   /* lod test evaluations */
    uint64_t nodes_culled;     /* nodes rejected by the view-frustum test */
    /* Per tier kind (grass_tier_kind), summed over fields and tiers of that kind: */
    uint64_t instances[GRASS_TIER_KIND_COUNT];   /* cells plus macro-cells drawn */
    uint64_t macro_cells[GRASS_TIER_KIND_COUNT]; /* instances larger than one cell */
    uint64_t cells[GRASS_TIER_KIND_COUNT];       /* cells those instances cover */
    uint64_t nodes_empty; /* nodes discarded, subtree and all, because their density is zero everywhere */
    /* 0.4: */
    /* Instanced draws in the frame plan: one per field (each grass type counts as a field)
     * and tier that draws at least one instance. Each grass_gl_render() or grass_vk_record()
     * of the frame issues this many instanced draw calls. */
    uint64_t draws;
    /* 0.5: */
    uint64_t colliders;          /* colliders given for this frame (grass_set_colliders) */
    uint64_t colliders_in_map;   /* of them, those that reach the interaction map's window */
    uint64_t interaction_texels; /* texels the interaction pass updates this frame (0: no pass) */
    double time_step;            /* seconds the responsive grass stepped this frame */
} grass_frame_stats;

/* Stats of the last planned view (of the last begun frame). */
GRASS_API grass_result grass_get_frame_stats(const grass_context* context, grass_frame_stats* out_stats);

/* GPU time of each tier kind (grass_tier_kind index) in the most recent frame whose
 * timings are available, in milliseconds; *out_available = 0 where the device or driver
 * has no timer queries (then the values are 0).
 * Timestamps are written around each kind's draws and read back without waiting: the
 * figures lag the current frame by the frames in flight (GL: up to 4 frames). Also
 * *out_available = 0 until a timed frame has finished on the GPU. Frames that draw
 * nothing or draw GRASS_VIEW_FLAG_DEBUG_CELLS are not timed. Several draw calls of one
 * frame (grass_gl_render, grass_vk_record) add up. GL: the host's GL context must be
 * current; Vulkan: call grass_vk_prepare every frame (it resets the queries). */
GRASS_API grass_result grass_get_tier_gpu_ms(const grass_context* context, double out_ms[GRASS_TIER_KIND_COUNT],
                                             grass_bool* out_available);

/* ---- Responsive grass (0.5): wind, gravity, colliders (docs/responsive.md) -------- */
/*
 * jahrmann2017 section 5, bakay2003 section 3.3. A field is tiled from one patch, so there
 * is no state per blade: wind and gravity are functions of position and time, evaluated
 * where blades and slices are drawn, and what colliders leave behind (pressed grass and its
 * recovery) is kept in an *interaction map*: a few texels per metre around the camera,
 * toroidally addressed, updated on the GPU once per frame (GL: by the frame's first
 * grass_gl_render; Vulkan: by grass_vk_prepare). Everything here is optional: with
 * no wind, no colliders and no gravity change, the shaders and GPU memory are those of
 * still grass. Each tier draws the same state: blades follow Jahrmann's three control
 * points, volume and image tiers shear their slice lookups as bakay's length-preserving
 * shells do, and pressed grass lies down and darkens in all three.
 */

/* How the blades of one grass type (a patch) respond (jahrmann2017 5.1). Per blade, each
 * value is scaled by a factor in [1 - variation, 1 + variation] drawn from the blade. */
typedef struct grass_blade_mechanics {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_BLADE_MECHANICS */
    const void* next;       /* NULL */
    /* Recovery (jahrmann eq. 3's s): the acceleration, m/s^2, that pushes a blade's tip
     * away from its rest pose by its own length. A blade settles where recovery balances
     * wind and gravity, so an acceleration a moves the tip a / stiffness of its length.
     * 0.1 .. 1e5; default 40. */
    float stiffness;
    /* Gravity response (eq. 4's m): multiplies grass_wind_desc.gravity's difference to
     * standard gravity (the patch's blades are their shape under standard gravity).
     * 0 .. 100; default 1. */
    float mass;
    /* Wind response: the acceleration, m/s^2, per m/s of wind across the blade
     * (jahrmann eq. 7-8 align it). 0 .. 100; default 2. */
    float wind_response;
    /* How far a collision presses the grass below the collider's own surface: 0 = down to
     * where the collider reached, 1 = flat wherever touched (jahrmann's crippling eta).
     * 0 .. 1; default 0.5. */
    float trample_depth;
    /* Time constant of standing up again after a collision, s: the pressed depth decays as
     * exp(-t / recovery_time). 0.01 .. 1e5; default 4. */
    float recovery_time;
    /* Per-blade variation of all the above, 0 .. 0.9; default 0.25. */
    float variation;
} grass_blade_mechanics;

GRASS_API grass_blade_mechanics grass_default_blade_mechanics(void);

/* Sets the mechanics of every blade of `patch` (all fields and grass types using it), from
 * the next grass_begin_frame on. A patch starts with grass_default_blade_mechanics(). */
GRASS_API grass_result grass_set_blade_mechanics(grass_context* context, grass_patch_id patch,
                                                 const grass_blade_mechanics* mechanics);

typedef enum grass_wind_source_kind {
    /* Blows outwards from `position` along the ground, strongest under it: a helicopter's
     * downwash (jahrmann 7.2), a fan pointing down. */
    GRASS_WIND_SOURCE_POINT = 0,
    /* Blows from `position` along `direction` within `cone_angle`: a fan, a jet. */
    GRASS_WIND_SOURCE_CONE = 1,
    /* A short blast: a ring front leaving `position` at `front_speed` at `start_time`,
     * blowing outwards where it passes, gone after `duration`. */
    GRASS_WIND_SOURCE_BLAST = 2
} grass_wind_source_kind;

#define GRASS_MAX_WIND_SOURCES 16

/* A local wind source. Its speed falls with the distance d from `position` as
 * 1 / (1 + (d / radius)^2). */
typedef struct grass_wind_source {
    grass_wind_source_kind kind;
    double position[3]; /* world metres, within +-1e12 */
    float direction[3]; /* CONE: the axis, not zero; otherwise unused */
    float cone_angle;   /* CONE: half angle, radians, (0, pi/2]; otherwise unused */
    float speed;        /* m/s at the source, 0 .. 1e3 */
    float radius;       /* metres where the speed has halved, 1e-3 .. 1e6 */
    double start_time;  /* BLAST: grass_view_desc.time when it goes off; otherwise unused */
    float duration;     /* BLAST: seconds it blows, > 0 .. 1e4; otherwise unused */
    float front_speed;  /* BLAST: m/s its front travels, > 0 .. 1e4; otherwise unused */
} grass_wind_source;

/* The wind of the whole context (every field) and the environmental gravity. */
typedef struct grass_wind_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_WIND_DESC */
    const void* next;       /* NULL */
    /* Mean wind, world space: a direction (need not be unit; its component along a field's
     * up is ignored) and a speed in m/s, 0 .. 1e3. Default (1, 0, 0.3) and 0: no wind. */
    float direction[3];
    float speed;
    /* Gusts (bakay 3.3: a strong attack and a slow fall, travelling with the wind): they add
     * up to gust_strength x speed; 0 .. 4, default 0.6. gust_length: the distance between
     * gusts along the wind, metres, 0.1 .. 1e5, default 14. The gust train is a sum of
     * waves of incommensurate periods, offset by position, so its period never shows. */
    float gust_strength;
    float gust_length;
    /* Small-scale changes of speed and direction, 0 .. 1; default 0.3. */
    float turbulence;
    /* Environmental gravity (jahrmann eq. 4, the direction form), m/s^2, each component
     * within +-1e3. Default (0, -9.81, 0): standard gravity, under which the patch's blades
     * have their generated shape, so it moves nothing; another value bends them by the
     * difference (grass_blade_mechanics.mass). */
    float gravity[3];
    /* Local sources, copied: 0 .. GRASS_MAX_WIND_SOURCES. */
    const grass_wind_source* sources;
    uint32_t source_count;
} grass_wind_desc;

GRASS_API grass_wind_desc grass_default_wind_desc(void);

/* Sets the wind and gravity from the next grass_begin_frame on; NULL restores the default
 * (no wind, standard gravity: still grass, which costs nothing). */
GRASS_API grass_result grass_set_wind(grass_context* context, const grass_wind_desc* wind);

/* A host wind-vector map of one field: wind painted over the field (a valley's draught, the
 * lee of a building, a fan's corridor) that adds to the context's wind and sources wherever
 * the field's grass is drawn, in every tier. Sampled bilinearly in map space, like the
 * design maps. */
typedef struct grass_wind_map_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_WIND_MAP_DESC */
    const void* next;       /* NULL */
    /* An RGBA map (grass_create_map, any RGBA format). r and g are the wind along the
     * field's +x and +z axes, encoded as v = (2 t - 1) x speed for a stored value t in 0..1:
     * 0.5 is calm (an 8-bit 128 is speed / 255). b and a are unused. The values are read as
     * stored (not as sRGB colour). A null id (the default) removes the field's wind map. */
    grass_map_id map;
    /* m/s for an encoded 1 (t = 1), finite, 0 .. 1e3; default 5. */
    float speed;
    /* Cell space to map space, as grass_map_stack.cell_to_map: map (u, v) = (m[0] x + m[2] z
     * + m[4], m[1] x + m[3] z + m[5]) for a point (x, z) of the field in cells. All zero (the
     * default): the map spans the whole field. */
    double cell_to_map[6];
} grass_wind_map_desc;

GRASS_API grass_wind_map_desc grass_default_wind_map_desc(void);

/* Sets the wind map of `field` (and its grass types) from the next grass_begin_frame on;
 * NULL or a null desc->map removes it. The map stays in use (grass_destroy_map refuses it)
 * until removed or the field is destroyed. A field without a wind map draws exactly what it
 * drew before: no texture bound, no shader work. Not between grass_begin_frame and
 * grass_end_frame. */
GRASS_API grass_result grass_set_field_wind_map(grass_context* context, grass_field_id field,
                                                const grass_wind_map_desc* desc);

typedef enum grass_collider_shape {
    GRASS_COLLIDER_SPHERE = 0, /* a ball, a wheel's contact, jahrmann's spheres */
    GRASS_COLLIDER_CAPSULE = 1 /* a segment with a radius: legs, bodies, logs */
} grass_collider_shape;

/* A collider of one frame. */
typedef struct grass_collider {
    grass_collider_shape shape;
    float radius; /* metres, 0 .. 1e6 (0 touches nothing) */
#if defined(GRASS_FIELD_ALIASES)
    union {
        double center[3];
        GRASS_RENAMED(centre, center, 0.5) double centre[3]; /* its 0.5 development name */
    };
#else
    double center[3]; /* SPHERE: the center; CAPSULE: one end of its axis. World metres, within +-1e12 */
#endif
    double end[3]; /* CAPSULE: the other end of its axis; unused for a sphere */
    /* Optional, world m/s, each component within +-1e5: how the collider moved over the last
     * time step. The pass sweeps it from center - velocity x step to center, so a fast
     * collider leaves a continuous trail at any frame rate. Zero: only where it is now. */
    float velocity[3];
} grass_collider;

#define GRASS_MAX_COLLIDERS 65536
/* 0.5: the most colliders one tile of the interaction map (16 x 16 texels) tests: a texel of
 * the pass tests at most this many. Of more, the tile keeps those whose lowest point over the
 * step is lowest (they press deepest), and warns GRASS_MSG_COLLIDER_TILE_CAP once. */
#define GRASS_MAX_COLLIDERS_PER_TILE 1024

/* Sets the colliders of the next frames (copied): they press the grass at each following
 * grass_begin_frame until replaced; count 0 clears them (trails recover). The work is
 * binned by the map's tiles: it grows with the area colliders touch, not with the field,
 * and a tile tests at most GRASS_MAX_COLLIDERS_PER_TILE of them.
 * 0 .. GRASS_MAX_COLLIDERS. */
GRASS_API grass_result grass_set_colliders(grass_context* context, const grass_collider* colliders, uint32_t count);

/* The interaction map: where collider trails live, around the camera. */
typedef struct grass_interaction_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_INTERACTION_DESC */
    const void* next;       /* NULL */
    /* The world's up; the map lies across it, and colliders press along it. Not zero;
     * default (0, 1, 0). A field whose up differs by more than 60 degrees ignores the map. */
    float up[3];
    /* Texels per side of each level, a power of two, 64 .. 2048; default 256. */
    uint32_t resolution;
    /* 1 or 2 levels; default 2: a fine level near the camera for the blades and a coarse
     * one for the volume and image tiers, so a trail stays visible from afar. The coarse
     * level widens a collider narrower than half its texel's diagonal to that radius. */
    uint32_t level_count;
    /* Metres per texel of each level (level 1 >= level 0), 1e-3 .. 1e3; default 0.05, 1:
     * 12.8 m and 256 m across at 256 texels, so a trail is kept out to 127 m from the
     * camera (half the coarse level less a texel). A trail outside the coarse level is gone. */
    float texel_size[2];
} grass_interaction_desc;

GRASS_API grass_interaction_desc grass_default_interaction_desc(void);

/* Configures the interaction map and clears it (every trail is gone); NULL restores the
 * default. The map's GPU memory (resolution^2 x 16 bytes per level) is made at the first
 * frame with colliders and kept until this call or the context's end. */
GRASS_API grass_result grass_set_interaction(grass_context* context, const grass_interaction_desc* desc);

/* ---- Per-blade culling in the geometry tier (jahrmann2017 6.2) ---------------------- */

/* Jahrmann's tests drop single blades that matter little to the picture, on the GPU, as a
 * blade's vertices are placed (a culled blade is moved outside the clip volume: it costs its
 * vertex work but nothing in the rasteriser). They thin the blades the geometry tier draws,
 * on top of the quadtree's view-frustum test of whole cells and the density thresholds. All
 * off by default; a field without them runs the shaders it ran before (no cost).
 * grass_frame_stats.blades_drawn counts the blades before these tests (the GPU decides).
 * docs/quality.md measures their saving and the error they add. */
typedef enum grass_distance_culling {
    GRASS_DISTANCE_CULLING_OFF = 0,
    /* Jahrmann's distance test (eq. 20): n = distance_levels levels, evenly over
     * [0, distance_max] of the distance from the camera measured across the field's up; at
     * distance d a blade is drawn while (its index in the patch mod n) <
     * ceil(n (1 - d / distance_max)): the nearest level keeps every blade, each farther one
     * drops one more of n, none is drawn beyond distance_max. */
    GRASS_DISTANCE_CULLING_BLADE_INDEX = 1,
    /* The same thinning by the blades' density thresholds (lemme 3.3): a blade is drawn while
     * its threshold <= local density x (1 - d / distance_max), so the density falls
     * continuously to zero at distance_max, evenly in space (distance_levels unused). */
    GRASS_DISTANCE_CULLING_THRESHOLD = 2
} grass_distance_culling;

typedef struct grass_blade_culling_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_BLADE_CULLING_DESC */
    const void* next;       /* NULL */
    /* Orientation test (eq. 17): a blade seen nearly edge-on, whose width direction makes
     * |cos| > orientation_limit with the direction from the camera to its root, is culled.
     * orientation_limit 0.5 .. 1 (1 culls nothing); default 0.9, Jahrmann's. */
    grass_bool orientation;
    float orientation_limit;
    /* View-frustum test (eq. 18): a blade whose root, curve midpoint and tip all lie
     * outside the view frustum widened by frustum_tolerance (a fraction of the view, in clip
     * units relative to w) is culled. 0 .. 1; default 0.1. */
    grass_bool view_frustum;
    float frustum_tolerance;
    /* Distance test (eq. 19-20): thinning with the distance, by blade index or by threshold. */
    grass_distance_culling distance; /* default GRASS_DISTANCE_CULLING_OFF */
    uint32_t distance_levels;        /* BLADE_INDEX: n, 1 .. 64; default 4 */
    /* Metres, > 0 and finite, or 0 (the default): the far end of the field's geometry tiers
     * (the largest finite end of their distance bands; refused when there is none). */
    float distance_max;
} grass_blade_culling_desc;

/* Every test off, their parameters at Jahrmann's values. */
GRASS_API grass_blade_culling_desc grass_default_blade_culling_desc(void);

/* Sets the per-blade culling of `field` and all its grass types, from the next
 * grass_begin_frame on; NULL turns it off. */
GRASS_API grass_result grass_set_blade_culling(grass_context* context, grass_field_id field,
                                               const grass_blade_culling_desc* culling);

/* ---- Dynamic tessellation of the blades (0.5; jahrmann2017 6.3) ----------------------
 * The geometry tier draws each cell's blades with fewer quads the smaller they are on
 * screen: level k keeps every 2^k-th row of a blade's quad strip (and its tip), down to one
 * quad a blade. Each level's error is the farthest any of the patch's blades strays from its
 * full outline at that level (its curve cut into fewer straight pieces, its pointed width
 * straightened), measured once when the patch is made. A cell takes the coarsest level whose
 * error stays within error_pixels on screen at the cell's nearest point (the view's pixels per
 * metre there), so a level changes where it moves an edge by error_pixels at most. The
 * coarser levels are index ranges of the patch (no vertex data, no shader change): each
 * level's cells are one more draw. Off by default and off in GRASS_QUALITY_REFERENCE: every
 * blade is drawn with the patch's subdivisions. The error is the blades' rest shape's:
 * blades bent further by wind or colliders stray more. docs/three-tiers.md measures what it
 * saves and the error it adds. */
typedef struct grass_blade_tessellation_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_BLADE_TESSELLATION_DESC */
    const void* next;       /* NULL */
    grass_bool enabled;     /* 0: full tessellation (the default) */
    float
        error_pixels; /* the most a coarser level may move a blade's outline on screen, pixels, 0.01..16; default 0.5 */
} grass_blade_tessellation_desc;

/* Off, error_pixels 0.5. */
GRASS_API grass_blade_tessellation_desc grass_default_blade_tessellation_desc(void);

/* The tessellation a quality preset means: off for GRASS_QUALITY_REFERENCE; on for the
 * others, with error_pixels 0.25 (HIGH), 0.5 (DEFAULT), 0.75 (LOW) and 1 (FASTEST). An
 * unknown level gives the default desc (off). */
GRASS_API grass_blade_tessellation_desc grass_quality_blade_tessellation(grass_quality_level level);

/* Sets the dynamic tessellation of `field`'s geometry tiers and all its grass types, from
 * the next grass_begin_frame on; NULL turns it off. A refusal leaves the earlier one. A mesh
 * field (grass_create_mesh_field) is refused with GRASS_MSG_MESH_FIELD. */
GRASS_API grass_result grass_set_blade_tessellation(grass_context* context, grass_field_id field,
                                                    const grass_blade_tessellation_desc* tessellation);

/* ---- Pipelines before the first frame (0.5) ----------------------------------------------
 * grass compiles a shader variant (a Vulkan pipeline, a GL program) the first time a draw
 * needs it: turning on wind, colliders, per-blade culling or a debug view would compile
 * inside that frame and make it hitch. grass_prepare_pipelines says what the host will use;
 * grass then compiles every variant those features need, for every field that exists now
 * and, from then on, for each field when it is created (grass_create_field), never in a
 * frame. A frame that uses a feature the host did not declare still works: its variants
 * are compiled in that frame, as without preparation. docs/integration.md "Compiling before
 * the first frame" measures what it saves and what it costs.
 *
 * The render target is no part of a variant: Vulkan pipelines are made for the render pass
 * or formats and sample count of grass_vk_desc; GL programs do not depend on the target.
 *
 * 0.5: the views of an engine's frame have variants of their own: a depth pass, a view that
 * receives the host's shadows, one that writes motion vectors, one lit by the host's lights,
 * a G-buffer view (GRASS_PIPELINE_FEATURE_DEPTH_PASS ... _GBUFFER). Each multiplies the
 * variants of the features above: a view mode (plain colour, depth, each combination of
 * receiving, motion and lights, G-buffer with or without motion) runs every responsive
 * variant. All ten bits and one G-buffer layout: 433 variants per set of maps and tier kinds
 * (49 without the view bits); the five view bits with wind alone: 60. A view mode the
 * context cannot draw is skipped, not an error: Vulkan without grass_vk_depth_pass_desc
 * makes no depth variant, without grass_vk_velocity_target_desc no motion variant (a
 * G-buffer layout with velocity included), without grass_vk_gbuffer_target_desc no G-buffer
 * variant, and a multiview context (grass_vk_multiview_desc) none but the depth pass's.
 * G-buffer variants on Vulkan are made per layout (the attachments the outputs go to):
 * GRASS_PIPELINE_FEATURE_GBUFFER takes the layout the host will draw as a
 * grass_view_gbuffer_desc chained on grass_pipeline_desc.next (GL, whose programs do not
 * depend on it, checks it and needs it too); call again with each other layout. */
typedef enum grass_pipeline_feature_bits {
    GRASS_PIPELINE_FEATURE_WIND = 0x1,          /* wind or non-standard gravity (grass_set_wind) */
    GRASS_PIPELINE_FEATURE_WIND_MAP = 0x2,      /* a field's wind map (grass_set_field_wind_map); brings WIND */
    GRASS_PIPELINE_FEATURE_INTERACTION = 0x4,   /* colliders or a trail (grass_set_interaction) */
    GRASS_PIPELINE_FEATURE_BLADE_CULLING = 0x8, /* per-blade culling (grass_set_blade_culling) */
    /* GRASS_VIEW_FLAG_DEBUG_TIERS, _THRESHOLDS or _CELLS, and NO_DEPTH_TEST: on Vulkan every
     * variant prepared is also compiled without the depth test (twice the pipelines) */
    GRASS_PIPELINE_FEATURE_DEBUG_VIEWS = 0x10,
    /* The five features above, as in 0.5's first header: enum values never change, so ALL
     * keeps this meaning and does not take in the view bits below. */
    GRASS_PIPELINE_FEATURE_ALL = 0x1F,
    /* 0.5: the variants of an engine's views (see above); not in GRASS_PIPELINE_FEATURE_ALL
     * nor in the default, each multiplies what the features above compile. */
    GRASS_PIPELINE_FEATURE_DEPTH_PASS = 0x20,     /* depth views (grass_view_pass_desc GRASS_PASS_DEPTH) */
    GRASS_PIPELINE_FEATURE_SHADOW_RECEIVE = 0x40, /* receiving views (grass_shadow_receive_desc) */
    GRASS_PIPELINE_FEATURE_MOTION_VECTORS = 0x80, /* motion views (grass_view_motion_desc) */
    GRASS_PIPELINE_FEATURE_HOST_LIGHTS = 0x100,   /* lit views (grass_view_lights_desc) */
    /* G-buffer views (GRASS_PASS_GBUFFER) of the layout chained on grass_pipeline_desc.next */
    GRASS_PIPELINE_FEATURE_GBUFFER = 0x200,
    GRASS_PIPELINE_FEATURE_ALL_VIEWS = 0x3E0 /* the five view bits */
} grass_pipeline_feature_bits;

typedef struct grass_pipeline_desc {
    grass_struct_type type; /* GRASS_STRUCT_TYPE_PIPELINE_DESC */
    /* NULL, or with GRASS_PIPELINE_FEATURE_GBUFFER (0.5) the grass_view_gbuffer_desc of the
     * G-buffer views to prepare (its own next NULL) */
    const void* next;
    /* The features the host may turn on, GRASS_PIPELINE_FEATURE_* bits; every combination of
     * them is compiled for each field's design maps (GRASS_PIPELINE_FEATURE_ALL: 49 variants
     * per set of maps; with the view bits, see above). 0: only still grass (what
     * grass_create_field compiles anyway). Default GRASS_PIPELINE_FEATURE_ALL &
     * ~GRASS_PIPELINE_FEATURE_DEBUG_VIEWS (24 variants): the responsive grass a host turns on
     * at run time; the view bits are left to the host that draws those views, since they
     * multiply the count (all of them: 433 variants, minutes of compiling on a CPU driver). */
    uint32_t features;
    /* A blob grass_get_pipeline_cache_data returned earlier (on a previous run), or NULL (the
     * default). Vulkan: merged into grass's own VkPipelineCache (refused when the host gave
     * grass_vk_host_objects_desc.pipeline_cache: seed that one itself); GL: the program binaries in it
     * replace compiling (GL_ARB_get_program_binary; ignored where the driver reports no
     * binary format). A blob of another backend, grass version, device, driver or shader
     * set, truncated or corrupt, is ignored with a GRASS_MSG_PIPELINE_CACHE warning. */
    const void* cache_data;
    uint64_t cache_data_size; /* bytes of cache_data; 0 with NULL */
} grass_pipeline_desc;

GRASS_API grass_pipeline_desc grass_default_pipeline_desc(void);

/* Compiles every pipeline or program the declared features need (see above), for the
 * fields that exist, and the interaction pass's with GRASS_PIPELINE_FEATURE_INTERACTION;
 * remembers the features for the fields created later. Outside a frame
 * (GRASS_MSG_FRAME_ALREADY_BEGUN); GL: with the context's GL context current. May be called
 * again: it then declares the new set, compiling what is missing (nothing is released).
 * Refused: features with bits outside GRASS_PIPELINE_FEATURE_ALL |
 * GRASS_PIPELINE_FEATURE_ALL_VIEWS, cache_data NULL with a size or a size of 0 with data,
 * GRASS_PIPELINE_FEATURE_GBUFFER without a grass_view_gbuffer_desc on next or with an invalid
 * one (on Vulkan also one whose attachment_count is not grass_vk_gbuffer_target_desc's),
 * anything else on next (GRASS_ERROR_INVALID_ARGUMENT or GRASS_ERROR_WRONG_STRUCT_TYPE,
 * naming the value). Cost:
 * the driver's compile time of each variant not made yet (docs/records/prepare-pipelines.md
 * measures it on llvmpipe and lavapipe); nothing when all exist. A context made by
 * grass_create_context compiles nothing. */
GRASS_API grass_result grass_prepare_pipelines(grass_context* context, const grass_pipeline_desc* desc);

/* The context's own pipeline cache as a blob to store and hand back next run through
 * grass_pipeline_desc.cache_data: Vulkan, grass's VkPipelineCache (vkGetPipelineCacheData);
 * GL, the binary of every program compiled so far. With data NULL, *size is set to the
 * bytes needed; otherwise at most *size bytes are written and *size is set to the bytes
 * written: GRASS_ERROR_INVALID_ARGUMENT (nothing written) when *size is too small. A
 * context without a cache of its own gives 0 bytes: grass_create_context's, a GL driver
 * without program binary formats; a Vulkan context given grass_vk_host_objects_desc.pipeline_cache is
 * refused (GRASS_ERROR_INVALID_STATE): the host saves its own cache. Outside a frame. */
GRASS_API grass_result grass_get_pipeline_cache_data(grass_context* context, void* data, uint64_t* size);

/* ---- 0.3 names (begin) ------------------------------------------------------------------
 * Functions renamed in 0.4 (docs/migrating.md lists every source change since 0.3), declared
 * with GRASS_RENAMED ("Renamed names" near the top). The library still exports their 0.3
 * symbols for programs built against grass.h 0.3. */
#if defined(GRASS_RENAMED)
GRASS_RENAMED(grass_context_backend, grass_get_context_backend, 0.4)
GRASS_API grass_backend grass_context_backend(const grass_context* context);
GRASS_RENAMED(grass_last_error, grass_get_last_error, 0.4)
GRASS_API const char* grass_last_error(const grass_context* context);
#endif
/* ---- 0.3 names (end) -------------------------------------------------------------------- */

/* ---- 0.4 names (begin) ------------------------------------------------------------------
 * Functions renamed in 0.5, in the 0.3 block's way: the library still exports the 0.4
 * symbols. (grass_collider.centre, renamed center in 0.5, is an alias in the struct.) */
#if defined(GRASS_RENAMED)
GRASS_RENAMED(grass_library_version, grass_get_library_version, 0.5)
GRASS_API uint32_t grass_library_version(void);
#endif
/* ---- 0.4 names (end) -------------------------------------------------------------------- */

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* GRASS_GRASS_H */
