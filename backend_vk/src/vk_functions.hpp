// The Vulkan entry points the backend calls, loaded per context through the host's
// vkGetInstanceProcAddr (instance level) and vkGetDeviceProcAddr (device level). There
// is no global function pointer: two contexts on two devices never share a table.
#pragma once

#include <grass/grass_vk.h>

#include <vulkan/vulkan.h>

namespace grass::vk {

// Instance-level functions: queried with the host's instance.
#define GRASS_VK_INSTANCE_FUNCTIONS(X)          \
    X(vkGetDeviceProcAddr)                      \
    X(vkGetPhysicalDeviceProperties)            \
    X(vkGetPhysicalDeviceMemoryProperties)      \
    X(vkGetPhysicalDeviceFormatProperties)      \
    X(vkGetPhysicalDeviceQueueFamilyProperties) \
    X(vkEnumerateDeviceExtensionProperties)

// Device-level functions: queried with the host's device, so calls skip the loader's
// dispatch trampoline.
#define GRASS_VK_DEVICE_FUNCTIONS(X) \
    X(vkCreateBuffer)                \
    X(vkDestroyBuffer)               \
    X(vkGetBufferMemoryRequirements) \
    X(vkBindBufferMemory)            \
    X(vkCreateImage)                 \
    X(vkDestroyImage)                \
    X(vkGetImageMemoryRequirements)  \
    X(vkBindImageMemory)             \
    X(vkCreateImageView)             \
    X(vkDestroyImageView)            \
    X(vkAllocateMemory)              \
    X(vkFreeMemory)                  \
    X(vkMapMemory)                   \
    X(vkUnmapMemory)                 \
    X(vkFlushMappedMemoryRanges)     \
    X(vkCreateSampler)               \
    X(vkDestroySampler)              \
    X(vkCreateShaderModule)          \
    X(vkDestroyShaderModule)         \
    X(vkCreateDescriptorSetLayout)   \
    X(vkDestroyDescriptorSetLayout)  \
    X(vkCreatePipelineLayout)        \
    X(vkDestroyPipelineLayout)       \
    X(vkCreateGraphicsPipelines)     \
    X(vkCreateComputePipelines)      \
    X(vkDestroyPipeline)             \
    X(vkCreatePipelineCache)         \
    X(vkDestroyPipelineCache)        \
    X(vkGetPipelineCacheData)        \
    X(vkMergePipelineCaches)         \
    X(vkCreateDescriptorPool)        \
    X(vkDestroyDescriptorPool)       \
    X(vkAllocateDescriptorSets)      \
    X(vkFreeDescriptorSets)          \
    X(vkResetDescriptorPool)         \
    X(vkUpdateDescriptorSets)        \
    X(vkCmdPipelineBarrier)          \
    X(vkCmdCopyBuffer)               \
    X(vkCmdCopyBufferToImage)        \
    X(vkCmdBindPipeline)             \
    X(vkCmdBindDescriptorSets)       \
    X(vkCmdPushConstants)            \
    X(vkCmdBindVertexBuffers)        \
    X(vkCmdBindIndexBuffer)          \
    X(vkCmdSetViewport)              \
    X(vkCmdSetScissor)               \
    X(vkCmdSetDepthBias)             \
    X(vkCmdDraw)                     \
    X(vkCmdDrawIndexed)              \
    X(vkCmdDispatch)                 \
    X(vkCmdClearColorImage)          \
    X(vkCreateQueryPool)             \
    X(vkDestroyQueryPool)            \
    X(vkGetQueryPoolResults)         \
    X(vkCmdResetQueryPool)           \
    X(vkCmdWriteTimestamp)

// Vulkan 1.1 functions grass does without (NULL where the host's instance is Vulkan 1.0):
// the heap budget (VK_EXT_memory_budget), the multiview and independentBlend feature queries
// (stereo contexts, velocity targets) and the driver's wish for dedicated allocations.
#define GRASS_VK_OPTIONAL_INSTANCE_FUNCTIONS(X) \
    X(vkGetPhysicalDeviceMemoryProperties2)     \
    X(vkGetPhysicalDeviceFeatures2)
#define GRASS_VK_OPTIONAL_DEVICE_FUNCTIONS(X) \
    X(vkGetBufferMemoryRequirements2)         \
    X(vkGetImageMemoryRequirements2)

struct Functions {
#define GRASS_VK_DECLARE_FUNCTION(name) PFN_##name name = nullptr;
    GRASS_VK_INSTANCE_FUNCTIONS(GRASS_VK_DECLARE_FUNCTION)
    GRASS_VK_DEVICE_FUNCTIONS(GRASS_VK_DECLARE_FUNCTION)
    GRASS_VK_OPTIONAL_INSTANCE_FUNCTIONS(GRASS_VK_DECLARE_FUNCTION)
    GRASS_VK_OPTIONAL_DEVICE_FUNCTIONS(GRASS_VK_DECLARE_FUNCTION)
#undef GRASS_VK_DECLARE_FUNCTION

    // The host's VkAllocationCallbacks (grass_vk_host_objects_desc::allocation_callbacks), copied: every
    // vkCreate*, vkDestroy*, vkAllocateMemory and vkFreeMemory of grass passes callbacks().
    VkAllocationCallbacks host_callbacks{};
    bool has_host_callbacks = false;
    const VkAllocationCallbacks* callbacks() const { return has_host_callbacks ? &host_callbacks : nullptr; }
    // VK_EXT_debug_utils: all three, or none when labels are off (vk_labels.hpp).
    PFN_vkSetDebugUtilsObjectNameEXT vkSetDebugUtilsObjectNameEXT = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT vkCmdBeginDebugUtilsLabelEXT = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT vkCmdEndDebugUtilsLabelEXT = nullptr;
};

// Fills `out`. Returns nullptr on success, or the name of the first function the loader
// did not return (the table is then partly filled and must not be used).
const char* load_functions(grass_vk_get_instance_proc_addr_fn get_instance_proc_addr, VkInstance instance,
                           VkDevice device, Functions* out);

} // namespace grass::vk
