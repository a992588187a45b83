// The Vulkan viewer window: a GLFW window without a GL context; the viewer owns the instance
// (validation layers on when installed and asked for), the device, the swapchain (sRGB,
// recreated on resize), a render pass with a depth buffer (multisampled and resolved into
// the swapchain image when MSAA is on) and two frames in flight. grass records with
// grass_vk_prepare / grass_vk_record in that pass, after the host's ground and meshes
// and before the overlay; a screenshot copies the swapchain image before it is presented.
#include "ground.hpp"
#include "host_shaders.hpp"
#include "mesh_drawer_vk.hpp"
#include "vk_bootstrap.hpp"
#include "window.hpp"

#include <grass/grass_vk.h>

#include <vulkan/vulkan.h>
#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

namespace grass_viewer {

namespace {

constexpr uint32_t kFramesInFlight = 2;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

using grass_bootstrap::vk_error;
using Image = grass_bootstrap::VkImageParts;
using Buffer = grass_bootstrap::VkBufferParts; // host-visible, coherent, mapped

// What one frame in flight owns.
struct Frame {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence done = VK_NULL_HANDLE; // signalled when the GPU has finished the frame
    VkSemaphore acquired = VK_NULL_HANDLE;
    Buffer ground; // the ground's uniforms
    VkDescriptorSet ground_set = VK_NULL_HANDLE;
};

class VkWindow final : public Window {
public:
    explicit VkWindow(const WindowDesc& desc) : Window(desc) {}
    ~VkWindow() override;
    bool init(std::string* error);

    grass_backend backend() const override { return GRASS_BACKEND_VULKAN; }
    std::string device_name() const override { return properties_.deviceName; }
    grass_result create_context(const grass_context_desc& desc, grass_context** out) override;
    glm::mat4 projection(float fovy, float aspect, float near_m, float far_m) const override {
        glm::mat4 p = glm::perspectiveRH_ZO(fovy, aspect, near_m, far_m);
        p[1][1] = -p[1][1]; // clip y down
        return p;
    }
    bool set_samples(uint32_t samples, bool* contexts_stale, std::string* error) override;
    void wait_idle() override { vkDeviceWaitIdle(device_); }
    void overlay_new_frame() override { ImGui_ImplVulkan_NewFrame(); }
    grass_result draw_frame(grass_context* ctx, const grass_view_desc& view, ImDrawData* overlay,
                            grass_host::Image* screenshot, std::string* error) override;

private:
    bool create_instance(std::string* error);
    bool pick_device(std::string* error);
    bool create_device(std::string* error);
    bool create_frames(std::string* error);
    bool create_swapchain(std::string* error);
    void destroy_swapchain();
    bool create_render_pass(std::string* error);
    bool create_targets(std::string* error); // depth, MSAA colour, framebuffers
    void destroy_targets();
    bool create_ground_pipeline(std::string* error);
    bool create_meshes(std::string* error); // the mesh drawer, for the current render pass
    bool start_overlay(std::string* error);
    void stop_overlay();
    bool create_image(VkFormat format, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                      VkImageAspectFlags aspect, Image* out, std::string* error);
    void destroy_image(Image* image);
    bool create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, Buffer* out, std::string* error);
    void destroy_buffer(Buffer* buffer);
    bool submit_once(void (*record)(VkCommandBuffer), std::string* error);
    void record_copy(VkCommandBuffer cmd, uint32_t image_index);
    void read_copy(grass_host::Image* out) const;
    static void on_message(void* log, const std::string& line) { static_cast<ValidationLog*>(log)->add(line); }

    grass_bootstrap::VkMessageSink sink_{&VkWindow::on_message, desc_.validation_log};
    grass_bootstrap::VkBootInstance instance_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_{};
    VkDevice device_ = VK_NULL_HANDLE;
    uint32_t family_ = 0;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    Frame frames_[kFramesInFlight];
    uint32_t frame_ = 0;

    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkSurfaceFormatKHR format_{};
    VkExtent2D extent_{};
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkSemaphore> rendered_; // per swapchain image: the frame's drawing is done
    bool swapchain_stale_ = false;
    bool can_copy_ = false; // the swapchain images allow transfers (screenshots)

    VkRenderPass render_pass_ = VK_NULL_HANDLE;
    Image depth_, msaa_color_;
    std::vector<VkFramebuffer> framebuffers_;

    VkDescriptorSetLayout ground_set_layout_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE; // the ground's sets and the overlay's font
    VkPipelineLayout ground_layout_ = VK_NULL_HANDLE;
    VkPipeline ground_pipeline_ = VK_NULL_HANDLE;
    std::unique_ptr<grass_host::VkMeshDrawer> meshes_; // the scene's host meshes (glTF)
    bool overlay_glfw_ = false, overlay_vk_ = false;

    Buffer readback_;
};

// ---- Creation ------------------------------------------------------------------------------

bool VkWindow::init(std::string* error) {
    if (!glfwVulkanSupported()) {
        *error = "GLFW finds no Vulkan loader";
        return false;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    if (!open("grass-viewer (Vulkan)", error) || !create_instance(error)) return false;
    VkResult r = glfwCreateWindowSurface(instance_.handle(), window_, nullptr, &surface_);
    if (r != VK_SUCCESS) {
        *error = vk_error("glfwCreateWindowSurface", r);
        return false;
    }
    return pick_device(error) && create_device(error) && create_frames(error) && create_swapchain(error) &&
           create_render_pass(error) && create_targets(error) && create_ground_pipeline(error) &&
           create_meshes(error) && start_overlay(error);
}

// Validation layers on when installed and asked for.
bool VkWindow::create_instance(std::string* error) {
    uint32_t count = 0;
    const char** glfw_extensions = glfwGetRequiredInstanceExtensions(&count);
    grass_bootstrap::VkInstanceDesc desc;
    desc.application = "grass-viewer";
    desc.validation = desc_.validation;
    desc.extensions.assign(glfw_extensions, glfw_extensions + count);
    desc.sink = &sink_;
    return instance_.create(desc, error);
}

// The first device with a queue family that draws and presents to the window.
bool VkWindow::pick_device(std::string* error) {
    for (VkPhysicalDevice d : grass_bootstrap::physical_devices(instance_.handle())) {
        vkGetPhysicalDeviceProperties(d, &properties_);
        if (properties_.apiVersion < VK_API_VERSION_1_1) continue;
        const std::vector<VkQueueFamilyProperties> families = grass_bootstrap::queue_families(d);
        for (uint32_t i = 0; i < families.size(); ++i) {
            VkBool32 present = VK_FALSE;
            vkGetPhysicalDeviceSurfaceSupportKHR(d, i, surface_, &present);
            if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && present) {
                physical_ = d;
                family_ = i;
                vkGetPhysicalDeviceMemoryProperties(d, &memory_);
                return true;
            }
        }
    }
    *error = "no Vulkan 1.1 device draws and presents to the window";
    return false;
}

bool VkWindow::create_device(std::string* error) {
    return grass_bootstrap::create_device(physical_, family_, {VK_KHR_SWAPCHAIN_EXTENSION_NAME}, nullptr, &device_,
                                          &queue_, error) &&
           grass_bootstrap::create_command_pool(device_, family_, &pool_, error);
}

// Per frame in flight: a command buffer, its fence and semaphore, the ground's uniforms.
bool VkWindow::create_frames(std::string* error) {
    if (!grass_bootstrap::create_uniform_layouts(device_, &ground_set_layout_, &ground_layout_, error)) return false;
    const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kFramesInFlight},
                                           {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT; // the overlay frees its font's set
    pool.maxSets = kFramesInFlight + 1;
    pool.poolSizeCount = 2;
    pool.pPoolSizes = sizes;
    VkResult r = vkCreateDescriptorPool(device_, &pool, nullptr, &descriptor_pool_);
    for (Frame& f : frames_) {
        if (r == VK_SUCCESS) r = grass_bootstrap::allocate_command_buffer(device_, pool_, &f.cmd);
        VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        if (r == VK_SUCCESS) r = vkCreateFence(device_, &fence, nullptr, &f.done);
        VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        if (r == VK_SUCCESS) r = vkCreateSemaphore(device_, &semaphore, nullptr, &f.acquired);
        if (r == VK_SUCCESS) {
            r = grass_bootstrap::allocate_descriptor_set(device_, descriptor_pool_, ground_set_layout_, &f.ground_set);
        }
        if (r != VK_SUCCESS) break;
        if (!create_buffer(sizeof(grass_host::GroundUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &f.ground, error)) {
            return false;
        }
        grass_bootstrap::write_uniform_descriptor(device_, f.ground_set, f.ground.buffer,
                                                  sizeof(grass_host::GroundUniforms));
    }
    if (r != VK_SUCCESS) *error = vk_error("creating the frames in flight", r);
    return r == VK_SUCCESS;
}

// An sRGB swapchain of the window's size; the render targets follow it.
bool VkWindow::create_swapchain(std::string* error) {
    VkSurfaceCapabilitiesKHR caps{};
    vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical_, surface_, &caps);
    uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(physical_, surface_, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(physical_, surface_, &count, formats.data());
    format_.format = VK_FORMAT_UNDEFINED;
    for (const VkSurfaceFormatKHR& f : formats) {
        if ((f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) &&
            f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR && format_.format == VK_FORMAT_UNDEFINED) {
            format_ = f;
        }
    }
    if (format_.format == VK_FORMAT_UNDEFINED) {
        *error = "the window's surface offers no B8G8R8A8_SRGB or R8G8B8A8_SRGB format";
        return false;
    }
    vkGetPhysicalDeviceSurfacePresentModesKHR(physical_, surface_, &count, nullptr);
    std::vector<VkPresentModeKHR> modes(count);
    vkGetPhysicalDeviceSurfacePresentModesKHR(physical_, surface_, &count, modes.data());
    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR; // always there: vsync
    if (!desc_.vsync) {
        for (VkPresentModeKHR m : modes) {
            if (m == VK_PRESENT_MODE_IMMEDIATE_KHR ||
                (m == VK_PRESENT_MODE_MAILBOX_KHR && mode == VK_PRESENT_MODE_FIFO_KHR))
                mode = m;
        }
    }
    extent_ = caps.currentExtent.width != 0xFFFFFFFFu ? caps.currentExtent : VkExtent2D{width_, height_};
    width_ = extent_.width;
    height_ = extent_.height;
    if (width_ == 0 || height_ == 0) return true; // minimised: no swapchain until it has a size
    can_copy_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = std::max(caps.minImageCount, 2u);
    if (caps.maxImageCount) info.minImageCount = std::min(info.minImageCount + 1, caps.maxImageCount);
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (can_copy_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = mode;
    info.clipped = VK_TRUE;
    VkResult r = vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain_);
    if (r != VK_SUCCESS) {
        *error = vk_error("vkCreateSwapchainKHR", r);
        return false;
    }
    vkGetSwapchainImagesKHR(device_, swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(device_, swapchain_, &count, images_.data());
    for (VkImage image : images_) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = image;
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format_.format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        views_.push_back(VK_NULL_HANDLE);
        rendered_.push_back(VK_NULL_HANDLE);
        VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        r = vkCreateImageView(device_, &view, nullptr, &views_.back());
        if (r == VK_SUCCESS) r = vkCreateSemaphore(device_, &semaphore, nullptr, &rendered_.back());
        if (r != VK_SUCCESS) {
            *error = vk_error("creating the swapchain's views", r);
            return false;
        }
    }
    swapchain_stale_ = false;
    return true;
}

void VkWindow::destroy_swapchain() {
    for (VkImageView v : views_) vkDestroyImageView(device_, v, nullptr);
    for (VkSemaphore s : rendered_) vkDestroySemaphore(device_, s, nullptr);
    views_.clear();
    rendered_.clear();
    images_.clear();
    if (swapchain_) vkDestroySwapchainKHR(device_, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

// Colour (the swapchain image, or a multisampled image resolved into it) and depth; the
// swapchain image ends ready to present.
bool VkWindow::create_render_pass(std::string* error) {
    grass_bootstrap::VkPassDesc pass;
    pass.color_format = format_.format;
    pass.depth_format = kDepthFormat;
    pass.samples = static_cast<VkSampleCountFlagBits>(samples_);
    pass.color_final = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    VkSubpassDependency* dependencies = pass.dependencies;
    // The acquired image and the last frame's depth are free before this pass writes them.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    dependencies[0].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    // A screenshot's copy of the presented image comes after the pass's writes (and resolve).
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    return grass_bootstrap::create_render_pass(device_, pass, &render_pass_, error);
}

bool VkWindow::create_targets(std::string* error) {
    if (!swapchain_) return true;
    const auto samples = static_cast<VkSampleCountFlagBits>(samples_);
    if (!create_image(kDepthFormat, samples, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT,
                      &depth_, error)) {
        return false;
    }
    if (samples_ > 1 && !create_image(format_.format, samples,
                                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                                      VK_IMAGE_ASPECT_COLOR_BIT, &msaa_color_, error)) {
        return false;
    }
    for (VkImageView view : views_) {
        const VkImageView single[2] = {view, depth_.view};
        const VkImageView resolved[3] = {msaa_color_.view, depth_.view, view};
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = render_pass_;
        fb.attachmentCount = samples_ > 1 ? 3 : 2;
        fb.pAttachments = samples_ > 1 ? resolved : single;
        fb.width = extent_.width;
        fb.height = extent_.height;
        fb.layers = 1;
        framebuffers_.push_back(VK_NULL_HANDLE);
        const VkResult r = vkCreateFramebuffer(device_, &fb, nullptr, &framebuffers_.back());
        if (r != VK_SUCCESS) {
            *error = vk_error("vkCreateFramebuffer", r);
            return false;
        }
    }
    return true;
}

void VkWindow::destroy_targets() {
    for (VkFramebuffer fb : framebuffers_) vkDestroyFramebuffer(device_, fb, nullptr);
    framebuffers_.clear();
    destroy_image(&msaa_color_);
    destroy_image(&depth_);
}

// The headless hosts' ground (test_hosts/shaders/ground.*) in this render pass.
bool VkWindow::create_ground_pipeline(std::string* error) {
    grass_host::VkHostPipelineDesc desc;
    desc.vertex_code = grass_host_spirv::ground_vert;
    desc.vertex_code_size = grass_host_spirv::ground_vert_size;
    desc.fragment_code = grass_host_spirv::ground_frag;
    desc.fragment_code_size = grass_host_spirv::ground_frag_size;
    desc.layout = ground_layout_;
    desc.target.render_pass = render_pass_;
    desc.target.samples = static_cast<VkSampleCountFlagBits>(samples_);
    const VkResult r = grass_host::create_host_pipeline(device_, desc, &ground_pipeline_);
    if (r != VK_SUCCESS) *error = vk_error("creating the ground's pipeline", r);
    return r == VK_SUCCESS;
}

void check_overlay_result(VkResult r) {
    if (r != VK_SUCCESS)
        std::fprintf(stderr, "grass-viewer: the overlay's Vulkan call failed with VkResult %d\n", int(r));
}

// ImGui's Vulkan backend, in this render pass, with its font uploaded.
bool VkWindow::start_overlay(std::string* error) {
    if (!overlay_glfw_) overlay_glfw_ = ImGui_ImplGlfw_InitForVulkan(window_, true);
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = instance_.handle();
    info.PhysicalDevice = physical_;
    info.Device = device_;
    info.QueueFamily = family_;
    info.Queue = queue_;
    info.DescriptorPool = descriptor_pool_;
    info.MinImageCount = 2;
    info.ImageCount = std::max<uint32_t>(uint32_t(images_.size()), kFramesInFlight);
    info.MSAASamples = static_cast<VkSampleCountFlagBits>(samples_);
    info.CheckVkResultFn = check_overlay_result;
    overlay_vk_ = overlay_glfw_ && ImGui_ImplVulkan_Init(&info, render_pass_);
    if (!overlay_vk_) {
        *error = "the overlay (ImGui's GLFW and Vulkan backends) cannot start";
        return false;
    }
    if (!submit_once([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); }, error)) return false;
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    return true;
}

void VkWindow::stop_overlay() {
    if (overlay_vk_) ImGui_ImplVulkan_Shutdown();
    overlay_vk_ = false;
}

bool VkWindow::submit_once(void (*record)(VkCommandBuffer), std::string* error) {
    VkCommandBuffer cmd = frames_[0].cmd;
    vkWaitForFences(device_, 1, &frames_[0].done, VK_TRUE, UINT64_MAX);
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VkResult r = vkBeginCommandBuffer(cmd, &begin);
    if (r == VK_SUCCESS) {
        record(cmd);
        r = vkEndCommandBuffer(cmd);
    }
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    if (r == VK_SUCCESS) r = vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE);
    if (r == VK_SUCCESS) r = vkQueueWaitIdle(queue_);
    if (r != VK_SUCCESS) *error = vk_error("a one-time submission", r);
    return r == VK_SUCCESS;
}

bool VkWindow::create_image(VkFormat format, VkSampleCountFlagBits samples, VkImageUsageFlags usage,
                            VkImageAspectFlags aspect, Image* out, std::string* error) {
    grass_bootstrap::VkImageDesc desc;
    desc.extent = extent_;
    desc.format = format;
    desc.samples = samples;
    desc.usage = usage;
    desc.aspect = aspect;
    return grass_bootstrap::create_image(device_, memory_, desc, out, error);
}

void VkWindow::destroy_image(Image* image) { grass_bootstrap::destroy_image(device_, image); }

// A host-visible, coherent, mapped buffer.
bool VkWindow::create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, Buffer* out, std::string* error) {
    return grass_bootstrap::create_buffer(device_, memory_, size, usage,
                                          VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                                          out, error);
}

void VkWindow::destroy_buffer(Buffer* buffer) { grass_bootstrap::destroy_buffer(device_, buffer); }

VkWindow::~VkWindow() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        stop_overlay();
        if (overlay_glfw_) ImGui_ImplGlfw_Shutdown();
        destroy_targets();
        destroy_swapchain();
        meshes_.reset();
        destroy_buffer(&readback_);
        for (Frame& f : frames_) {
            destroy_buffer(&f.ground);
            if (f.done) vkDestroyFence(device_, f.done, nullptr);
            if (f.acquired) vkDestroySemaphore(device_, f.acquired, nullptr);
        }
        if (ground_pipeline_) vkDestroyPipeline(device_, ground_pipeline_, nullptr);
        if (ground_layout_) vkDestroyPipelineLayout(device_, ground_layout_, nullptr);
        if (descriptor_pool_) vkDestroyDescriptorPool(device_, descriptor_pool_, nullptr);
        if (ground_set_layout_) vkDestroyDescriptorSetLayout(device_, ground_set_layout_, nullptr);
        if (render_pass_) vkDestroyRenderPass(device_, render_pass_, nullptr);
        if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
    }
    if (surface_) vkDestroySurfaceKHR(instance_.handle(), surface_, nullptr);
    instance_.destroy();
}

// ---- The grass context and the sample count -------------------------------------------------

grass_result VkWindow::create_context(const grass_context_desc& desc, grass_context** out) {
    grass_vk_desc vk = grass_default_vk_desc();
    vk.get_instance_proc_addr = vkGetInstanceProcAddr; // PFN_vkGetInstanceProcAddr itself: no cast
    vk.instance = instance_.handle();
    vk.physical_device = physical_;
    vk.device = device_;
    vk.queue_family = family_;
    vk.render_pass = reinterpret_cast<uint64_t>(render_pass_);
    vk.subpass = 0;
    vk.color_format = format_.format;
    vk.depth_format = kDepthFormat;
    vk.sample_count = samples_;
    vk.frames_in_flight = kFramesInFlight;
    return grass_vk_create_context(GRASS_HEADER_VERSION, &desc, &vk, out);
}

// A new render pass for the new count: the pipelines made for the old one (the ground's, the
// overlay's, grass's) are made again.
bool VkWindow::set_samples(uint32_t samples, bool* contexts_stale, std::string* error) {
    const VkSampleCountFlags supported =
        properties_.limits.framebufferColorSampleCounts & properties_.limits.framebufferDepthSampleCounts;
    if (!(supported & samples)) {
        *error = "the device cannot render with " + std::to_string(samples) + " samples";
        return false;
    }
    vkDeviceWaitIdle(device_);
    stop_overlay();
    destroy_targets();
    vkDestroyPipeline(device_, ground_pipeline_, nullptr);
    vkDestroyRenderPass(device_, render_pass_, nullptr);
    ground_pipeline_ = VK_NULL_HANDLE;
    render_pass_ = VK_NULL_HANDLE;
    meshes_.reset();
    samples_ = samples;
    *contexts_stale = true;
    return create_render_pass(error) && create_targets(error) && create_ground_pipeline(error) &&
           create_meshes(error) && start_overlay(error);
}

// The host meshes' pipeline is made for the render pass (its sample count): made again with it.
// Push constants carry each draw's data, so frames in flight share the drawer.
bool VkWindow::create_meshes(std::string* error) {
    if (desc_.scene.meshes.empty()) return true;
    grass_host::VkPassTarget target;
    target.render_pass = render_pass_;
    target.color_format = format_.format;
    target.depth_format = kDepthFormat;
    target.samples = VkSampleCountFlagBits(samples_);
    meshes_ = std::make_unique<grass_host::VkMeshDrawer>();
    return meshes_->init(physical_, device_, target, desc_.scene.meshes, error);
}

// ---- A frame -----------------------------------------------------------------------------

void VkWindow::record_copy(VkCommandBuffer cmd, uint32_t image_index) {
    VkImageMemoryBarrier to_copy{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    to_copy.srcAccessMask = 0; // made available by the pass's dependency to VK_SUBPASS_EXTERNAL
    to_copy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    to_copy.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    to_copy.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    to_copy.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_copy.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_copy.image = images_[image_index];
    to_copy.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr,
                         1, &to_copy);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(cmd, images_[image_index], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1,
                           &region);
    VkImageMemoryBarrier to_present = to_copy;
    to_present.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    to_present.dstAccessMask = 0;
    to_present.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    to_present.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    const VkBufferMemoryBarrier to_host = grass_bootstrap::host_read_barrier(readback_.buffer);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &to_host,
                         1, &to_present);
}

// The copied swapchain image as RGBA8 (swizzled from BGRA), top row first.
void VkWindow::read_copy(grass_host::Image* out) const {
    out->width = extent_.width;
    out->height = extent_.height;
    out->rgba.resize(size_t(extent_.width) * extent_.height * 4);
    const auto* src = static_cast<const uint8_t*>(readback_.mapped);
    const bool bgra = format_.format == VK_FORMAT_B8G8R8A8_SRGB;
    for (size_t i = 0; i < out->rgba.size(); i += 4) {
        out->rgba[i + 0] = src[i + (bgra ? 2 : 0)];
        out->rgba[i + 1] = src[i + 1];
        out->rgba[i + 2] = src[i + (bgra ? 0 : 2)];
        out->rgba[i + 3] = 255; // opaque, as presented
    }
}

grass_result VkWindow::draw_frame(grass_context* ctx, const grass_view_desc& view, ImDrawData* overlay,
                                  grass_host::Image* screenshot, std::string* error) {
    auto host_failure = [&](const char* call, VkResult r) {
        *error = vk_error(call, r);
        return GRASS_ERROR_BACKEND;
    };
    Frame& f = frames_[frame_];
    // The GPU has finished this frame's previous use (frames_in_flight frames ago), as grass
    // requires before grass_begin_frame.
    vkWaitForFences(device_, 1, &f.done, VK_TRUE, UINT64_MAX);
    uint32_t image = 0;
    for (int attempt = 0;; ++attempt) {
        if (width_ != extent_.width || height_ != extent_.height || swapchain_stale_ || !swapchain_) {
            vkDeviceWaitIdle(device_);
            destroy_targets();
            destroy_swapchain();
            if (!create_swapchain(error) || !create_targets(error)) return GRASS_ERROR_BACKEND;
            if (swapchain_) ImGui_ImplVulkan_SetMinImageCount(2);
        }
        if (!swapchain_) return GRASS_SUCCESS; // minimised
        const VkResult r = vkAcquireNextImageKHR(device_, swapchain_, UINT64_MAX, f.acquired, VK_NULL_HANDLE, &image);
        if (r == VK_SUCCESS || r == VK_SUBOPTIMAL_KHR) break;
        if (r != VK_ERROR_OUT_OF_DATE_KHR || attempt > 2) return host_failure("vkAcquireNextImageKHR", r);
        swapchain_stale_ = true;
    }
    if (screenshot && !can_copy_) {
        *error = "the swapchain's images cannot be copied: no screenshot";
        screenshot = nullptr;
    }
    const VkDeviceSize bytes = VkDeviceSize(extent_.width) * extent_.height * 4;
    if (screenshot && readback_.size < bytes) {
        vkDeviceWaitIdle(device_);
        destroy_buffer(&readback_);
        if (!create_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, &readback_, error)) return GRASS_ERROR_BACKEND;
    }
    vkResetFences(device_, 1, &f.done);
    vkResetCommandBuffer(f.cmd, 0);
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(f.cmd, &begin);

    // grass plans, records its uploads outside the pass and its draws inside, after the ground.
    grass_result result = grass_begin_frame(ctx, &view);
    const bool begun = result == GRASS_SUCCESS;
    if (begun) {
        grass_vk_prepare_desc prepare = grass_default_vk_prepare_desc();
        prepare.command_buffer = f.cmd;
        result = grass_vk_prepare(ctx, &prepare);
    }
    VkClearValue clears[2] = {};
    for (int c = 0; c < 4; ++c) clears[0].color.float32[c] = desc_.scene.clear_color[c];
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    pass.renderPass = render_pass_;
    pass.framebuffer = framebuffers_[image];
    pass.renderArea = {{0, 0}, extent_};
    pass.clearValueCount = 2;
    pass.pClearValues = clears;
    vkCmdBeginRenderPass(f.cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
    if (desc_.scene.ground) {
        const grass_host::GroundUniforms u = grass_host::make_ground_uniforms(view, desc_.scene);
        std::memcpy(f.ground.mapped, &u, sizeof(u));
        const VkViewport viewport{0.0f, 0.0f, float(extent_.width), float(extent_.height), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, extent_};
        vkCmdBindPipeline(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ground_pipeline_);
        vkCmdSetViewport(f.cmd, 0, 1, &viewport);
        vkCmdSetScissor(f.cmd, 0, 1, &scissor);
        vkCmdBindDescriptorSets(f.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ground_layout_, 0, 1, &f.ground_set, 0,
                                nullptr);
        vkCmdDraw(f.cmd, grass_host::kGroundVertexCount, 1, 0, 0);
    }
    if (meshes_) meshes_->record(f.cmd, view, extent_.width, extent_.height); // into the depth grass shares
    if (result == GRASS_SUCCESS) {
        grass_vk_record_desc record = grass_default_vk_record_desc();
        record.command_buffer = f.cmd;
        result = grass_vk_record(ctx, &record);
    }
    if (overlay) ImGui_ImplVulkan_RenderDrawData(overlay, f.cmd);
    vkCmdEndRenderPass(f.cmd);
    if (screenshot) record_copy(f.cmd, image);
    VkResult r = vkEndCommandBuffer(f.cmd);

    const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &f.acquired;
    submit.pWaitDstStageMask = &wait_stage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &f.cmd;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &rendered_[image];
    if (r == VK_SUCCESS) r = vkQueueSubmit(queue_, 1, &submit, f.done);
    if (begun) {
        const grass_result end = grass_end_frame(ctx);
        if (result == GRASS_SUCCESS) result = end;
    }
    if (r != VK_SUCCESS) return host_failure("vkQueueSubmit", r);
    if (screenshot) {
        vkWaitForFences(device_, 1, &f.done, VK_TRUE, UINT64_MAX);
        read_copy(screenshot);
    }
    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &rendered_[image];
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_;
    present.pImageIndices = &image;
    r = vkQueuePresentKHR(queue_, &present);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        swapchain_stale_ = true;
    } else if (r != VK_SUCCESS) {
        return host_failure("vkQueuePresentKHR", r);
    }
    frame_ = (frame_ + 1) % kFramesInFlight;
    if (result != GRASS_SUCCESS) *error = grass_get_last_error(ctx);
    return result;
}

} // namespace

std::unique_ptr<Window> create_vk_window(const WindowDesc& desc, std::string* error) {
    auto window = std::make_unique<VkWindow>(desc);
    if (!window->init(error)) return nullptr;
    return window;
}

} // namespace grass_viewer
