// The context: the root object behind the opaque grass_context pointer. Internal header,
// shared by the core and the backends (which never see each other).
#pragma once

#include "context/allocator.hpp"
#include "context/backend.hpp"
#include "context/handle_pool.hpp"
#include "dynamics/blade_mechanics.hpp"
#include "dynamics/dynamics_state.hpp"
#include "dynamics/wind_map.hpp"
#include "maps/design_map.hpp"
#include "patch/patch_data.hpp"
#include "plan/blade_culling.hpp"
#include "plan/frame_plan.hpp"
#include "plan/lod_setup_types.hpp"
#include "plan/plan_scratch.hpp"
#include "plan/quadtree.hpp"

#include <grass/grass.h>

#include <cstdarg>
#include <cstdint>

namespace grass {

struct Patch {
    explicit Patch(HostAllocator* h) : data(h), host(h), slice_sets(StlAllocator<SliceSet*>(h)) {}
    ~Patch() {
        for (SliceSet* s : slice_sets) host->destroy(s);
    }
    Patch(const Patch&) = delete;
    Patch& operator=(const Patch&) = delete;
    // The baked set with `slices_per_axis` (0 = the horizontal slice), or nullptr.
    const SliceSet* slices(uint32_t slices_per_axis) const {
        for (const SliceSet* s : slice_sets) {
            if (s->slices_per_axis == slices_per_axis) return s;
        }
        return nullptr;
    }
    PatchData data;
    HostAllocator* host;
    grass_patch_desc desc{};
    uint32_t field_users = 0;     // fields that use this patch
    Vector<SliceSet*> slice_sets; // baked on demand by the fields' tiers, uploaded once each
    // Responsive grass: how its blades respond (grass_set_blade_mechanics), and whether the
    // backend holds its blade curves (uploaded at the first responsive draw of the patch).
    grass_blade_mechanics mechanics = default_blade_mechanics();
    bool blade_curves_uploaded = false;
};

struct Field {
    grass_field_desc desc{}; // pointers in it are cleared; maps are referenced below
    uint32_t patch_slot = 0;
    FieldMaps maps;                             // map slot per role (kNoMap: none) and the feature mask
    bool owns_density_map = false;              // maps.map_slot[kMapDensity] was made from desc.density_map
    double cell_to_map[6] = {0, 0, 0, 0, 0, 0}; // cell (x, z) -> map (u, v), lemme's configTf
    double height_scale = 0.0;                  // metres per height-map unit (0 without a height map)
    // Grass types (lemme 6.4.5): the first type is the field the host holds an id for; the
    // others are fields of their own, hidden behind it, made and destroyed with it.
    uint32_t parent = 0xffffffffu; // slot of the host's field for a hidden type, else none
    uint32_t children[GRASS_MAX_GRASS_TYPES - 1] = {};
    uint32_t child_count = 0;
    double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; // base transform's rotation, column-major
    double translation[3] = {0, 0, 0};
    LodSetup lod;                         // tiers and lod tests, copied from the desc
    QuadtreeShape tree;                   // implicit: nothing per node or cell
    LevelExtent extents[32];              // vertical extent of each level's nodes, in cells
    float bands[GRASS_MAX_TIERS][4] = {}; // per tier: its distance band (begin, end, in, out) for the transitions
    double overhang = 0.0;                // how far blade tips may leave their cell, in cells
    FieldWindMap wind_map;                // responsive grass: the host's wind map (grass_set_field_wind_map)
    BladeCulling culling;                 // per-blade culling of its geometry tiers (grass_set_blade_culling)
};

// Creates the backend of a new context; the context's allocator and log are ready.
using BackendFactory = grass_result (*)(grass_context* context, void* user_data, Backend** out_backend);

} // namespace grass

struct grass_context {
    grass_context(const grass_context_desc& desc, uint16_t owner_tag);
    ~grass_context();

    grass::HostAllocator host;
    grass_context_desc desc;
    uint16_t owner;
    uint32_t header_minor = GRASS_VERSION_MINOR; // of the header the host was built against (abi_sizes.hpp)
    grass::Backend* backend = nullptr;
    grass::HandlePool<grass::Patch> patches;
    grass::HandlePool<grass::Field> fields;
    grass::HandlePool<grass::DesignMap> maps;
    grass::FramePlan plan;
    grass::PlanScratch plan_scratch;
    grass::DynamicsState dynamics; // wind, colliders, the interaction map's state, the clock
    bool in_frame = false;
    uint64_t frame_number = 0;
    char last_error[512] = {0};
    grass::Vector<char> cache_directory; // copy of desc.cache_directory (empty: no disk cache)
    bool cache_write_warned = false;     // the cache directory could not be written: said once
    // Host callbacks running on this context (grass.h "Re-entrancy"): lod test callbacks and
    // the log callback; the allocator's hooks are counted by `host`. While one runs, every
    // call on the context but the pure getters is refused (refuse_reentrant).
    uint32_t lod_callbacks_running = 0;
    uint32_t log_callbacks_running = 0;
    bool in_callback() const { return lod_callbacks_running > 0 || log_callbacks_running > 0 || host.hook_running(); }
    // Logs and returns the refusal of `function`, called from inside a callback.
    grass_result refuse_reentrant(const char* function);

    // Logs `message` (printf format) at error level with `id`, keeps it as the last error,
    // and returns `result`: `return ctx->fail(GRASS_ERROR_..., GRASS_MSG_..., "...", ...);`
    grass_result fail(grass_result result, grass_message_id id, const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 4, 5)))
#endif
        ;
    void warn(grass_message_id id, const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 3, 4)))
#endif
        ;
    void info(grass_message_id id, const char* format, ...)
#if defined(__GNUC__)
        __attribute__((format(printf, 3, 4)))
#endif
        ;

private:
    void emit(grass_log_level level, grass_message_id id, const char* format, va_list args);
};

namespace grass {

// Makes a context with the backend `factory` creates (used by grass_create_context,
// grass_gl_create_context and grass_vk_create_context). `function` names the public call
// for messages. On failure *out_context stays untouched and nothing leaks.
grass_result create_context(const char* function, uint32_t header_version, const grass_context_desc* desc,
                            BackendFactory factory, void* factory_user_data, grass_context** out_context);
void destroy_context(grass_context* context);

// Counts a host callback in flight for its lifetime: `CallbackScope scope(ctx->lod_callbacks_running);`.
class CallbackScope {
public:
    explicit CallbackScope(uint32_t& counter) noexcept : counter_(counter) { ++counter_; }
    ~CallbackScope() { --counter_; }
    CallbackScope(const CallbackScope&) = delete;
    CallbackScope& operator=(const CallbackScope&) = delete;

private:
    uint32_t& counter_;
};

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

// Runs `body` and turns C++ exceptions into result codes (std::bad_alloc into
// GRASS_ERROR_OUT_OF_MEMORY), so that no exception crosses the C boundary. Makes the
// entry check (check_entry) first.
template <class Body>
grass_result guarded(grass_context* ctx, const char* function, Body&& body) noexcept;

} // namespace grass

#include "context/context_guard.inl"
