// The small Vulkan scene of the responsive passes' tests (vk_interaction_test.cpp,
// vk_blade_window_test.cpp): a 4 m x 4 m field of blades (16 x 16 cells of the default patch)
// on a 96 x 96 target, through grass's own dispatch table (vk_intercept.hpp), with the
// context's messages kept; the validation layers must stay silent to its end.
#pragma once

#include "render_fixture.hpp"
#include "vk_intercept.hpp"

#include <memory>
#include <string>

namespace grass_test {

struct VkSmallScene {
    std::unique_ptr<grass_host::Host> host;
    grass_context* ctx = nullptr;
    std::string log;
    ~VkSmallScene() {
        if (ctx) grass_destroy_context(ctx);
        if (host) {
            EXPECT_EQ(host->validation_messages(), 0u) << host->validation_log();
        }
    }
};

inline void make_small_scene(VkSmallScene* s) {
    grass_host::TargetDesc t;
    t.width = t.height = 96;
    t.vk_get_instance_proc_addr = vk_intercept::get_instance_proc_addr();
    std::string error;
    s->host = grass_host::Host::create(GRASS_BACKEND_VULKAN, t, &error);
    ASSERT_TRUE(s->host) << error;
    grass_context_desc cd = grass_default_context_desc();
    cd.log_user_data = &s->log;
    cd.log_fn = [](void* user, grass_log_level, grass_message_id id, const char* message) {
        *static_cast<std::string*>(user) += std::to_string(int(id)) + ": " + message + "\n";
    };
    ASSERT_EQ(s->host->create_context(cd, &s->ctx), GRASS_SUCCESS) << s->log;
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(s->ctx, &pd, &patch), GRASS_SUCCESS) << s->log;
    grass_field_id field{};
    ASSERT_EQ(create_blade_field(s->ctx, patch, 16, &field), GRASS_SUCCESS) << s->log;
}

} // namespace grass_test
