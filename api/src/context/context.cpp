// The context: creation with a version check, logging, memory stats, destruction.
#include "context/context.hpp"

#include "foundation/abi_sizes.hpp"
#include "foundation/owner_tags.hpp"
#include "foundation/raw_enum.hpp"
#include "foundation/validate.hpp"

#include <cassert>
#include <cstdio>
#include <cstring>

grass_context::grass_context(const grass_context_desc& d, uint16_t owner_tag)
    : grass::Log(d), host(d.allocator), desc(d), owner(owner_tag), patches(&host), fields(&host), maps(&host),
      plan(&host), views(&host, &plan), plan_scratch(&host), dynamics(&host),
      cache_directory(grass::StlAllocator<char>(&host)),
      prepared_gbuffer_layouts(grass::StlAllocator<grass::GBufferLayout>(&host)) {
    if (d.cache_directory && d.cache_directory[0]) {
        cache_directory.assign(d.cache_directory, d.cache_directory + std::strlen(d.cache_directory) + 1);
        desc.cache_directory = cache_directory.data();
    } else {
        desc.cache_directory = nullptr;
    }
    desc.next = nullptr; // the host's chain is read during the create call only (debug_labels)
}

grass_context::~grass_context() {
    // Fields and patches release their GPU resources before the backend goes (not those of
    // an abandoned backend: destroy_context).
    if (backend && backend->abandoned()) {
        host.destroy(backend);
        backend = nullptr;
    }
    for (uint32_t slot = 0; slot < fields.capacity(); ++slot) {
        if (fields.get(slot) && backend) backend->release_field(slot);
    }
    for (uint32_t slot = 0; slot < maps.capacity(); ++slot) {
        if (maps.get(slot) && backend) backend->release_map(slot);
    }
    for (uint32_t slot = 0; slot < patches.capacity(); ++slot) {
        if (patches.get(slot) && backend) backend->release_patch(slot);
    }
    host.destroy(backend);
    backend = nullptr;
    grass::release_owner_tag(owner);
}

grass_result grass_context::refuse_reentrant(const char* function) {
    const char* callback = log_callbacks_running > 0 ? "the log callback"
                           : host.hook_running()     ? "an allocator hook"
                                                     : "a lod test callback";
    return fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_REENTRANT_CALL,
                "%s: called from inside %s of this context; a callback must not call its own context (grass.h "
                "\"Re-entrancy\")",
                function, callback);
}

namespace grass {

namespace {

// Logs through the desc's callback before a context exists (version or desc errors).
grass_result early_fail(const grass_context_desc* desc, grass_result result, grass_message_id id, const char* format,
                        ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
grass_result early_fail(const grass_context_desc* desc, grass_result result, grass_message_id id, const char* format,
                        ...) {
    if (desc && desc->log_fn) {
        char message[512];
        va_list args;
        va_start(args, format);
        std::vsnprintf(message, sizeof(message), format, args);
        va_end(args);
        desc->log_fn(desc->log_user_data, GRASS_LOG_ERROR, id, message);
    }
    return result;
}

} // namespace

grass_result create_context(const char* function, uint32_t header_version, const grass_context_desc* desc,
                            BackendFactory factory, void* factory_user_data, grass_context** out_context) {
    if (!out_context)
        return early_fail(desc, GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT, "%s: out_context is NULL",
                          function);
    if (!desc) return GRASS_ERROR_INVALID_ARGUMENT;
    const uint32_t major = header_version >> 22, minor = (header_version >> 12) & 0x3ff;
    if (major != GRASS_VERSION_MAJOR || minor > GRASS_VERSION_MINOR || minor < kOldestHeaderMinor) {
        return early_fail(desc, GRASS_ERROR_VERSION_MISMATCH, GRASS_MSG_VERSION_MISMATCH,
                          "%s: the caller was compiled against grass.h %u.%u but the library is %u.%u, which runs "
                          "programs built against grass.h %u.%u to %u.%u",
                          function, major, minor, GRASS_VERSION_MAJOR, GRASS_VERSION_MINOR, GRASS_VERSION_MAJOR,
                          kOldestHeaderMinor, GRASS_VERSION_MAJOR, GRASS_VERSION_MINOR);
    }
    if (raw_enum(desc->type) != GRASS_STRUCT_TYPE_CONTEXT_DESC) {
        return early_fail(desc, GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                          "%s: desc->type is 0x%08llx; expected GRASS_STRUCT_TYPE_CONTEXT_DESC (0x%08x)", function,
                          static_cast<unsigned long long>(raw_enum(desc->type)),
                          static_cast<unsigned>(GRASS_STRUCT_TYPE_CONTEXT_DESC));
    }
    // The extensions chained through desc->next (grass.h): each known type once, no loop.
    grass_debug_labels debug_labels = GRASS_DEBUG_LABELS_AUTO;
    bool has_debug_labels = false;
    struct Link {
        grass_struct_type type;
        const void* next;
    };
    uint32_t links = 0;
    for (const void* p = desc->next; p; p = static_cast<const Link*>(p)->next) {
        const int64_t type = raw_enum(static_cast<const Link*>(p)->type);
        links += 1;
        if (type != GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC || has_debug_labels) {
            return early_fail(desc, GRASS_ERROR_WRONG_STRUCT_TYPE, GRASS_MSG_WRONG_STRUCT_TYPE,
                              "%s: desc->next's chain holds, as its link %u, a struct of type 0x%08llx; expected "
                              "GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC (0x%08x), once",
                              function, links, static_cast<unsigned long long>(type),
                              static_cast<unsigned>(GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC));
        }
        has_debug_labels = true;
        const int64_t labels = raw_enum(static_cast<const grass_debug_labels_desc*>(p)->labels);
        if (labels != GRASS_DEBUG_LABELS_AUTO && labels != GRASS_DEBUG_LABELS_OFF && labels != GRASS_DEBUG_LABELS_ON) {
            return early_fail(desc, GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                              "%s: the grass_debug_labels_desc chained to desc->next has labels %lld; it must be "
                              "GRASS_DEBUG_LABELS_AUTO, _OFF or _ON (0..2)",
                              function, static_cast<long long>(labels));
        }
        debug_labels = static_cast<grass_debug_labels>(labels);
    }
    const grass_allocator& a = desc->allocator;
    if ((a.alloc_fn == nullptr) != (a.free_fn == nullptr)) {
        return early_fail(desc, GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_NULL_ARGUMENT,
                          "%s: desc->allocator must set both alloc_fn and free_fn, or neither", function);
    }
    const int64_t log_level = raw_enum(desc->log_level), depth_mode = raw_enum(desc->depth_mode);
    if (log_level < GRASS_LOG_ERROR || log_level > GRASS_LOG_INFO) {
        return early_fail(desc, GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                          "%s: desc->log_level is %lld; it must be 0..2", function, static_cast<long long>(log_level));
    }
    if (depth_mode != GRASS_DEPTH_LESS && depth_mode != GRASS_DEPTH_GREATER) {
        return early_fail(desc, GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                          "%s: desc->depth_mode is %lld; it must be GRASS_DEPTH_LESS or GRASS_DEPTH_GREATER", function,
                          static_cast<long long>(depth_mode));
    }

    // The context lives in memory from its own allocator.
    // The tag tells this context's ids from every other live context's (owner_tags.hpp);
    // the context releases it when it is destroyed.
    const uint16_t owner = acquire_owner_tag();
    if (owner == 0) {
        return early_fail(desc, GRASS_ERROR_OUT_OF_MEMORY, GRASS_MSG_TOO_MANY_OBJECTS,
                          "%s: 65535 contexts are live in this process; destroy one first", function);
    }
    HostAllocator bootstrap(desc->allocator);
    grass_context* ctx = nullptr;
    void* memory = nullptr;
    try {
        memory = bootstrap.allocate(sizeof(grass_context), alignof(grass_context));
        ctx = new (memory) grass_context(*desc, owner);
        ctx->header_minor = minor;
        ctx->debug_labels = debug_labels;
    } catch (const std::bad_alloc&) {
        if (memory) bootstrap.deallocate(memory);
        release_owner_tag(owner);
        return early_fail(desc, GRASS_ERROR_OUT_OF_MEMORY, GRASS_MSG_OUT_OF_MEMORY, "%s: out of host memory", function);
    }
    const grass_result r = guarded(ctx, function, [&] { return factory(ctx, factory_user_data, &ctx->backend); });
    if (r != GRASS_SUCCESS) {
        destroy_context(ctx);
        return r;
    }
    ctx->info(GRASS_MSG_CONTEXT_CREATED, "%s: context created (grass %u.%u.%u)", function, GRASS_VERSION_MAJOR,
              GRASS_VERSION_MINOR, GRASS_VERSION_PATCH);
    *out_context = ctx;
    return GRASS_SUCCESS;
}

void destroy_context(grass_context* ctx) {
    if (!ctx) return;
    if (ctx->in_callback()) {
        ctx->refuse_reentrant("grass_destroy_context");
        return;
    }
    // Without its GPU context current, the context frees its host memory and leaves its GPU
    // objects to the GPU context (check_gpu_current logged why).
    if (check_gpu_current(ctx, "grass_destroy_context") != GRASS_SUCCESS) ctx->backend->abandon();
    const grass_allocator hooks = ctx->desc.allocator;
    ctx->~grass_context();
    HostAllocator(hooks).deallocate(ctx);
}

namespace {
// The blade window's variants of `variants` (a backend that runs the window), prepared like them.
grass_result prepare_window_variants(grass_context* ctx, const char* function, const ShaderVariant* variants,
                                     uint32_t count, bool no_depth_test, const GBufferLayout* layout) {
    if (!ctx->backend->runs_blade_window()) return GRASS_SUCCESS;
    ShaderVariant window[kMaxFieldVariants];
    const uint32_t n = blade_window_variants(variants, count, window);
    return n == 0 ? GRASS_SUCCESS : ctx->backend->prepare_variants(function, window, n, false, no_depth_test, layout);
}
} // namespace

grass_result prepare_field_variants(grass_context* ctx, const char* function, uint32_t slot) {
    const Field* field = ctx->fields.get(slot);
    // A mesh field has no grid variants to make (docs/mesh-fields.md).
    if (ctx->prepared_features == 0 || field == nullptr || field->mesh) return GRASS_SUCCESS;
    uint32_t tier_kinds = 0;
    for (uint32_t t = 0; t < field->lod.tier_count; ++t) tier_kinds |= 1u << field->lod.tiers[t].kind;
    const uint32_t declared = ctx->prepared_features;
    const RenderTarget target = ctx->backend->render_target();
    const bool fixed_targets = ctx->backend->kind() == GRASS_BACKEND_VULKAN; // pipelines made for its targets
    const uint32_t views = drawable_view_bits(declared, target, fixed_targets);
    uint32_t modes[kMaxViewModes];
    const uint32_t mode_count = view_modes(views, modes);
    ShaderVariant variants[kMaxFieldVariants];
    uint32_t count = field_variants(declared, modes, mode_count, field->maps.features, tier_kinds, variants);
    grass_result r = ctx->backend->prepare_variants(function, variants, count, /*interaction_pass=*/false,
                                                    declares_no_depth_test(declared), nullptr);
    if (r == GRASS_SUCCESS)
        r = prepare_window_variants(ctx, function, variants, count, declares_no_depth_test(declared), nullptr);
    if (r != GRASS_SUCCESS || (views & kFeatureGBuffer) == 0) return r;
    // A G-buffer view with velocity writes motion vectors: skipped where the context cannot.
    const bool motion = drawable_view_bits(kFeatureMotion, target, fixed_targets) != 0;
    for (const GBufferLayout& layout : ctx->prepared_gbuffer_layouts) {
        const uint32_t mode = gbuffer_view_mode(layout);
        if ((mode & kFeatureMotion) && !motion) continue;
        count = field_variants(declared, &mode, 1, field->maps.features, tier_kinds, variants);
        r = ctx->backend->prepare_variants(function, variants, count, false, false, &layout);
        if (r == GRASS_SUCCESS) r = prepare_window_variants(ctx, function, variants, count, false, &layout);
        if (r != GRASS_SUCCESS) return r;
    }
    return GRASS_SUCCESS;
}

namespace {
grass_result make_null_backend(grass_context* ctx, void*, Backend** out) {
    *out = ctx->host.create<NullBackend>();
    return GRASS_SUCCESS;
}
} // namespace

} // namespace grass

extern "C" {

GRASS_API uint32_t grass_get_library_version(void) { return GRASS_HEADER_VERSION; }

GRASS_API const char* grass_result_string(grass_result result) {
    // A C host may pass any int: read it as one (raw_enum.hpp).
    switch (grass::raw_enum(result)) {
    case GRASS_SUCCESS:
        return "GRASS_SUCCESS";
    case GRASS_ERROR_INVALID_ARGUMENT:
        return "GRASS_ERROR_INVALID_ARGUMENT";
    case GRASS_ERROR_INVALID_HANDLE:
        return "GRASS_ERROR_INVALID_HANDLE";
    case GRASS_ERROR_WRONG_STRUCT_TYPE:
        return "GRASS_ERROR_WRONG_STRUCT_TYPE";
    case GRASS_ERROR_INVALID_STATE:
        return "GRASS_ERROR_INVALID_STATE";
    case GRASS_ERROR_OUT_OF_MEMORY:
        return "GRASS_ERROR_OUT_OF_MEMORY";
    case GRASS_ERROR_VERSION_MISMATCH:
        return "GRASS_ERROR_VERSION_MISMATCH";
    case GRASS_ERROR_BACKEND:
        return "GRASS_ERROR_BACKEND";
    case GRASS_ERROR_UNSUPPORTED:
        return "GRASS_ERROR_UNSUPPORTED";
    case GRASS_ERROR_IN_USE:
        return "GRASS_ERROR_IN_USE";
    }
    return "GRASS_ERROR_UNKNOWN";
}

GRASS_API grass_context_desc grass_default_context_desc(void) {
    grass_context_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_CONTEXT_DESC;
    d.log_level = GRASS_LOG_WARNING;
    d.depth_mode = GRASS_DEPTH_LESS;
    return d;
}

GRASS_API grass_debug_labels_desc grass_default_debug_labels_desc(void) {
    grass_debug_labels_desc d;
    std::memset(&d, 0, sizeof(d));
    d.type = GRASS_STRUCT_TYPE_DEBUG_LABELS_DESC;
    d.labels = GRASS_DEBUG_LABELS_AUTO;
    return d;
}

GRASS_API grass_result grass_create_context(uint32_t header_version, const grass_context_desc* desc,
                                            grass_context** out_context) {
    return grass::create_context("grass_create_context", header_version, desc, grass::make_null_backend, nullptr,
                                 out_context);
}

GRASS_API void grass_destroy_context(grass_context* context) { grass::destroy_context(context); }

GRASS_API grass_backend grass_get_context_backend(const grass_context* context) {
    return context && context->backend ? context->backend->kind() : GRASS_BACKEND_NONE;
}

GRASS_API const char* grass_get_last_error(const grass_context* context) { return context ? context->last_error : ""; }

GRASS_API grass_result grass_get_memory_stats(const grass_context* context, grass_memory_stats* out_stats) {
    auto* ctx = const_cast<grass_context*>(context); // logging only
    if (!ctx) return GRASS_ERROR_INVALID_ARGUMENT;
    const char* fn = "grass_get_memory_stats";
    GRASS_TRY(grass::check_entry(ctx, fn));
    GRASS_TRY(grass::check_not_null(ctx, fn, "out_stats", out_stats));
    grass_memory_stats stats{};
    stats.host_bytes = context->host.bytes();
    stats.host_allocations = context->host.allocations();
    stats.gpu_bytes = context->backend ? context->backend->gpu_bytes() : 0;
    stats.host_bytes_peak = context->host.bytes_peak();
    stats.dynamics_gpu_bytes = context->backend ? context->backend->dynamics_gpu_bytes() : 0;
    if (context->backend) context->backend->device_memory(&stats);
    grass::write_out_struct(context->header_minor, stats, out_stats);
    return GRASS_SUCCESS;
}

} // extern "C"
