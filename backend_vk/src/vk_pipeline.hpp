// The pipelines of the backend: the descriptor set layout every one of them uses (Frame and
// Field uniform blocks as dynamic uniform buffers, the design maps with an immutable linear
// clamp sampler, the baked slices of the volume and image tiers with immutable trilinear /
// nearest samplers), the pipeline layout, and the graphics pipelines of each kind (blades,
// volume, image, debug view) per map feature mask, each with the depth test and, when
// something will draw with it (GRASS_VIEW_FLAG_NO_DEPTH_TEST), without; and the state every
// pipeline shares (create_pipeline).
#pragma once

#include "foundation/allocator.hpp"
#include "foundation/shader_interface.hpp"
#include "foundation/shader_variants.hpp"
#include "vk_functions.hpp"
#include "vk_gbuffer.hpp"
#include "vk_result.hpp"
#include "vk_spirv.hpp"
#include "vk_view_extras.hpp"

#include <cstddef>
#include <cstdint>

namespace grass::vk {

// Binding numbers of blade_interface.glsl, descriptor set 0.
enum BladeBinding : uint32_t {
    kBindingFrame = 0,
    kBindingField = 1,
    kBindingDensityMap = 2,
    kBindingSliceColor = 3,
    kBindingSliceNormal = 4,
    kBindingSliceThreshold = 5,
    kBindingColorMap = 6,
    kBindingAmbientMap = 7,
    kBindingDiffuseMap = 8,
    kBindingHeightMap = 9,
    // Responsive grass (kFeatureWind, kFeatureInteraction): the interaction map's levels
    // (RGBA32F, GENERAL layout, read with texelFetch through a nearest sampler) and the
    // patch's blade control points (a storage buffer). Draws without those features bind
    // stand-ins the shaders never read (VkBackend::write_set).
    kBindingInteractionMap0 = 10,
    kBindingInteractionMap1 = 11,
    kBindingBladeCurves = 12,
    // A field's wind map (kFeatureWindMap: an RGBA design map read with texelFetch); draws
    // without it bind the default black map, which they never read.
    kBindingWindMap = 13,
    // The blade window (kFeatureBladeWindow, vk_blade_window.hpp): the frame slot's table and
    // the poses (storage buffers), read by the window variant of blade.vert; the pass writes
    // the poses through the same binding. Other draws bind the 16-byte stand-in.
    kBindingWindowTable = 14,
    kBindingWindowPoses = 15,
    kBindingCount = 16
};
static_assert(kBindingDensityMap == 2 && kBindingColorMap == 6 && kBindingHeightMap == 9,
              "kMapBinding of api/src/foundation/shader_interface.hpp");
// The stages of set 0: the graphics shaders and the blade window pass, which binds a
// responsive draw's set (vk_blade_window.hpp).
constexpr VkShaderStageFlags kBladeSetStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
static_assert(
    kBindingInteractionMap0 == 10 && kBindingInteractionMap1 == 11 && kBindingBladeCurves == 12 &&
        kBindingWindMap == kWindMapBinding,
    "kInteractionMapBinding, kBladeCurvesBinding and kWindMapBinding of api/src/foundation/shader_interface.hpp");

// The kinds of graphics pipeline; each exists per map feature mask (GRASS_FEATURES).
enum PipelineKind : uint32_t {
    kPipelineBlade = 0,
    kPipelineVolume = 1,
    kPipelineImage = 2,
    kPipelineDebugView = 3,
    kPipelineKindCount = 4
};
static_assert(kPipelineBlade == static_cast<uint32_t>(kShaderBlades) &&
                  kPipelineVolume == static_cast<uint32_t>(kShaderVolume) &&
                  kPipelineImage == static_cast<uint32_t>(kShaderImage) &&
                  kPipelineDebugView == static_cast<uint32_t>(kShaderDebugBoxes),
              "the programs of foundation/shader_variants.hpp");
// Feature masks are 10 bits (kFeatureMaskCount, backend.hpp): one per MapRole, then
// kFeatureWind, kFeatureInteraction, kFeatureWindMap, kFeatureBladeCulling and kFeatureDebugView.
// The 11th, kFeatureDepthPass, marks a depth view's draws: their pipelines (blades, volume,
// image; depth-tested) live in a table of their own, made on the first depth pass, so the
// colour table holds the colour masks alone; the 12th, kFeatureShadowReceive, a receiving
// view's draws, and the 13th, kFeatureMotion, a motion view's, alone or together
// (ViewExtrasPipelines, vk_view_extras.hpp).
constexpr uint32_t kColourFeatureMasks = kFeatureDepthPass;
constexpr uint32_t kDepthPipelineKinds = 3; // blades, volume, image: a depth pass draws no debug view

struct PipelineTarget {
    VkRenderPass render_pass = VK_NULL_HANDLE; // VK_NULL_HANDLE: dynamic rendering with the formats
    uint32_t subpass = 0;
    VkFormat color_format = VK_FORMAT_UNDEFINED;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool depth_greater = false;             // reversed-Z host: GREATER_OR_EQUAL
    bool indexed_blocks = false;            // Frame and Field at a push-constant index (vk_spirv.hpp; Device)
    VkPipelineCache cache = VK_NULL_HANDLE; // every pipeline goes through it: the host's or grass's own
    // Multiview (grass_vk_multiview_desc.view_mask): 0x3 for a stereo pass (the GRASS_MULTIVIEW
    // modules; dynamic rendering's viewMask; a render pass's subpass carries its own), 0 for mono.
    uint32_t view_mask = 0;
    // A depth pass's target (grass_vk_depth_pass_desc): no colour attachment (color_format
    // unused), no colour writes, no alpha to coverage, the depth bias dynamic (vkCmdSetDepthBias).
    bool depth_only = false;
    // A pass with a velocity target (grass_vk_velocity_target_desc): `color_count` colour
    // attachments (attachment 0 color_format, attachment i other_formats[i - 1] under dynamic
    // rendering), the velocity at `velocity_attachment` (written .rg unblended), every other
    // but 0 with write mask 0. 1 and 0: the plain target.
    uint32_t color_count = 1;
    uint32_t velocity_attachment = 0;
    VkFormat other_formats[7] = {};
    // A G-buffer view's pipelines (vk_gbuffer.hpp): each attachment's colorWriteMask is
    // write_masks[i] (RGBA bits), attachment 0's too, all unblended.
    bool explicit_masks = false;
    uint32_t write_masks[8] = {};
};

// The descriptor type of the Frame and Field blocks (dynamic offsets: one per draw).
constexpr VkDescriptorType kBlockDescriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
// The push constants of the indexed-block shaders (GRASS_INDEXED_BLOCKS): the blocks' index, 0.
constexpr VkShaderStageFlags kBlockIndexStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr uint32_t kBlockIndexBytes = 4;

// What differs between the graphics pipelines of the backend; the rest (viewport and
// scissor dynamic, no culling, opaque colour, the target's samples and formats) is shared.
struct PipelineShape {
    const uint32_t* vertex_code;
    size_t vertex_code_size; // bytes
    const uint32_t* fragment_code;
    size_t fragment_code_size;
    VkPipelineVertexInputStateCreateInfo vertex_input; // its arrays live as long as the program
    bool alpha_to_coverage;                            // only with multisampling
    const char* name;                                  // for *what: "the blade pipelines"
};

// A sampler's state: bilinear, one level (the nearest mip), clamped to the edge.
VkSamplerCreateInfo linear_clamped_sampler_info();

// The blade pipelines' shape of the modules `variant` (vertex input: patch vertices and instances).
PipelineShape blade_shape(SpirvVariant variant);

// The vertex input of the shaders that read instances only (locations 5, 6 and 7 on
// binding 0: debug_tiers, volume and image): its arrays live as long as the program.
VkPipelineVertexInputStateCreateInfo instance_only_vertex_input();

// A descriptor set layout of `bindings` and a pipeline layout of that one set (the blade
// pipelines', the interaction pass's), with `push_range` (or none: nullptr). *what names the
// object being made (`set_name`, `layout_name`) when it fails; what was made stays in
// *set_layout / *layout for the caller to destroy.
bool create_set_and_pipeline_layout(const Functions& fn, VkDevice device, const VkDescriptorSetLayoutBinding* bindings,
                                    uint32_t binding_count, const VkPushConstantRange* push_range, const char* set_name,
                                    const char* layout_name, VkDescriptorSetLayout* set_layout,
                                    VkPipelineLayout* layout, VkFailure* failure, const char** what);

// One graphics pipeline of `shape`: with `depth_test` it depth-tests and writes depth (the
// target's compare op), without it does neither (GRASS_VIEW_FLAG_NO_DEPTH_TEST); both vertex
// and fragment stages are specialised with `features` (constant id 0, blade_interface.glsl).
// Its shader modules live only as long as the call. On failure *out_pipeline is VK_NULL_HANDLE.
bool create_pipeline(const Functions& fn, VkDevice device, const PipelineTarget& target, VkPipelineLayout layout,
                     const PipelineShape& shape, uint32_t features, bool depth_test, VkPipeline* out_pipeline,
                     VkFailure* failure, const char** what);

class BladePipeline {
public:
    BladePipeline(const Functions& functions, VkDevice device, HostAllocator* host)
        : fn_(functions), device_(device), depth_pipelines_(StlAllocator<VkPipeline>(host)),
          extras_(functions, device, host), gbuffer_(functions, device, host),
          window_pipelines_(StlAllocator<WindowPipeline>(host)) {}
    ~BladePipeline() { destroy(); }
    BladePipeline(const BladePipeline&) = delete;
    BladePipeline& operator=(const BladePipeline&) = delete;

    // The layouts and the depth-tested pipelines of every kind without maps (features 0).
    // *what names the object being made when it fails.
    bool create(const PipelineTarget& target, VkFailure* failure, const char** what);
    // The depth-only target of depth views (grass_vk_depth_pass_desc; target.depth_only),
    // before any depth variant is made. Without it create_variant refuses kFeatureDepthPass.
    void set_depth_target(const PipelineTarget& target) { depth_target_ = target; }
    // The colour attachments of motion views (grass_vk_velocity_target_desc; its
    // velocity_attachment not 0), before any motion variant is made. Without it
    // create_variant refuses kFeatureMotion.
    void set_velocity_target(const PipelineTarget& target) { velocity_target_ = target; }
    // The colour attachments of G-buffer views (grass_vk_gbuffer_target_desc), before any
    // G-buffer variant is made. Without it create_variant refuses kFeatureGBuffer.
    void set_gbuffer_target(const PipelineTarget& target) { gbuffer_target_ = target; }
    // The routes of the G-buffer view being recorded: kFeatureGBuffer variants made, looked
    // up and drawn after it are those of this layout.
    void select_gbuffer(const GBufferRoutes& routes) { routes_ = routes; }
    // The pipelines of G-buffer views (empty until the first).
    const GBufferPipelines& gbuffer() const { return gbuffer_; }
    void destroy();

    // Makes the pipeline of `variant` (foundation/shader_variants.hpp) with the depth test
    // or without it (`depth_test` false: GRASS_VIEW_FLAG_NO_DEPTH_TEST) unless it exists.
    // Only grass_prepare_pipelines with the debug views and a frame that turns the depth
    // test off ask for the latter. A variant with kFeatureDepthPass (depth-tested, not a
    // debug view) is made against the depth target, in the depth table (made by the first:
    // may throw std::bad_alloc); one with kFeatureShadowReceive, kFeatureMotion or
    // kFeatureHostLights (any of them together) by extras() (mono only; motion against the
    // velocity target).
    // On failure it does not exist.
    bool create_variant(const ShaderVariant& variant, bool depth_test, VkFailure* failure, const char** what);
    // The depth-tested pipelines of every kind for `features` (a field's maps: upload_field).
    bool create_variants(uint32_t features, VkFailure* failure, const char** what);
    bool has_variant(const ShaderVariant& v, bool depth_test) const {
        if ((v.features & kFeatureBladeWindow) && !(v.features & kFeatureGBuffer))
            return window_pipeline(v.program, v.features, depth_test) != VK_NULL_HANDLE;
        if (v.features & kFeatureGBuffer)
            return gbuffer_.pipeline(routes_, v.program, v.features, depth_test) != VK_NULL_HANDLE;
        if (v.features & kViewExtras) return extras_.has_variant(v, depth_test);
        if (v.features & kFeatureDepthPass) return depth_test && depth_slot(v.program, v.features) != nullptr;
        return v.features < kColourFeatureMasks &&
               pipelines_[v.features][v.program][depth_test ? 0 : 1] != VK_NULL_HANDLE;
    }

    VkDescriptorSetLayout set_layout() const { return set_layout_; }
    VkPipelineLayout layout() const { return layout_; }
    // The pipelines, samplers and layout of views that receive shadows, write motion vectors
    // or are lit by the host's lights (set 1: the view extras, vk_view_extras.hpp).
    const ViewExtrasPipelines& extras() const { return extras_; }
    // The pipeline of `kind` for `features` (has_variant(features, depth_test)).
    VkPipeline pipeline(PipelineKind kind, uint32_t features, bool depth_test) const {
        if ((features & kFeatureBladeWindow) && !(features & kFeatureGBuffer))
            return window_pipeline(kind, features, depth_test);
        if (features & kFeatureGBuffer) return gbuffer_.pipeline(routes_, kind, features, depth_test);
        if (features & kViewExtras) return extras_.pipeline(kind, features, depth_test);
        if (features & kFeatureDepthPass) return *depth_slot(kind, features);
        return pipelines_[features][kind][depth_test ? 0 : 1];
    }

private:
    // A blade window variant's pipeline (kFeatureBladeWindow, in any view but a G-buffer
    // view's, whose table keys every feature): VK_NULL_HANDLE where not made.
    struct WindowPipeline {
        uint32_t program;
        uint32_t features;
        bool depth_test;
        VkPipeline pipeline;
    };
    VkPipeline window_pipeline(uint32_t program, uint32_t features, bool depth_test) const {
        for (const WindowPipeline& w : window_pipelines_) {
            if (w.program == program && w.features == features && w.depth_test == depth_test) return w.pipeline;
        }
        return VK_NULL_HANDLE;
    }
    // Its entry, added unless it exists (may throw std::bad_alloc before anything is made).
    VkPipeline* window_slot(uint32_t program, uint32_t features, bool depth_test);
    bool create_layouts(VkFailure* failure, const char** what);
    // A kFeatureGBuffer variant for the selected routes (create_variant).
    bool create_gbuffer_variant(const ShaderVariant& variant, bool depth_test, VkFailure* failure, const char** what);
    void destroy_variants(uint32_t features);
    // The depth table's entry of `program` for `features` (with kFeatureDepthPass), or
    // nullptr where it has none (no table yet, a debug view); the entry may be VK_NULL_HANDLE.
    const VkPipeline* depth_slot(uint32_t program, uint32_t features) const {
        if (depth_pipelines_.empty() || program >= kDepthPipelineKinds) return nullptr;
        const uint32_t colour = features & ~kFeatureDepthPass;
        if (colour >= kColourFeatureMasks) return nullptr;
        const VkPipeline* p = &depth_pipelines_[colour * kDepthPipelineKinds + program];
        return *p != VK_NULL_HANDLE ? p : nullptr;
    }

    const Functions& fn_;
    VkDevice device_;
    PipelineTarget target_;
    VkSampler sampler_ = VK_NULL_HANDLE;       // design maps: bilinear, one mip
    VkSampler slice_linear_ = VK_NULL_HANDLE;  // slice colour and normal: trilinear
    VkSampler slice_nearest_ = VK_NULL_HANDLE; // slice thresholds: never blended
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    // [features][kind][0 = depth tested, 1 = depth off]; VK_NULL_HANDLE: not made yet
    VkPipeline pipelines_[kColourFeatureMasks][kPipelineKindCount][2] = {};
    // Depth views: [colour features][kind] (kColourFeatureMasks x kDepthPipelineKinds), empty
    // until the first depth variant; depth_target_.depth_only: the host gave a depth target.
    PipelineTarget depth_target_;
    Vector<VkPipeline> depth_pipelines_;
    PipelineTarget velocity_target_;          // velocity_attachment 0: the host gave no velocity target
    ViewExtrasPipelines extras_;              // empty until the first view with extras
    PipelineTarget gbuffer_target_;           // color_count 0: the host gave no G-buffer target
    GBufferRoutes routes_;                    // the G-buffer view being recorded (select_gbuffer)
    GBufferPipelines gbuffer_;                // empty until the first G-buffer view
    Vector<WindowPipeline> window_pipelines_; // empty until the first blade window variant
};

} // namespace grass::vk
