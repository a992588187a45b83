#include "vk_intercept.hpp"

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstring>
#include <type_traits>
#include <vector>

namespace grass_test::vk_intercept {
namespace {

PFN_vkGetDeviceProcAddr real_device_proc_addr = nullptr;
Live counts;
struct Failure {
    const char* call = nullptr;
    VkResult result = VK_SUCCESS;
    int count = 0, skip = 0;
} failure;
int injected = 0;
uint64_t heap_limit = 0;
bool budget_emulated = false;
VkPhysicalDevice last_physical_device = VK_NULL_HANDLE;
PFN_vkGetPhysicalDeviceMemoryProperties real_vkGetPhysicalDeviceMemoryProperties = nullptr;
PFN_vkGetPhysicalDeviceMemoryProperties2 real_vkGetPhysicalDeviceMemoryProperties2 = nullptr;
PFN_vkEnumerateDeviceExtensionProperties real_vkEnumerateDeviceExtensionProperties = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL wrap_vkEnumerateDeviceExtensionProperties(VkPhysicalDevice pd, const char* layer,
                                                                         uint32_t* count, VkExtensionProperties* out) {
    if (!budget_emulated || layer) return real_vkEnumerateDeviceExtensionProperties(pd, layer, count, out);
    uint32_t real_count = 0;
    VkResult r = real_vkEnumerateDeviceExtensionProperties(pd, nullptr, &real_count, nullptr);
    if (r != VK_SUCCESS) return r;
    if (!out) {
        *count = real_count + 1;
        return VK_SUCCESS;
    }
    if (*count < real_count + 1) return VK_INCOMPLETE;
    r = real_vkEnumerateDeviceExtensionProperties(pd, nullptr, &real_count, out);
    if (r != VK_SUCCESS) return r;
    VkExtensionProperties budget{};
    std::strcpy(budget.extensionName, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    budget.specVersion = 1;
    out[real_count] = budget;
    *count = real_count + 1;
    return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL wrap_vkGetPhysicalDeviceMemoryProperties2(VkPhysicalDevice pd,
                                                                     VkPhysicalDeviceMemoryProperties2* out) {
    VkPhysicalDeviceMemoryBudgetPropertiesEXT* budget = nullptr;
    if (budget_emulated) { // take the budget struct out of the chain the driver sees
        for (VkBaseOutStructure* s = reinterpret_cast<VkBaseOutStructure*>(out); s && s->pNext;) {
            if (s->pNext->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT) {
                budget = reinterpret_cast<VkPhysicalDeviceMemoryBudgetPropertiesEXT*>(s->pNext);
                s->pNext = s->pNext->pNext;
            } else {
                s = s->pNext;
            }
        }
    }
    real_vkGetPhysicalDeviceMemoryProperties2(pd, out);
    if (budget) {
        for (uint32_t h = 0; h < VK_MAX_MEMORY_HEAPS; ++h) {
            budget->heapBudget[h] = h < out->memoryProperties.memoryHeapCount ? emulated_budget(h) : 0;
            budget->heapUsage[h] = h < out->memoryProperties.memoryHeapCount ? emulated_usage(h) : 0;
        }
        budget->pNext = out->pNext; // back in the caller's chain, first after the head
        out->pNext = budget;
    }
}

VKAPI_ATTR void VKAPI_CALL wrap_vkGetPhysicalDeviceMemoryProperties(VkPhysicalDevice pd,
                                                                    VkPhysicalDeviceMemoryProperties* out) {
    last_physical_device = pd;
    real_vkGetPhysicalDeviceMemoryProperties(pd, out);
    for (uint32_t h = 0; h < out->memoryHeapCount && heap_limit > 0; ++h) {
        if (out->memoryHeaps[h].size > heap_limit) out->memoryHeaps[h].size = heap_limit;
    }
}

std::vector<Handle> made_handles;
std::map<Handle, std::string> given_names;
std::vector<std::string> labels;
bool debug_utils_hidden = false;

template <class H>
uint64_t bits(H h) {
    if constexpr (std::is_pointer_v<H>) {
        return reinterpret_cast<uint64_t>(h);
    } else {
        return static_cast<uint64_t>(h);
    }
}
template <class H>
void record_made(VkObjectType type, const H* handles, uint32_t n = 1) {
    for (uint32_t i = 0; i < n; ++i) made_handles.push_back({int32_t(type), bits(handles[i])});
}

// True (and counted) when this call of `call` is to fail.
bool fails(const char* call) {
    if (!failure.call || std::strcmp(failure.call, call) != 0 || failure.count == 0) return false;
    if (failure.skip > 0) {
        failure.skip -= 1;
        return false;
    }
    failure.count -= 1;
    injected += 1;
    return true;
}

#define GRASS_REAL(name) PFN_##name real_##name = nullptr;
GRASS_REAL(vkCreateBuffer)
GRASS_REAL(vkDestroyBuffer)
GRASS_REAL(vkCreateImage)
GRASS_REAL(vkDestroyImage)
GRASS_REAL(vkCreateImageView)
GRASS_REAL(vkDestroyImageView)
GRASS_REAL(vkAllocateMemory)
GRASS_REAL(vkFreeMemory)
GRASS_REAL(vkMapMemory)
GRASS_REAL(vkCreateSampler)
GRASS_REAL(vkDestroySampler)
GRASS_REAL(vkCreateDescriptorPool)
GRASS_REAL(vkDestroyDescriptorPool)
GRASS_REAL(vkAllocateDescriptorSets)
GRASS_REAL(vkCreateGraphicsPipelines)
GRASS_REAL(vkCreateComputePipelines)
GRASS_REAL(vkCmdDispatch)
GRASS_REAL(vkDestroyPipeline)
GRASS_REAL(vkCreateQueryPool)
GRASS_REAL(vkDestroyQueryPool)
GRASS_REAL(vkCreateDescriptorSetLayout)
GRASS_REAL(vkCreatePipelineLayout)
GRASS_REAL(vkCreateShaderModule)
GRASS_REAL(vkSetDebugUtilsObjectNameEXT)
GRASS_REAL(vkCmdBeginDebugUtilsLabelEXT)
GRASS_REAL(vkCmdEndDebugUtilsLabelEXT)
#undef GRASS_REAL

// A create call: fails when told to, else counts what it made.
#define GRASS_CREATE(name, Info, Handle, counter, object_type)                                               \
    VKAPI_ATTR VkResult VKAPI_CALL wrap_##name(VkDevice d, const Info* info, const VkAllocationCallbacks* a, \
                                               Handle* out) {                                                \
        if (fails(#name)) return failure.result;                                                             \
        const VkResult r = real_##name(d, info, a, out);                                                     \
        if (r == VK_SUCCESS) {                                                                               \
            counts.counter += 1;                                                                             \
            record_made(object_type, out);                                                                   \
        }                                                                                                    \
        return r;                                                                                            \
    }
#define GRASS_DESTROY(name, Handle, counter)                                                       \
    VKAPI_ATTR void VKAPI_CALL wrap_##name(VkDevice d, Handle h, const VkAllocationCallbacks* a) { \
        if (h != VK_NULL_HANDLE) counts.counter -= 1;                                              \
        real_##name(d, h, a);                                                                      \
    }
GRASS_CREATE(vkCreateBuffer, VkBufferCreateInfo, VkBuffer, buffers, VK_OBJECT_TYPE_BUFFER)
GRASS_DESTROY(vkDestroyBuffer, VkBuffer, buffers)
GRASS_CREATE(vkCreateImage, VkImageCreateInfo, VkImage, images, VK_OBJECT_TYPE_IMAGE)
GRASS_DESTROY(vkDestroyImage, VkImage, images)
GRASS_CREATE(vkCreateImageView, VkImageViewCreateInfo, VkImageView, views, VK_OBJECT_TYPE_IMAGE_VIEW)
GRASS_DESTROY(vkDestroyImageView, VkImageView, views)
VKAPI_ATTR VkResult VKAPI_CALL wrap_vkAllocateMemory(VkDevice d, const VkMemoryAllocateInfo* info,
                                                     const VkAllocationCallbacks* a, VkDeviceMemory* out) {
    if (fails("vkAllocateMemory")) return failure.result;
    const VkResult r = real_vkAllocateMemory(d, info, a, out);
    if (r == VK_SUCCESS) {
        counts.memory += 1;
        counts.memory_made += 1;
        record_made(VK_OBJECT_TYPE_DEVICE_MEMORY, out);
    }
    return r;
}
GRASS_DESTROY(vkFreeMemory, VkDeviceMemory, memory)
GRASS_CREATE(vkCreateSampler, VkSamplerCreateInfo, VkSampler, samplers, VK_OBJECT_TYPE_SAMPLER)
GRASS_DESTROY(vkDestroySampler, VkSampler, samplers)
GRASS_CREATE(vkCreateDescriptorPool, VkDescriptorPoolCreateInfo, VkDescriptorPool, pools,
             VK_OBJECT_TYPE_DESCRIPTOR_POOL)
GRASS_DESTROY(vkDestroyDescriptorPool, VkDescriptorPool, pools)
GRASS_CREATE(vkCreateQueryPool, VkQueryPoolCreateInfo, VkQueryPool, queries, VK_OBJECT_TYPE_QUERY_POOL)
GRASS_DESTROY(vkDestroyQueryPool, VkQueryPool, queries)
GRASS_DESTROY(vkDestroyPipeline, VkPipeline, pipelines)
#undef GRASS_CREATE
#undef GRASS_DESTROY

VKAPI_ATTR VkResult VKAPI_CALL wrap_vkMapMemory(VkDevice d, VkDeviceMemory m, VkDeviceSize offset, VkDeviceSize size,
                                                VkMemoryMapFlags flags, void** out) {
    if (fails("vkMapMemory")) return failure.result;
    return real_vkMapMemory(d, m, offset, size, flags, out);
}

VKAPI_ATTR VkResult VKAPI_CALL wrap_vkAllocateDescriptorSets(VkDevice d, const VkDescriptorSetAllocateInfo* info,
                                                             VkDescriptorSet* out) {
    if (fails("vkAllocateDescriptorSets")) return failure.result;
    return real_vkAllocateDescriptorSets(d, info, out);
}

// Counts `n` pipelines made through `cache` (graphics and compute alike).
void count_pipelines(VkResult r, VkPipelineCache cache, uint32_t n, VkPipeline* out) {
    if (r != VK_SUCCESS) return;
    counts.pipelines += n;
    counts.pipelines_made += n;
    if (cache == VK_NULL_HANDLE) counts.pipelines_without_cache += n;
    counts.last_pipeline_cache = reinterpret_cast<uint64_t>(cache);
    record_made(VK_OBJECT_TYPE_PIPELINE, out, n);
}

VKAPI_ATTR VkResult VKAPI_CALL wrap_vkCreateGraphicsPipelines(VkDevice d, VkPipelineCache cache, uint32_t n,
                                                              const VkGraphicsPipelineCreateInfo* infos,
                                                              const VkAllocationCallbacks* a, VkPipeline* out) {
    if (fails("vkCreateGraphicsPipelines")) return failure.result;
    const VkResult r = real_vkCreateGraphicsPipelines(d, cache, n, infos, a, out);
    count_pipelines(r, cache, n, out);
    return r;
}

VKAPI_ATTR VkResult VKAPI_CALL wrap_vkCreateComputePipelines(VkDevice d, VkPipelineCache cache, uint32_t n,
                                                             const VkComputePipelineCreateInfo* infos,
                                                             const VkAllocationCallbacks* a, VkPipeline* out) {
    if (fails("vkCreateComputePipelines")) return failure.result;
    const VkResult r = real_vkCreateComputePipelines(d, cache, n, infos, a, out);
    count_pipelines(r, cache, n, out);
    return r;
}

// Objects counted only for their names.
#define GRASS_MADE(name, Info, Handle, object_type)                                                          \
    VKAPI_ATTR VkResult VKAPI_CALL wrap_##name(VkDevice d, const Info* info, const VkAllocationCallbacks* a, \
                                               Handle* out) {                                                \
        const VkResult r = real_##name(d, info, a, out);                                                     \
        if (r == VK_SUCCESS) record_made(object_type, out);                                                  \
        return r;                                                                                            \
    }
GRASS_MADE(vkCreateDescriptorSetLayout, VkDescriptorSetLayoutCreateInfo, VkDescriptorSetLayout,
           VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT)
GRASS_MADE(vkCreatePipelineLayout, VkPipelineLayoutCreateInfo, VkPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT)
GRASS_MADE(vkCreateShaderModule, VkShaderModuleCreateInfo, VkShaderModule, VK_OBJECT_TYPE_SHADER_MODULE)
#undef GRASS_MADE

VKAPI_ATTR VkResult VKAPI_CALL wrap_vkSetDebugUtilsObjectNameEXT(VkDevice d,
                                                                 const VkDebugUtilsObjectNameInfoEXT* info) {
    given_names[Handle{int32_t(info->objectType), info->objectHandle}] = info->pObjectName ? info->pObjectName : "";
    return real_vkSetDebugUtilsObjectNameEXT(d, info);
}

VKAPI_ATTR void VKAPI_CALL wrap_vkCmdBeginDebugUtilsLabelEXT(VkCommandBuffer cmd, const VkDebugUtilsLabelEXT* label) {
    labels.push_back(std::string("+") + label->pLabelName);
    real_vkCmdBeginDebugUtilsLabelEXT(cmd, label);
}

VKAPI_ATTR void VKAPI_CALL wrap_vkCmdEndDebugUtilsLabelEXT(VkCommandBuffer cmd) {
    labels.push_back("-");
    real_vkCmdEndDebugUtilsLabelEXT(cmd);
}

VKAPI_ATTR void VKAPI_CALL wrap_vkCmdDispatch(VkCommandBuffer cmd, uint32_t x, uint32_t y, uint32_t z) {
    counts.dispatches += 1;
    real_vkCmdDispatch(cmd, x, y, z);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL wrap_vkGetDeviceProcAddr(VkDevice device, const char* name) {
    const PFN_vkVoidFunction real = real_device_proc_addr(device, name);
    if (!real) return real;
#define GRASS_WRAP(fn)                                           \
    if (std::strcmp(name, #fn) == 0) {                           \
        real_##fn = reinterpret_cast<PFN_##fn>(real);            \
        return reinterpret_cast<PFN_vkVoidFunction>(&wrap_##fn); \
    }
    GRASS_WRAP(vkCreateBuffer)
    GRASS_WRAP(vkDestroyBuffer)
    GRASS_WRAP(vkCreateImage)
    GRASS_WRAP(vkDestroyImage)
    GRASS_WRAP(vkCreateImageView)
    GRASS_WRAP(vkDestroyImageView)
    GRASS_WRAP(vkAllocateMemory)
    GRASS_WRAP(vkFreeMemory)
    GRASS_WRAP(vkMapMemory)
    GRASS_WRAP(vkCreateSampler)
    GRASS_WRAP(vkDestroySampler)
    GRASS_WRAP(vkCreateDescriptorPool)
    GRASS_WRAP(vkDestroyDescriptorPool)
    GRASS_WRAP(vkAllocateDescriptorSets)
    GRASS_WRAP(vkCreateGraphicsPipelines)
    GRASS_WRAP(vkCreateComputePipelines)
    GRASS_WRAP(vkCmdDispatch)
    GRASS_WRAP(vkDestroyPipeline)
    GRASS_WRAP(vkCreateQueryPool)
    GRASS_WRAP(vkDestroyQueryPool)
    GRASS_WRAP(vkCreateDescriptorSetLayout)
    GRASS_WRAP(vkCreatePipelineLayout)
    GRASS_WRAP(vkCreateShaderModule)
    return real;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL wrap_get_instance_proc_addr(VkInstance instance, const char* name) {
    const PFN_vkVoidFunction real = vkGetInstanceProcAddr(instance, name);
    if (real && std::strcmp(name, "vkGetPhysicalDeviceMemoryProperties2") == 0) {
        real_vkGetPhysicalDeviceMemoryProperties2 = reinterpret_cast<PFN_vkGetPhysicalDeviceMemoryProperties2>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(&wrap_vkGetPhysicalDeviceMemoryProperties2);
    }
    if (real && std::strcmp(name, "vkEnumerateDeviceExtensionProperties") == 0) {
        real_vkEnumerateDeviceExtensionProperties = reinterpret_cast<PFN_vkEnumerateDeviceExtensionProperties>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(&wrap_vkEnumerateDeviceExtensionProperties);
    }
    if (real && std::strcmp(name, "vkGetPhysicalDeviceMemoryProperties") == 0) {
        real_vkGetPhysicalDeviceMemoryProperties = reinterpret_cast<PFN_vkGetPhysicalDeviceMemoryProperties>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(&wrap_vkGetPhysicalDeviceMemoryProperties);
    }
    if (real && std::strcmp(name, "vkGetDeviceProcAddr") == 0) {
        real_device_proc_addr = reinterpret_cast<PFN_vkGetDeviceProcAddr>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(&wrap_vkGetDeviceProcAddr);
    }
    if (!real) return real;
    const bool debug_utils = std::strcmp(name, "vkSetDebugUtilsObjectNameEXT") == 0 ||
                             std::strcmp(name, "vkCmdBeginDebugUtilsLabelEXT") == 0 ||
                             std::strcmp(name, "vkCmdEndDebugUtilsLabelEXT") == 0;
    if (debug_utils && debug_utils_hidden) return nullptr;
    GRASS_WRAP(vkSetDebugUtilsObjectNameEXT)
    GRASS_WRAP(vkCmdBeginDebugUtilsLabelEXT)
    GRASS_WRAP(vkCmdEndDebugUtilsLabelEXT)
#undef GRASS_WRAP
    return real;
}

} // namespace

GetInstanceProcAddr get_instance_proc_addr() { return &wrap_get_instance_proc_addr; }

void fail_calls(const char* call, int32_t vk_result, int count, int skip) {
    failure.call = call;
    failure.result = static_cast<VkResult>(vk_result);
    failure.count = count;
    failure.skip = skip;
}

void clear_failures() { failure = Failure{}; }
void limit_heaps(uint64_t bytes) { heap_limit = bytes; }
void emulate_memory_budget(bool on) { budget_emulated = on; }
uint64_t emulated_budget(uint32_t heap) { return (uint64_t{3} << 30) + heap; }
uint64_t emulated_usage(uint32_t heap) { return (uint64_t{123} << 20) + heap; }

bool driver_has_memory_budget() {
    if (!last_physical_device || !real_vkEnumerateDeviceExtensionProperties) return false;
    uint32_t count = 0;
    if (real_vkEnumerateDeviceExtensionProperties(last_physical_device, nullptr, &count, nullptr) != VK_SUCCESS) {
        return false;
    }
    std::vector<VkExtensionProperties> extensions(count);
    if (real_vkEnumerateDeviceExtensionProperties(last_physical_device, nullptr, &count, extensions.data()) < 0) {
        return false;
    }
    for (const VkExtensionProperties& e : extensions) {
        if (std::strcmp(e.extensionName, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME) == 0) return true;
    }
    return false;
}
int failures_injected() { return injected; }
Live live() { return counts; }

std::vector<Handle> made() { return made_handles; }
std::map<Handle, std::string> names() { return given_names; }
std::vector<std::string> label_events() { return labels; }
void clear_debug_records() {
    made_handles.clear();
    given_names.clear();
    labels.clear();
}
void hide_debug_utils(bool hide) { debug_utils_hidden = hide; }

std::string Live::describe() const {
    return std::to_string(buffers) + " buffers, " + std::to_string(images) + " images, " + std::to_string(views) +
           " views, " + std::to_string(memory) + " allocations, " + std::to_string(samplers) + " samplers, " +
           std::to_string(pools) + " descriptor pools, " + std::to_string(pipelines) + " pipelines, " +
           std::to_string(queries) + " query pools";
}

} // namespace grass_test::vk_intercept
