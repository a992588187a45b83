// The Vulkan set-up every host writes the same way, written once: the instance with the
// validation layer and its messenger, the device lists, one-queue device creation, memory
// types, 2D images and mapped buffers. Used by the headless Vulkan host (test_hosts/host_vk.cpp),
// the viewer's Vulkan window (samples/viewer/window_vk.cpp) and the Vulkan mesh drawer.
// Hosts link the Vulkan loader; the library (backend_vk/) keeps its own device code, which
// hosts must not link.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace grass_bootstrap {

// "<call> failed with VkResult <n>".
std::string vk_error(const char* call, VkResult result);

// Where the validation messages go: one line a message, "[error] ..." or "[warning] ...".
struct VkMessageSink {
    void (*add)(void* user, const std::string& line) = nullptr;
    void* user = nullptr;
};

struct VkInstanceDesc {
    const char* application = "grass host";
    // Enable VK_LAYER_KHRONOS_validation when it is installed.
    bool validation = true;
    // Also use VK_EXT_debug_utils's messenger when the extension is there without the layer.
    bool messenger_without_layer = false;
    std::vector<const char*> extensions; // more instance extensions (a window system's)
    const VkMessageSink* sink = nullptr; // must outlive the instance
};

// An instance at Vulkan 1.3 when the loader has it, else 1.1, with a messenger for warnings
// and errors of every type (also during vkCreateInstance and vkDestroyInstance). It destroys
// both when it goes.
class VkBootInstance {
public:
    VkBootInstance() = default;
    ~VkBootInstance() { destroy(); }
    VkBootInstance(const VkBootInstance&) = delete;
    VkBootInstance& operator=(const VkBootInstance&) = delete;

    bool create(const VkInstanceDesc& desc, std::string* error);
    void destroy(); // the messenger, then the instance; the sink must still be there
    VkInstance handle() const { return instance_; }
    uint32_t api_version() const { return api_version_; }

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    uint32_t api_version_ = VK_API_VERSION_1_1;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
};

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance);
std::vector<VkQueueFamilyProperties> queue_families(VkPhysicalDevice device);
bool has_device_extension(VkPhysicalDevice device, const char* name);

// A device with one queue of `family` (priority 1), the given extensions and feature chain.
bool create_device(VkPhysicalDevice physical, uint32_t family, const std::vector<const char*>& extensions,
                   const void* features, VkDevice* device, VkQueue* queue, std::string* error);
// A pool whose command buffers can be reset one by one.
bool create_command_pool(VkDevice device, uint32_t family, VkCommandPool* out, std::string* error);
VkResult allocate_command_buffer(VkDevice device, VkCommandPool pool, VkCommandBuffer* out);

// The first memory type of `bits` that has every flag; false when none.
bool memory_type(const VkPhysicalDeviceMemoryProperties& memory, uint32_t bits, VkMemoryPropertyFlags flags,
                 uint32_t* out);
// Memory for `requirements` of a type with `flags`; VK_ERROR_FEATURE_NOT_PRESENT when no type fits.
VkResult allocate_memory(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory,
                         const VkMemoryRequirements& requirements, VkMemoryPropertyFlags flags, VkDeviceMemory* out);

// A 2D image (one level, optimal tiling) in device-local memory, with a view: of one layer,
// or a 2D array view of `layers` (a multiview pass's attachments: one layer per view).
struct VkImageParts {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};
struct VkImageDesc {
    VkExtent2D extent{};
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkImageUsageFlags usage = 0;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    uint32_t layers = 1;
};
bool create_image(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, const VkImageDesc& desc,
                  VkImageParts* out, std::string* error);
void destroy_image(VkDevice device, VkImageParts* image);

// A buffer in memory with `flags` (host-visible ones are mapped whole).
struct VkBufferParts {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    VkDeviceSize size = 0;
};
bool create_buffer(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, VkDeviceSize size,
                   VkBufferUsageFlags usage, VkMemoryPropertyFlags flags, VkBufferParts* out, std::string* error);
void destroy_buffer(VkDevice device, VkBufferParts* buffer);

// A barrier that makes a transfer's writes to `buffer` visible to the host (the read-back).
VkBufferMemoryBarrier host_read_barrier(VkBuffer buffer);

// A descriptor set layout of one uniform buffer at binding 0 (vertex and fragment stages) and
// a pipeline layout of that set: the ground's.
bool create_uniform_layouts(VkDevice device, VkDescriptorSetLayout* set_layout, VkPipelineLayout* layout,
                            std::string* error);
VkResult allocate_descriptor_set(VkDevice device, VkDescriptorPool pool, VkDescriptorSetLayout layout,
                                 VkDescriptorSet* out);
// Points binding 0 of `set` at `size` bytes of `buffer`.
void write_uniform_descriptor(VkDevice device, VkDescriptorSet set, VkBuffer buffer, VkDeviceSize size);

// The attachments of a one-subpass colour + depth pass (+ a single-sample resolve when
// multisampled): colour cleared, its final layout `color_final` (the resolve target's when
// multisampled), depth cleared and stored only when `keep_depth`, `depth_final` its final layout.
struct VkPassDesc {
    VkFormat color_format = VK_FORMAT_UNDEFINED;  // UNDEFINED: a depth-only pass (its one attachment, 0)
    VkFormat depth_format = VK_FORMAT_D32_SFLOAT; // UNDEFINED, single-sampled: the colour attachment alone
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkImageLayout color_final = VK_IMAGE_LAYOUT_UNDEFINED;
    bool keep_depth = false;
    VkImageLayout depth_final = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    VkSubpassDependency dependencies[2] = {}; // into and out of the pass
    const void* next = nullptr;               // VkRenderPassCreateInfo::pNext (a multiview pass's view masks)
    // Further colour attachments (colour attachments 1..), cleared, ending in color_final (an
    // extra target's pass). Single-sampled: the pass's attachments 2.., stored. Multisampled:
    // the pass's attachments 3.. (after the resolve target), each resolved into a single-sample
    // attachment after them all (3 + more_color_count..), as attachment 0 is into 2.
    const VkFormat* more_colors = nullptr;
    uint32_t more_color_count = 0; // at most 7, multisampled 3
};
bool create_render_pass(VkDevice device, const VkPassDesc& desc, VkRenderPass* out, std::string* error);

} // namespace grass_bootstrap
