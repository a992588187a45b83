// G-buffer views on Vulkan (grass_view_pass_desc GRASS_PASS_GBUFFER, grass_view_gbuffer_desc,
// grass_vk_gbuffer_target_desc): their pipelines, one per layout the host draws (the routes of
// the view's outputs: the attachment and write mask of each), tier, feature mask and depth
// test, made on the first view that draws each. Their fragment modules are the GRASS_GBUFFER
// variants (with GRASS_VELOCITY where the view writes motion vectors) rewritten for the layout
// (route_gbuffer_outputs): each output's Location moved to its attachment, every output the
// host did not ask for turned into a private variable, so that no output lacks an attachment
// and no attachment without an output has a write mask (the validation layers warn of either).
// They share the view extras' pipeline layout (set 1: the GrassGBuffer block at binding 3,
// the GrassMotion block at 0; vk_view_extras.hpp). A context whose views draw no G-buffer
// holds none of it. BladePipeline owns one.
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/frame_plan.hpp"
#include "foundation/shader_interface.hpp"
#include "foundation/shader_variants.hpp"
#include "vk_functions.hpp"
#include "vk_result.hpp"

#include <cstddef>
#include <cstdint>

namespace grass::vk {

struct PipelineTarget; // vk_pipeline.hpp, which includes this header
struct PipelineShape;

// Where a G-buffer view's outputs go: per output location (kGBufferOutput) the host's
// attachment (kNoGBufferOutput: none) and its write mask (RGBA bits).
struct GBufferRoutes {
    uint32_t attachment[kGBufferOutputs] = {kNoGBufferOutput, kNoGBufferOutput, kNoGBufferOutput, kNoGBufferOutput};
    uint32_t mask[kGBufferOutputs] = {0, 0, 0, 0};
    static GBufferRoutes of(const FramePlan& plan);
    static GBufferRoutes of(const GBufferLayout& layout); // a layout grass_prepare_pipelines was given
    bool operator==(const GBufferRoutes& o) const;
};

// `code` (SPIR-V of a fragment shader, `words` long) into *out with each Output variable at a
// location o < kGBufferOutputs moved to routes.attachment[o], or, where that is
// kNoGBufferOutput, made a Private variable (out of the entry point's interface, without its
// Location). False when the module is not one this can read.
bool route_gbuffer_outputs(const uint32_t* code, size_t words, const GBufferRoutes& routes, Vector<uint32_t>* out);

class GBufferPipelines {
public:
    GBufferPipelines(const Functions& functions, VkDevice device, HostAllocator* host)
        : fn_(functions), device_(device), host_(host), entries_(StlAllocator<Entry>(host)) {}
    ~GBufferPipelines() { destroy(); }
    GBufferPipelines(const GBufferPipelines&) = delete;
    GBufferPipelines& operator=(const GBufferPipelines&) = delete;

    // Makes the pipeline of `variant` (kFeatureGBuffer, perhaps kFeatureMotion; blades, volume
    // or image) for `routes` from `shape` (the GRASS_GBUFFER modules) against `target` (the
    // host's G-buffer pass) in `layout` (the view extras'), unless it exists. May throw
    // std::bad_alloc. On failure it does not exist and *what names what was being made.
    bool create_variant(const PipelineTarget& target, VkPipelineLayout layout, const GBufferRoutes& routes,
                        const ShaderVariant& variant, const PipelineShape& shape, bool depth_test, VkFailure* failure,
                        const char** what);
    // The pipeline of `kind` for `features` and `routes`, or VK_NULL_HANDLE where not made.
    VkPipeline pipeline(const GBufferRoutes& routes, uint32_t kind, uint32_t features, bool depth_test) const;
    // How many pipelines exist (0: a context that drew no G-buffer view holds none).
    size_t size() const { return entries_.size(); }
    void destroy();

private:
    struct Entry {
        GBufferRoutes routes;
        uint32_t kind;
        uint32_t features;
        bool depth_test;
        VkPipeline pipeline;
    };
    const Functions& fn_;
    VkDevice device_;
    HostAllocator* host_;
    Vector<Entry> entries_;
};

} // namespace grass::vk
