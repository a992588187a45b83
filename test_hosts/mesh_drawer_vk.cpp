#include "mesh_drawer_vk.hpp"

#include "host_shaders.hpp"
#include "mesh_draw.hpp"
#include "vk_bootstrap.hpp"

#include <cstdio>
#include <cstring>

namespace grass_host {

using grass_bootstrap::vk_error;

VkResult create_host_pipeline(VkDevice device, const VkHostPipelineDesc& desc, VkPipeline* out) {
    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    const uint32_t* code[2] = {desc.vertex_code, desc.fragment_code};
    const size_t code_size[2] = {desc.vertex_code_size, desc.fragment_code_size};
    VkResult r = VK_SUCCESS;
    const uint32_t stage_count = desc.fragment_code ? 2 : 1; // a depth-only caster may have no fragment stage
    for (uint32_t i = 0; i < stage_count && r == VK_SUCCESS; ++i) {
        VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        info.codeSize = code_size[i];
        info.pCode = code[i];
        r = vkCreateShaderModule(device, &info, nullptr, &modules[i]);
    }
    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = modules[0];
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = modules[1];
    stages[1].pName = "main";
    const VkPipelineVertexInputStateCreateInfo no_vertices{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.lineWidth = 1.0f;
    raster.depthBiasEnable = desc.target.depth_bias_constant != 0.0f || desc.target.depth_bias_slope != 0.0f;
    raster.depthBiasConstantFactor = desc.target.depth_bias_constant;
    raster.depthBiasSlopeFactor = desc.target.depth_bias_slope;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = desc.target.samples;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = VK_TRUE;
    depth.depthCompareOp = desc.target.reversed_z ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
    VkPipelineColorBlendAttachmentState attachments[8] = {};
    for (VkPipelineColorBlendAttachmentState& a : attachments) a.colorWriteMask = 0xf;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = desc.target.depth_only ? 0 : std::min(desc.target.color_attachments, 8u);
    blend.pAttachments = attachments;
    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamic_states;
    const VkFormat color_format = desc.target.color_format;
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = desc.target.depth_only ? 0 : 1;
    rendering.pColorAttachmentFormats = &color_format;
    rendering.depthAttachmentFormat = desc.target.depth_format;
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = desc.target.render_pass ? nullptr : &rendering;
    info.stageCount = stage_count;
    info.pStages = stages;
    info.pVertexInputState = desc.vertex_input ? desc.vertex_input : &no_vertices;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = desc.layout;
    info.renderPass = desc.target.render_pass;
    info.subpass = desc.target.subpass;
    if (r == VK_SUCCESS) r = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, out);
    for (VkShaderModule m : modules) {
        if (m) vkDestroyShaderModule(device, m, nullptr);
    }
    return r;
}

VkMeshDrawer::~VkMeshDrawer() {
    if (!device_) return;
    if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
    if (caster_pipeline_) vkDestroyPipeline(device_, caster_pipeline_, nullptr);
    if (receiving_pipeline_) vkDestroyPipeline(device_, receiving_pipeline_, nullptr);
    if (receiving_layout_) vkDestroyPipelineLayout(device_, receiving_layout_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
}

bool VkMeshDrawer::init(VkPhysicalDevice physical_device, VkDevice device, const VkPassTarget& target,
                        const std::vector<HostMesh>& meshes, std::string* error) {
    std::string ignored;
    std::string* e = error ? error : &ignored;
    device_ = device;
    target_ = target;
    meshes_ = meshes;
    VkDeviceSize vertex_bytes = 0, index_count = 0;
    for (const HostMesh& m : meshes_) {
        ranges_.push_back({uint32_t(index_count), int32_t(vertex_bytes / (HostMesh::kFloatsPerVertex * 4))});
        vertex_bytes += m.vertices.size() * sizeof(float);
        index_count += m.indices.size();
    }
    index_offset_ = vertex_bytes;
    VkPhysicalDeviceMemoryProperties props{};
    vkGetPhysicalDeviceMemoryProperties(physical_device, &props);
    const VkDeviceSize size = vertex_bytes + index_count * sizeof(uint32_t);
    grass_bootstrap::VkBufferParts geometry;
    const bool made = grass_bootstrap::create_buffer(
        device_, props, size ? size : 4, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, &geometry, e);
    buffer_ = geometry.buffer;
    memory_ = geometry.memory;
    if (!made) return false;
    void* mapped = geometry.mapped;
    auto* bytes = static_cast<unsigned char*>(mapped);
    VkDeviceSize v = 0, i = index_offset_;
    for (const HostMesh& m : meshes_) {
        std::memcpy(bytes + v, m.vertices.data(), m.vertices.size() * sizeof(float));
        std::memcpy(bytes + i, m.indices.data(), m.indices.size() * sizeof(uint32_t));
        v += m.vertices.size() * sizeof(float);
        i += m.indices.size() * sizeof(uint32_t);
    }
    vkUnmapMemory(device_, memory_);

    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(MeshDraw)};
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.pushConstantRangeCount = 1;
    layout.pPushConstantRanges = &push;
    VkResult r = vkCreatePipelineLayout(device_, &layout, nullptr, &layout_);
    if (r != VK_SUCCESS) {
        *e = vk_error("vkCreatePipelineLayout (host meshes)", r);
        return false;
    }
    const VkVertexInputBindingDescription binding{0, HostMesh::kFloatsPerVertex * sizeof(float),
                                                  VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                             {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12}};
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = 1;
    vertex_input.pVertexBindingDescriptions = &binding;
    vertex_input.vertexAttributeDescriptionCount = 2;
    vertex_input.pVertexAttributeDescriptions = attributes;
    VkHostPipelineDesc pd;
    pd.vertex_code = grass_host_spirv::mesh_vert;
    pd.vertex_code_size = grass_host_spirv::mesh_vert_size;
    pd.fragment_code = grass_host_spirv::mesh_frag;
    pd.fragment_code_size = grass_host_spirv::mesh_frag_size;
    pd.layout = layout_;
    pd.vertex_input = &vertex_input;
    pd.target = target_;
    r = create_host_pipeline(device_, pd, &pipeline_);
    if (r != VK_SUCCESS) {
        *e = vk_error("creating the host meshes' pipeline", r);
        return false;
    }
    return true;
}

bool VkMeshDrawer::init_shadows(const VkPassTarget& cascade, VkDescriptorSetLayout shadow_set_layout,
                                std::string* error) {
    // Set 0 is unused by the mesh shaders (the ground's block is set 0 of its own).
    const VkDescriptorSetLayout sets[2] = {shadow_set_layout, shadow_set_layout};
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(MeshDraw)};
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.setLayoutCount = 2;
    layout.pSetLayouts = sets;
    layout.pushConstantRangeCount = 1;
    layout.pPushConstantRanges = &push;
    VkResult r = vkCreatePipelineLayout(device_, &layout, nullptr, &receiving_layout_);
    const VkVertexInputBindingDescription binding{0, HostMesh::kFloatsPerVertex * sizeof(float),
                                                  VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                             {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12}};
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = 1;
    vertex_input.pVertexBindingDescriptions = &binding;
    vertex_input.vertexAttributeDescriptionCount = 2;
    vertex_input.pVertexAttributeDescriptions = attributes;
    VkHostPipelineDesc pd;
    pd.vertex_code = grass_host_spirv::mesh_vert;
    pd.vertex_code_size = grass_host_spirv::mesh_vert_size;
    pd.layout = layout_;
    pd.vertex_input = &vertex_input;
    pd.target = cascade;
    pd.fragment_code = nullptr; // depth alone: no colour output without an attachment
    if (r == VK_SUCCESS) r = create_host_pipeline(device_, pd, &caster_pipeline_);
    pd.fragment_code = grass_host_spirv::mesh_frag_host_shadows;
    pd.fragment_code_size = grass_host_spirv::mesh_frag_host_shadows_size;
    pd.layout = receiving_layout_;
    pd.target = target_;
    if (r == VK_SUCCESS) r = create_host_pipeline(device_, pd, &receiving_pipeline_);
    if (r != VK_SUCCESS && error) *error = vk_error("creating the host meshes' shadow pipelines", r);
    return r == VK_SUCCESS;
}

void VkMeshDrawer::record_caster(VkCommandBuffer cmd, const grass_view_desc& light_view) const {
    if (!caster_pipeline_ || meshes_.empty()) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, caster_pipeline_);
    record_draws(cmd, layout_, light_view);
}

void VkMeshDrawer::record(VkCommandBuffer cmd, const grass_view_desc& view, uint32_t width, uint32_t height,
                          VkDescriptorSet shadow_set) const {
    if (!pipeline_ || meshes_.empty()) return;
    const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {width, height}};
    const bool receive = shadow_set != VK_NULL_HANDLE && receiving_pipeline_;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, receive ? receiving_pipeline_ : pipeline_);
    if (receive) {
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, receiving_layout_, 1, 1, &shadow_set, 0, nullptr);
    }
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    record_draws(cmd, receive ? receiving_layout_ : layout_, view);
}

void VkMeshDrawer::record_draws(VkCommandBuffer cmd, VkPipelineLayout layout, const grass_view_desc& view) const {
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &buffer_, &zero);
    vkCmdBindIndexBuffer(cmd, buffer_, index_offset_, VK_INDEX_TYPE_UINT32);
    for (size_t k = 0; k < meshes_.size(); ++k) {
        const MeshDraw d = make_mesh_draw(view, meshes_[k], target_.encode_srgb);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(d), &d);
        vkCmdDrawIndexed(cmd, uint32_t(meshes_[k].indices.size()), 1, ranges_[k].first_index, ranges_[k].vertex_offset,
                         0);
    }
}

} // namespace grass_host
