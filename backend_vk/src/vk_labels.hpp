// Debug labels and object names through VK_EXT_debug_utils (grass.h, grass_debug_labels):
// every object grass creates is named "grass ...", and its work in a command buffer is
// grouped under labels that RenderDoc, Nsight and the validation layers show. The host
// enables the instance extension (grass cannot); grass finds it through the host's
// vkGetInstanceProcAddr. Off (the functions not loaded), naming and labelling cost one
// branch and build no string.
#pragma once

#include "vk_functions.hpp"

#include <cstdint>
#include <type_traits>

namespace grass::vk {

// Loads vkSetDebugUtilsObjectNameEXT, vkCmdBeginDebugUtilsLabelEXT and
// vkCmdEndDebugUtilsLabelEXT into `out` when `labels` (the context's grass_debug_labels)
// asks for them and the instance has VK_EXT_debug_utils: all three, or none. Returns false
// when the extension is not there (the table then has none).
bool load_labels(grass_debug_labels labels, grass_vk_get_instance_proc_addr_fn get_instance_proc_addr,
                 VkInstance instance, Functions* out);

void set_object_name(const Functions& fn, VkDevice device, VkObjectType type, uint64_t handle, const char* name);

// Names `handle` (of `type`) `name` where labels are on: a literal beginning "grass ", or
// the words a failure message uses ("the blade pipelines"), named "grass blade pipelines".
template <class Handle>
inline void name_object(const Functions& fn, VkDevice device, VkObjectType type, Handle handle, const char* name) {
    if (!fn.vkSetDebugUtilsObjectNameEXT || handle == VK_NULL_HANDLE) return;
    // Non-dispatchable handles are pointers on 64-bit platforms and uint64_t elsewhere.
    if constexpr (std::is_pointer_v<Handle>) {
        set_object_name(fn, device, type, reinterpret_cast<uint64_t>(handle), name);
    } else {
        set_object_name(fn, device, type, static_cast<uint64_t>(handle), name);
    }
}

// A label around the commands recorded while it lives (vkCmdBegin/EndDebugUtilsLabelEXT).
class LabelScope {
public:
    LabelScope(const Functions& fn, VkCommandBuffer cmd, const char* name) : fn_(fn), cmd_(cmd) {
        if (fn_.vkCmdBeginDebugUtilsLabelEXT) begin(name);
    }
    ~LabelScope() {
        if (fn_.vkCmdEndDebugUtilsLabelEXT) fn_.vkCmdEndDebugUtilsLabelEXT(cmd_);
    }
    LabelScope(const LabelScope&) = delete;
    LabelScope& operator=(const LabelScope&) = delete;

private:
    void begin(const char* name);
    const Functions& fn_;
    VkCommandBuffer cmd_;
};

} // namespace grass::vk
