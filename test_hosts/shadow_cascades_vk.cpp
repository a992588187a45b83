#include "shadow_cascades_vk.hpp"

#include "host_shaders.hpp"
#include "vk_bootstrap.hpp"

#include <grass/grass_vk.h>

#include <cstring>

namespace grass_host {

using grass_bootstrap::vk_error;

VkShadowCascades::~VkShadowCascades() {
    if (!device_) return;
    if (ground_pipeline_) vkDestroyPipeline(device_, ground_pipeline_, nullptr);
    if (ground_layout_) vkDestroyPipelineLayout(device_, ground_layout_, nullptr);
    if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
    if (uniforms_) vkDestroyBuffer(device_, uniforms_, nullptr);
    if (uniform_memory_) vkFreeMemory(device_, uniform_memory_, nullptr);
    if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device_, f, nullptr);
    if (render_pass_) vkDestroyRenderPass(device_, render_pass_, nullptr);
    for (VkImageView v : layer_views_) vkDestroyImageView(device_, v, nullptr);
    if (array_view_) vkDestroyImageView(device_, array_view_, nullptr);
    if (image_) vkDestroyImage(device_, image_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
}

bool VkShadowCascades::init(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, const HostShadows& shadows,
                            std::string* error) {
    device_ = device;
    size_ = shadows.map_size;
    const uint32_t layers = shadows.cascades;
    const auto fail = [&](const char* call, VkResult r) {
        *error = vk_error(call, r) + " (the host's shadow cascades)";
        return false;
    };
    grass_bootstrap::VkImageDesc desc;
    desc.extent = {size_, size_};
    desc.format = VK_FORMAT_D32_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    desc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    desc.layers = layers;
    grass_bootstrap::VkImageParts parts;
    if (!grass_bootstrap::create_image(device, memory, desc, &parts, error)) return false;
    image_ = parts.image;
    memory_ = parts.memory;
    if (parts.view) vkDestroyImageView(device, parts.view, nullptr);
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    view.format = VK_FORMAT_D32_SFLOAT;
    view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
    VkResult r = vkCreateImageView(device, &view, nullptr, &array_view_);
    if (r != VK_SUCCESS) return fail("vkCreateImageView", r);

    // Depth alone, cleared; the final layout is the one grass and the host read it in.
    grass_bootstrap::VkPassDesc pass;
    pass.depth_format = VK_FORMAT_D32_SFLOAT;
    pass.keep_depth = true;
    pass.depth_final = kReadLayout;
    VkSubpassDependency* d = pass.dependencies;
    // The previous frame's reads of the map (fragment shaders) come before this pass writes it.
    d[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    d[0].dstSubpass = 0;
    d[0].srcStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    d[0].dstStageMask = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    d[0].srcAccessMask = VK_ACCESS_SHADER_READ_BIT;
    d[0].dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    // Its depth writes (and the move to the read-only layout) come before the main pass reads it.
    d[1].srcSubpass = 0;
    d[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    d[1].srcStageMask = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    d[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    d[1].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    d[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    if (!grass_bootstrap::create_render_pass(device, pass, &render_pass_, error)) return false;

    for (uint32_t layer = 0; layer < layers; ++layer) {
        VkImageView layer_view = VK_NULL_HANDLE;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, layer, 1};
        r = vkCreateImageView(device, &view, nullptr, &layer_view);
        if (r != VK_SUCCESS) return fail("vkCreateImageView", r);
        layer_views_.push_back(layer_view);
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = render_pass_;
        fb.attachmentCount = 1;
        fb.pAttachments = &layer_view;
        fb.width = fb.height = size_;
        fb.layers = 1;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        r = vkCreateFramebuffer(device, &fb, nullptr, &framebuffer);
        if (r != VK_SUCCESS) return fail("vkCreateFramebuffer", r);
        framebuffers_.push_back(framebuffer);
    }

    VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sampler.magFilter = sampler.minFilter = VK_FILTER_LINEAR;
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler.compareEnable = VK_TRUE;
    sampler.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    r = vkCreateSampler(device, &sampler, nullptr, &sampler_);
    if (r != VK_SUCCESS) return fail("vkCreateSampler", r);

    grass_bootstrap::VkBufferParts buffer;
    if (!grass_bootstrap::create_buffer(device, memory, sizeof(HostShadowUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                        &buffer, error)) {
        return false;
    }
    uniforms_ = buffer.buffer;
    uniform_memory_ = buffer.memory;
    uniforms_mapped_ = buffer.mapped;

    const VkDescriptorSetLayoutBinding bindings[2] = {
        {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 2;
    set_info.pBindings = bindings;
    r = vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout_);
    if (r != VK_SUCCESS) return fail("vkCreateDescriptorSetLayout", r);
    const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                           {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.maxSets = 1;
    pool.poolSizeCount = 2;
    pool.pPoolSizes = sizes;
    r = vkCreateDescriptorPool(device, &pool, nullptr, &pool_);
    if (r == VK_SUCCESS) r = grass_bootstrap::allocate_descriptor_set(device, pool_, set_layout_, &set_);
    if (r != VK_SUCCESS) return fail("vkAllocateDescriptorSets", r);
    const VkDescriptorBufferInfo buffer_info{uniforms_, 0, sizeof(HostShadowUniforms)};
    const VkDescriptorImageInfo image_info{sampler_, array_view_, kReadLayout};
    VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET},
                                      {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    writes[0].dstSet = writes[1].dstSet = set_;
    writes[0].dstBinding = 0;
    writes[0].descriptorCount = 1;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[0].pBufferInfo = &buffer_info;
    writes[1].dstBinding = 1;
    writes[1].descriptorCount = 1;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[1].pImageInfo = &image_info;
    vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);
    return true;
}

VkPassTarget VkShadowCascades::caster_target(float bias_constant, float bias_slope) const {
    VkPassTarget t;
    t.render_pass = render_pass_;
    t.depth_format = VK_FORMAT_D32_SFLOAT;
    t.depth_only = true;
    t.depth_bias_constant = bias_constant;
    t.depth_bias_slope = bias_slope;
    return t;
}

bool VkShadowCascades::init_ground(const VkPassTarget& main_pass, VkDescriptorSetLayout ground_set_layout,
                                   std::string* error) {
    const VkDescriptorSetLayout sets[2] = {ground_set_layout, set_layout_};
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.setLayoutCount = 2;
    layout.pSetLayouts = sets;
    VkResult r = vkCreatePipelineLayout(device_, &layout, nullptr, &ground_layout_);
    VkHostPipelineDesc desc;
    desc.vertex_code = grass_host_spirv::ground_vert_host_shadows;
    desc.vertex_code_size = grass_host_spirv::ground_vert_host_shadows_size;
    desc.fragment_code = grass_host_spirv::ground_frag_host_shadows;
    desc.fragment_code_size = grass_host_spirv::ground_frag_host_shadows_size;
    desc.layout = ground_layout_;
    desc.target = main_pass;
    if (r == VK_SUCCESS) r = create_host_pipeline(device_, desc, &ground_pipeline_);
    if (r != VK_SUCCESS) *error = vk_error("creating the ground's shadow-receiving pipeline", r);
    return r == VK_SUCCESS;
}

void VkShadowCascades::bind_ground_set(VkCommandBuffer cmd) const {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ground_layout_, 1, 1, &set_, 0, nullptr);
}

grass_result VkShadowCascades::record_cascades(VkCommandBuffer cmd, grass_context* context,
                                               const LightCascades& cascades, const VkMeshDrawer* casters,
                                               bool grass_casts) const {
    grass_result result = GRASS_SUCCESS;
    for (uint32_t i = 0; i < cascades.count; ++i) {
        begin(cmd, i);
        if (casters) casters->record_caster(cmd, cascades.light_view[i]);
        if (grass_casts && result == GRASS_SUCCESS) {
            grass_vk_record_desc record = grass_default_vk_record_desc();
            record.command_buffer = cmd;
            result = grass_vk_record_view(context, 1 + i, &record);
        }
        vkCmdEndRenderPass(cmd); // every layer ends in kReadLayout, cleared at least
    }
    return result;
}

bool create_vk_shadow_cascades(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory,
                               const TargetDesc& target, const VkPassTarget& main_pass,
                               VkDescriptorSetLayout ground_set_layout, VkMeshDrawer* meshes,
                               std::unique_ptr<VkShadowCascades>* out, std::string* error) {
    const HostShadows& s = target.host_shadows;
    if (!check_host_shadows(target, error)) return false;
    if (s.cascades == 0) return true;
    *out = std::make_unique<VkShadowCascades>();
    VkShadowCascades& c = **out;
    if (!c.init(device, memory, s, error)) return false;
    const VkPassTarget casters = c.caster_target(s.mesh_bias_constant, s.mesh_bias_slope); // after init
    return (!target.ground || c.init_ground(main_pass, ground_set_layout, error)) &&
           (!meshes || meshes->init_shadows(casters, c.set_layout(), error));
}

void VkShadowCascades::set_uniforms(const HostShadowUniforms& uniforms) {
    std::memcpy(uniforms_mapped_, &uniforms, sizeof uniforms);
}

void VkShadowCascades::begin(VkCommandBuffer cmd, uint32_t layer) const {
    VkClearValue clear{};
    clear.depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = render_pass_;
    info.framebuffer = framebuffers_[layer];
    info.renderArea = {{0, 0}, {size_, size_}};
    info.clearValueCount = 1;
    info.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(size_), float(size_), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {size_, size_}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

} // namespace grass_host
