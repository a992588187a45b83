// Vulkan failures as grass results: which call failed, with which VkResult, and the
// message the context logs for it.
#pragma once

#include <grass/grass.h>

#include <vulkan/vulkan.h>

struct grass_context;

namespace grass::vk {

// A failed Vulkan call: its name (a string literal) and its result. call == nullptr: none.
struct VkFailure {
    const char* call = nullptr;
    VkResult result = VK_SUCCESS;
};

// Records `result` of `call` into *failure when it is an error. Returns true on success.
inline bool vk_ok(VkResult result, const char* call, VkFailure* failure) {
    if (result >= VK_SUCCESS) return true;
    failure->call = call;
    failure->result = result;
    return false;
}

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" and so on; "VkResult(<n>)" for a code it does not know.
const char* vk_result_name(VkResult result, char (&scratch)[32]);

// Logs "<function>: <call> failed with <VkResult> (<what>)" and returns
// GRASS_ERROR_OUT_OF_MEMORY for the out-of-memory results (GRASS_MSG_OUT_OF_MEMORY),
// GRASS_ERROR_BACKEND otherwise: GRASS_MSG_DEVICE_LOST for VK_ERROR_DEVICE_LOST,
// GRASS_MSG_BACKEND_CALL_FAILED for the rest. A failure without a Vulkan error (no call
// failed: the backend declined what the core should have refused) is
// GRASS_ERROR_INVALID_STATE with GRASS_MSG_INTERNAL_ERROR.
grass_result report_failure(grass_context* context, const char* function, const char* what, const VkFailure& failure);

} // namespace grass::vk
