// grass-deferred's Vulkan deferred host: its device, the grass context and the frame
// (vk_deferred_host.hpp). The images, passes and pipelines: vk_deferred_passes.cpp.
#include "vk_deferred_host.hpp"

#include <grass/grass_vk.h>

#include <cmath>
#include <cstring>

namespace deferred {

using grass_bootstrap::vk_error;

std::unique_ptr<VkDeferredHost> VkDeferredHost::create(const grass_host::TargetDesc& target, std::string* error) {
    std::unique_ptr<VkDeferredHost> host(new VkDeferredHost(target));
    if (!host->init(error)) return nullptr;
    return host;
}

void VkDeferredHost::on_message(void* user, const std::string& line) {
    static_cast<VkDeferredHost*>(user)->add_validation_message(line);
}

bool VkDeferredHost::init(std::string* error) {
    if (target_.width == 0 || target_.height == 0 || target_.samples != 1) {
        *error = "grass-deferred's Vulkan host draws single-sampled targets of at least 1 x 1 pixels (target is " +
                 std::to_string(target_.width) + " x " + std::to_string(target_.height) + ", samples " +
                 std::to_string(target_.samples) + ")";
        return false;
    }
    grass_bootstrap::VkInstanceDesc desc;
    desc.application = "grass-deferred";
    desc.messenger_without_layer = true;
    desc.sink = &sink_;
    return instance_.create(desc, error) && create_device(error) && create_images(error) && create_passes(error) &&
           create_pipelines(error) && create_lighting_set(error);
}

// The first device with a graphics queue, Vulkan 1.1 and independentBlend (grass writes the
// G-buffer's attachments with different masks).
bool VkDeferredHost::create_device(std::string* error) {
    for (VkPhysicalDevice d : grass_bootstrap::physical_devices(instance_.handle())) {
        VkPhysicalDeviceProperties properties{};
        VkPhysicalDeviceFeatures features{};
        vkGetPhysicalDeviceProperties(d, &properties);
        vkGetPhysicalDeviceFeatures(d, &features);
        const std::vector<VkQueueFamilyProperties> families = grass_bootstrap::queue_families(d);
        for (uint32_t i = 0; i < families.size() && !physical_device_; ++i) {
            if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && properties.apiVersion >= VK_API_VERSION_1_1 &&
                features.independentBlend) {
                physical_device_ = d;
                queue_family_ = i;
                device_name_ = properties.deviceName;
            }
        }
    }
    if (!physical_device_) {
        *error = "no Vulkan 1.1 device with a graphics queue and independentBlend";
        return false;
    }
    vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
    VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enable.features.independentBlend = VK_TRUE;
    if (!grass_bootstrap::create_device(physical_device_, queue_family_, {}, &enable, &device_, &queue_, error) ||
        !grass_bootstrap::create_command_pool(device_, queue_family_, &command_pool_, error)) {
        return false;
    }
    VkResult r = grass_bootstrap::allocate_command_buffer(device_, command_pool_, &cmd_);
    const VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    if (r == VK_SUCCESS) r = vkCreateFence(device_, &fence, nullptr, &fence_);
    if (r != VK_SUCCESS) *error = vk_error("creating the command buffer and fence", r);
    return r == VK_SUCCESS;
}

VkDeferredHost::~VkDeferredHost() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        for (VkPipeline p : {ground_pipeline_, lighting_pipeline_})
            if (p) vkDestroyPipeline(device_, p, nullptr);
        for (VkPipelineLayout l : {ground_layout_, lighting_layout_})
            if (l) vkDestroyPipelineLayout(device_, l, nullptr);
        if (lighting_pool_) vkDestroyDescriptorPool(device_, lighting_pool_, nullptr); // frees lighting_set_
        if (lighting_set_layout_) vkDestroyDescriptorSetLayout(device_, lighting_set_layout_, nullptr);
        if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
        for (VkFramebuffer f : {gbuffer_framebuffer_, lighting_framebuffer_})
            if (f) vkDestroyFramebuffer(device_, f, nullptr);
        for (VkRenderPass p : {gbuffer_pass_, lighting_pass_})
            if (p) vkDestroyRenderPass(device_, p, nullptr);
        grass_bootstrap::destroy_buffer(device_, &lighting_buffer_);
        grass_bootstrap::destroy_buffer(device_, &readback_);
        grass_bootstrap::destroy_image(device_, &lit_);
        for (grass_bootstrap::VkImageParts& image : gbuffer_) grass_bootstrap::destroy_image(device_, &image);
        if (fence_) vkDestroyFence(device_, fence_, nullptr);
        if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr); // frees cmd_
        vkDestroyDevice(device_, nullptr);
    }
    instance_.destroy(); // while the validation log is still there
}

grass_result VkDeferredHost::create_context(const grass_context_desc& desc, grass_context** out) {
    grass_vk_gbuffer_target_desc gbuffer = grass_default_vk_gbuffer_target_desc();
    gbuffer.color_attachment_count = 4; // albedo, normal, material, velocity
    grass_vk_velocity_target_desc velocity = grass_default_vk_velocity_target_desc();
    velocity.color_attachment_count = 4;
    velocity.velocity_attachment = 3;
    if (velocity_) gbuffer.next = &velocity;
    grass_vk_desc vk = grass_default_vk_desc();
    vk.next = &gbuffer;
    vk.get_instance_proc_addr = vkGetInstanceProcAddr;
    vk.instance = instance_.handle();
    vk.physical_device = physical_device_;
    vk.device = device_;
    vk.queue_family = queue_family_;
    vk.render_pass = reinterpret_cast<uint64_t>(gbuffer_pass_);
    vk.subpass = 0;
    vk.color_format = VK_FORMAT_R16G16B16A16_SFLOAT;
    vk.depth_format = VK_FORMAT_D32_SFLOAT;
    return grass_vk_create_context(GRASS_HEADER_VERSION, &desc, &vk, out);
}

void VkDeferredHost::projection(float fovy_radians, float aspect, float near_m, float far_m, float out[16]) const {
    grass_host::vk_projection(fovy_radians, aspect, near_m, far_m, false, out);
}

bool VkDeferredHost::begin_commands(std::string* error) {
    VkResult r = vkResetCommandBuffer(cmd_, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (r == VK_SUCCESS) r = vkBeginCommandBuffer(cmd_, &begin);
    if (r != VK_SUCCESS && error) *error = vk_error("vkBeginCommandBuffer", r);
    return r == VK_SUCCESS;
}

// Ends the command buffer (the lighting pass recorded), copies the lit image into the
// read-back buffer, submits, waits and fills *out (null: nothing read).
bool VkDeferredHost::submit_and_read(grass_host::Image* out, std::string* error) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {target_.width, target_.height, 1};
    vkCmdCopyImageToBuffer(cmd_, lit_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &region);
    if (!submit(error)) return false;
    if (out) {
        out->width = target_.width;
        out->height = target_.height;
        out->rgba.resize(size_t(target_.width) * target_.height * 4);
        std::memcpy(out->rgba.data(), readback_.mapped, out->rgba.size()); // Vulkan rows run top-down
    }
    return true;
}

// Makes the read-back copy visible to the host, ends the command buffer, submits and waits.
bool VkDeferredHost::submit(std::string* error) {
    const VkBufferMemoryBarrier b = grass_bootstrap::host_read_barrier(readback_.buffer);
    vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &b, 0,
                         nullptr);
    VkResult r = vkEndCommandBuffer(cmd_);
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd_;
    if (r == VK_SUCCESS) r = vkQueueSubmit(queue_, 1, &submit, fence_);
    if (r == VK_SUCCESS) r = vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
    if (r == VK_SUCCESS) r = vkResetFences(device_, 1, &fence_);
    if (r != VK_SUCCESS) {
        if (error) *error = vk_error("vkEndCommandBuffer/vkQueueSubmit/vkWaitForFences", r);
        return false;
    }
    return true;
}

// grass plans the frame and records its uploads before the G-buffer pass, its draws in it
// after the ground. Once grass_vk_prepare has recorded, the command buffer is submitted even
// when a later grass call fails: its uploads must run.
grass_result VkDeferredHost::render(grass_context* context, const grass_view_desc& view,
                                    const grass_host::Occluder* occluder, grass_host::Image* out, std::string* error) {
    if (occluder) {
        if (error) *error = "grass-deferred's Vulkan host draws no occluder (occluder must be null)";
        return GRASS_ERROR_INVALID_ARGUMENT;
    }
    if (!begin_commands(error)) return GRASS_ERROR_BACKEND;
    grass_result result = grass_begin_frame(context, &view);
    const bool frame_begun = result == GRASS_SUCCESS;
    if (frame_begun) {
        grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
        prepare.command_buffer = cmd_;
        result = grass_vk_prepare(context, &prepare);
    }
    record_gbuffer_begin(cmd_, view);
    if (result == GRASS_SUCCESS) {
        grass_vk_record_desc record = grass_default_vk_record_desc();
        record.command_buffer = cmd_;
        result = grass_vk_record(context, &record);
    }
    vkCmdEndRenderPass(cmd_);
    record_lighting(cmd_);
    const bool submitted = submit_and_read(out, error);
    has_frame_ = has_frame_ || submitted;
    if (frame_begun) {
        const grass_result end = grass_end_frame(context);
        if (result == GRASS_SUCCESS) result = end;
    }
    if (!submitted) return GRASS_ERROR_BACKEND;
    if (result != GRASS_SUCCESS && error) *error = grass_get_last_error(context);
    if (result == GRASS_SUCCESS && messages_ != 0 && error) *error = log_;
    return result;
}

bool VkDeferredHost::relight(grass_host::Image* out, std::string* error) {
    if (!has_frame_) {
        if (error) *error = "relight: no frame has filled the G-buffer yet (render one first)";
        return false;
    }
    if (!begin_commands(error)) return false;
    record_lighting(cmd_);
    return submit_and_read(out, error);
}

namespace {

// An IEEE half (the velocity image's texels) as a float.
float half_to_float(uint16_t h) {
    const int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    const float sign = (h & 0x8000) ? -1.0f : 1.0f;
    if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
    if (exponent == 31) return mantissa ? std::nanf("") : sign * INFINITY;
    return sign * std::ldexp(float(mantissa + 1024), exponent - 25);
}

// The velocity image from the G-buffer pass's final layout to the copy's, or back.
void transition_velocity(VkCommandBuffer cmd, VkImage image, bool to_copy) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = to_copy ? VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT : VK_ACCESS_TRANSFER_READ_BIT;
    b.dstAccessMask = to_copy ? VK_ACCESS_TRANSFER_READ_BIT : VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    b.oldLayout = to_copy ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    b.newLayout = to_copy ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    const VkPipelineStageFlags attachment = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                               transfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
    vkCmdPipelineBarrier(cmd, to_copy ? attachment : transfer, to_copy ? transfer : attachment, 0, 0, nullptr, 0,
                         nullptr, 1, &b);
}

} // namespace

bool VkDeferredHost::read_velocity(std::vector<float>* rgba, std::string* error) {
    if (!has_frame_) {
        if (error) *error = "read_velocity: no frame has filled the G-buffer yet (render one first)";
        return false;
    }
    if (!begin_commands(error)) return false;
    transition_velocity(cmd_, gbuffer_[4].image, true);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {target_.width, target_.height, 1};
    vkCmdCopyImageToBuffer(cmd_, gbuffer_[4].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &region);
    transition_velocity(cmd_, gbuffer_[4].image, false); // as the next G-buffer pass finds it
    if (!submit(error)) return false;
    rgba->resize(size_t(target_.width) * target_.height * 4);
    const auto* halves = static_cast<const uint16_t*>(readback_.mapped); // Vulkan rows run top-down
    for (size_t i = 0; i < rgba->size(); ++i) (*rgba)[i] = half_to_float(halves[i]);
    return true;
}

} // namespace deferred
