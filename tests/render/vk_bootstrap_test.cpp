// The hosts' Vulkan bootstrap (test_hosts/bootstrap/vk_bootstrap.*): a message through the
// instance's messenger reaches the host's sink as one "[error] ..." or "[warning] ..." line.
// That is the path by which a validation message fails every Vulkan render test.
#include "driver_residency.hpp"
#include "vk_bootstrap.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

void collect(void* user, const std::string& line) { static_cast<std::vector<std::string>*>(user)->push_back(line); }

void submit(VkInstance instance, VkDebugUtilsMessageSeverityFlagBitsEXT severity, const char* text) {
    auto fn = reinterpret_cast<PFN_vkSubmitDebugUtilsMessageEXT>(
        vkGetInstanceProcAddr(instance, "vkSubmitDebugUtilsMessageEXT"));
    ASSERT_NE(fn, nullptr);
    VkDebugUtilsMessengerCallbackDataEXT data{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CALLBACK_DATA_EXT};
    data.pMessage = text;
    fn(instance, severity, VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT, &data);
}

} // namespace

TEST(VkBootstrap, TheMessengerHandsEveryWarningAndErrorToTheSink) {
    std::vector<std::string> lines;
    const grass_bootstrap::VkMessageSink sink{&collect, &lines};
    grass_bootstrap::VkBootInstance instance;
    grass_bootstrap::VkInstanceDesc desc;
    desc.application = "grass bootstrap test";
    desc.messenger_without_layer = true; // as the headless host
    desc.sink = &sink;
    std::string error;
    ASSERT_TRUE(instance.create(desc, &error)) << error;
    // As the hosts do: the layer and the ICDs stay loaded past vkDestroyInstance, so that
    // LeakSanitizer can name their allocations (tests/sanitizer/lsan.supp matches them by
    // library; once unloaded, a layer's buffer is an "<unknown module>" leak).
    static const char* const kDrivers[] = {"libvulkan_", "libVkLayer_", nullptr};
    grass_host::keep_drivers_resident(kDrivers);
    if (!vkGetInstanceProcAddr(instance.handle(), "vkSubmitDebugUtilsMessageEXT")) {
        GTEST_SKIP() << "neither the validation layer nor VK_EXT_debug_utils is installed";
    }
    lines.clear(); // whatever creation reported
    submit(instance.handle(), VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT, "an error");
    submit(instance.handle(), VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT, "a warning");
    submit(instance.handle(), VK_DEBUG_UTILS_MESSAGE_SEVERITY_INFO_BIT_EXT, "information"); // not asked for
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "[error] an error");
    EXPECT_EQ(lines[1], "[warning] a warning");
}
