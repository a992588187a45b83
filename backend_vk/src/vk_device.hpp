// The host's device as the backend sees it: the loaded function table, the handles, and
// the properties it needs; with the checks that the device can run grass.
#pragma once

#include "vk_desc_check.hpp"
#include "vk_functions.hpp"

#include <grass/grass_vk.h>

struct grass_context;

namespace grass::vk {

struct Device {
    Functions fn;
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memory{};
    // The Frame and Field blocks read at an index from a push constant: on lavapipe only
    // (vk_spirv.hpp says why).
    bool indexed_blocks = false;
    // The device lists VK_EXT_memory_budget (and vkGetPhysicalDeviceMemoryProperties2 is
    // loaded): grass_memory_stats reports each heap's budget and the process's usage.
    bool memory_budget = false;
    // The host's VkPipelineCache (grass_vk_host_objects_desc), or none: grass makes its own.
    VkPipelineCache host_pipeline_cache = VK_NULL_HANDLE;
    // The view mask of the host's pass (grass_vk_multiview_desc): 0 mono, 0x3 stereo (the
    // device has the multiview feature).
    uint32_t view_mask = 0;
    // The host's depth-only target (grass_vk_depth_pass_desc), when chained: depth views
    // draw with pipelines made against it. Absent: the context refuses depth views.
    bool has_depth_pass = false;
    grass_vk_depth_pass_desc depth_pass{};
    // The colour attachments of the host's pass when it holds a velocity target
    // (grass_vk_velocity_target_desc): motion views draw with pipelines made against them.
    // Absent: the context refuses motion views.
    bool has_velocity = false;
    grass_vk_velocity_target_desc velocity{};
    // The colour attachments of the host's pass when it draws G-buffer views in it
    // (grass_vk_gbuffer_target_desc). Absent: the context refuses G-buffer views.
    bool has_gbuffer = false;
    grass_vk_gbuffer_target_desc gbuffer{};
};

// The format of single-channel design maps (density, ambient, diffuse, height): 16-bit
// unorm, sampled with linear filtering. Colour maps are R16G16B16A16_UNORM where the
// device samples it (VkBackend::init checks; load_device does not require it).
constexpr VkFormat kDensityMapFormat = VK_FORMAT_R16_UNORM;
// The formats of the baked slices (api/src/baked_slices.hpp): sRGB albedo + coverage and
// normal + height trilinear, thresholds nearest.
constexpr VkFormat kSliceColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kSliceNormalFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kSliceThresholdFormat = VK_FORMAT_R16G16B16A16_UNORM; // threshold + coverage curve

// Loads the functions and checks the device: Vulkan 1.1, dynamic rendering when
// vk_desc->render_pass is 0, a graphics queue family, the sample count, the density map
// and slice formats. Logs and returns GRASS_ERROR_UNSUPPORTED (or GRASS_ERROR_BACKEND when the
// loader lacks a function). `vk_desc` has passed check_vk_desc().
grass_result load_device(grass_context* context, const char* function, const grass_vk_desc& vk_desc,
                         const VkDescExtensions& extensions, Device* out);

} // namespace grass::vk
