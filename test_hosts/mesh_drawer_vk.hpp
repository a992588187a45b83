// Draws the host's meshes (host_mesh.hpp) with Vulkan: camera-relative, Lambert + ambient
// under the view's sun, depth-tested and depth-writing in the host's pass, so grass recorded
// after them is hidden behind them. Used by the headless Vulkan host; a windowed host
// (samples/viewer) makes one the same way:
//
//   grass_host::VkMeshDrawer meshes;
//   meshes.init(device_info, target, scene.meshes, &error);  // once
//   meshes.record(cmd, view, width, height);                  // inside the pass, before grass
//
// Per-mesh data travels as push constants, so any number of frames may be in flight; the
// geometry lives in one host-visible buffer written once.
#pragma once

#include "host_mesh.hpp"
#include "mesh_draw.hpp"

#include <grass/grass.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <string>
#include <vector>

namespace grass_host {

// The pass a host pipeline draws in: a render pass (and subpass), or dynamic rendering
// with these formats when render_pass is null.
struct VkPassTarget {
    VkRenderPass render_pass = VK_NULL_HANDLE;
    uint32_t subpass = 0;
    VkFormat color_format = VK_FORMAT_R8G8B8A8_SRGB;
    VkFormat depth_format = VK_FORMAT_D32_SFLOAT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool reversed_z = false;  // depth test GREATER instead of LESS
    bool encode_srgb = false; // the colour target stores what the shader writes (UNORM)
    // A depth-only pass (a shadow map's: no colour attachment), with a static depth bias.
    bool depth_only = false;
    float depth_bias_constant = 0.0f, depth_bias_slope = 0.0f;
    // Colour attachments the pipeline writes, each whole and unblended: 1 to 8, more than one
    // with a render pass only (a G-buffer pass's: samples/deferred_host).
    uint32_t color_attachments = 1;
};

// A graphics pipeline of the hosts' own (ground, meshes): triangle list, no culling, depth
// test and write, viewport and scissor dynamic.
struct VkHostPipelineDesc {
    const uint32_t* vertex_code = nullptr;
    size_t vertex_code_size = 0;             // bytes
    const uint32_t* fragment_code = nullptr; // null: no fragment stage (a depth-only caster)
    size_t fragment_code_size = 0;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    const VkPipelineVertexInputStateCreateInfo* vertex_input = nullptr; // null: none
    VkPassTarget target;
};
VkResult create_host_pipeline(VkDevice device, const VkHostPipelineDesc& desc, VkPipeline* out);

class VkMeshDrawer final : public MovableMeshes {
public:
    VkMeshDrawer() = default;
    ~VkMeshDrawer() override;
    VkMeshDrawer(const VkMeshDrawer&) = delete;
    VkMeshDrawer& operator=(const VkMeshDrawer&) = delete;

    // Creates the pipeline and uploads the meshes; false and *error on a Vulkan failure.
    bool init(VkPhysicalDevice physical_device, VkDevice device, const VkPassTarget& target,
              const std::vector<HostMesh>& meshes, std::string* error);

    // Records every mesh's draw into `cmd`, inside the pass (sets viewport and scissor to
    // width x height).
    // receive: the meshes sample the host's shadow map through `shadow_set` (set 1, see
    // init_shadows).
    void record(VkCommandBuffer cmd, const grass_view_desc& view, uint32_t width, uint32_t height,
                VkDescriptorSet shadow_set = VK_NULL_HANDLE) const;

    // TargetDesc::host_shadows: a pipeline that casts into `cascade` (a depth-only pass) and
    // one that receives through a set of `shadow_set_layout` (shaders/cascade_shadows.glsl).
    bool init_shadows(const VkPassTarget& cascade, VkDescriptorSetLayout shadow_set_layout, std::string* error);
    // Records every mesh's depth into a cascade's pass (its viewport set by the caller).
    void record_caster(VkCommandBuffer cmd, const grass_view_desc& light_view) const;

    // Moves mesh `index` (of init's list) to a new world origin: a host object that moves.
    void set_origin(size_t index, const double origin[3]) override {
        if (index < meshes_.size()) std::copy(origin, origin + 3, meshes_[index].origin);
    }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkPassTarget target_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipeline caster_pipeline_ = VK_NULL_HANDLE;
    VkPipelineLayout receiving_layout_ = VK_NULL_HANDLE;
    VkPipeline receiving_pipeline_ = VK_NULL_HANDLE;
    void record_draws(VkCommandBuffer cmd, VkPipelineLayout layout, const grass_view_desc& view) const;
    std::vector<HostMesh> meshes_;
    struct Range {
        uint32_t first_index;
        int32_t vertex_offset;
    };
    std::vector<Range> ranges_;
    VkDeviceSize index_offset_ = 0; // bytes: where the indices begin in buffer_
};

} // namespace grass_host
