#include "vk_functions.hpp"

namespace grass::vk {

const char* load_functions(grass_vk_get_instance_proc_addr_fn get_instance_proc_addr, VkInstance instance,
                           VkDevice device, Functions* out) {
    // The loader hands out PFN_vkVoidFunction; each is cast back to its real type.
#define GRASS_VK_LOAD_INSTANCE(name)                                                   \
    out->name = reinterpret_cast<PFN_##name>(get_instance_proc_addr(instance, #name)); \
    if (!out->name) return #name;
    GRASS_VK_INSTANCE_FUNCTIONS(GRASS_VK_LOAD_INSTANCE)
#undef GRASS_VK_LOAD_INSTANCE

#define GRASS_VK_LOAD_DEVICE(name)                                                     \
    out->name = reinterpret_cast<PFN_##name>(out->vkGetDeviceProcAddr(device, #name)); \
    if (!out->name) return #name;
    GRASS_VK_DEVICE_FUNCTIONS(GRASS_VK_LOAD_DEVICE)
#undef GRASS_VK_LOAD_DEVICE
#define GRASS_VK_LOAD_OPTIONAL_INSTANCE(name) \
    out->name = reinterpret_cast<PFN_##name>(get_instance_proc_addr(instance, #name));
    GRASS_VK_OPTIONAL_INSTANCE_FUNCTIONS(GRASS_VK_LOAD_OPTIONAL_INSTANCE)
#undef GRASS_VK_LOAD_OPTIONAL_INSTANCE
#define GRASS_VK_LOAD_OPTIONAL_DEVICE(name) \
    out->name = reinterpret_cast<PFN_##name>(out->vkGetDeviceProcAddr(device, #name));
    GRASS_VK_OPTIONAL_DEVICE_FUNCTIONS(GRASS_VK_LOAD_OPTIONAL_DEVICE)
#undef GRASS_VK_LOAD_OPTIONAL_DEVICE
    return nullptr;
}

} // namespace grass::vk
