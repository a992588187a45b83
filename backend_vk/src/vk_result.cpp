#include "vk_result.hpp"

#include "context/context.hpp"

#include <cstdio>

namespace grass::vk {

const char* vk_result_name(VkResult result, char (&scratch)[32]) {
    switch (result) {
#define GRASS_VK_RESULT_CASE(name) \
    case name:                     \
        return #name;
        GRASS_VK_RESULT_CASE(VK_SUCCESS)
        GRASS_VK_RESULT_CASE(VK_NOT_READY)
        GRASS_VK_RESULT_CASE(VK_TIMEOUT)
        GRASS_VK_RESULT_CASE(VK_INCOMPLETE)
        GRASS_VK_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        GRASS_VK_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        GRASS_VK_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        GRASS_VK_RESULT_CASE(VK_ERROR_DEVICE_LOST)
        GRASS_VK_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        GRASS_VK_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        GRASS_VK_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        GRASS_VK_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        GRASS_VK_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        GRASS_VK_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        GRASS_VK_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
        GRASS_VK_RESULT_CASE(VK_ERROR_UNKNOWN)
        GRASS_VK_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        GRASS_VK_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        GRASS_VK_RESULT_CASE(VK_ERROR_FRAGMENTATION)
        GRASS_VK_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        GRASS_VK_RESULT_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef GRASS_VK_RESULT_CASE
    default:
        std::snprintf(scratch, sizeof(scratch), "VkResult(%d)", static_cast<int>(result));
        return scratch;
    }
}

grass_result report_failure(grass_context* context, const char* function, const char* what, const VkFailure& failure) {
    if (failure.result == VK_SUCCESS) {
        // No Vulkan call failed: the backend declined what the core should have refused first
        // (a pipeline for a target the context was not made with): a bug in grass.
        return context->fail(GRASS_ERROR_INVALID_STATE, GRASS_MSG_INTERNAL_ERROR,
                             "%s: the Vulkan backend cannot make %s for this context, and no Vulkan call failed: the "
                             "core should have refused this earlier (please report it)",
                             function, what && *what ? what : "what this call needs");
    }
    char scratch[32];
    const char* name = vk_result_name(failure.result, scratch);
    const bool out_of_memory =
        failure.result == VK_ERROR_OUT_OF_HOST_MEMORY || failure.result == VK_ERROR_OUT_OF_DEVICE_MEMORY;
    if (out_of_memory) {
        return context->fail(GRASS_ERROR_OUT_OF_MEMORY, GRASS_MSG_OUT_OF_MEMORY, "%s: %s failed with %s (%s)", function,
                             failure.call ? failure.call : "a Vulkan call", name, what);
    }
    if (failure.result == VK_ERROR_DEVICE_LOST) {
        return context->fail(GRASS_ERROR_BACKEND, GRASS_MSG_DEVICE_LOST,
                             "%s: %s failed with VK_ERROR_DEVICE_LOST (%s): the device is lost; destroy this context "
                             "and make a new one on a new device",
                             function, failure.call ? failure.call : "a Vulkan call", what);
    }
    return context->fail(GRASS_ERROR_BACKEND, GRASS_MSG_BACKEND_CALL_FAILED, "%s: %s failed with %s (%s)", function,
                         failure.call ? failure.call : "a Vulkan call", name, what);
}

} // namespace grass::vk
