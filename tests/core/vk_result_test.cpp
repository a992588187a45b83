// How the Vulkan backend reports a failure (backend_vk/src/vk_result.hpp), without a device:
// the code and message id for each kind of VkResult, and a failure without one.
#include "vk_result.hpp"

#include <grass/grass.h>

#include <gtest/gtest.h>

#include <string>

namespace {

struct Logged {
    grass_message_id id = GRASS_MSG_NONE;
    std::string text;
};

class VkResultTest : public ::testing::Test {
protected:
    void SetUp() override {
        grass_context_desc d = grass_default_context_desc();
        d.log_fn = [](void* user, grass_log_level, grass_message_id id, const char* message) {
            auto* logged = static_cast<Logged*>(user);
            logged->id = id;
            logged->text = message;
        };
        d.log_user_data = &logged_;
        ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &ctx_), GRASS_SUCCESS);
    }
    void TearDown() override { grass_destroy_context(ctx_); }
    grass_context* ctx_ = nullptr;
    Logged logged_;
};

TEST_F(VkResultTest, AFailedCallIsNamedWithItsResult) {
    const grass::vk::VkFailure failure{"vkCreateGraphicsPipelines", VK_ERROR_INITIALIZATION_FAILED};
    EXPECT_EQ(grass::vk::report_failure(ctx_, "grass_vk_record", "a blade pipeline", failure), GRASS_ERROR_BACKEND);
    EXPECT_EQ(logged_.id, GRASS_MSG_BACKEND_CALL_FAILED);
    EXPECT_NE(logged_.text.find("vkCreateGraphicsPipelines failed with VK_ERROR_INITIALIZATION_FAILED"),
              std::string::npos)
        << logged_.text;
}

TEST_F(VkResultTest, OutOfMemoryAndDeviceLostHaveTheirOwnIds) {
    EXPECT_EQ(grass::vk::report_failure(ctx_, "f", "w", {"vkAllocateMemory", VK_ERROR_OUT_OF_DEVICE_MEMORY}),
              GRASS_ERROR_OUT_OF_MEMORY);
    EXPECT_EQ(logged_.id, GRASS_MSG_OUT_OF_MEMORY);
    EXPECT_EQ(grass::vk::report_failure(ctx_, "f", "w", {"vkQueueSubmit", VK_ERROR_DEVICE_LOST}), GRASS_ERROR_BACKEND);
    EXPECT_EQ(logged_.id, GRASS_MSG_DEVICE_LOST);
}

// A pipeline the backend declines without a Vulkan error (the core should have refused the
// view first) is grass's bug: never "a Vulkan call failed with VK_SUCCESS".
TEST_F(VkResultTest, ADeclinedPipelineIsNotAFailedVulkanCall) {
    const grass::vk::VkFailure none{};
    EXPECT_EQ(
        grass::vk::report_failure(ctx_, "grass_vk_record", "a depth-only pipeline (no grass_vk_depth_pass_desc)", none),
        GRASS_ERROR_INVALID_STATE);
    EXPECT_EQ(logged_.id, GRASS_MSG_INTERNAL_ERROR);
    EXPECT_EQ(logged_.text.find("VK_SUCCESS"), std::string::npos) << logged_.text;
    EXPECT_NE(logged_.text.find("a depth-only pipeline (no grass_vk_depth_pass_desc)"), std::string::npos)
        << logged_.text;
}

} // namespace
