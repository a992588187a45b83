/* A host hands vkGetInstanceProcAddr to grass with no cast: grass_vk_get_instance_proc_addr_fn
 * is PFN_vkGetInstanceProcAddr's very type, calling convention (VKAPI_PTR) included, though
 * grass_vk.h includes no Vulkan header (ctest header_vk_loader_is_c and _is_cpp: this file
 * as C99 and as C++11, -pedantic -Wall -Wextra -Werror; in C an incompatible pointer type
 * is a warning, so an error here). A host callback is defined with GRASS_API_PTR. */
#include <grass/grass_vk.h>
#include <vulkan/vulkan.h>

#ifdef __cplusplus
#    include <type_traits>
static_assert(std::is_same<grass_vk_get_instance_proc_addr_fn, PFN_vkGetInstanceProcAddr>::value,
              "grass_vk_get_instance_proc_addr_fn is PFN_vkGetInstanceProcAddr");
#endif

static void GRASS_API_PTR log_message(void* user_data, grass_log_level level, grass_message_id id,
                                      const char* message) {
    (void)user_data;
    (void)level;
    (void)id;
    (void)message;
}

grass_vk_desc make_vk_desc(void);
grass_vk_desc make_vk_desc(void) {
    grass_vk_desc vk = grass_default_vk_desc();
    vk.get_instance_proc_addr = vkGetInstanceProcAddr;
    return vk;
}

/* Debug labels on whatever the context (GRASS_DEBUG_LABELS_AUTO, the default, labels in
 * debug contexts only): `labels` must live until the create call returns. */
grass_context_desc make_context_desc(grass_debug_labels_desc* labels);
grass_context_desc make_context_desc(grass_debug_labels_desc* labels) {
    grass_context_desc desc = grass_default_context_desc();
    desc.log_fn = log_message;
    *labels = grass_default_debug_labels_desc();
    labels->labels = GRASS_DEBUG_LABELS_ON;
    desc.next = labels;
    return desc;
}
