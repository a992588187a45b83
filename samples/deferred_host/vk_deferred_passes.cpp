// grass-deferred's Vulkan deferred host: the G-buffer and lit images, the G-buffer pass and
// the lighting pass with their pipelines (the ground's, the lighting's) and the lighting's
// descriptors, and the recording of both passes (vk_deferred_host.hpp).
#include "mesh_drawer_vk.hpp"
#include "scene.hpp"
#include "velocity.hpp"
#include "vk_deferred_host.hpp"

#include <cstring>

namespace deferred_spirv { // shaders/, compiled by glslc at build time
extern const uint32_t gbuffer_ground_vert[];
extern const uint32_t gbuffer_ground_vert_size; // bytes
extern const uint32_t gbuffer_ground_frag[];
extern const uint32_t gbuffer_ground_frag_size;
extern const uint32_t lighting_vert[];
extern const uint32_t lighting_vert_size;
extern const uint32_t lighting_frag[];
extern const uint32_t lighting_frag_size;
} // namespace deferred_spirv

namespace deferred {

namespace {

using grass_bootstrap::vk_error;

// The G-buffer's formats (albedo, normal, material, depth, velocity) and the lit target's.
constexpr VkFormat kGBufferFormats[5] = {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R8G8B8A8_UNORM,
                                         VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_FORMAT_R16G16B16A16_SFLOAT};
// The colour attachments after the first: normal, material, velocity.
constexpr VkFormat kMoreColors[3] = {kGBufferFormats[1], kGBufferFormats[2], kGBufferFormats[4]};
constexpr VkFormat kLitFormat = VK_FORMAT_R8G8B8A8_SRGB;
// The layouts the G-buffer pass leaves its images in, for the lighting pass to sample.
constexpr VkImageLayout kColorRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
constexpr VkImageLayout kDepthRead = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;

// gbuffer_ground.vert's push constants (velocity.hpp's ground_matrices).
struct GroundConstants {
    float world_to_clip[16];
    float world_to_previous_clip[16];
};

// A dependency between the pass's one subpass and what comes before it (`into`) or after it.
VkSubpassDependency external(bool into, VkPipelineStageFlags src_stages, VkAccessFlags src_access,
                             VkPipelineStageFlags dst_stages, VkAccessFlags dst_access) {
    VkSubpassDependency d{};
    d.srcSubpass = into ? VK_SUBPASS_EXTERNAL : 0;
    d.dstSubpass = into ? 0 : VK_SUBPASS_EXTERNAL;
    d.srcStageMask = src_stages;
    d.dstStageMask = dst_stages;
    d.srcAccessMask = src_access;
    d.dstAccessMask = dst_access;
    return d;
}

// One of the host's pipelines (mesh_drawer_vk.hpp: no culling, depth tested and written
// where the pass has depth) in `pass` with `attachments` colour attachments.
VkResult create_pipeline(VkDevice device, const uint32_t* vert, uint32_t vert_size, const uint32_t* frag,
                         uint32_t frag_size, VkPipelineLayout layout, VkRenderPass pass, VkFormat color_format,
                         uint32_t attachments, VkPipeline* out) {
    grass_host::VkHostPipelineDesc desc;
    desc.vertex_code = vert;
    desc.vertex_code_size = vert_size;
    desc.fragment_code = frag;
    desc.fragment_code_size = frag_size;
    desc.layout = layout;
    desc.target.render_pass = pass;
    desc.target.color_format = color_format;
    desc.target.color_attachments = attachments;
    return grass_host::create_host_pipeline(device, desc, out);
}

} // namespace

bool VkDeferredHost::create_images(std::string* error) {
    grass_bootstrap::VkImageDesc desc;
    desc.extent = {target_.width, target_.height};
    for (int i = 0; i < 5; ++i) { // the velocity (4) is copied out, and left as the others
        desc.format = kGBufferFormats[i];
        desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT |
                     (i == 3 ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) |
                     (i == 4 ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
        desc.aspect = i == 3 ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
        if (!grass_bootstrap::create_image(device_, memory_properties_, desc, &gbuffer_[i], error)) return false;
    }
    desc.format = kLitFormat;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    desc.aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    const VkMemoryPropertyFlags mapped = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    return grass_bootstrap::create_image(device_, memory_properties_, desc, &lit_, error) &&
           grass_bootstrap::create_buffer(device_, memory_properties_, VkDeviceSize(target_.width) * target_.height * 8,
                                          VK_BUFFER_USAGE_TRANSFER_DST_BIT, mapped, &readback_, error) &&
           grass_bootstrap::create_buffer(device_, memory_properties_, sizeof(LightingUniforms),
                                          VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, mapped, &lighting_buffer_, error);
}

bool VkDeferredHost::create_passes(std::string* error) {
    // The G-buffer pass (the bootstrap's: colour attachment 0 the albedo, the pass's
    // attachment 1 the depth, 2, 3 and 4 the normal, material and velocity), every image
    // left readable.
    grass_bootstrap::VkPassDesc pass;
    pass.color_format = kGBufferFormats[0];
    pass.depth_format = kGBufferFormats[3];
    pass.more_colors = kMoreColors;
    pass.more_color_count = 3;
    pass.color_final = kColorRead;
    pass.keep_depth = true;
    pass.depth_final = kDepthRead;
    const VkPipelineStageFlags attachment_stages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    // The last lighting pass's reads come before this pass writes the images again.
    pass.dependencies[0] =
        external(true, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, attachment_stages,
                 VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    // Its writes come before the lighting pass samples them.
    pass.dependencies[1] = external(false, attachment_stages,
                                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    if (!grass_bootstrap::create_render_pass(device_, pass, &gbuffer_pass_, error)) return false;
    // The lighting pass: the lit image alone, left for the read-back copy.
    grass_bootstrap::VkPassDesc lighting;
    lighting.color_format = kLitFormat;
    lighting.depth_format = VK_FORMAT_UNDEFINED;
    lighting.color_final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    // The last read-back copy of the lit image comes before this pass writes it (the G-buffer
    // pass's own dependency makes its writes visible to this pass's fragment shader).
    lighting.dependencies[0] =
        external(true, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    // Its writes come before the read-back copy.
    lighting.dependencies[1] =
        external(false, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    if (!grass_bootstrap::create_render_pass(device_, lighting, &lighting_pass_, error)) return false;
    const VkImageView views[5] = {gbuffer_[0].view, gbuffer_[3].view, gbuffer_[1].view, gbuffer_[2].view,
                                  gbuffer_[4].view};
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = gbuffer_pass_;
    fb.attachmentCount = 5;
    fb.pAttachments = views;
    fb.width = target_.width;
    fb.height = target_.height;
    fb.layers = 1;
    VkResult r = vkCreateFramebuffer(device_, &fb, nullptr, &gbuffer_framebuffer_);
    fb.renderPass = lighting_pass_;
    fb.attachmentCount = 1;
    fb.pAttachments = &lit_.view;
    if (r == VK_SUCCESS) r = vkCreateFramebuffer(device_, &fb, nullptr, &lighting_framebuffer_);
    if (r != VK_SUCCESS) *error = vk_error("vkCreateFramebuffer", r);
    return r == VK_SUCCESS;
}

bool VkDeferredHost::create_pipelines(std::string* error) {
    // The lighting's set: the four G-buffer images (bindings 0-3), the Lighting block (4).
    VkDescriptorSetLayoutBinding bindings[5] = {};
    for (uint32_t i = 0; i < 5; ++i) {
        bindings[i].binding = i;
        bindings[i].descriptorType =
            i < 4 ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        bindings[i].descriptorCount = 1;
        bindings[i].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    }
    VkDescriptorSetLayoutCreateInfo set{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set.bindingCount = 5;
    set.pBindings = bindings;
    VkResult r = vkCreateDescriptorSetLayout(device_, &set, nullptr, &lighting_set_layout_);
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.setLayoutCount = 1;
    layout.pSetLayouts = &lighting_set_layout_;
    if (r == VK_SUCCESS) r = vkCreatePipelineLayout(device_, &layout, nullptr, &lighting_layout_);
    const VkPushConstantRange constants{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(GroundConstants)};
    layout.setLayoutCount = 0;
    layout.pushConstantRangeCount = 1;
    layout.pPushConstantRanges = &constants;
    if (r == VK_SUCCESS) r = vkCreatePipelineLayout(device_, &layout, nullptr, &ground_layout_);

    using namespace deferred_spirv;
    if (r == VK_SUCCESS) // depth-tested and written, four attachments
        r = create_pipeline(device_, gbuffer_ground_vert, gbuffer_ground_vert_size, gbuffer_ground_frag,
                            gbuffer_ground_frag_size, ground_layout_, gbuffer_pass_, kGBufferFormats[0], 4,
                            &ground_pipeline_);
    if (r == VK_SUCCESS) // the pass has no depth: the pipeline's depth state is ignored
        r = create_pipeline(device_, lighting_vert, lighting_vert_size, lighting_frag, lighting_frag_size,
                            lighting_layout_, lighting_pass_, kLitFormat, 1, &lighting_pipeline_);
    if (r != VK_SUCCESS) *error = vk_error("creating the ground's and the lighting's pipelines", r);
    return r == VK_SUCCESS;
}

bool VkDeferredHost::create_lighting_set(std::string* error) {
    VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO}; // texelFetch only: nearest, clamped
    sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkResult r = vkCreateSampler(device_, &sampler, nullptr, &sampler_);
    const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4},
                                           {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.maxSets = 1;
    pool.poolSizeCount = 2;
    pool.pPoolSizes = sizes;
    if (r == VK_SUCCESS) r = vkCreateDescriptorPool(device_, &pool, nullptr, &lighting_pool_);
    if (r == VK_SUCCESS)
        r = grass_bootstrap::allocate_descriptor_set(device_, lighting_pool_, lighting_set_layout_, &lighting_set_);
    if (r != VK_SUCCESS) {
        *error = vk_error("creating the lighting's descriptors", r);
        return false;
    }
    VkDescriptorImageInfo images[4];
    VkWriteDescriptorSet writes[5];
    for (uint32_t i = 0; i < 4; ++i) images[i] = {sampler_, gbuffer_[i].view, i < 3 ? kColorRead : kDepthRead};
    const VkDescriptorBufferInfo buffer{lighting_buffer_.buffer, 0, sizeof(LightingUniforms)};
    for (uint32_t i = 0; i < 5; ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = lighting_set_;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType =
            i < 4 ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        writes[i].pImageInfo = i < 4 ? &images[i] : nullptr;
        writes[i].pBufferInfo = i < 4 ? nullptr : &buffer;
    }
    vkUpdateDescriptorSets(device_, 5, writes, 0, nullptr);
    return true;
}

// Begins the G-buffer pass (colours cleared to 0, depth to 1) and draws the ground.
void VkDeferredHost::record_gbuffer_begin(VkCommandBuffer cmd, const grass_view_desc& view) {
    view_projection(view, view_projection_);
    VkClearValue clears[5] = {};
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = gbuffer_pass_;
    info.framebuffer = gbuffer_framebuffer_;
    info.renderArea = {{0, 0}, {target_.width, target_.height}};
    info.clearValueCount = 5;
    info.pClearValues = clears;
    vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(target_.width), float(target_.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &info.renderArea);
    GroundConstants ground{};
    ground_matrices(view, ground.world_to_clip, ground.world_to_previous_clip);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ground_pipeline_);
    vkCmdPushConstants(cmd, ground_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(ground), &ground);
    vkCmdDraw(cmd, 6, 1, 0, 0);
}

// The lighting pass over the whole lit image (the host waits for each submission, so the
// uniform buffer is free to rewrite).
void VkDeferredHost::record_lighting(VkCommandBuffer cmd) {
    LightingUniforms u = lights_;
    std::memcpy(u.view_projection, view_projection_, sizeof(view_projection_));
    u.size[0] = float(target_.width);
    u.size[1] = float(target_.height);
    std::memcpy(lighting_buffer_.mapped, &u, sizeof(u));
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = lighting_pass_;
    info.framebuffer = lighting_framebuffer_;
    info.renderArea = {{0, 0}, {target_.width, target_.height}};
    const VkClearValue clear{}; // the bootstrap's passes clear (the triangle covers every pixel anyway)
    info.clearValueCount = 1;
    info.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(target_.width), float(target_.height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &info.renderArea);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lighting_pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lighting_layout_, 0, 1, &lighting_set_, 0, nullptr);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRenderPass(cmd);
}

} // namespace deferred
