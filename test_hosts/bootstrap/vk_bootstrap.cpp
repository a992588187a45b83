#include "vk_bootstrap.hpp"

#include <cstdio>
#include <cstring>

namespace grass_bootstrap {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    const auto* sink = static_cast<const VkMessageSink*>(user);
    if (sink && sink->add) {
        sink->add(sink->user,
                  std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "[error] " : "[warning] ") +
                      (data && data->pMessage ? data->pMessage : "(no message)"));
    }
    return VK_FALSE; // never abort the call
}

} // namespace

std::string vk_error(const char* call, VkResult result) {
    char text[128];
    std::snprintf(text, sizeof(text), "%s failed with VkResult %d", call, static_cast<int>(result));
    return text;
}

bool VkBootInstance::create(const VkInstanceDesc& desc, std::string* error) {
    uint32_t loader_version = VK_API_VERSION_1_0;
    vkEnumerateInstanceVersion(&loader_version);
    if (loader_version < VK_API_VERSION_1_1) {
        *error = "the Vulkan loader is older than 1.1";
        return false;
    }
    api_version_ = loader_version >= VK_API_VERSION_1_3 ? VK_API_VERSION_1_3 : VK_API_VERSION_1_1;

    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    bool validation = false;
    for (const VkLayerProperties& l : layers) {
        validation |= desc.validation && std::strcmp(l.layerName, kValidationLayer) == 0;
    }
    // The validation layer brings VK_EXT_debug_utils with it.
    bool debug_utils = validation;
    if (desc.messenger_without_layer) {
        count = 0;
        vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
        std::vector<VkExtensionProperties> extensions(count);
        vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
        for (const VkExtensionProperties& e : extensions) {
            debug_utils |= std::strcmp(e.extensionName, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) == 0;
        }
    }
    std::vector<const char*> extensions = desc.extensions;
    if (debug_utils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = desc.application;
    app.pEngineName = "grass";
    app.apiVersion = api_version_;

    // Warnings and errors of every type, also during vkCreateInstance/vkDestroyInstance.
    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = &on_message;
    messenger.pUserData = const_cast<VkMessageSink*>(desc.sink);

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pNext = debug_utils ? &messenger : nullptr;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = validation ? 1 : 0;
    info.ppEnabledLayerNames = &kValidationLayer;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult r = vkCreateInstance(&info, nullptr, &instance_);
    if (r != VK_SUCCESS) {
        *error = vk_error("vkCreateInstance", r);
        return false;
    }
    if (debug_utils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        r = create ? create(instance_, &messenger, nullptr, &messenger_) : VK_ERROR_EXTENSION_NOT_PRESENT;
        if (r != VK_SUCCESS) {
            *error = vk_error("vkCreateDebugUtilsMessengerEXT", r);
            return false;
        }
    }
    return true;
}

void VkBootInstance::destroy() {
    if (messenger_) {
        auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
    messenger_ = VK_NULL_HANDLE;
    instance_ = VK_NULL_HANDLE;
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    devices.resize(count);
    return devices;
}

std::vector<VkQueueFamilyProperties> queue_families(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    families.resize(count);
    return families;
}

bool has_device_extension(VkPhysicalDevice device, const char* name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
    for (uint32_t i = 0; i < count && i < extensions.size(); ++i) {
        if (std::strcmp(extensions[i].extensionName, name) == 0) return true;
    }
    return false;
}

bool create_device(VkPhysicalDevice physical, uint32_t family, const std::vector<const char*>& extensions,
                   const void* features, VkDevice* device, VkQueue* queue, std::string* error) {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = family;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue_info;
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.empty() ? nullptr : extensions.data();
    const VkResult r = vkCreateDevice(physical, &info, nullptr, device);
    if (r != VK_SUCCESS) {
        *error = vk_error("vkCreateDevice", r);
        return false;
    }
    vkGetDeviceQueue(*device, family, 0, queue);
    return true;
}

bool create_command_pool(VkDevice device, uint32_t family, VkCommandPool* out, std::string* error) {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = family;
    const VkResult r = vkCreateCommandPool(device, &pool, nullptr, out);
    if (r != VK_SUCCESS) *error = vk_error("vkCreateCommandPool", r);
    return r == VK_SUCCESS;
}

VkResult allocate_command_buffer(VkDevice device, VkCommandPool pool, VkCommandBuffer* out) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    return vkAllocateCommandBuffers(device, &alloc, out);
}

bool memory_type(const VkPhysicalDeviceMemoryProperties& memory, uint32_t bits, VkMemoryPropertyFlags flags,
                 uint32_t* out) {
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) {
            *out = i;
            return true;
        }
    }
    return false;
}

VkResult allocate_memory(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory,
                         const VkMemoryRequirements& requirements, VkMemoryPropertyFlags flags, VkDeviceMemory* out) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    if (!memory_type(memory, requirements.memoryTypeBits, flags, &info.memoryTypeIndex)) {
        return VK_ERROR_FEATURE_NOT_PRESENT;
    }
    return vkAllocateMemory(device, &info, nullptr, out);
}

bool create_image(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, const VkImageDesc& desc,
                  VkImageParts* out, std::string* error) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.extent.width, desc.extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = desc.layers;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkResult r = vkCreateImage(device, &info, nullptr, &out->image);
    if (r == VK_SUCCESS) {
        VkMemoryRequirements requirements{};
        vkGetImageMemoryRequirements(device, out->image, &requirements);
        r = allocate_memory(device, memory, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &out->memory);
    }
    if (r == VK_SUCCESS) r = vkBindImageMemory(device, out->image, out->memory, 0);
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = out->image;
    view.viewType = desc.layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    view.format = desc.format;
    view.subresourceRange = {desc.aspect, 0, 1, 0, desc.layers};
    if (r == VK_SUCCESS) r = vkCreateImageView(device, &view, nullptr, &out->view);
    if (r != VK_SUCCESS) *error = vk_error("creating a render target", r);
    return r == VK_SUCCESS;
}

void destroy_image(VkDevice device, VkImageParts* image) {
    if (image->view) vkDestroyImageView(device, image->view, nullptr);
    if (image->image) vkDestroyImage(device, image->image, nullptr);
    if (image->memory) vkFreeMemory(device, image->memory, nullptr);
    *image = VkImageParts{};
}

bool create_buffer(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory, VkDeviceSize size,
                   VkBufferUsageFlags usage, VkMemoryPropertyFlags flags, VkBufferParts* out, std::string* error) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkResult r = vkCreateBuffer(device, &info, nullptr, &out->buffer);
    if (r == VK_SUCCESS) {
        VkMemoryRequirements requirements{};
        vkGetBufferMemoryRequirements(device, out->buffer, &requirements);
        r = allocate_memory(device, memory, requirements, flags, &out->memory);
    }
    if (r == VK_SUCCESS) r = vkBindBufferMemory(device, out->buffer, out->memory, 0);
    if (r == VK_SUCCESS && (flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)) {
        r = vkMapMemory(device, out->memory, 0, VK_WHOLE_SIZE, 0, &out->mapped);
    }
    out->size = size;
    if (r != VK_SUCCESS) *error = vk_error("creating a buffer", r);
    return r == VK_SUCCESS;
}

void destroy_buffer(VkDevice device, VkBufferParts* buffer) {
    if (buffer->buffer) vkDestroyBuffer(device, buffer->buffer, nullptr);
    if (buffer->memory) vkFreeMemory(device, buffer->memory, nullptr); // unmaps
    *buffer = VkBufferParts{};
}

VkBufferMemoryBarrier host_read_barrier(VkBuffer buffer) {
    VkBufferMemoryBarrier b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.buffer = buffer;
    b.size = VK_WHOLE_SIZE;
    return b;
}

bool create_uniform_layouts(VkDevice device, VkDescriptorSetLayout* set_layout, VkPipelineLayout* layout,
                            std::string* error) {
    const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 1;
    set_info.pBindings = &binding;
    VkResult r = vkCreateDescriptorSetLayout(device, &set_info, nullptr, set_layout);
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = set_layout;
    if (r == VK_SUCCESS) r = vkCreatePipelineLayout(device, &layout_info, nullptr, layout);
    if (r != VK_SUCCESS) *error = vk_error("creating the ground's layouts", r);
    return r == VK_SUCCESS;
}

VkResult allocate_descriptor_set(VkDevice device, VkDescriptorPool pool, VkDescriptorSetLayout layout,
                                 VkDescriptorSet* out) {
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &layout;
    return vkAllocateDescriptorSets(device, &alloc, out);
}

void write_uniform_descriptor(VkDevice device, VkDescriptorSet set, VkBuffer buffer, VkDeviceSize size) {
    const VkDescriptorBufferInfo info{buffer, 0, size};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

bool create_render_pass(VkDevice device, const VkPassDesc& desc, VkRenderPass* out, std::string* error) {
    const bool msaa = desc.samples != VK_SAMPLE_COUNT_1_BIT;
    const bool depth_only = desc.color_format == VK_FORMAT_UNDEFINED;          // a shadow map's pass: depth alone
    const bool color_only = desc.depth_format == VK_FORMAT_UNDEFINED && !msaa; // one colour attachment alone
    VkAttachmentDescription attachments[9] = {};
    // 0: colour (multisampled or not). Single-sample: the image the pass ends in.
    attachments[0].format = desc.color_format;
    attachments[0].samples = desc.samples;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : desc.color_final;
    // 1: depth.
    attachments[1] = attachments[0];
    attachments[1].format = desc.depth_format;
    attachments[1].storeOp = desc.keep_depth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].finalLayout = desc.depth_final;
    // 2: the single-sample resolve target.
    attachments[2] = attachments[0];
    attachments[2].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[2].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[2].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[2].finalLayout = desc.color_final;

    VkAttachmentReference color_refs[8] = {{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    VkAttachmentReference resolve_refs[8] = {{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    const uint32_t most = msaa ? 3 : 7;
    const uint32_t more = depth_only || color_only ? 0 : desc.more_color_count < most ? desc.more_color_count : most;
    for (uint32_t i = 0; i < more; ++i) {
        // Single-sampled: attachment 2 + i. Multisampled: 3 + i, its resolve target 3 + more + i.
        const uint32_t at = msaa ? 3 + i : 2 + i;
        attachments[at] = attachments[0];
        attachments[at].format = desc.more_colors[i];
        color_refs[1 + i] = {at, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        if (!msaa) continue;
        attachments[at + more] = attachments[2];
        attachments[at + more].format = desc.more_colors[i];
        resolve_refs[1 + i] = {at + more, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    }
    const VkAttachmentReference depth_ref{depth_only ? 0u : 1u, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = depth_only ? 0 : 1 + more;
    subpass.pColorAttachments = depth_only ? nullptr : color_refs;
    subpass.pResolveAttachments = msaa && !depth_only ? resolve_refs : nullptr;
    subpass.pDepthStencilAttachment = color_only ? nullptr : &depth_ref;

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.pNext = desc.next;
    info.attachmentCount = depth_only || color_only ? 1 : msaa ? 3 + 2 * more : 2 + more;
    info.pAttachments = depth_only ? &attachments[1] : attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = desc.dependencies;
    const VkResult r = vkCreateRenderPass(device, &info, nullptr, out);
    if (r != VK_SUCCESS) *error = vk_error("vkCreateRenderPass", r);
    return r == VK_SUCCESS;
}

} // namespace grass_bootstrap
