// The context: the root object behind the opaque grass_context pointer. Internal header,
// shared by the core and the backends (which never see each other). It owns every concept's
// state (the patches and fields of plan/field.hpp, maps, the plan, responsive grass) and lies
// above the concepts, which never include it (docs/architecture.md "Layers"); it is their Log.
#pragma once

#include "context/backend.hpp"
#include "context/frame_views.hpp"
#include "dynamics/dynamics_state.hpp"
#include "foundation/allocator.hpp"
#include "foundation/frame_plan.hpp"
#include "foundation/handle_pool.hpp"
#include "foundation/log.hpp"
#include "maps/design_map.hpp"
#include "plan/field.hpp"
#include "plan/plan_scratch.hpp"

#include <grass/grass.h>

#include <cstdint>

namespace grass {

// Creates the backend of a new context; the context's allocator and log are ready.
using BackendFactory = grass_result (*)(grass_context* context, void* user_data, Backend** out_backend);

} // namespace grass

struct grass_context : grass::Log {
    grass_context(const grass_context_desc& desc, uint16_t owner_tag);
    ~grass_context();

    grass::HostAllocator host;
    grass_context_desc desc;
    uint16_t owner;
    uint32_t header_minor = GRASS_VERSION_MINOR; // of the header the host was built against (abi_sizes.hpp)
    // From the grass_debug_labels_desc chained to the create call's desc (grass.h); the
    // backend resolves AUTO when it is made.
    grass_debug_labels debug_labels = GRASS_DEBUG_LABELS_AUTO;
    grass::Backend* backend = nullptr;
    grass::HandlePool<grass::Patch> patches;
    grass::HandlePool<grass::Field> fields;
    grass::HandlePool<grass::DesignMap> maps;
    grass::FramePlan plan;   // view 0 of the frame (the only one of grass_begin_frame)
    grass::FrameViews views; // every planned view of the frame, plan first
    grass::HostFrame host_frame;
    grass::PlanScratch plan_scratch;
    grass::DynamicsState dynamics; // wind, colliders, the interaction map's state, the clock
    bool in_frame = false;
    uint64_t frame_number = 0;
    grass::Vector<char> cache_directory; // copy of desc.cache_directory (empty: no disk cache)
    bool cache_write_warned = false;     // the cache directory could not be written: said once
    // grass_prepare_pipelines: the feature bits the host declared (declared_feature_bits),
    // whose variants each new field gets at creation (prepare_field_variants). 0: none.
    uint32_t prepared_features = 0;
    // The G-buffer layouts declared with GRASS_PIPELINE_FEATURE_GBUFFER, each once: Vulkan
    // makes G-buffer pipelines per layout.
    grass::Vector<grass::GBufferLayout> prepared_gbuffer_layouts;
    // Host callbacks running on this context (grass.h "Re-entrancy"): lod test callbacks and
    // the log callback; the allocator's hooks are counted by `host`. While one runs, every
    // call on the context but the pure getters is refused (refuse_reentrant).
    uint32_t lod_callbacks_running = 0;
    bool in_callback() const { return lod_callbacks_running > 0 || log_callbacks_running > 0 || host.hook_running(); }
    // Logs and returns the refusal of `function`, called from inside a callback.
    grass_result refuse_reentrant(const char* function);
};

namespace grass {

// Makes a context with the backend `factory` creates (used by grass_create_context,
// grass_gl_create_context and grass_vk_create_context). `function` names the public call
// for messages. On failure *out_context stays untouched and nothing leaks.
grass_result create_context(const char* function, uint32_t header_version, const grass_context_desc* desc,
                            BackendFactory factory, void* factory_user_data, grass_context** out_context);
void destroy_context(grass_context* context);

// Has the backend make every variant the declared features (context->prepared_features)
// need for the field in `slot` (grass_prepare_pipelines, grass_create_field): the responsive
// variants in each view mode the context can draw (drawable_view_bits), the G-buffer modes
// once per declared layout. Nothing without a declaration.
grass_result prepare_field_variants(grass_context* context, const char* function, uint32_t slot);

// The entry check of every call on a context: refuses a call made from inside one of the
// context's callbacks (grass.h "Re-entrancy"). guarded() makes it; calls that do not go
// through guarded() make it themselves: `GRASS_TRY(grass::check_entry(ctx, fn));`.
inline grass_result check_entry(grass_context* ctx, const char* function) {
    return ctx->in_callback() ? ctx->refuse_reentrant(function) : GRASS_SUCCESS;
}

// The check of every call that makes GPU calls (grass_gl.h): the backend's GPU context is
// current. `GRASS_TRY(grass::check_gpu_current(ctx, fn));` before anything else.
inline grass_result check_gpu_current(grass_context* ctx, const char* function) {
    return ctx->backend ? ctx->backend->check_current(function) : GRASS_SUCCESS;
}

// The view a draw call names (grass_gl_render_view, grass_vk_record_view; 0 for
// grass_gl_render and grass_vk_record): one planned in the begun frame.
inline grass_result check_view_planned(grass_context* ctx, const char* function, uint32_t view) {
    if (view < ctx->views.count()) return GRASS_SUCCESS;
    return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                     "%s: view is %u, but the begun frame has %u planned view(s) (grass_plan_view numbers them "
                     "from 0)",
                     function, view, ctx->views.count());
}

// Runs `body` and turns C++ exceptions into result codes (std::bad_alloc into
// GRASS_ERROR_OUT_OF_MEMORY), so that no exception crosses the C boundary. Makes the
// entry check (check_entry) first.
template <class Body>
grass_result guarded(grass_context* ctx, const char* function, Body&& body) noexcept;

} // namespace grass

#include "context/context_guard.inl"
