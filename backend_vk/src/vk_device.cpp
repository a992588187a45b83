#include "vk_device.hpp"

#include "context/context.hpp"
#include "foundation/allocator.hpp"
#include "vk_labels.hpp"

#include <cstring>

namespace grass::vk {

namespace {

bool has_device_extension(const Device& d, HostAllocator* host, const char* name) {
    uint32_t count = 0;
    if (d.fn.vkEnumerateDeviceExtensionProperties(d.physical_device, nullptr, &count, nullptr) != VK_SUCCESS) {
        return false;
    }
    Vector<VkExtensionProperties> extensions(count, VkExtensionProperties{}, StlAllocator<VkExtensionProperties>(host));
    if (d.fn.vkEnumerateDeviceExtensionProperties(d.physical_device, nullptr, &count, extensions.data()) < VK_SUCCESS) {
        return false;
    }
    for (uint32_t i = 0; i < count && i < extensions.size(); ++i) {
        if (std::strcmp(extensions[i].extensionName, name) == 0) return true;
    }
    return false;
}

grass_result unsupported(grass_context* ctx, const char* function, const Device& d, const char* what) {
    return ctx->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED, "%s: the device \"%s\" (Vulkan %u.%u) %s",
                     function, d.properties.deviceName, VK_API_VERSION_MAJOR(d.properties.apiVersion),
                     VK_API_VERSION_MINOR(d.properties.apiVersion), what);
}

} // namespace

grass_result load_device(grass_context* ctx, const char* function, const grass_vk_desc& vk_desc,
                         const VkDescExtensions& extensions, Device* out) {
    const grass_vk_host_objects_desc& host_objects = extensions.host_objects;
    Device& d = *out;
    d.instance = static_cast<VkInstance>(vk_desc.instance);
    d.physical_device = static_cast<VkPhysicalDevice>(vk_desc.physical_device);
    d.device = static_cast<VkDevice>(vk_desc.device);
    if (const char* missing = load_functions(vk_desc.get_instance_proc_addr, d.instance, d.device, &d.fn)) {
        return ctx->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED,
                         "%s: vk_desc->get_instance_proc_addr returned NULL for %s (is the instance or device valid, "
                         "and Vulkan 1.1 or newer?)",
                         function, missing);
    }
    if (host_objects.allocation_callbacks) { // checked by check_vk_desc
        d.fn.host_callbacks = *static_cast<const VkAllocationCallbacks*>(host_objects.allocation_callbacks);
        d.fn.has_host_callbacks = true;
    }
    d.host_pipeline_cache = reinterpret_cast<VkPipelineCache>(host_objects.pipeline_cache); // 64-bit handles
    d.fn.vkGetPhysicalDeviceProperties(d.physical_device, &d.properties);
    d.fn.vkGetPhysicalDeviceMemoryProperties(d.physical_device, &d.memory);
    // The heap budget is a physical-device query: where the device lists VK_EXT_memory_budget
    // it may be made without the host enabling the extension on its VkDevice.
    d.memory_budget = d.fn.vkGetPhysicalDeviceMemoryProperties2 != nullptr &&
                      has_device_extension(d, &ctx->host, VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    constexpr uint32_t kVendorMesa = 0x10005; // VK_VENDOR_ID_MESA
    d.indexed_blocks =
        d.properties.vendorID == kVendorMesa && std::strncmp(d.properties.deviceName, "llvmpipe", 8) == 0;

    if (d.properties.apiVersion < VK_API_VERSION_1_1) {
        return unsupported(ctx, function, d, "is older than Vulkan 1.1, which grass needs");
    }
    if (vk_desc.render_pass == 0 && d.properties.apiVersion < VK_API_VERSION_1_3 &&
        !has_device_extension(d, &ctx->host, VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME)) {
        return unsupported(ctx, function, d,
                           "has neither Vulkan 1.3 nor VK_KHR_dynamic_rendering, which vk_desc->render_pass 0 "
                           "(dynamic rendering) needs");
    }
    d.has_depth_pass = extensions.has_depth_pass;
    d.has_velocity = extensions.has_velocity;
    d.velocity = extensions.velocity;
    d.has_gbuffer = extensions.has_gbuffer;
    d.gbuffer = extensions.gbuffer;
    d.depth_pass = extensions.depth_pass;
    if (d.has_depth_pass && d.depth_pass.render_pass == 0 && d.properties.apiVersion < VK_API_VERSION_1_3 &&
        !has_device_extension(d, &ctx->host, VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME)) {
        return unsupported(ctx, function, d,
                           "has neither Vulkan 1.3 nor VK_KHR_dynamic_rendering, which "
                           "grass_vk_depth_pass_desc.render_pass 0 (dynamic rendering) needs");
    }

    d.view_mask = extensions.multiview.view_mask;
    if (d.view_mask != 0) { // stereo: multiview is core in 1.1, but optional
        VkPhysicalDeviceMultiviewFeatures multiview{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES};
        VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        features.pNext = &multiview;
        if (d.fn.vkGetPhysicalDeviceFeatures2) d.fn.vkGetPhysicalDeviceFeatures2(d.physical_device, &features);
        if (!multiview.multiview) {
            return unsupported(ctx, function, d,
                               "lacks the multiview feature (VkPhysicalDeviceMultiviewFeatures::multiview), which "
                               "grass_vk_multiview_desc.view_mask 0x3 (stereo) needs");
        }
    }
    if (d.has_velocity || (d.has_gbuffer && d.gbuffer.color_attachment_count > 1)) {
        // the pipelines write the pass's colour attachments with different masks
        VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        if (d.fn.vkGetPhysicalDeviceFeatures2) d.fn.vkGetPhysicalDeviceFeatures2(d.physical_device, &features);
        if (!features.features.independentBlend) {
            return unsupported(ctx, function, d,
                               "lacks the independentBlend feature, which grass_vk_velocity_target_desc or "
                               "grass_vk_gbuffer_target_desc with more than one attachment (a pass whose "
                               "colour attachments grass writes with different masks) needs");
        }
    }

    uint32_t family_count = 0;
    d.fn.vkGetPhysicalDeviceQueueFamilyProperties(d.physical_device, &family_count, nullptr);
    if (vk_desc.queue_family >= family_count) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: vk_desc->queue_family is %u; the device's queue families are 0..%u", function,
                         vk_desc.queue_family, family_count - 1);
    }
    Vector<VkQueueFamilyProperties> families(family_count, VkQueueFamilyProperties{},
                                             StlAllocator<VkQueueFamilyProperties>(&ctx->host));
    d.fn.vkGetPhysicalDeviceQueueFamilyProperties(d.physical_device, &family_count, families.data());
    if (!(families[vk_desc.queue_family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_OUT_OF_RANGE,
                         "%s: vk_desc->queue_family is %u, a family without VK_QUEUE_GRAPHICS_BIT; grass records "
                         "draws, so the host must submit them to a graphics queue",
                         function, vk_desc.queue_family);
    }

    const VkSampleCountFlags samples =
        d.properties.limits.framebufferColorSampleCounts & d.properties.limits.framebufferDepthSampleCounts;
    if (!(samples & vk_desc.sample_count)) {
        return ctx->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                         "%s: vk_desc->sample_count is %u; the device \"%s\" supports the sample counts 0x%x for "
                         "colour and depth",
                         function, vk_desc.sample_count, d.properties.deviceName, static_cast<unsigned>(samples));
    }

    VkFormatProperties format{};
    d.fn.vkGetPhysicalDeviceFormatProperties(d.physical_device, static_cast<VkFormat>(vk_desc.depth_format), &format);
    if (!(format.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
        return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                         "%s: vk_desc->depth_format is %u, which the device \"%s\" cannot use as a depth attachment",
                         function, vk_desc.depth_format, d.properties.deviceName);
    }
    if (d.has_depth_pass) {
        if (!(d.properties.limits.framebufferDepthSampleCounts & d.depth_pass.sample_count)) {
            return ctx->fail(GRASS_ERROR_UNSUPPORTED, GRASS_MSG_DEVICE_UNSUPPORTED,
                             "%s: grass_vk_depth_pass_desc.sample_count is %u; the device \"%s\" supports the sample "
                             "counts 0x%x for depth",
                             function, d.depth_pass.sample_count, d.properties.deviceName,
                             static_cast<unsigned>(d.properties.limits.framebufferDepthSampleCounts));
        }
        d.fn.vkGetPhysicalDeviceFormatProperties(d.physical_device, static_cast<VkFormat>(d.depth_pass.depth_format),
                                                 &format);
        if (!(format.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: grass_vk_depth_pass_desc.depth_format is %u, which the device \"%s\" cannot use as "
                             "a depth attachment",
                             function, d.depth_pass.depth_format, d.properties.deviceName);
        }
    }
    if (vk_desc.render_pass == 0) {
        d.fn.vkGetPhysicalDeviceFormatProperties(d.physical_device, static_cast<VkFormat>(vk_desc.color_format),
                                                 &format);
        if (!(format.optimalTilingFeatures & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT)) {
            return ctx->fail(GRASS_ERROR_INVALID_ARGUMENT, GRASS_MSG_BAD_ENUM,
                             "%s: vk_desc->color_format is %u, which the device \"%s\" cannot use as a colour "
                             "attachment",
                             function, vk_desc.color_format, d.properties.deviceName);
        }
    }

    d.fn.vkGetPhysicalDeviceFormatProperties(d.physical_device, kDensityMapFormat, &format);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                        VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((format.optimalTilingFeatures & needed) != needed) {
        return unsupported(ctx, function, d,
                           "cannot sample VK_FORMAT_R16_UNORM images with linear filtering, which density maps need");
    }

    // The baked slices of the volume and image tiers.
    const struct {
        VkFormat format;
        bool linear;
        const char* what;
    } slice_formats[] = {
        {kSliceColorFormat, true,
         "cannot sample VK_FORMAT_R8G8B8A8_SRGB images with linear filtering, which the baked slice colours of the "
         "volume and image tiers need"},
        {kSliceNormalFormat, true,
         "cannot sample VK_FORMAT_R8G8B8A8_UNORM images with linear filtering, which the baked slice normals of the "
         "volume and image tiers need"},
        {kSliceThresholdFormat, false,
         "cannot sample VK_FORMAT_R16G16B16A16_UNORM images, which the baked slice thresholds of the volume and image "
         "tiers "
         "need"},
    };
    for (const auto& f : slice_formats) {
        d.fn.vkGetPhysicalDeviceFormatProperties(d.physical_device, f.format, &format);
        VkFormatFeatureFlags wanted = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
        if (f.linear) wanted |= VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
        if ((format.optimalTilingFeatures & wanted) != wanted) return unsupported(ctx, function, d, f.what);
    }

    // Debug labels and object names (grass.h, grass_debug_labels): AUTO and ON take them
    // where the host enabled VK_EXT_debug_utils.
    if (!load_labels(ctx->debug_labels, vk_desc.get_instance_proc_addr, d.instance, &d.fn) &&
        ctx->debug_labels == GRASS_DEBUG_LABELS_ON) {
        ctx->warn(GRASS_MSG_DEBUG_LABELS_UNAVAILABLE,
                  "%s: debug labels are GRASS_DEBUG_LABELS_ON, but the instance has no VK_EXT_debug_utils (the "
                  "host's vkGetInstanceProcAddr returned NULL for vkSetDebugUtilsObjectNameEXT or "
                  "vkCmdBeginDebugUtilsLabelEXT): enable the extension on the instance to see grass's labels",
                  function);
    }
    return GRASS_SUCCESS;
}

} // namespace grass::vk
