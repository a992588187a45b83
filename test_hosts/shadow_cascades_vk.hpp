// The Vulkan host's cascaded sun shadow map (TargetDesc::host_shadows): a D32_SFLOAT 2D array
// image, a layer per cascade, drawn in a depth-only render pass (a framebuffer per layer) that
// is the context's grass_vk_depth_pass_desc, so grass's depth views record in it. The pass
// leaves the image in DEPTH_STENCIL_READ_ONLY_OPTIMAL, its writes made visible to fragment
// shader reads by the pass's outgoing dependency; the next frame's pass waits for those reads.
// Also the descriptor set (set 1 of the receiving pipelines: the HostShadowBlock and the map
// through a compare sampler) the ground and the meshes read it through.
#pragma once

#include "light_cascades.hpp"
#include "mesh_drawer_vk.hpp"

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

namespace grass_host {

class VkShadowCascades {
public:
    VkShadowCascades() = default;
    ~VkShadowCascades(); // the device must be idle for it
    VkShadowCascades(const VkShadowCascades&) = delete;
    VkShadowCascades& operator=(const VkShadowCascades&) = delete;

    bool init(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, const HostShadows& shadows,
              std::string* error);

    VkRenderPass render_pass() const { return render_pass_; }
    VkDescriptorSetLayout set_layout() const { return set_layout_; }
    VkDescriptorSet set() const { return set_; }
    // The 2D array view of the depth aspect (grass_shadow_receive_desc.shadow_map) and the
    // layout the pass leaves it in.
    uint64_t array_view() const { return reinterpret_cast<uint64_t>(array_view_); }
    static constexpr VkImageLayout kReadLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;

    // Writes the block the receiving shaders read (the host waits for each frame before the next).
    void set_uniforms(const HostShadowUniforms& uniforms);
    // Begins cascade `layer`'s pass (depth cleared to 1) and sets its viewport and scissor.
    void begin(VkCommandBuffer cmd, uint32_t layer) const;
    // The cascade pass as a host pipeline's target (the casters' depth bias in it).
    VkPassTarget caster_target(float bias_constant, float bias_slope) const;

    // The ground's receiving pipeline: its layout is the ground's set (0) and this set (1).
    bool init_ground(const VkPassTarget& main_pass, VkDescriptorSetLayout ground_set_layout, std::string* error);
    VkPipeline ground_pipeline() const { return ground_pipeline_; }
    // Binds set() as set 1 of the ground's receiving layout.
    void bind_ground_set(VkCommandBuffer cmd) const;

    // Records every cascade's pass, outside any other pass, after grass_vk_prepare: the
    // meshes' depth (`casters`, may be null) and, when grass_casts, grass's depth view 1 + i
    // (plan_shadow_frame's numbering).
    grass_result record_cascades(VkCommandBuffer cmd, grass_context* context, const LightCascades& cascades,
                                 const VkMeshDrawer* casters, bool grass_casts) const;

private:
    VkDevice device_ = VK_NULL_HANDLE;
    uint32_t size_ = 0;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkImageView array_view_ = VK_NULL_HANDLE;
    std::vector<VkImageView> layer_views_;
    std::vector<VkFramebuffer> framebuffers_;
    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkBuffer uniforms_ = VK_NULL_HANDLE;
    VkDeviceMemory uniform_memory_ = VK_NULL_HANDLE;
    void* uniforms_mapped_ = nullptr;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkPipelineLayout ground_layout_ = VK_NULL_HANDLE;
    VkPipeline ground_pipeline_ = VK_NULL_HANDLE;
};

// TargetDesc::host_shadows on a Vulkan host: *out the cascades (null when the target has
// none), with the ground's receiving pipeline (ground_set_layout: the ground's set 0, null
// without a ground) and the meshes' casting and receiving ones (meshes: null without).
// False and *error when the target's host_shadows is refused or Vulkan fails.
bool create_vk_shadow_cascades(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory,
                               const TargetDesc& target, const VkPassTarget& main_pass,
                               VkDescriptorSetLayout ground_set_layout, VkMeshDrawer* meshes,
                               std::unique_ptr<VkShadowCascades>* out, std::string* error);

} // namespace grass_host
