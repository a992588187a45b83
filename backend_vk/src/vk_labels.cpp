#include "vk_labels.hpp"

#include <cstdio>
#include <cstring>

namespace grass::vk {

bool load_labels(grass_debug_labels labels, grass_vk_get_instance_proc_addr_fn get_instance_proc_addr,
                 VkInstance instance, Functions* out) {
    out->vkSetDebugUtilsObjectNameEXT = nullptr;
    out->vkCmdBeginDebugUtilsLabelEXT = nullptr;
    out->vkCmdEndDebugUtilsLabelEXT = nullptr;
    if (labels == GRASS_DEBUG_LABELS_OFF) return true;
    // The loader returns these only when the host enabled VK_EXT_debug_utils on the instance.
    const auto name = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        get_instance_proc_addr(instance, "vkSetDebugUtilsObjectNameEXT"));
    const auto begin = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        get_instance_proc_addr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
    const auto end = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        get_instance_proc_addr(instance, "vkCmdEndDebugUtilsLabelEXT"));
    if (!name || !begin || !end) return false;
    out->vkSetDebugUtilsObjectNameEXT = name;
    out->vkCmdBeginDebugUtilsLabelEXT = begin;
    out->vkCmdEndDebugUtilsLabelEXT = end;
    return true;
}

void set_object_name(const Functions& fn, VkDevice device, VkObjectType type, uint64_t handle, const char* name) {
    // "the blade pipelines" (a failure message's words) becomes "grass blade pipelines".
    char named[160];
    if (std::strncmp(name, "grass ", 6) != 0) {
        static const char* const kArticles[] = {"the ", "a ", "an "};
        for (const char* article : kArticles) {
            const size_t n = std::strlen(article);
            if (std::strncmp(name, article, n) == 0) {
                name += n;
                break;
            }
        }
        std::snprintf(named, sizeof(named), "grass %s", name);
        name = named;
    }
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name;
    // Naming is a debugging aid: a failure (out of host memory) changes nothing grass does.
    (void)fn.vkSetDebugUtilsObjectNameEXT(device, &info);
}

void LabelScope::begin(const char* name) {
    VkDebugUtilsLabelEXT label{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    label.pLabelName = name;
    // A grass green, for the frame debuggers that colour labels.
    label.color[0] = 0.3f;
    label.color[1] = 0.7f;
    label.color[2] = 0.2f;
    label.color[3] = 1.0f;
    fn_.vkCmdBeginDebugUtilsLabelEXT(cmd_, &label);
}

} // namespace grass::vk
