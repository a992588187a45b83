// Stereo on Vulkan (grass_stereo_view_desc, grass_vk_multiview_desc.view_mask; docs/integration.md,
// "Stereo: multiview"), on a host of its own (the bootstrap's; dynamic rendering, the
// multiview feature on, validation layers on and silent):
// - the two eyes drawn by one grass_vk_record into a multiview pass (view mask 0x3) of 2-layer
//   colour and depth arrays, with dynamic rendering and in a render pass, are, layer for layer and pixel for pixel, the eyes drawn one at a
//   time as mono views by a mono context with the stereo frame's lod origin (the eyes'
//   midpoint), over the geometry, volume and image tiers and the debug boxes. The positions
//   are dyadic (the eyes 1/32 m either side of the midpoint, cells of 1/4 m), so that the
//   multiview shaders' instance origin minus the eye is exactly the mono plan's origin;
// - a stereo frame in a mono context, a mono frame in a stereo context and a view mask other
//   than 0 or 0x3 are refused, naming what is wrong; so is a stereo frame on GL
//   (GL_OVR_multiview: Mesa's llvmpipe has none), tested in GlStereo below.
#include "driver_residency.hpp"
#include "render_fixture.hpp"
#include "vk_bootstrap.hpp"

#include <grass/grass_vk.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdlib.h> // mkdtemp

#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <string>
#include <vector>

namespace grass_test {
namespace {

using grass_bootstrap::VkBufferParts;
using grass_bootstrap::VkImageParts;

constexpr uint32_t kWidth = 128, kHeight = 80;
constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM; // stores exactly what grass writes
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// The eyes: 1/32 m either side of a dyadic midpoint, looking at one point (toed in).
constexpr double kMid[3] = {8.0, 1.5, -1.0};
constexpr double kEyeOffset = 0.03125;
constexpr double kLook[3] = {8.0, 0.0, 6.0};

void on_message(void* user, const std::string& line) { *static_cast<std::string*>(user) += line + "\n"; }

// A device with dynamic rendering and multiview, and the frame a test records.
struct StereoHost {
    std::string messages;
    grass_bootstrap::VkMessageSink sink{&on_message, &messages};
    grass_bootstrap::VkBootInstance instance;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory{};
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool pool = VK_NULL_HANDLE;
    uint32_t family = 0;

    VkRenderPass multiview_pass = VK_NULL_HANDLE;        // 0: dynamic rendering (create_multiview_pass)
    std::deque<grass_vk_multiview_desc> multiview_descs; // chained by vk_desc (a deque: they stay put)

    ~StereoHost() {
        if (multiview_pass) vkDestroyRenderPass(device, multiview_pass, nullptr);
        if (pool) vkDestroyCommandPool(device, pool, nullptr);
        if (device) vkDestroyDevice(device, nullptr);
    }

    // False (with *skip set) where the device lacks Vulkan 1.3 or multiview.
    bool create(std::string* error, std::string* skip) {
        grass_bootstrap::VkInstanceDesc desc;
        desc.application = "grass stereo test";
        desc.messenger_without_layer = true;
        desc.sink = &sink;
        if (!instance.create(desc, error)) return false;
        // As the hosts do: the layer and the ICDs stay loaded past vkDestroyInstance, so that
        // LeakSanitizer can name their allocations (tests/sanitizer/lsan.supp).
        static const char* const kDrivers[] = {"libvulkan_", "libVkLayer_", nullptr};
        grass_host::keep_drivers_resident(kDrivers);
        const auto devices = grass_bootstrap::physical_devices(instance.handle());
        if (devices.empty()) return *error = "no Vulkan device", false;
        physical = devices[0];
        VkPhysicalDeviceProperties properties{};
        vkGetPhysicalDeviceProperties(physical, &properties);
        VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
        VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        f11.pNext = &f13;
        VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        features.pNext = &f11;
        if (instance.api_version() < VK_API_VERSION_1_3 || properties.apiVersion < VK_API_VERSION_1_3) {
            return *skip = "the device is older than Vulkan 1.3", false;
        }
        vkGetPhysicalDeviceFeatures2(physical, &features);
        if (!f11.multiview || !f13.dynamicRendering) return *skip = "no multiview or dynamic rendering", false;
        vkGetPhysicalDeviceMemoryProperties(physical, &memory);
        const auto families = grass_bootstrap::queue_families(physical);
        while (family < families.size() && !(families[family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) family += 1;
        VkPhysicalDeviceVulkan11Features enable11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
        VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        enable11.multiview = VK_TRUE;
        enable11.pNext = &enable13;
        enable13.dynamicRendering = VK_TRUE;
        return grass_bootstrap::create_device(physical, family, {}, &enable11, &device, &queue, error) &&
               grass_bootstrap::create_command_pool(device, family, &pool, error);
    }

    // A classic render pass whose one subpass has view mask 0x3 (VkRenderPassMultiviewCreateInfo):
    // colour cleared and kept for the copy, depth cleared.
    bool create_multiview_pass(std::string* error) {
        grass_bootstrap::VkPassDesc desc;
        desc.color_format = kColorFormat;
        desc.depth_format = kDepthFormat;
        desc.color_final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        desc.dependencies[0] = {VK_SUBPASS_EXTERNAL,
                                0,
                                VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                                VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
                                0,
                                VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                                0};
        desc.dependencies[1] = {0,
                                VK_SUBPASS_EXTERNAL,
                                VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                VK_PIPELINE_STAGE_TRANSFER_BIT,
                                VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                                VK_ACCESS_TRANSFER_READ_BIT,
                                0};
        const uint32_t view_mask = 0x3, correlation = 0x3;
        VkRenderPassMultiviewCreateInfo multiview{VK_STRUCTURE_TYPE_RENDER_PASS_MULTIVIEW_CREATE_INFO};
        multiview.subpassCount = 1;
        multiview.pViewMasks = &view_mask;
        multiview.correlationMaskCount = 1;
        multiview.pCorrelationMasks = &correlation;
        desc.next = &multiview;
        return grass_bootstrap::create_render_pass(device, desc, &multiview_pass, error);
    }

    // view_mask 0: nothing chained (mono, as a host without stereo); otherwise a
    // grass_vk_multiview_desc of that mask chained on next (kept alive by the host).
    grass_vk_desc vk_desc(uint32_t view_mask, bool render_pass = false) {
        grass_vk_desc d = grass_default_vk_desc();
        d.get_instance_proc_addr = reinterpret_cast<grass_vk_get_instance_proc_addr_fn>(vkGetInstanceProcAddr);
        d.instance = instance.handle();
        d.physical_device = physical;
        d.device = device;
        d.queue_family = family;
        d.color_format = kColorFormat;
        d.depth_format = kDepthFormat;
        if (view_mask != 0) {
            multiview_descs.push_back(grass_default_vk_multiview_desc());
            multiview_descs.back().view_mask = view_mask;
            d.next = &multiview_descs.back();
        }
        if (render_pass) d.render_pass = reinterpret_cast<uint64_t>(multiview_pass);
        return d;
    }

    // One frame of `view` into `layers`-layer colour and depth (a multiview pass of view mask
    // 0x3 for two), read back layer by layer (RGBA8, top row first).
    // With render_pass: in multiview_pass (two layers) instead of dynamic rendering.
    grass_result render(grass_context* ctx, const grass_view_desc& view, uint32_t layers,
                        std::vector<std::vector<uint8_t>>* out, std::string* error, bool render_pass = false) {
        VkImageParts color, depth;
        VkBufferParts readback;
        grass_bootstrap::VkImageDesc image;
        image.extent = {kWidth, kHeight};
        image.layers = layers;
        image.format = kColorFormat;
        image.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        const VkDeviceSize layer_bytes = VkDeviceSize(kWidth) * kHeight * 4;
        bool ok = grass_bootstrap::create_image(device, memory, image, &color, error);
        image.format = kDepthFormat;
        image.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        image.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
        ok = ok && grass_bootstrap::create_image(device, memory, image, &depth, error) &&
             grass_bootstrap::create_buffer(device, memory, layer_bytes * layers, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                            &readback, error);
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        ok = ok && grass_bootstrap::allocate_command_buffer(device, pool, &cmd) == VK_SUCCESS;
        VkFramebuffer framebuffer = VK_NULL_HANDLE;
        if (ok && render_pass) { // multiview: a framebuffer of one layer, the views are the array's layers
            const VkImageView attachments[2] = {color.view, depth.view};
            VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
            info.renderPass = multiview_pass;
            info.attachmentCount = 2;
            info.pAttachments = attachments;
            info.width = kWidth;
            info.height = kHeight;
            info.layers = 1;
            ok = vkCreateFramebuffer(device, &info, nullptr, &framebuffer) == VK_SUCCESS;
        }
        grass_result r = ok ? GRASS_SUCCESS : GRASS_ERROR_BACKEND;
        if (ok)
            r = record_and_submit(ctx, view, layers, cmd, color.image, color.view, depth.image, depth.view,
                                  readback.buffer, framebuffer);
        if (framebuffer) vkDestroyFramebuffer(device, framebuffer, nullptr);
        if (r == GRASS_SUCCESS) {
            out->assign(layers, std::vector<uint8_t>(layer_bytes));
            for (uint32_t l = 0; l < layers; ++l) {
                std::memcpy((*out)[l].data(), static_cast<const uint8_t*>(readback.mapped) + l * layer_bytes,
                            layer_bytes);
            }
        }
        if (cmd) vkFreeCommandBuffers(device, pool, 1, &cmd);
        grass_bootstrap::destroy_buffer(device, &readback);
        grass_bootstrap::destroy_image(device, &depth);
        grass_bootstrap::destroy_image(device, &color);
        return r;
    }

private:
    static VkImageMemoryBarrier barrier(VkImage image, VkImageAspectFlags aspect, uint32_t layers, VkImageLayout from,
                                        VkImageLayout to, VkAccessFlags src, VkAccessFlags dst) {
        VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        b.srcAccessMask = src;
        b.dstAccessMask = dst;
        b.oldLayout = from;
        b.newLayout = to;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image;
        b.subresourceRange = {aspect, 0, 1, 0, layers};
        return b;
    }

    grass_result record_and_submit(grass_context* ctx, const grass_view_desc& view, uint32_t layers,
                                   VkCommandBuffer cmd, VkImage color, VkImageView color_view, VkImage depth,
                                   VkImageView depth_view, VkBuffer readback, VkFramebuffer framebuffer) {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(cmd, &begin);
        grass_result r = grass_begin_frame(ctx, &view);
        if (r != GRASS_SUCCESS) {
            vkEndCommandBuffer(cmd);
            return r;
        }
        grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
        prepare.command_buffer = cmd;
        r = grass_vk_prepare(ctx, &prepare);
        const VkImageMemoryBarrier into[2] = {
            barrier(color, VK_IMAGE_ASPECT_COLOR_BIT, layers, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 0, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT),
            barrier(depth, VK_IMAGE_ASPECT_DEPTH_BIT, layers, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, 0,
                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)};
        if (!framebuffer) {
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                     VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
                                 0, 0, nullptr, 0, nullptr, 2, into);
        }
        VkRenderingAttachmentInfo color_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color_attachment.imageView = color_view;
        color_attachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        color_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        color_attachment.clearValue.color = {{0.2f, 0.3f, 0.5f, 1.0f}};
        VkRenderingAttachmentInfo depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth_attachment.imageView = depth_view;
        depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        depth_attachment.clearValue.depthStencil = {1.0f, 0};
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, {kWidth, kHeight}};
        rendering.layerCount = 1;
        rendering.viewMask = layers == 2 ? 0x3u : 0u;
        rendering.colorAttachmentCount = 1;
        rendering.pColorAttachments = &color_attachment;
        rendering.pDepthAttachment = &depth_attachment;
        VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        const VkClearValue clears[2] = {color_attachment.clearValue, depth_attachment.clearValue};
        pass.renderPass = multiview_pass;
        pass.framebuffer = framebuffer;
        pass.renderArea = rendering.renderArea;
        pass.clearValueCount = 2;
        pass.pClearValues = clears;
        if (framebuffer) {
            vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
        } else {
            vkCmdBeginRendering(cmd, &rendering);
        }
        grass_vk_record_desc record = grass_default_vk_record_desc();
        record.command_buffer = cmd;
        if (r == GRASS_SUCCESS) r = grass_vk_record(ctx, &record);
        if (framebuffer) {
            vkCmdEndRenderPass(cmd); // ends in TRANSFER_SRC_OPTIMAL
        } else {
            vkCmdEndRendering(cmd);
            const VkImageMemoryBarrier out =
                barrier(color, VK_IMAGE_ASPECT_COLOR_BIT, layers, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                        VK_ACCESS_TRANSFER_READ_BIT);
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                                 0, nullptr, 0, nullptr, 1, &out);
        }
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
        copy.imageExtent = {kWidth, kHeight, 1};
        vkCmdCopyImageToBuffer(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &copy);
        const VkBufferMemoryBarrier host = grass_bootstrap::host_read_barrier(readback);
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &host,
                             0, nullptr);
        vkEndCommandBuffer(cmd);
        const grass_result end = grass_end_frame(ctx);
        if (r != GRASS_SUCCESS) return r;
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmd;
        if (vkQueueSubmit(queue, 1, &submit, VK_NULL_HANDLE) != VK_SUCCESS) return GRASS_ERROR_BACKEND;
        vkQueueWaitIdle(queue);
        return end;
    }
};

// A look-at view from `eye` (rotation only) with a Vulkan projection (z 0..1, y down).
void eye_view(const double eye[3], float view[16], float projection[16]) {
    double f[3], r[3], u[3];
    look_at_basis(eye, kLook, f, r, u);
    for (int k = 0; k < 16; ++k) view[k] = projection[k] = 0.0f;
    for (int c = 0; c < 3; ++c) {
        view[4 * c + 0] = static_cast<float>(r[c]);
        view[4 * c + 1] = static_cast<float>(u[c]);
        view[4 * c + 2] = static_cast<float>(-f[c]);
    }
    view[15] = 1.0f;
    const float near_m = 0.05f, far_m = 200.0f, t = 1.0f / std::tan(0.5f * 60.0f * 3.14159265f / 180.0f);
    projection[0] = t * float(kHeight) / float(kWidth);
    projection[5] = -t;
    projection[10] = far_m / (near_m - far_m);
    projection[11] = -1.0f;
    projection[14] = far_m * near_m / (near_m - far_m);
}

// The eye `e` (0 left, 1 right) as a mono view desc.
grass_view_desc mono_eye(int e, uint32_t flags) {
    grass_view_desc v = grass_default_view_desc();
    v.camera_position[0] = kMid[0] + (e == 0 ? -kEyeOffset : kEyeOffset);
    v.camera_position[1] = kMid[1];
    v.camera_position[2] = kMid[2];
    eye_view(v.camera_position, v.view, v.projection);
    v.viewport[2] = int32_t(kWidth);
    v.viewport[3] = int32_t(kHeight);
    v.flags = flags;
    return v;
}

// A 20 m x 20 m field of cells of 1/4 m with a geometry, a volume and an image tier.
void make_scene(grass_context* ctx) {
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS);
    const grass_tier_desc tiers[3] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_VOLUME, 4}, {GRASS_TIER_IMAGE, 0}};
    grass_lod_test tests[3] = {};
    const float bands[3][2] = {{0.0f, 3.0f}, {2.5f, 9.0f}, {8.0f, INFINITY}};
    for (uint32_t t = 0; t < 3; ++t) {
        tests[t].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[t].tier = t;
        tests[t].begin = bands[t][0];
        tests[t].end = bands[t][1];
        tests[t].transition_in = t > 0 ? 0.5f : 0.0f;
        tests[t].transition_out = t < 2 ? 0.5f : 0.0f;
        tests[t].edge_ratio = t > 0 ? 0.25f : 0.0f;
    }
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 80;
    fd.tiers = tiers;
    fd.tier_count = 3;
    fd.lod_tests = tests;
    fd.lod_test_count = 3;
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS);
}

// A directory of baked slices for the test's contexts, removed at exit.
struct BakeCache {
    std::string path;
    BakeCache() {
        std::string pattern = (std::filesystem::temp_directory_path() / "grass-stereo-XXXXXX").string();
        if (mkdtemp(pattern.data())) path = pattern;
    }
    ~BakeCache() {
        std::error_code ignored;
        if (!path.empty()) std::filesystem::remove_all(path, ignored);
    }
};

const char* bake_cache() {
    static BakeCache cache;
    return cache.path.empty() ? nullptr : cache.path.c_str();
}

struct Contexts {
    std::string log;
    grass_context* mono = nullptr;
    grass_context* stereo = nullptr;
    grass_context* stereo_pass = nullptr; // stereo in the host's multiview render pass
    ~Contexts() {
        grass_destroy_context(stereo_pass);
        grass_destroy_context(stereo);
        grass_destroy_context(mono);
    }
    grass_context_desc desc() {
        grass_context_desc cd = grass_default_context_desc();
        cd.cache_directory = bake_cache(); // the three contexts bake the same slices once
        cd.log_user_data = &log;
        cd.log_fn = [](void* user, grass_log_level, grass_message_id, const char* message) {
            *static_cast<std::string*>(user) += std::string(message) + "\n";
        };
        return cd;
    }
};

size_t differing_pixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t n = 0;
    for (size_t i = 0; i + 3 < a.size() && i + 3 < b.size(); i += 4) {
        n += std::memcmp(&a[i], &b[i], 4) != 0 ? 1 : 0;
    }
    return n;
}

// One host and its three contexts (mono, stereo with dynamic rendering, stereo in a render
// pass) for the suite: creating a context compiles its pipelines, seconds on lavapipe.
class VkStereo : public ::testing::Test {
protected:
    // grass_vk_create_context with a copy of the extension `ext` chained in front of the
    // (view_mask) desc's chain (its next that chain when NULL) is refused
    // (GRASS_ERROR_INVALID_ARGUMENT) logging `message`, and makes no context.
    template <class Extension>
    void expect_refused(const Extension& ext, uint32_t view_mask, const char* message) {
        grass_context_desc cd = contexts.desc();
        grass_context* ctx = nullptr;
        grass_vk_desc d = host.vk_desc(view_mask);
        Extension chained = ext;
        if (!chained.next) chained.next = d.next;
        d.next = &chained;
        contexts.log.clear();
        EXPECT_EQ(grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &d, &ctx), GRASS_ERROR_INVALID_ARGUMENT)
            << message;
        EXPECT_EQ(ctx, nullptr);
        EXPECT_NE(contexts.log.find(message), std::string::npos) << contexts.log;
        if (ctx) grass_destroy_context(ctx); // made by mistake
    }

    static void SetUpTestSuite() {
        shared_host = new StereoHost;
        shared_contexts = new Contexts;
        if (!shared_host->create(&setup_error, &setup_skip)) return;
        StereoHost& host = *shared_host;
        Contexts& contexts = *shared_contexts;
        grass_context_desc cd = contexts.desc();
        const grass_vk_desc mono = host.vk_desc(0), stereo = host.vk_desc(0x3);
        if (grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &mono, &contexts.mono) != GRASS_SUCCESS ||
            grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &stereo, &contexts.stereo) != GRASS_SUCCESS ||
            !host.create_multiview_pass(&setup_error)) {
            setup_error += contexts.log;
            return;
        }
        const grass_vk_desc stereo_pass = host.vk_desc(0x3, true);
        if (grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &stereo_pass, &contexts.stereo_pass) != GRASS_SUCCESS) {
            setup_error += contexts.log;
        }
    }
    static void TearDownTestSuite() {
        delete shared_contexts; // the contexts before their device
        delete shared_host;
        shared_contexts = nullptr;
        shared_host = nullptr;
    }
    void SetUp() override {
        if (!setup_skip.empty()) GTEST_SKIP() << setup_skip;
        ASSERT_EQ(setup_error, "");
        ASSERT_NE(contexts.stereo_pass, nullptr);
    }
    void TearDown() override { EXPECT_EQ(host.messages, ""); }

    static StereoHost* shared_host;
    static Contexts* shared_contexts;
    static std::string setup_error, setup_skip;
    StereoHost& host = *shared_host;
    Contexts& contexts = *shared_contexts;
};

StereoHost* VkStereo::shared_host = nullptr;
Contexts* VkStereo::shared_contexts = nullptr;
std::string VkStereo::setup_error, VkStereo::setup_skip;

// The stereo frame's eyes, each pixel for pixel the mono frame of that eye with the same
// lod origin, for the tiers (flags 0) and the debug boxes (DEBUG_CELLS).
TEST_F(VkStereo, EachLayerOfTheMultiviewPassIsThatEyeDrawnAlone) {
    make_scene(contexts.mono);
    make_scene(contexts.stereo);
    make_scene(contexts.stereo_pass);
    for (uint32_t flags : {0u, uint32_t(GRASS_VIEW_FLAG_DEBUG_CELLS)}) {
        SCOPED_TRACE(flags);
        grass_view_desc left = mono_eye(0, flags), right = mono_eye(1, flags);
        grass_stereo_view_desc second = grass_default_stereo_view_desc();
        std::memcpy(second.camera_position, right.camera_position, sizeof(second.camera_position));
        std::memcpy(second.view, right.view, sizeof(second.view));
        std::memcpy(second.projection, right.projection, sizeof(second.projection));
        grass_view_desc stereo = left;
        stereo.next = &second;
        std::vector<std::vector<uint8_t>> layers, pass_layers, mono_left, mono_right;
        std::string error;
        ASSERT_EQ(host.render(contexts.stereo, stereo, 2, &layers, &error), GRASS_SUCCESS) << error << contexts.log;
        ASSERT_EQ(host.render(contexts.stereo_pass, stereo, 2, &pass_layers, &error, true), GRASS_SUCCESS)
            << error << contexts.log;
        grass_frame_stats stereo_stats{};
        ASSERT_EQ(grass_get_frame_stats(contexts.stereo, &stereo_stats), GRASS_SUCCESS);

        // The mono eyes with the stereo frame's lod origin: the eyes' midpoint.
        grass_lod_origin_desc origin = grass_default_lod_origin_desc();
        std::memcpy(origin.position, kMid, sizeof(origin.position));
        left.next = right.next = &origin;
        ASSERT_EQ(host.render(contexts.mono, left, 1, &mono_left, &error), GRASS_SUCCESS) << error << contexts.log;
        ASSERT_EQ(host.render(contexts.mono, right, 1, &mono_right, &error), GRASS_SUCCESS) << error << contexts.log;

        ASSERT_EQ(layers.size(), 2u);
        EXPECT_EQ(differing_pixels(layers[0], mono_left[0]), 0u);
        EXPECT_EQ(differing_pixels(layers[1], mono_right[0]), 0u);
        // The same in the host's multiview render pass.
        ASSERT_EQ(pass_layers.size(), 2u);
        EXPECT_EQ(differing_pixels(pass_layers[0], mono_left[0]), 0u);
        EXPECT_EQ(differing_pixels(pass_layers[1], mono_right[0]), 0u);
        // The eyes see different pictures, and grass in them.
        EXPECT_GT(differing_pixels(layers[0], layers[1]), size_t(kWidth) * kHeight / 50);
        EXPECT_GT(stereo_stats.instances[GRASS_TIER_GEOMETRY], 0u);
        EXPECT_GT(stereo_stats.instances[GRASS_TIER_VOLUME], 0u);
        EXPECT_GT(stereo_stats.instances[GRASS_TIER_IMAGE], 0u);
    }
}

TEST_F(VkStereo, AFrameWhoseEyesDoNotMatchTheContextsPassIsRefused) {
    grass_view_desc left = mono_eye(0, 0), right = mono_eye(1, 0);
    grass_stereo_view_desc second = grass_default_stereo_view_desc();
    std::memcpy(second.camera_position, right.camera_position, sizeof(second.camera_position));
    std::memcpy(second.view, right.view, sizeof(second.view));
    std::memcpy(second.projection, right.projection, sizeof(second.projection));
    grass_view_desc stereo = left;
    stereo.next = &second;
    contexts.log.clear();
    EXPECT_EQ(grass_begin_frame(contexts.mono, &stereo), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(contexts.log.find("view_mask 0 (a mono pass)"), std::string::npos) << contexts.log;
    contexts.log.clear();
    EXPECT_EQ(grass_begin_frame(contexts.stereo, &left), GRASS_ERROR_INVALID_STATE);
    EXPECT_NE(contexts.log.find("chains no grass_stereo_view_desc"), std::string::npos) << contexts.log;
    // The host's shadow maps: a multiview pass receives none (grass_shadow_receive_desc).
    grass_shadow_receive_desc shadow = grass_default_shadow_receive_desc();
    shadow.shadow_map = 7;      // never drawn: the view is refused
    shadow.vk_image_layout = 4; // VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
    second.next = &shadow;
    contexts.log.clear();
    EXPECT_EQ(grass_begin_frame(contexts.stereo, &stereo), GRASS_ERROR_UNSUPPORTED);
    EXPECT_NE(contexts.log.find("do not receive the host's shadow maps"), std::string::npos) << contexts.log;
    // The host's lights: a multiview pass is not lit by them (grass_view_lights_desc).
    grass_view_lights_desc lights = grass_default_view_lights_desc();
    second.next = &lights;
    contexts.log.clear();
    EXPECT_EQ(grass_begin_frame(contexts.stereo, &stereo), GRASS_ERROR_UNSUPPORTED);
    EXPECT_NE(contexts.log.find("grass_view_lights_desc, but the context draws into a multiview pass"),
              std::string::npos)
        << contexts.log;
    // A bad chain: the same extension twice.
    second.next = &second;
    contexts.log.clear();
    EXPECT_EQ(grass_begin_frame(contexts.stereo, &stereo), GRASS_ERROR_WRONG_STRUCT_TYPE);
    EXPECT_NE(contexts.log.find("view->next chain element 1"), std::string::npos) << contexts.log;
    // Nothing began: a good frame still can.
    second.next = nullptr;
    EXPECT_EQ(grass_begin_frame(contexts.stereo, &stereo), GRASS_SUCCESS) << contexts.log;
    EXPECT_EQ(grass_end_frame(contexts.stereo), GRASS_SUCCESS);

    grass_context_desc cd = contexts.desc();
    grass_vk_desc bad = host.vk_desc(0x5);
    grass_context* ctx = nullptr;
    contexts.log.clear();
    EXPECT_EQ(grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &bad, &ctx), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ctx, nullptr);
    EXPECT_NE(contexts.log.find("grass_vk_multiview_desc.view_mask is 0x5"), std::string::npos) << contexts.log;
    // The multiview desc chained twice (even with good masks) is refused, naming the type.
    grass_vk_desc twice = host.vk_desc(0x3);
    grass_vk_multiview_desc again = grass_default_vk_multiview_desc();
    again.view_mask = 0x3;
    const_cast<grass_vk_multiview_desc*>(static_cast<const grass_vk_multiview_desc*>(twice.next))->next = &again;
    contexts.log.clear();
    EXPECT_EQ(grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &twice, &ctx), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ctx, nullptr);
    EXPECT_NE(contexts.log.find("type 0x67720205 a second time"), std::string::npos) << contexts.log;
    // With the host objects chained too, in either order, stereo is accepted.
    grass_vk_host_objects_desc objects = grass_default_vk_host_objects_desc();
    grass_vk_desc both = host.vk_desc(0x3);
    objects.next = both.next;
    both.next = &objects;
    EXPECT_EQ(grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &both, &ctx), GRASS_SUCCESS) << contexts.log;
    grass_destroy_context(ctx);
}

// A grass_vk_depth_pass_desc (depth-only passes, grass_view_pass_desc) is checked as
// grass_vk_desc is: its depth format (required, and one the device can attach), sample count,
// a subpass without a render pass, chained twice, and with a stereo pass (depth views are
// mono) are refused naming the field and its value, and no context is made.
TEST_F(VkStereo, ABadDepthPassDescIsRefusedNamingTheField) {
    const auto refused = [this](const grass_vk_depth_pass_desc& depth, uint32_t view_mask, const char* message) {
        expect_refused(depth, view_mask, message);
    };
    grass_vk_depth_pass_desc depth = grass_default_vk_depth_pass_desc();
    EXPECT_EQ(depth.type, GRASS_STRUCT_TYPE_VK_DEPTH_PASS_DESC);
    EXPECT_EQ(depth.sample_count, 1u);
    refused(depth, 0, "grass_vk_depth_pass_desc.depth_format is 0 (VK_FORMAT_UNDEFINED)");
    depth.depth_format = kDepthFormat;
    depth.sample_count = 3;
    refused(depth, 0, "grass_vk_depth_pass_desc.sample_count is 3");
    depth.sample_count = 1;
    depth.subpass = 1;
    refused(depth, 0, "grass_vk_depth_pass_desc.subpass is 1 with render_pass 0");
    depth.subpass = 0;
    depth.depth_format = VK_FORMAT_R8G8B8A8_UNORM;
    refused(depth, 0, "grass_vk_depth_pass_desc.depth_format is 37, which the device");
    depth.depth_format = kDepthFormat;
    refused(depth, 0x3, "grass_vk_multiview_desc with view_mask 0x3; depth passes are drawn by mono contexts only");
    grass_vk_depth_pass_desc again = depth;
    depth.next = &again;
    refused(depth, 0, "type 0x67720206 a second time");
}

// A grass_vk_velocity_target_desc (motion vectors, grass_view_motion_desc) is checked as
// grass_vk_desc is: its attachment count, the velocity attachment among them, the formats of
// a dynamic-rendering pass, chained twice, and with a stereo pass (motion views are mono)
// are refused naming the field and its value, and no context is made.
TEST_F(VkStereo, ABadVelocityTargetDescIsRefusedNamingTheField) {
    const auto refused = [this](const grass_vk_velocity_target_desc& velocity, uint32_t view_mask,
                                const char* message) {
        expect_refused(velocity, view_mask, message); // host.vk_desc: dynamic rendering
    };
    grass_vk_velocity_target_desc velocity = grass_default_vk_velocity_target_desc();
    EXPECT_EQ(velocity.type, GRASS_STRUCT_TYPE_VK_VELOCITY_TARGET_DESC);
    EXPECT_EQ(velocity.color_attachment_count, 2u);
    EXPECT_EQ(velocity.velocity_attachment, 1u);
    refused(velocity, 0, "grass_vk_velocity_target_desc.color_formats[0] is 0 (VK_FORMAT_UNDEFINED)");
    velocity.color_formats[0] = VK_FORMAT_R16G16_SFLOAT;
    velocity.color_attachment_count = 1;
    refused(velocity, 0, "grass_vk_velocity_target_desc.color_attachment_count is 1");
    velocity.color_attachment_count = 9;
    refused(velocity, 0, "grass_vk_velocity_target_desc.color_attachment_count is 9");
    velocity.color_attachment_count = 2;
    velocity.velocity_attachment = 2;
    refused(velocity, 0, "grass_vk_velocity_target_desc.velocity_attachment is 2; it must be 1 to 1");
    velocity.velocity_attachment = 0;
    refused(velocity, 0, "grass_vk_velocity_target_desc.velocity_attachment is 0");
    velocity.velocity_attachment = 1;
    refused(velocity, 0x3,
            "grass_vk_multiview_desc with view_mask 0x3; motion vectors are drawn by mono contexts only");
    grass_vk_velocity_target_desc again = velocity;
    velocity.next = &again;
    refused(velocity, 0, "type 0x67720207 a second time");
}

} // namespace
} // namespace grass_test
