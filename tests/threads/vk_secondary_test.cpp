// Recording views into the host's secondary command buffers on worker threads (grass_vk.h,
// "Threads"; docs/integration.md, "Threads and secondary command buffers"): a main view and
// three orthographic "cascade" views, one grass context each on one VkDevice, each with its
// own field. Each worker thread (its own command pool) plans its view, records its uploads
// into a primary of its own and its draws into a secondary begun with the pass's
// inheritance (render pass + subpass, or VkCommandBufferInheritanceRenderingInfo); the main
// thread executes the four secondaries in one pass (VK_SUBPASS_CONTENTS_SECONDARY_COMMAND_BUFFERS
// or VK_RENDERING_CONTENTS_SECONDARY_COMMAND_BUFFERS_BIT) and submits. The picture must be the
// one of the same views recorded serially into a primary, pixel for pixel, with the
// validation layers silent; under ThreadSanitizer (GRASS_TSAN=ON, scripts/test.sh) it must
// stay silent too.
//
// The cascades are orthographic, which grass culls wrongly today (issue 33: the cone cull
// has its apex at the camera): the test compares threaded with serial recording of the same
// views, so whatever grass draws for them, it must draw the same.
#include "driver_residency.hpp"
#include "vk_bootstrap.hpp"

#include <grass/grass.h>
#include <grass/grass_vk.h>

#include <vulkan/vulkan.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace {

using grass_bootstrap::vk_error;

constexpr int kViews = 4;
constexpr uint32_t kQuadrant = 64;        // each view's viewport: a quadrant of the target
constexpr uint32_t kSize = 2 * kQuadrant; // the target, square
constexpr int kFrames = 2;                // the first uploads, the second draws from the ring's next slot
constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr float kSky[4] = {0.55f, 0.70f, 0.90f, 1.0f};

enum class PassKind { kRenderPass, kDynamicRendering };

// Validation messages, which may come from any thread.
struct Messages {
    std::mutex mutex;
    std::string log;
    uint32_t count = 0;
    static void add(void* user, const std::string& line) {
        auto* m = static_cast<Messages*>(user);
        const std::lock_guard<std::mutex> lock(m->mutex);
        m->count += 1;
        m->log += line + "\n";
    }
};

// One view: its grass context and the worker's command pool with a primary (uploads) and a
// secondary (draws).
struct View {
    grass_context* ctx = nullptr;
    grass_view_desc desc{};
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer prepare = VK_NULL_HANDLE;
    VkCommandBuffer draws = VK_NULL_HANDLE;
    std::string error;
};

// The view of view k in its quadrant: 0 a perspective camera looking over the field, 1-3
// orthographic cameras 20 m straight above its centre, 1, 2 and 4 m half-widths. Vulkan
// projections: clip z 0..1, y down.
grass_view_desc view_desc(int k) {
    grass_view_desc v = grass_default_view_desc();
    v.viewport[0] = int32_t((k % 2) * kQuadrant);
    v.viewport[1] = int32_t((k / 2) * kQuadrant);
    v.viewport[2] = v.viewport[3] = int32_t(kQuadrant);
    std::memset(v.projection, 0, sizeof(v.projection));
    const float n = 0.1f, f = 100.0f;
    if (k == 0) {
        const double eye[3] = {2.0, 1.2, -0.5}, look[3] = {2.0, 0.0, 2.0};
        double fw[3], len = 0.0;
        for (int i = 0; i < 3; ++i) fw[i] = look[i] - eye[i], len += fw[i] * fw[i];
        for (double& c : fw) c /= std::sqrt(len);
        double r[3] = {-fw[2], 0.0, fw[0]}; // fw x (0, 1, 0)
        const double rl = std::sqrt(r[0] * r[0] + r[2] * r[2]);
        r[0] /= rl, r[2] /= rl;
        const double u[3] = {r[1] * fw[2] - r[2] * fw[1], r[2] * fw[0] - r[0] * fw[2], r[0] * fw[1] - r[1] * fw[0]};
        for (int i = 0; i < 3; ++i) {
            v.view[4 * i + 0] = float(r[i]);
            v.view[4 * i + 1] = float(u[i]);
            v.view[4 * i + 2] = float(-fw[i]);
            v.view[4 * i + 3] = 0.0f;
        }
        v.view[15] = 1.0f;
        std::memcpy(v.camera_position, eye, sizeof(eye));
        const float t = 1.0f / std::tan(0.5f * 50.0f * 3.14159265f / 180.0f);
        v.projection[0] = t;
        v.projection[5] = -t;
        v.projection[10] = f / (n - f);
        v.projection[11] = -1.0f;
        v.projection[14] = n * f / (n - f);
        return v;
    }
    const float down[16] = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1}; // looking straight down
    std::memcpy(v.view, down, sizeof(down));
    v.camera_position[0] = v.camera_position[2] = 2.0;
    v.camera_position[1] = 20.0;
    const float half = float(1 << k) * 0.5f; // 1, 2, 4 m
    v.projection[0] = 1.0f / half;
    v.projection[5] = -1.0f / half;
    v.projection[10] = -1.0f / (f - n);
    v.projection[14] = -n / (f - n);
    v.projection[15] = 1.0f;
    return v;
}

class VkSecondaryTest : public ::testing::TestWithParam<PassKind> {
protected:
    void SetUp() override;
    void TearDown() override;
    bool dynamic() const { return GetParam() == PassKind::kDynamicRendering; }

    bool create_device(std::string* error);
    bool create_target(std::string* error);
    // A context, a patch and a field of its own on the shared device.
    void make_context(View* view) const;
    // The pass around the draws, in `cmd`: begun with the given contents, ended with the
    // colour image in TRANSFER_SRC_OPTIMAL, then copied to the read-back buffer.
    void begin_pass(VkCommandBuffer cmd, bool secondaries) const;
    void end_pass_and_copy(VkCommandBuffer cmd) const;
    // A worker's frame: plan, uploads into its primary, draws into its secondary.
    void record_view(View* view) const;
    // kFrames frames of the four views; the last one's picture.
    std::vector<uint8_t> render(bool threaded);

    Messages messages_;
    grass_bootstrap::VkMessageSink sink_{&Messages::add, &messages_};
    grass_bootstrap::VkBootInstance instance_;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkPhysicalDeviceMemoryProperties memory_{};
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t family_ = 0;
    PFN_vkCmdBeginRendering begin_rendering_ = nullptr;
    PFN_vkCmdEndRendering end_rendering_ = nullptr;
    grass_bootstrap::VkImageParts color_, depth_;
    grass_bootstrap::VkBufferParts readback_;
    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    VkCommandPool main_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer main_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    View views_[kViews];
};

void VkSecondaryTest::SetUp() {
    std::string error;
    grass_bootstrap::VkInstanceDesc desc;
    desc.application = "grass secondary command buffer test";
    desc.messenger_without_layer = true;
    desc.sink = &sink_;
    ASSERT_TRUE(instance_.create(desc, &error)) << error;
    ASSERT_TRUE(create_device(&error)) << error;
    ASSERT_TRUE(create_target(&error)) << error;
}

bool VkSecondaryTest::create_device(std::string* error) {
    const std::vector<VkPhysicalDevice> devices = grass_bootstrap::physical_devices(instance_.handle());
    if (devices.empty()) {
        *error = "no Vulkan physical device";
        return false;
    }
    physical_ = devices[0];
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(physical_, &properties);
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    const std::vector<VkQueueFamilyProperties> families = grass_bootstrap::queue_families(physical_);
    family_ = UINT32_MAX;
    for (uint32_t i = 0; i < families.size() && family_ == UINT32_MAX; ++i) {
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) family_ = i;
    }
    if (family_ == UINT32_MAX) {
        *error = "no graphics queue";
        return false;
    }
    // Dynamic rendering: Vulkan 1.3 core only (lavapipe has it).
    const bool core13 = instance_.api_version() >= VK_API_VERSION_1_3 && properties.apiVersion >= VK_API_VERSION_1_3;
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    if (core13) {
        VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        features.pNext = &features13;
        vkGetPhysicalDeviceFeatures2(physical_, &features);
    }
    if (dynamic() && features13.dynamicRendering != VK_TRUE) return true; // skipped: no device_
    VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    enable13.dynamicRendering = dynamic() ? VK_TRUE : VK_FALSE;
    if (!grass_bootstrap::create_device(physical_, family_, {}, dynamic() ? &enable13 : nullptr, &device_, &queue_,
                                        error)) {
        return false;
    }
    static const char* const kDrivers[] = {"libvulkan_", "libVkLayer_", nullptr};
    grass_host::keep_drivers_resident(kDrivers);
    if (dynamic()) {
        begin_rendering_ =
            reinterpret_cast<PFN_vkCmdBeginRendering>(vkGetDeviceProcAddr(device_, "vkCmdBeginRendering"));
        end_rendering_ = reinterpret_cast<PFN_vkCmdEndRendering>(vkGetDeviceProcAddr(device_, "vkCmdEndRendering"));
    }
    return true;
}

bool VkSecondaryTest::create_target(std::string* error) {
    if (!device_) return true; // skipped
    grass_bootstrap::VkImageDesc image;
    image.extent = {kSize, kSize};
    image.format = kColorFormat;
    image.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (!grass_bootstrap::create_image(device_, memory_, image, &color_, error)) return false;
    image.format = kDepthFormat;
    image.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    image.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    if (!grass_bootstrap::create_image(device_, memory_, image, &depth_, error)) return false;
    if (!grass_bootstrap::create_buffer(
            device_, memory_, VkDeviceSize(kSize) * kSize * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, &readback_, error)) {
        return false;
    }
    if (!grass_bootstrap::create_command_pool(device_, family_, &main_pool_, error)) return false;
    VkResult r = grass_bootstrap::allocate_command_buffer(device_, main_pool_, &main_);
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    if (r == VK_SUCCESS) r = vkCreateFence(device_, &fence, nullptr, &fence_);
    if (r != VK_SUCCESS) {
        *error = vk_error("vkAllocateCommandBuffers/vkCreateFence", r);
        return false;
    }
    for (View& v : views_) {
        if (!grass_bootstrap::create_command_pool(device_, family_, &v.pool, error)) return false;
        VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        info.commandPool = v.pool;
        info.commandBufferCount = 1;
        info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        r = vkAllocateCommandBuffers(device_, &info, &v.prepare);
        info.level = VK_COMMAND_BUFFER_LEVEL_SECONDARY;
        if (r == VK_SUCCESS) r = vkAllocateCommandBuffers(device_, &info, &v.draws);
        if (r != VK_SUCCESS) {
            *error = vk_error("vkAllocateCommandBuffers", r);
            return false;
        }
    }
    if (dynamic()) return true;

    grass_bootstrap::VkPassDesc pass;
    pass.color_format = kColorFormat;
    pass.depth_format = kDepthFormat;
    pass.color_final = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    // The previous frame's copy and attachment writes before this pass writes; the pass's
    // writes before the copy.
    pass.dependencies[0] = {VK_SUBPASS_EXTERNAL,
                            0,
                            VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                                VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                            0};
    pass.dependencies[1] = {0,
                            VK_SUBPASS_EXTERNAL,
                            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_PIPELINE_STAGE_TRANSFER_BIT,
                            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                            VK_ACCESS_TRANSFER_READ_BIT,
                            0};
    if (!grass_bootstrap::create_render_pass(device_, pass, &render_pass_, error)) return false;
    const VkImageView attachments[2] = {color_.view, depth_.view};
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = render_pass_;
    fb.attachmentCount = 2;
    fb.pAttachments = attachments;
    fb.width = fb.height = kSize;
    fb.layers = 1;
    r = vkCreateFramebuffer(device_, &fb, nullptr, &framebuffer_);
    if (r != VK_SUCCESS) *error = vk_error("vkCreateFramebuffer", r);
    return r == VK_SUCCESS;
}

void VkSecondaryTest::TearDown() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        for (View& v : views_) {
            if (v.ctx) grass_destroy_context(v.ctx);
            if (v.pool) vkDestroyCommandPool(device_, v.pool, nullptr);
        }
        if (fence_) vkDestroyFence(device_, fence_, nullptr);
        if (main_pool_) vkDestroyCommandPool(device_, main_pool_, nullptr);
        if (framebuffer_) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
        if (render_pass_) vkDestroyRenderPass(device_, render_pass_, nullptr);
        grass_bootstrap::destroy_buffer(device_, &readback_);
        grass_bootstrap::destroy_image(device_, &depth_);
        grass_bootstrap::destroy_image(device_, &color_);
        vkDestroyDevice(device_, nullptr);
    }
    instance_.destroy();
    EXPECT_EQ(messages_.count, 0u) << messages_.log;
}

void VkSecondaryTest::make_context(View* view) const {
    grass_vk_desc vk = grass_default_vk_desc();
    vk.get_instance_proc_addr = reinterpret_cast<grass_vk_get_instance_proc_addr_fn>(&vkGetInstanceProcAddr);
    vk.instance = instance_.handle();
    vk.physical_device = physical_;
    vk.device = device_;
    vk.queue_family = family_;
    vk.render_pass = reinterpret_cast<uint64_t>(render_pass_); // 0 for dynamic rendering
    vk.color_format = kColorFormat;
    vk.depth_format = kDepthFormat;
    const grass_context_desc cd = grass_default_context_desc();
    if (grass_vk_create_context(GRASS_HEADER_VERSION, &cd, &vk, &view->ctx) != GRASS_SUCCESS) {
        view->error = "grass_vk_create_context failed";
        return;
    }
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 96;
    grass_patch_id patch{};
    const grass_tier_desc tier{GRASS_TIER_GEOMETRY, 0};
    grass_lod_test band{};
    band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    band.end = 60.0f;
    grass_field_desc fd = grass_default_field_desc();
    fd.cells_x = fd.cells_z = 16; // 4 m x 4 m
    fd.tiers = &tier;
    fd.tier_count = 1;
    fd.lod_tests = &band;
    fd.lod_test_count = 1;
    grass_field_id field{};
    if (grass_create_patch(view->ctx, &pd, &patch) != GRASS_SUCCESS ||
        (fd.patch = patch, grass_create_field(view->ctx, &fd, &field)) != GRASS_SUCCESS) {
        view->error = grass_get_last_error(view->ctx);
    }
}

void VkSecondaryTest::begin_pass(VkCommandBuffer cmd, bool secondaries) const {
    VkClearValue clears[2] = {};
    std::memcpy(clears[0].color.float32, kSky, sizeof(kSky));
    clears[1].depthStencil = {1.0f, 0};
    const VkRect2D area{{0, 0}, {kSize, kSize}};
    if (!dynamic()) {
        VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        info.renderPass = render_pass_;
        info.framebuffer = framebuffer_;
        info.renderArea = area;
        info.clearValueCount = 2;
        info.pClearValues = clears;
        vkCmdBeginRenderPass(cmd, &info,
                             secondaries ? VK_SUBPASS_CONTENTS_SECONDARY_COMMAND_BUFFERS : VK_SUBPASS_CONTENTS_INLINE);
        return;
    }
    VkImageMemoryBarrier barriers[2] = {};
    for (VkImageMemoryBarrier& b : barriers) {
        b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
        b.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        b.newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        b.image = color_.image;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    }
    barriers[1].srcAccessMask = 0;
    barriers[1].newLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    barriers[1].dstAccessMask =
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    barriers[1].image = depth_.image;
    barriers[1].subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                             VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                         0, 0, nullptr, 0, nullptr, 2, barriers);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = color_.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue = clears[0];
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = depth_.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue = clears[1];
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.flags = secondaries ? VK_RENDERING_CONTENTS_SECONDARY_COMMAND_BUFFERS_BIT : 0;
    info.renderArea = area;
    info.layerCount = 1;
    info.colorAttachmentCount = 1;
    info.pColorAttachments = &color;
    info.pDepthAttachment = &depth;
    begin_rendering_(cmd, &info);
}

void VkSecondaryTest::end_pass_and_copy(VkCommandBuffer cmd) const {
    if (!dynamic()) {
        vkCmdEndRenderPass(cmd); // leaves the colour image in TRANSFER_SRC_OPTIMAL
    } else {
        end_rendering_(cmd);
        VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        b.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        b.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = color_.image;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                             nullptr, 0, nullptr, 1, &b);
    }
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {kSize, kSize, 1};
    vkCmdCopyImageToBuffer(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &region);
    const VkBufferMemoryBarrier b = grass_bootstrap::host_read_barrier(readback_.buffer);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &b, 0,
                         nullptr);
}

// On the view's worker thread: only its own context, command pool and command buffers.
void VkSecondaryTest::record_view(View* view) const {
    if (!view->ctx) make_context(view);
    if (!view->error.empty()) return;
    const auto fail = [&](const char* what) {
        view->error = std::string(what) + ": " + grass_get_last_error(view->ctx);
    };
    VkResult r = vkResetCommandPool(device_, view->pool, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (r == VK_SUCCESS) r = vkBeginCommandBuffer(view->prepare, &begin);
    if (r != VK_SUCCESS) {
        view->error = vk_error("vkBeginCommandBuffer (primary)", r);
        return;
    }
    if (grass_begin_frame(view->ctx, &view->desc) != GRASS_SUCCESS) return fail("grass_begin_frame");
    grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
    prepare.command_buffer = view->prepare;
    if (grass_vk_prepare(view->ctx, &prepare) != GRASS_SUCCESS) fail("grass_vk_prepare");
    r = vkEndCommandBuffer(view->prepare);
    if (r != VK_SUCCESS) view->error = vk_error("vkEndCommandBuffer (primary)", r);

    // The secondary inherits the pass: its render pass and subpass, or its formats.
    VkCommandBufferInheritanceRenderingInfo rendering{VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_RENDERING_INFO};
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachmentFormats = &kColorFormat;
    rendering.depthAttachmentFormat = kDepthFormat;
    rendering.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkCommandBufferInheritanceInfo inheritance{VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_INFO};
    inheritance.pNext = dynamic() ? &rendering : nullptr;
    inheritance.renderPass = render_pass_;
    inheritance.subpass = 0;
    inheritance.framebuffer = framebuffer_;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT | VK_COMMAND_BUFFER_USAGE_RENDER_PASS_CONTINUE_BIT;
    begin.pInheritanceInfo = &inheritance;
    r = vkBeginCommandBuffer(view->draws, &begin);
    if (r != VK_SUCCESS) {
        view->error = vk_error("vkBeginCommandBuffer (secondary)", r);
        return;
    }
    grass_vk_record_desc record = grass_default_vk_record_desc();
    record.command_buffer = view->draws;
    if (view->error.empty() && grass_vk_record(view->ctx, &record) != GRASS_SUCCESS) fail("grass_vk_record");
    r = vkEndCommandBuffer(view->draws);
    if (r != VK_SUCCESS && view->error.empty()) view->error = vk_error("vkEndCommandBuffer (secondary)", r);
}

std::vector<uint8_t> VkSecondaryTest::render(bool threaded) {
    for (int k = 0; k < kViews; ++k) {
        views_[k].desc = view_desc(k);
        // The first recording makes the contexts: serially on this thread, threaded each on
        // its worker (at the same time: pipelines and buffers made on one device at once).
        if (!threaded && !views_[k].ctx) make_context(&views_[k]);
    }
    for (int frame = 0; frame < kFrames; ++frame) {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        EXPECT_EQ(vkResetCommandPool(device_, main_pool_, 0), VK_SUCCESS);
        EXPECT_EQ(vkBeginCommandBuffer(main_, &begin), VK_SUCCESS);
        std::vector<VkCommandBuffer> submitted;
        if (threaded) {
            std::vector<std::thread> workers;
            for (View& v : views_) workers.emplace_back([this, &v] { record_view(&v); });
            for (std::thread& w : workers) w.join();
            VkCommandBuffer draws[kViews];
            for (int k = 0; k < kViews; ++k) {
                EXPECT_EQ(views_[k].error, "") << "view " << k;
                submitted.push_back(views_[k].prepare);
                draws[k] = views_[k].draws;
            }
            begin_pass(main_, true);
            vkCmdExecuteCommands(main_, kViews, draws);
        } else {
            for (View& v : views_) {
                EXPECT_EQ(grass_begin_frame(v.ctx, &v.desc), GRASS_SUCCESS) << grass_get_last_error(v.ctx);
                grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
                prepare.command_buffer = main_;
                EXPECT_EQ(grass_vk_prepare(v.ctx, &prepare), GRASS_SUCCESS) << grass_get_last_error(v.ctx);
            }
            begin_pass(main_, false);
            for (View& v : views_) {
                grass_vk_record_desc record = grass_default_vk_record_desc();
                record.command_buffer = main_;
                EXPECT_EQ(grass_vk_record(v.ctx, &record), GRASS_SUCCESS) << grass_get_last_error(v.ctx);
            }
        }
        end_pass_and_copy(main_);
        EXPECT_EQ(vkEndCommandBuffer(main_), VK_SUCCESS);
        submitted.push_back(main_); // after the workers' uploads, in submission order
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = uint32_t(submitted.size());
        submit.pCommandBuffers = submitted.data();
        EXPECT_EQ(vkQueueSubmit(queue_, 1, &submit, fence_), VK_SUCCESS);
        EXPECT_EQ(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), VK_SUCCESS);
        EXPECT_EQ(vkResetFences(device_, 1, &fence_), VK_SUCCESS);
        // The main thread closes the frames: a context may move between threads once the
        // host orders the calls (here the joins).
        for (View& v : views_) {
            if (v.ctx) {
                EXPECT_EQ(grass_end_frame(v.ctx), GRASS_SUCCESS);
            }
        }
    }
    const auto* bytes = static_cast<const uint8_t*>(readback_.mapped);
    return std::vector<uint8_t>(bytes, bytes + size_t(kSize) * kSize * 4);
}

TEST_P(VkSecondaryTest, FourViewsRecordedOnFourThreadsIntoSecondariesMatchSerialRecording) {
    if (!device_) GTEST_SKIP() << "the device has no Vulkan 1.3 dynamic rendering";
    // Threaded first, then serially through the same contexts (each made once: pipelines
    // are most of the test's time on lavapipe, the more so under ThreadSanitizer). Every
    // frame plans, uploads and records anew; the contexts' lasting data (patch, field) must
    // hold grass in every view, checked on the serial picture.
    const std::vector<uint8_t> threaded = render(true);
    const std::vector<uint8_t> serial = render(false);
    // Not a comparison of empty pictures: each quadrant shows grass (green over blue).
    for (int k = 0; k < kViews; ++k) {
        size_t grass = 0;
        const uint32_t x0 = (k % 2) * kQuadrant, y0 = (k / 2) * kQuadrant;
        for (uint32_t y = y0; y < y0 + kQuadrant; ++y) {
            for (uint32_t x = x0; x < x0 + kQuadrant; ++x) {
                const uint8_t* p = &serial[(size_t(y) * kSize + x) * 4];
                grass += p[1] > p[2] ? 1 : 0;
            }
        }
        EXPECT_GT(grass, size_t(kQuadrant) * kQuadrant / 10) << "view " << k << " shows grass";
    }
    size_t differ = 0;
    for (size_t p = 0; p < serial.size(); ++p) differ += serial[p] != threaded[p] ? 1 : 0;
    EXPECT_EQ(differ, 0u) << "bytes differ between serial and threaded recording";
}

INSTANTIATE_TEST_SUITE_P(Passes, VkSecondaryTest, ::testing::Values(PassKind::kRenderPass, PassKind::kDynamicRendering),
                         [](const auto& p) {
                             return p.param == PassKind::kRenderPass ? "RenderPass" : "DynamicRendering";
                         });

} // namespace
