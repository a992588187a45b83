// A vkGetInstanceProcAddr for grass's dispatch table (TargetDesc::vk_get_instance_proc_addr)
// that wraps some device functions: it counts the live Vulkan objects grass holds and can
// make a chosen call fail. The host's own calls go straight to the loader. One device at a
// time per process (the wrappers keep the loader's pointers in globals).
#pragma once

#include <grass/grass_vk.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace grass_test::vk_intercept {

using GetInstanceProcAddr = grass_vk_get_instance_proc_addr_fn;

// The wrapper to give the host.
GetInstanceProcAddr get_instance_proc_addr();

// The next `count` calls of `call` ("vkAllocateMemory", "vkAllocateDescriptorSets",
// "vkCreateBuffer", "vkMapMemory") return `vk_result` (a VkResult) without calling the
// driver, after `skip` calls that go through.
void fail_calls(const char* call, int32_t vk_result, int count = 1, int skip = 0);
void clear_failures();
int failures_injected();

// Every memory heap grass is told of (vkGetPhysicalDeviceMemoryProperties) is at most `bytes`
// large (0: as the driver says): a device with small heaps, whose device-memory blocks are
// small, so that a scene needs several of them.
void limit_heaps(uint64_t bytes);

// A device with VK_EXT_memory_budget, whatever the driver has: the extension is listed
// (vkEnumerateDeviceExtensionProperties) and vkGetPhysicalDeviceMemoryProperties2 answers a
// VkPhysicalDeviceMemoryBudgetPropertiesEXT with heapBudget[h] = emulated_budget(h) and
// heapUsage[h] = emulated_usage(h) (the driver sees the chain without it).
void emulate_memory_budget(bool on);
uint64_t emulated_budget(uint32_t heap);
uint64_t emulated_usage(uint32_t heap);
// Whether the driver itself lists VK_EXT_memory_budget for the physical device grass was
// given (known once a context was made).
bool driver_has_memory_budget();

// Objects grass created and has not destroyed: buffers, images, image views, memory
// allocations, samplers, descriptor pools, pipelines (graphics and compute), query pools.
struct Live {
    int64_t buffers = 0, images = 0, views = 0, memory = 0, samplers = 0, pools = 0, pipelines = 0, queries = 0;
    int64_t memory_made = 0;             // vkAllocateMemory calls that succeeded, ever
    int64_t dispatches = 0;              // vkCmdDispatch calls grass recorded, ever (not an object)
    int64_t pipelines_made = 0;          // pipelines grass created (graphics and compute), ever
    int64_t pipelines_without_cache = 0; // of those, made with pipelineCache VK_NULL_HANDLE
    uint64_t last_pipeline_cache = 0;    // the pipelineCache of the last one made
    int64_t total() const { return buffers + images + views + memory + samplers + pools + pipelines + queries; }
    std::string describe() const;
};
Live live();

// Debug labels (VK_EXT_debug_utils, grass.h grass_debug_labels): what grass made and named
// through this wrapper, and the labels it recorded. The wrapper hands grass its own
// vkSetDebugUtilsObjectNameEXT and vkCmdBegin/EndDebugUtilsLabelEXT, which record and then
// call the loader's.
struct Handle {
    int32_t type; // VkObjectType
    uint64_t handle;
    bool operator<(const Handle& o) const { return type != o.type ? type < o.type : handle < o.handle; }
};
// Every object grass created since clear_debug_records(): buffers, images, views, memory,
// samplers, descriptor pools, descriptor set layouts, pipeline layouts, shader modules,
// pipelines, query pools.
std::vector<Handle> made();
// The names grass gave, by object (the last name of each).
std::map<Handle, std::string> names();
// "+name" for each vkCmdBeginDebugUtilsLabelEXT, "-" for each vkCmdEndDebugUtilsLabelEXT, in order.
std::vector<std::string> label_events();
void clear_debug_records();
// true: the wrapper answers NULL for the three functions, as the loader does for an instance
// without VK_EXT_debug_utils.
void hide_debug_utils(bool hide);

} // namespace grass_test::vk_intercept
