// The headless Vulkan host: an instance with the validation layers when installed (every
// warning and error is counted), one graphics queue, an offscreen sRGB colour + depth
// target (multisampled with a resolve image when asked), a render pass or dynamic
// rendering, extra colour targets (extra_targets_vk.hpp), and the frame around
// grass_vk_prepare / grass_vk_record. It links the Vulkan loader; grass gets only
// vkGetInstanceProcAddr and the handles.
//
// GRASS_VK_DEVICE: pick the first physical device whose name contains this text.
#include "driver_residency.hpp"
#include "extra_targets_vk.hpp"
#include "ground.hpp"
#include "host_factories.hpp"
#include "host_shaders.hpp"
#include "mesh_drawer_vk.hpp"
#include "shadow_cascades_vk.hpp"
#include "shadow_map_vk.hpp"
#include "vk_bootstrap.hpp"
#include "vk_occluder.hpp"

#include <grass/grass_vk.h>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace grass_host {

namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;            // linear shader output is sRGB-encoded
constexpr VkFormat kFloatColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT; // TargetDesc::float_color
constexpr VkFormat kUnormColorFormat = VK_FORMAT_R8G8B8A8_UNORM;      // TargetDesc::unorm_color
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

using grass_bootstrap::vk_error;
using Attachment = grass_bootstrap::VkImageParts; // an image with its memory and view

class VkHost final : public Host {
public:
    explicit VkHost(const TargetDesc& target)
        : Host(target), color_format_(target.float_color   ? kFloatColorFormat
                                      : target.unorm_color ? kUnormColorFormat
                                                           : kColorFormat),
          texel_bytes_(target.float_color ? 16u : 4u) {}
    ~VkHost() override;
    VkHost(const VkHost&) = delete;
    VkHost& operator=(const VkHost&) = delete;

    bool init(std::string* error);

    grass_backend backend() const override { return GRASS_BACKEND_VULKAN; }
    grass_result create_context(const grass_context_desc& desc, grass_context** out) override;
    uint64_t vk_pipeline_cache() const override { return reinterpret_cast<uint64_t>(pipeline_cache_); }
    void projection(float fovy_radians, float aspect, float near_m, float far_m, float out[16]) const override;
    grass_result render(grass_context* context, const grass_view_desc& view, const Occluder* occluder, Image* out,
                        std::string* error) override;
    uint64_t make_vk_shadow_map(uint32_t size, uint32_t layers, const float* depths, uint32_t vk_layout,
                                std::string* error) override {
        return shadow_map_.make({device_, &memory_properties_, queue_, cmd_, fence_}, size, layers, depths,
                                static_cast<VkImageLayout>(vk_layout), error);
    }

private:
    bool create_instance(std::string* error);
    bool pick_device(std::string* error);
    bool create_device(std::string* error);
    bool create_target(std::string* error);
    bool create_render_pass(std::string* error);
    bool create_commands(std::string* error);
    bool create_ground(std::string* error);
    bool create_ground_pipeline(std::string* error);
    bool create_meshes(std::string* error);
    void draw_ground(VkCommandBuffer cmd, const grass_view_desc& view, bool receive_shadows);
    bool create_attachment(VkFormat format, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                           VkImageAspectFlags aspect, Attachment* out, std::string* error);
    void begin_pass(VkCommandBuffer cmd);
    void begin_depth_pass(VkCommandBuffer cmd); // Host::depth_only
    void end_pass(VkCommandBuffer cmd);
    void copy_to_readback(VkCommandBuffer cmd);
    static void on_message(void* user, const std::string& line);

    grass_bootstrap::VkMessageSink sink_{&VkHost::on_message, this};
    grass_bootstrap::VkBootInstance instance_;
    VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_properties_{};
    VkDevice device_ = VK_NULL_HANDLE;
    VkPipelineCache pipeline_cache_ = VK_NULL_HANDLE; // target.vk_host_pipeline_cache
    uint32_t queue_family_ = 0;
    VkQueue queue_ = VK_NULL_HANDLE;
    bool dynamic_rendering_ = false; // the feature is enabled on the device
    PFN_vkCmdBeginRendering begin_rendering_ = nullptr;
    PFN_vkCmdEndRendering end_rendering_ = nullptr;

    const VkFormat color_format_; // kColorFormat, or kFloatColorFormat for float targets
    const uint32_t texel_bytes_;  // of color_format_
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    Attachment color_; // multisampled when samples_ > 1
    Attachment depth_;
    Attachment resolve_;                        // only when samples_ > 1
    VkRenderPass render_pass_ = VK_NULL_HANDLE; // null with dynamic rendering
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkRenderPass depth_pass_ = VK_NULL_HANDLE; // target.vk_depth_pass: depth alone
    VkFramebuffer depth_framebuffer_ = VK_NULL_HANDLE;
    grass_bootstrap::VkBufferParts readback_; // host-visible, mapped
    bool readback_coherent_ = true;

    // The host's terrain stand-in (target.ground): shaders/ground.*, one uniform buffer.
    grass_bootstrap::VkBufferParts ground_buffer_;
    VkDescriptorSetLayout ground_set_layout_ = VK_NULL_HANDLE;
    VkDescriptorPool ground_pool_ = VK_NULL_HANDLE;
    VkDescriptorSet ground_set_ = VK_NULL_HANDLE;
    VkPipelineLayout ground_layout_ = VK_NULL_HANDLE;
    VkPipeline ground_pipeline_ = VK_NULL_HANDLE;
    std::unique_ptr<VkMeshDrawer> meshes_;      // target.meshes
    VkExtraTargets extras_;                     // target.vk_velocity_attachment, vk_gbuffer_formats
    std::unique_ptr<VkShadowCascades> shadows_; // target.host_shadows
    VkPassTarget pass_target() const;

    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkShadowMap shadow_map_; // make_vk_shadow_map
};

void VkHost::on_message(void* user, const std::string& line) {
    static_cast<VkHost*>(user)->add_validation_message(line);
}

// ---- Creation -----------------------------------------------------------------------------

bool VkHost::init(std::string* error) {
    samples_ = static_cast<VkSampleCountFlagBits>(target_.samples);
    if (target_.samples == 0 || (target_.samples & (target_.samples - 1)) != 0 || target_.samples > 64 ||
        target_.width == 0 || target_.height == 0) {
        *error = "target.samples must be 1, 2, 4, 8, 16, 32 or 64, and its width and height at least 1";
        return false;
    }
    return create_instance(error) && pick_device(error) && create_device(error) && create_target(error) &&
           create_render_pass(error) && create_commands(error) && (!target_.ground || create_ground(error)) &&
           create_meshes(error) &&
           create_vk_shadow_cascades(device_, memory_properties_, target_, pass_target(), ground_set_layout_,
                                     meshes_.get(), &shadows_, error);
}

VkPassTarget VkHost::pass_target() const {
    VkPassTarget t;
    t.render_pass = render_pass_;
    t.color_format = color_format_;
    t.depth_format = kDepthFormat;
    t.samples = samples_;
    t.reversed_z = target_.reversed_z;
    t.encode_srgb = target_.unorm_color;
    return t;
}

bool VkHost::create_meshes(std::string* error) {
    if (target_.meshes.empty()) return true;
    meshes_ = std::make_unique<VkMeshDrawer>();
    movable_meshes_ = meshes_.get();
    return meshes_->init(physical_device_, device_, pass_target(), target_.meshes, error);
}

// Validation layers on when installed; the messenger also without them when VK_EXT_debug_utils is there.
bool VkHost::create_instance(std::string* error) {
    grass_bootstrap::VkInstanceDesc desc;
    desc.application = "grass headless host";
    desc.messenger_without_layer = true;
    desc.sink = &sink_;
    return instance_.create(desc, error);
}

bool VkHost::pick_device(std::string* error) {
    const std::vector<VkPhysicalDevice> devices = grass_bootstrap::physical_devices(instance_.handle());
    if (devices.empty()) {
        *error = "no Vulkan physical device";
        return false;
    }
    const char* wanted = std::getenv("GRASS_VK_DEVICE");
    physical_device_ = VK_NULL_HANDLE;
    for (size_t i = 0; i < devices.size() && !physical_device_; ++i) {
        VkPhysicalDeviceProperties p{};
        vkGetPhysicalDeviceProperties(devices[i], &p);
        if (wanted && *wanted && std::strstr(p.deviceName, wanted)) physical_device_ = devices[i];
    }
    if (!physical_device_) {
        if (wanted && *wanted) {
            *error = std::string("no Vulkan device name contains GRASS_VK_DEVICE=\"") + wanted + "\"";
            return false;
        }
        physical_device_ = devices[0];
    }
    vkGetPhysicalDeviceProperties(physical_device_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
    device_name_ = properties_.deviceName;
    if (properties_.apiVersion < VK_API_VERSION_1_1) {
        *error = "the Vulkan device \"" + device_name_ + "\" is older than Vulkan 1.1";
        return false;
    }

    const VkSampleCountFlags supported =
        properties_.limits.framebufferColorSampleCounts & properties_.limits.framebufferDepthSampleCounts;
    if (!(supported & samples_)) {
        *error = "the Vulkan device \"" + device_name_ + "\" cannot render with " + std::to_string(target_.samples) +
                 " samples";
        return false;
    }

    const std::vector<VkQueueFamilyProperties> families = grass_bootstrap::queue_families(physical_device_);
    for (uint32_t i = 0; i < families.size(); ++i) {
        queue_family_ = i;
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return true;
    }
    *error = "the Vulkan device \"" + device_name_ + "\" has no graphics queue";
    return false;
}

bool VkHost::create_device(std::string* error) {
    // Vulkan 1.3 core needs both the instance and the device at 1.3.
    const bool core13 = instance_.api_version() >= VK_API_VERSION_1_3 && properties_.apiVersion >= VK_API_VERSION_1_3;
    const bool khr_dynamic_rendering =
        grass_bootstrap::has_device_extension(physical_device_, VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);

    // Is dynamicRendering there? (Vulkan 1.3 core, else the KHR extension.)
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceDynamicRenderingFeaturesKHR features_khr{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    if (core13) {
        features.pNext = &features13;
    } else if (khr_dynamic_rendering) {
        features.pNext = &features_khr;
    }
    vkGetPhysicalDeviceFeatures2(physical_device_, &features);
    dynamic_rendering_ = core13 ? features13.dynamicRendering == VK_TRUE
                                : khr_dynamic_rendering && features_khr.dynamicRendering == VK_TRUE;
    if (target_.vk_dynamic_rendering && !dynamic_rendering_) {
        *error = "the Vulkan device \"" + device_name_ + "\" has no dynamic rendering";
        return false;
    }

    // Enable only dynamicRendering (when there), nothing else.
    VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceDynamicRenderingFeaturesKHR enable_khr{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR};
    std::vector<const char*> extension_names;
    const void* enable = nullptr;
    if (dynamic_rendering_ && core13) {
        enable13.dynamicRendering = VK_TRUE;
        enable = &enable13;
    } else if (dynamic_rendering_) {
        enable_khr.dynamicRendering = VK_TRUE;
        enable = &enable_khr;
        extension_names.push_back(VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);
    }
    enable = extras_.enable_features(target_, enable);
    if (!grass_bootstrap::create_device(physical_device_, queue_family_, extension_names, enable, &device_, &queue_,
                                        error)) {
        return false;
    }
    static const char* const kDrivers[] = {"libvulkan_", "libVkLayer_", nullptr};
    keep_drivers_resident(kDrivers);
    if (dynamic_rendering_) {
        const char* begin_name = core13 ? "vkCmdBeginRendering" : "vkCmdBeginRenderingKHR";
        const char* end_name = core13 ? "vkCmdEndRendering" : "vkCmdEndRenderingKHR";
        begin_rendering_ = reinterpret_cast<PFN_vkCmdBeginRendering>(vkGetDeviceProcAddr(device_, begin_name));
        end_rendering_ = reinterpret_cast<PFN_vkCmdEndRendering>(vkGetDeviceProcAddr(device_, end_name));
        if (!begin_rendering_ || !end_rendering_) {
            *error = "the Vulkan device lacks vkCmdBeginRendering";
            return false;
        }
    }
    return true;
}

bool VkHost::create_attachment(VkFormat format, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                               VkImageAspectFlags aspect, Attachment* out, std::string* error) {
    grass_bootstrap::VkImageDesc desc;
    desc.extent = {target_.width, target_.height};
    desc.format = format;
    desc.samples = samples;
    desc.usage = usage;
    desc.aspect = aspect;
    return grass_bootstrap::create_image(device_, memory_properties_, desc, out, error);
}

bool VkHost::create_target(std::string* error) {
    const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;
    const VkImageUsageFlags color_usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                          (msaa ? 0 : VK_IMAGE_USAGE_TRANSFER_SRC_BIT) |
                                          (target_.vk_depth_pass ? VK_IMAGE_USAGE_TRANSFER_DST_BIT : 0);
    if (!create_attachment(color_format_, samples_, color_usage, VK_IMAGE_ASPECT_COLOR_BIT, &color_, error) ||
        !create_attachment(kDepthFormat, samples_,
                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                               (target_.read_depth ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0),
                           VK_IMAGE_ASPECT_DEPTH_BIT, &depth_, error)) {
        return false;
    }
    if (msaa && !create_attachment(color_format_, VK_SAMPLE_COUNT_1_BIT,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_IMAGE_ASPECT_COLOR_BIT, &resolve_, error)) {
        return false;
    }

    if (target_.read_depth && (msaa || target_.vk_dynamic_rendering)) {
        *error = "read_depth needs a single-sampled target drawn with a render pass";
        return false;
    }
    if (target_.vk_depth_pass && !target_.read_depth) {
        *error = "vk_depth_pass needs read_depth";
        return false;
    }
    // Read-back buffer: host-visible, cached when possible. Colour, then (read_depth) depth.
    const VkDeviceSize size =
        VkDeviceSize(target_.width) * target_.height * (texel_bytes_ + (target_.read_depth ? 4 : 0));
    std::string ignored;
    if (grass_bootstrap::create_buffer(device_, memory_properties_, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                       &readback_, &ignored)) {
        readback_coherent_ = true;
        return true;
    }
    grass_bootstrap::destroy_buffer(device_, &readback_);
    readback_coherent_ = false;
    return grass_bootstrap::create_buffer(device_, memory_properties_, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                          VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, &readback_, error);
}

bool VkHost::create_render_pass(std::string* error) {
    grass_bootstrap::VkPassDesc pass;
    if (!extras_.create(device_, memory_properties_, target_, &pass, error)) return false;
    if (target_.vk_dynamic_rendering) return true;
    pass.color_format = color_format_;
    pass.depth_format = kDepthFormat;
    pass.samples = samples_;
    pass.color_final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL; // read back
    pass.keep_depth = target_.read_depth;
    pass.depth_final =
        target_.read_depth ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    VkSubpassDependency* dependencies = pass.dependencies;
    // The last frame's read-back copy and attachment writes come before this pass writes.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    dependencies[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    // The pass's colour writes (and resolve) come before the read-back copy.
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

    if (!grass_bootstrap::create_render_pass(device_, pass, &render_pass_, error)) return false;

    VkImageView views[9] = {color_.view, depth_.view, resolve_.view};
    const uint32_t own = samples_ != VK_SAMPLE_COUNT_1_BIT ? 3 : 2;
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = render_pass_;
    fb.attachmentCount = own + extras_.views(views + own);
    fb.pAttachments = views;
    fb.width = target_.width;
    fb.height = target_.height;
    fb.layers = 1;
    VkResult r = vkCreateFramebuffer(device_, &fb, nullptr, &framebuffer_);
    if (r == VK_SUCCESS && target_.vk_depth_pass) { // the same pass and dependencies, depth alone
        pass.color_format = VK_FORMAT_UNDEFINED;
        if (!grass_bootstrap::create_render_pass(device_, pass, &depth_pass_, error)) return false;
        fb.renderPass = depth_pass_;
        fb.attachmentCount = 1;
        fb.pAttachments = &depth_.view;
        r = vkCreateFramebuffer(device_, &fb, nullptr, &depth_framebuffer_);
    }
    if (r != VK_SUCCESS) {
        *error = vk_error("vkCreateFramebuffer", r);
        return false;
    }
    return true;
}

bool VkHost::create_commands(std::string* error) {
    if (!grass_bootstrap::create_command_pool(device_, queue_family_, &command_pool_, error)) return false;
    VkResult r = grass_bootstrap::allocate_command_buffer(device_, command_pool_, &cmd_);
    const VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    if (r == VK_SUCCESS) r = vkCreateFence(device_, &fence, nullptr, &fence_);
    if (r != VK_SUCCESS) *error = vk_error(cmd_ ? "vkCreateFence" : "vkAllocateCommandBuffers", r);
    return r == VK_SUCCESS;
}

VkHost::~VkHost() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        movable_meshes_ = nullptr;
        meshes_.reset();
        shadows_.reset();
        shadow_map_.destroy();
        if (ground_pipeline_) vkDestroyPipeline(device_, ground_pipeline_, nullptr);
        if (pipeline_cache_) vkDestroyPipelineCache(device_, pipeline_cache_, nullptr);
        if (ground_layout_) vkDestroyPipelineLayout(device_, ground_layout_, nullptr);
        if (ground_pool_) vkDestroyDescriptorPool(device_, ground_pool_, nullptr); // frees ground_set_
        if (ground_set_layout_) vkDestroyDescriptorSetLayout(device_, ground_set_layout_, nullptr);
        grass_bootstrap::destroy_buffer(device_, &ground_buffer_);
        if (fence_) vkDestroyFence(device_, fence_, nullptr);
        if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr); // frees cmd_
        if (depth_framebuffer_) vkDestroyFramebuffer(device_, depth_framebuffer_, nullptr);
        if (depth_pass_) vkDestroyRenderPass(device_, depth_pass_, nullptr);
        if (framebuffer_) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
        if (render_pass_) vkDestroyRenderPass(device_, render_pass_, nullptr);
        grass_bootstrap::destroy_buffer(device_, &readback_);
        grass_bootstrap::destroy_image(device_, &resolve_);
        grass_bootstrap::destroy_image(device_, &depth_);
        grass_bootstrap::destroy_image(device_, &color_);
        extras_.destroy(device_);
        vkDestroyDevice(device_, nullptr);
    }
    instance_.destroy(); // while the validation log is still there
}

// ---- The host's ground --------------------------------------------------------------------

bool VkHost::create_ground(std::string* error) {
    if (!grass_bootstrap::create_buffer(
            device_, memory_properties_, sizeof(GroundUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, &ground_buffer_, error) ||
        !grass_bootstrap::create_uniform_layouts(device_, &ground_set_layout_, &ground_layout_, error)) {
        return false;
    }
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.maxSets = 1;
    pool.poolSizeCount = 1;
    pool.pPoolSizes = &size;
    VkResult r = vkCreateDescriptorPool(device_, &pool, nullptr, &ground_pool_);
    if (r == VK_SUCCESS)
        r = grass_bootstrap::allocate_descriptor_set(device_, ground_pool_, ground_set_layout_, &ground_set_);
    if (r != VK_SUCCESS) {
        *error = vk_error("creating the ground's descriptors", r);
        return false;
    }
    grass_bootstrap::write_uniform_descriptor(device_, ground_set_, ground_buffer_.buffer, sizeof(GroundUniforms));
    return create_ground_pipeline(error);
}

bool VkHost::create_ground_pipeline(std::string* error) {
    VkHostPipelineDesc desc;
    desc.vertex_code = grass_host_spirv::ground_vert;
    desc.vertex_code_size = grass_host_spirv::ground_vert_size;
    desc.fragment_code = grass_host_spirv::ground_frag;
    desc.fragment_code_size = grass_host_spirv::ground_frag_size;
    desc.layout = ground_layout_;
    desc.target = pass_target();
    const VkResult r = create_host_pipeline(device_, desc, &ground_pipeline_);
    if (r != VK_SUCCESS) {
        *error = vk_error("creating the ground pipeline", r);
        return false;
    }
    return true;
}

// Drawn first in the pass, like an engine's terrain (the host waits for each frame, so
// the uniform buffer is free to rewrite).
void VkHost::draw_ground(VkCommandBuffer cmd, const grass_view_desc& view, bool receive_shadows) {
    const GroundUniforms u = make_ground_uniforms(view, target_);
    std::memcpy(ground_buffer_.mapped, &u, sizeof(u));
    const VkViewport viewport{0.0f, 0.0f, float(target_.width), float(target_.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {target_.width, target_.height}};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      receive_shadows ? shadows_->ground_pipeline() : ground_pipeline_);
    if (receive_shadows) shadows_->bind_ground_set(cmd); // set 1; set 0's layouts are compatible
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ground_layout_, 0, 1, &ground_set_, 0, nullptr);
    vkCmdDraw(cmd, kGroundVertexCount, 1, 0, 0);
}

// ---- The grass context --------------------------------------------------------------------

grass_result VkHost::create_context(const grass_context_desc& desc, grass_context** out) {
    grass_vk_desc vk = grass_default_vk_desc();
    vk.get_instance_proc_addr =
        target_.vk_get_instance_proc_addr ? target_.vk_get_instance_proc_addr : vkGetInstanceProcAddr;
    vk.instance = instance_.handle();
    vk.physical_device = physical_device_;
    vk.device = device_;
    vk.queue_family = queue_family_;
    vk.render_pass = reinterpret_cast<uint64_t>(render_pass_);
    vk.subpass = 0;
    vk.color_format = color_format_;
    vk.depth_format = kDepthFormat;
    vk.sample_count = samples_;
    vk.frames_in_flight = 2;
    if (target_.vk_host_pipeline_cache && !pipeline_cache_) {
        VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
        if (vkCreatePipelineCache(device_, &info, nullptr, &pipeline_cache_) != VK_SUCCESS) return GRASS_ERROR_BACKEND;
    }
    // What the host lends grass besides its device, chained only when it lends something (as
    // an engine would: a host lending nothing passes the bare desc).
    grass_vk_host_objects_desc lent = grass_default_vk_host_objects_desc();
    lent.allocation_callbacks = target_.vk_allocation_callbacks;
    lent.pipeline_cache = reinterpret_cast<uint64_t>(pipeline_cache_);
    if (lent.allocation_callbacks || lent.pipeline_cache) vk.next = &lent;
    grass_vk_depth_pass_desc depth = grass_default_vk_depth_pass_desc(); // target.vk_depth_pass
    depth.render_pass = reinterpret_cast<uint64_t>(depth_pass_);
    depth.depth_format = kDepthFormat;
    depth.next = vk.next;
    if (shadows_) depth.render_pass = reinterpret_cast<uint64_t>(shadows_->render_pass()); // the cascades' pass
    if (depth.render_pass) vk.next = &depth;
    vk.next = extras_.chain(vk.next); // target.vk_velocity_attachment
    return grass_vk_create_context(GRASS_HEADER_VERSION, &desc, &vk, out);
}

// Right-handed view looking down -z; clip y points down and z runs 0 (near) .. 1 (far), or 1 .. 0
// with reversed_z.
void VkHost::projection(float fovy_radians, float aspect, float near_m, float far_m, float out[16]) const {
    vk_projection(fovy_radians, aspect, near_m, far_m, target_.reversed_z, out);
}

// ---- A frame ------------------------------------------------------------------------------

void VkHost::begin_pass(VkCommandBuffer cmd) {
    VkClearValue clears[6] = {};
    stored_clear_color(target_, clears[0].color.float32);
    clears[1].depthStencil = {target_.reversed_z ? 0.0f : 1.0f, 0};
    const uint32_t clear_count = extras_.clear_values(clears);
    const VkRect2D area{{0, 0}, {target_.width, target_.height}};
    if (render_pass_) {
        VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        info.renderPass = render_pass_;
        info.framebuffer = framebuffer_;
        info.renderArea = area;
        info.clearValueCount = clear_count;
        info.pClearValues = clears;
        vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
        return;
    }

    // Dynamic rendering: the layout transitions a render pass would do.
    const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;
    VkImageMemoryBarrier barriers[3] = {};
    for (VkImageMemoryBarrier& b : barriers) {
        b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
        b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        b.newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    }
    barriers[0].image = color_.image;
    barriers[1].image = depth_.image;
    barriers[1].newLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    barriers[1].dstAccessMask =
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    barriers[1].subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    barriers[2].image = resolve_.image;
    vkCmdPipelineBarrier(cmd,
                         VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                             VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                             VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                         0, 0, nullptr, 0, nullptr, msaa ? 3 : 2, barriers);

    VkRenderingAttachmentInfo colors[4] = {{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO}};
    extras_.begin_rendering(cmd, colors + 1); // colour attachments 1..
    VkRenderingAttachmentInfo& color = colors[0];
    color.imageView = color_.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue = clears[0];
    if (msaa) {
        color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        color.resolveImageView = resolve_.view;
        color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = depth_.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue = clears[1];
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = area;
    info.layerCount = 1;
    info.colorAttachmentCount = 1 + extras_.count();
    info.pColorAttachments = colors;
    info.pDepthAttachment = &depth;
    begin_rendering_(cmd, &info);
}

// Host::depth_only: the colour image cleared outside any pass (it reads back as the colour
// pass's clear), then the depth-only pass over the depth image.
void VkHost::begin_depth_pass(VkCommandBuffer cmd) {
    VkClearColorValue colour{};
    stored_clear_color(target_, colour.float32);
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = color_.image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &b);
    vkCmdClearColorImage(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1, &b.subresourceRange);
    b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL; // as the colour pass leaves it: read back
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &b);
    VkClearValue clear{};
    clear.depthStencil = {target_.reversed_z ? 0.0f : 1.0f, 0};
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = depth_pass_;
    info.framebuffer = depth_framebuffer_;
    info.renderArea = {{0, 0}, {target_.width, target_.height}};
    info.clearValueCount = 1;
    info.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void VkHost::end_pass(VkCommandBuffer cmd) {
    if (render_pass_) {
        vkCmdEndRenderPass(cmd); // leaves the read-back image in TRANSFER_SRC_OPTIMAL
        return;
    }
    end_rendering_(cmd);
    extras_.end_rendering(cmd);
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = samples_ != VK_SAMPLE_COUNT_1_BIT ? resolve_.image : color_.image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &b);
}

void VkHost::copy_to_readback(VkCommandBuffer cmd) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {target_.width, target_.height, 1};
    const VkImage image = samples_ != VK_SAMPLE_COUNT_1_BIT ? resolve_.image : color_.image;
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &region);
    if (target_.read_depth) {
        region.bufferOffset = VkDeviceSize(target_.width) * target_.height * texel_bytes_;
        region.imageSubresource.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        vkCmdCopyImageToBuffer(cmd, depth_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &region);
    }
    const VkBufferMemoryBarrier b = grass_bootstrap::host_read_barrier(readback_.buffer);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &b, 0,
                         nullptr);
    if (extras_.count()) extras_.copy(cmd);
}

grass_result VkHost::render(grass_context* context, const grass_view_desc& view, const Occluder* occluder, Image* out,
                            std::string* error) {
    auto host_failure = [&](const char* call, VkResult r) {
        if (error) *error = vk_error(call, r);
        return GRASS_ERROR_BACKEND;
    };
    VkResult r = vkResetCommandBuffer(cmd_, 0);
    if (r != VK_SUCCESS) return host_failure("vkResetCommandBuffer", r);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    r = vkBeginCommandBuffer(cmd_, &begin);
    if (r != VK_SUCCESS) return host_failure("vkBeginCommandBuffer", r);

    // grass plans the frame, then records its uploads outside the pass and its draws in it.
    // Once grass_vk_prepare has recorded, the command buffer is submitted even when a later
    // grass call fails: its uploads must run.
    // TargetDesc::host_shadows: one frame of the main view (receiving) and the cascades' depth
    // views, the cascades' passes recorded before the main pass.
    const bool shadowed = shadows_ && shadow_parts.any();
    LightCascades cascades;
    ShadowFrameViews views;
    if (shadowed) {
        cascades = fit_light_cascades(view, target_.host_shadows, true);
        make_shadow_frame_views(view, cascades, target_.host_shadows, shadows_->array_view(),
                                VkShadowCascades::kReadLayout, shadow_parts.grass_receives, &views);
        shadows_->set_uniforms(cascades.uniforms);
    }
    grass_result result = shadowed ? plan_shadow_frame(context, views, cascades.count, shadow_parts.grass_casts)
                          : begin_grass_frame ? begin_grass_frame(context)
                                              : grass_begin_frame(context, &view);
    const bool frame_begun = result == GRASS_SUCCESS;
    if (frame_begun) {
        grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
        prepare.command_buffer = cmd_;
        result = grass_vk_prepare(context, &prepare);
    }
    if (shadowed) { // every layer's pass runs (it leaves the map in its read layout)
        const grass_result c =
            shadows_->record_cascades(cmd_, context, cascades, shadow_parts.host_casts ? meshes_.get() : nullptr,
                                      shadow_parts.grass_casts && result == GRASS_SUCCESS);
        if (result == GRASS_SUCCESS) result = c;
    }
    const bool host_receives = shadowed && shadow_parts.host_receives;
    const bool depth_pass = depth_only && depth_pass_;
    if (depth_pass) {
        begin_depth_pass(cmd_);
    } else {
        begin_pass(cmd_);
        if (target_.ground) draw_ground(cmd_, view, host_receives);
        if (meshes_)
            meshes_->record(cmd_, view, target_.width, target_.height, host_receives ? shadows_->set() : nullptr);
        if (occluder) record_occluder(cmd_, target_, view, *occluder);
    }
    if (result == GRASS_SUCCESS) {
        grass_vk_record_desc record = grass_default_vk_record_desc();
        record.command_buffer = cmd_;
        result = draw_grass ? draw_grass(context, cmd_)
                 : shadowed ? grass_vk_record_view(context, 0, &record)
                            : grass_vk_record(context, &record);
    }
    if (depth_pass) {
        vkCmdEndRenderPass(cmd_); // the depth image ends in TRANSFER_SRC_OPTIMAL (read_depth)
    } else {
        end_pass(cmd_);
    }
    copy_to_readback(cmd_);
    r = vkEndCommandBuffer(cmd_);
    if (r != VK_SUCCESS) {
        if (frame_begun) grass_end_frame(context);
        return host_failure("vkEndCommandBuffer", r);
    }

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd_;
    r = vkQueueSubmit(queue_, 1, &submit, fence_);
    if (r == VK_SUCCESS) r = vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
    if (r == VK_SUCCESS) r = vkResetFences(device_, 1, &fence_);
    if (frame_begun) {
        const grass_result end = grass_end_frame(context);
        if (result == GRASS_SUCCESS) result = end;
    }
    if (r != VK_SUCCESS) return host_failure("vkQueueSubmit/vkWaitForFences", r);
    if (result != GRASS_SUCCESS) {
        if (error) *error = grass_get_last_error(context);
        return result;
    }

    if (!readback_coherent_) {
        VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
        range.memory = readback_.memory;
        range.size = VK_WHOLE_SIZE;
        vkInvalidateMappedMemoryRanges(device_, 1, &range);
    }
    out->width = target_.width;
    out->height = target_.height;
    if (target_.float_color) {
        out->rgba_f32.resize(size_t(target_.width) * target_.height * 4);
        std::memcpy(out->rgba_f32.data(), readback_.mapped, out->rgba_f32.size() * sizeof(float)); // rows top-down
        encode_float_image(out);
    } else {
        out->rgba.resize(size_t(target_.width) * target_.height * 4);
        std::memcpy(out->rgba.data(), readback_.mapped, out->rgba.size()); // Vulkan rows run top-down
    }
    if (target_.read_depth) {
        out->depth.resize(size_t(target_.width) * target_.height); // D32_SFLOAT, top-down
        std::memcpy(out->depth.data(),
                    static_cast<const uint8_t*>(readback_.mapped) +
                        size_t(target_.width) * target_.height * texel_bytes_,
                    out->depth.size() * sizeof(float));
    }
    if (extras_.count()) extras_.read(device_, out);
    if (messages_ != 0 && error) *error = log_;
    return GRASS_SUCCESS;
}

} // namespace

std::unique_ptr<Host> create_vk_host(const TargetDesc& target, std::string* error) {
    std::string ignored;
    std::string* e = error ? error : &ignored;
    auto host = std::make_unique<VkHost>(target);
    if (!host->init(e)) return nullptr;
    return host;
}

} // namespace grass_host
