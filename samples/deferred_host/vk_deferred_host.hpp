// grass-deferred's Vulkan deferred host (grass-deferred --backend vk): a grass_host::Host of
// its own device (the bootstrap's instance with the validation layers, one graphics queue,
// independentBlend), whose frame is a deferred renderer's:
// 1. The G-buffer pass: albedo (RGBA16F, linear, colour attachment 0), normal (RGBA8 UNORM,
//    n * 0.5 + 0.5), material (RGBA8 UNORM: roughness, translucency, ambient occlusion),
//    velocity (RGBA16F, colour attachment 3; velocity.hpp) and depth (D32). The host draws its ground (shaders/gbuffer_ground.*), then grass records the
//    view it is given (a GRASS_PASS_GBUFFER view, scene.hpp's gbuffer_layout) into the same
//    attachments; grass was told of the pass with a grass_vk_gbuffer_target_desc.
// 2. The lighting pass: a second render pass whose one full-screen triangle samples the four
//    images (left readable by the first pass's final layouts and dependency) with
//    shaders/lighting.frag, the GL half's lighting text, into an sRGB target read back as the
//    Image. Two render passes, not one with input attachments, so that both halves sample
//    the G-buffer with the same texelFetch.
// Single-sampled, render passes (no dynamic rendering), no occluder.
#pragma once

#include "headless_host.hpp"
#include "vk_bootstrap.hpp"

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

namespace deferred {

// lighting.frag's Lighting block (std140).
struct LightingUniforms {
    float view_projection[16]; // camera-relative world -> clip
    float size[2], pad0[2];
    float sun_direction[3], pad1; // towards the sun
    float sun_color[3], pad2;
    float ambient[3], pad3;
    float light_position[3][4]; // camera-relative xyz, w: range
    float light_color[3][4];    // rgb x intensity
};
static_assert(sizeof(LightingUniforms) == 224, "lighting.frag's std140 block");

class VkDeferredHost final : public grass_host::Host {
public:
    // A host for `target`: its width and height (samples 1; its other fields are not read,
    // the G-buffer, ground and lights being this host's own). nullptr and *error for another
    // target or when there is no Vulkan device.
    static std::unique_ptr<VkDeferredHost> create(const grass_host::TargetDesc& target, std::string* error);
    ~VkDeferredHost() override;
    VkDeferredHost(const VkDeferredHost&) = delete;
    VkDeferredHost& operator=(const VkDeferredHost&) = delete;

    grass_backend backend() const override { return GRASS_BACKEND_VULKAN; }
    // A context that draws in the G-buffer pass (its four colour attachments and depth), with
    // a grass_vk_velocity_target_desc (attachment 3) when `velocity` was set before.
    grass_result create_context(const grass_context_desc& desc, grass_context** out) override;
    void set_velocity(bool velocity) { velocity_ = velocity; }
    void projection(float fovy_radians, float aspect, float near_m, float far_m, float out[16]) const override;
    // One deferred frame of `view` (the ground, grass, the lighting with the lights last given
    // to set_lights), its lit picture in out->rgba (sRGB, top row first). `occluder` must be
    // null (GRASS_ERROR_INVALID_ARGUMENT otherwise).
    grass_result render(grass_context* context, const grass_view_desc& view, const grass_host::Occluder* occluder,
                        grass_host::Image* out, std::string* error) override;
    // The lights of the next lighting pass (view_projection and size are the host's own).
    void set_lights(const LightingUniforms& lights) { lights_ = lights; }
    // Lights the last frame's G-buffer again with the lights now set, into *out; false and
    // *error before the first frame.
    bool relight(grass_host::Image* out, std::string* error);
    // The last frame's velocity attachment, RGBA floats, top row first; false and *error
    // before the first frame.
    bool read_velocity(std::vector<float>* rgba, std::string* error);

private:
    explicit VkDeferredHost(const grass_host::TargetDesc& target) : Host(target) {}
    bool init(std::string* error);
    bool create_device(std::string* error);
    // vk_deferred_passes.cpp: the images, the two passes, their pipelines and descriptors.
    bool create_images(std::string* error);
    bool create_passes(std::string* error);
    bool create_pipelines(std::string* error);
    bool create_lighting_set(std::string* error);
    void record_gbuffer_begin(VkCommandBuffer cmd, const grass_view_desc& view);
    void record_lighting(VkCommandBuffer cmd);
    bool begin_commands(std::string* error);
    bool submit_and_read(grass_host::Image* out, std::string* error);
    bool submit(std::string* error); // ends, submits and waits for the command buffer
    static void on_message(void* user, const std::string& line);

    grass_bootstrap::VkMessageSink sink_{&VkDeferredHost::on_message, this};
    grass_bootstrap::VkBootInstance instance_;
    VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory_properties_{};
    uint32_t queue_family_ = 0;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;

    // The G-buffer: albedo, normal, material, depth, velocity; then the lit target.
    grass_bootstrap::VkImageParts gbuffer_[5];
    grass_bootstrap::VkImageParts lit_;
    grass_bootstrap::VkBufferParts readback_; // host-visible, coherent: the lit or velocity texels
    VkRenderPass gbuffer_pass_ = VK_NULL_HANDLE, lighting_pass_ = VK_NULL_HANDLE;
    VkFramebuffer gbuffer_framebuffer_ = VK_NULL_HANDLE, lighting_framebuffer_ = VK_NULL_HANDLE;
    VkPipelineLayout ground_layout_ = VK_NULL_HANDLE; // push constants: GroundConstants
    VkPipeline ground_pipeline_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout lighting_set_layout_ = VK_NULL_HANDLE;
    VkDescriptorPool lighting_pool_ = VK_NULL_HANDLE;
    VkDescriptorSet lighting_set_ = VK_NULL_HANDLE;
    VkPipelineLayout lighting_layout_ = VK_NULL_HANDLE;
    VkPipeline lighting_pipeline_ = VK_NULL_HANDLE;
    grass_bootstrap::VkBufferParts lighting_buffer_; // host-visible, coherent: LightingUniforms
    LightingUniforms lights_{};
    float view_projection_[16] = {}; // of the last frame's view
    bool has_frame_ = false;         // a frame has filled the G-buffer
    bool velocity_ = false;          // the context writes velocity
};

} // namespace deferred
