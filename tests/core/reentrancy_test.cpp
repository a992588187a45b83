// Re-entrancy (grass.h "Re-entrancy"): every call on a context made from inside one of its
// callbacks (a lod test callback, the log callback, an allocator hook) is refused with
// GRASS_MSG_REENTRANT_CALL and changes nothing; the pure getters answer. Each call kind is
// made from each callback kind. (Before, a lod test callback that destroyed its own field
// freed what grass_begin_frame was iterating: heap-use-after-free under ASan.)
#include "view_helpers.hpp"

#include <grass/grass.h>
#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

enum class Callback { lod_test, log, allocator };

const char* callback_name(Callback c) {
    switch (c) {
    case Callback::lod_test:
        return "lod_test";
    case Callback::log:
        return "log";
    case Callback::allocator:
        return "allocator";
    }
    return "?";
}

// The objects a call may act on, made before the callback runs.
struct Objects {
    grass_context* ctx = nullptr;
    grass_patch_id patch{};
    grass_field_id field{};
    grass_map_id map{};
    grass_field_desc field_desc{};
    grass_map_desc map_desc{};
    grass_view_desc view{};
    unsigned char texels[4] = {255, 255, 255, 255};
};

struct Call {
    const char* name;
    std::function<grass_result(Objects&)> run;
};

std::vector<Call> calls() {
    return {
        {"grass_create_patch",
         [](Objects& o) {
             grass_patch_desc d = grass_default_patch_desc();
             d.blade_count = 8;
             grass_patch_id p{};
             return grass_create_patch(o.ctx, &d, &p);
         }},
        {"grass_destroy_patch", [](Objects& o) { return grass_destroy_patch(o.ctx, o.patch); }},
        {"grass_get_patch_info",
         [](Objects& o) {
             grass_patch_info info{};
             return grass_get_patch_info(o.ctx, o.patch, &info);
         }},
        {"grass_get_patch_thresholds",
         [](Objects& o) {
             float t[64];
             return grass_get_patch_thresholds(o.ctx, o.patch, t, 64);
         }},
        {"grass_create_field",
         [](Objects& o) {
             grass_field_id f{};
             return grass_create_field(o.ctx, &o.field_desc, &f);
         }},
        {"grass_destroy_field", [](Objects& o) { return grass_destroy_field(o.ctx, o.field); }},
        {"grass_create_map",
         [](Objects& o) {
             grass_map_id m{};
             return grass_create_map(o.ctx, &o.map_desc, &m);
         }},
        {"grass_update_map", [](Objects& o) { return grass_update_map(o.ctx, o.map, 0, 0, &o.map_desc); }},
        {"grass_destroy_map", [](Objects& o) { return grass_destroy_map(o.ctx, o.map); }},
        {"grass_begin_frame", [](Objects& o) { return grass_begin_frame(o.ctx, &o.view); }},
        {"grass_end_frame", [](Objects& o) { return grass_end_frame(o.ctx); }},
        {"grass_get_frame_stats",
         [](Objects& o) {
             grass_frame_stats s{};
             return grass_get_frame_stats(o.ctx, &s);
         }},
        {"grass_get_memory_stats",
         [](Objects& o) {
             grass_memory_stats s{};
             return grass_get_memory_stats(o.ctx, &s);
         }},
        {"grass_get_tier_gpu_ms",
         [](Objects& o) {
             double ms[GRASS_TIER_KIND_COUNT];
             grass_bool available = 0;
             return grass_get_tier_gpu_ms(o.ctx, ms, &available);
         }},
        {"grass_apply_quality",
         [](Objects& o) {
             const grass_quality_desc q = grass_quality_preset(GRASS_QUALITY_DEFAULT);
             grass_patch_desc p = grass_default_patch_desc();
             grass_tier_desc tiers[GRASS_MAX_TIERS];
             grass_lod_test tests[GRASS_MAX_LOD_TESTS];
             uint32_t tier_count = 0, test_count = 0;
             return grass_apply_quality(o.ctx, &q, 0.25, &p, tiers, &tier_count, tests, &test_count);
         }},
        {"grass_set_blade_mechanics",
         [](Objects& o) {
             const grass_blade_mechanics m = grass_default_blade_mechanics();
             return grass_set_blade_mechanics(o.ctx, o.patch, &m);
         }},
        {"grass_set_wind", [](Objects& o) { return grass_set_wind(o.ctx, nullptr); }},
        {"grass_set_colliders", [](Objects& o) { return grass_set_colliders(o.ctx, nullptr, 0); }},
        {"grass_set_interaction", [](Objects& o) { return grass_set_interaction(o.ctx, nullptr); }},
        {"grass_set_field_wind_map", [](Objects& o) { return grass_set_field_wind_map(o.ctx, o.field, nullptr); }},
        {"grass_set_blade_culling", [](Objects& o) { return grass_set_blade_culling(o.ctx, o.field, nullptr); }},
        {"grass_set_blade_tessellation",
         [](Objects& o) { return grass_set_blade_tessellation(o.ctx, o.field, nullptr); }},
        {"grass_gl_render", [](Objects& o) { return grass_gl_render(o.ctx); }},
        {"grass_vk_record",
         [](Objects& o) {
             const grass_vk_record_desc r = grass_default_vk_record_desc();
             return grass_vk_record(o.ctx, &r);
         }},
        {"grass_vk_prepare",
         [](Objects& o) {
             int dummy = 0;
             grass_vk_prepare_desc p = grass_default_vk_prepare_desc();
             p.command_buffer = &dummy;
             return grass_vk_prepare(o.ctx, &p);
         }},
        {"grass_destroy_context",
         [](Objects& o) {
             grass_destroy_context(o.ctx); // refused: the context must stay alive
             return GRASS_ERROR_INVALID_STATE;
         }},
    };
}

// One run: the context, its objects, and the call the callback makes once when armed.
struct Armed {
    Objects objects;
    const Call* call = nullptr;
    bool armed = false;
    bool made = false; // the callback made the call
    grass_result result = GRASS_SUCCESS;
    std::string last_error_inside; // grass_get_last_error, read inside the callback after the call
    grass_backend backend_inside = GRASS_BACKEND_VULKAN;
    std::vector<grass_message_id> ids; // every message logged
    std::vector<std::string> messages;

    void fire() {
        if (!armed) return;
        armed = false;
        made = true;
        result = call->run(objects);
        last_error_inside = grass_get_last_error(objects.ctx);
        backend_inside = grass_get_context_backend(objects.ctx);
    }
};

void log_fn(void* user, grass_log_level, grass_message_id id, const char* message) {
    Armed* run = static_cast<Armed*>(user);
    run->ids.push_back(id);
    run->messages.push_back(message);
    run->fire();
}
void* alloc_fn(void* user, size_t size, size_t alignment) {
    Armed* run = static_cast<Armed*>(user);
    void* p = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    run->fire();
    return p;
}
void free_fn(void*, void* p) { std::free(p); }
grass_lod_answer lod_fn(void* user, const grass_lod_node*) {
    static_cast<Armed*>(user)->fire();
    return GRASS_LOD_DRAW;
}

class ReentrancyTest : public ::testing::TestWithParam<Callback> {
protected:
    void SetUp() override {
        grass_context_desc d = grass_default_context_desc();
        d.log_fn = log_fn;
        d.log_user_data = &run_;
        d.allocator.alloc_fn = alloc_fn;
        d.allocator.free_fn = free_fn;
        d.allocator.user_data = &run_;
        ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &run_.objects.ctx), GRASS_SUCCESS);
        Objects& o = run_.objects;
        grass_patch_desc pd = grass_default_patch_desc();
        pd.blade_count = 16;
        ASSERT_EQ(grass_create_patch(o.ctx, &pd, &o.patch), GRASS_SUCCESS);
        tier_.kind = GRASS_TIER_GEOMETRY;
        test_.kind = GRASS_LOD_TEST_CALLBACK;
        test_.callback = lod_fn;
        test_.user_data = &run_;
        o.field_desc = grass_default_field_desc();
        o.field_desc.patch = o.patch;
        o.field_desc.cells_x = o.field_desc.cells_z = 2;
        o.field_desc.tiers = &tier_;
        o.field_desc.tier_count = 1;
        o.field_desc.lod_tests = &test_;
        o.field_desc.lod_test_count = 1;
        ASSERT_EQ(grass_create_field(o.ctx, &o.field_desc, &o.field), GRASS_SUCCESS);
        o.map_desc = grass_default_map_desc();
        o.map_desc.width = o.map_desc.height = 2;
        o.map_desc.row_pitch = 2;
        o.map_desc.pixels = o.texels;
        ASSERT_EQ(grass_create_map(o.ctx, &o.map_desc, &o.map), GRASS_SUCCESS);
        const double eye[3] = {0.25, 2.0, 0.25}, target[3] = {0.25, 0.0, 0.26};
        o.view = test_view(eye, target);
    }
    void TearDown() override { grass_destroy_context(run_.objects.ctx); }

    // Makes a call that runs the callback kind `c` with `call` armed.
    void trigger(Callback c, const Call& call) {
        run_.call = &call;
        run_.armed = true;
        Objects& o = run_.objects;
        switch (c) {
        case Callback::lod_test:
            ASSERT_EQ(grass_begin_frame(o.ctx, &o.view), GRASS_SUCCESS) << grass_get_last_error(o.ctx);
            ASSERT_EQ(grass_end_frame(o.ctx), GRASS_SUCCESS);
            break;
        case Callback::log: {
            grass_patch_id p{};
            ASSERT_EQ(grass_create_patch(o.ctx, nullptr, &p), GRASS_ERROR_INVALID_ARGUMENT); // logs an error
            break;
        }
        case Callback::allocator: {
            grass_patch_desc pd = grass_default_patch_desc();
            pd.blade_count = 8;
            grass_patch_id p{};
            ASSERT_EQ(grass_create_patch(o.ctx, &pd, &p), GRASS_SUCCESS); // allocates
            break;
        }
        }
    }

    // The objects of SetUp are all there and usable, and a frame still plans.
    void expect_state_intact() {
        Objects& o = run_.objects;
        grass_patch_info info{};
        EXPECT_EQ(grass_get_patch_info(o.ctx, o.patch, &info), GRASS_SUCCESS) << "the patch is alive";
        EXPECT_EQ(grass_set_blade_culling(o.ctx, o.field, nullptr), GRASS_SUCCESS) << "the field is alive";
        EXPECT_EQ(grass_update_map(o.ctx, o.map, 0, 0, &o.map_desc), GRASS_SUCCESS) << "the map is alive";
        EXPECT_EQ(grass_begin_frame(o.ctx, &o.view), GRASS_SUCCESS) << grass_get_last_error(o.ctx);
        EXPECT_EQ(grass_end_frame(o.ctx), GRASS_SUCCESS);
        grass_frame_stats s{};
        ASSERT_EQ(grass_get_frame_stats(o.ctx, &s), GRASS_SUCCESS);
        EXPECT_EQ(s.cells_drawn, 4u);
    }

    Armed run_;
    grass_tier_desc tier_{};
    grass_lod_test test_{};
};

TEST_P(ReentrancyTest, EveryCallOnTheContextIsRefusedAndChangesNothing) {
    const Callback c = GetParam();
    bool fresh = true; // the fixture's SetUp made the first context
    for (const Call& call : calls()) {
        SCOPED_TRACE(std::string(call.name) + " from the " + callback_name(c) + " callback");
        if (!fresh) {
            TearDown();
            run_ = Armed();
            SetUp();
        }
        fresh = false;
        trigger(c, call);
        ASSERT_TRUE(run_.made) << "the callback ran";
        EXPECT_EQ(run_.result, GRASS_ERROR_INVALID_STATE);
        EXPECT_NE(run_.last_error_inside.find(call.name), std::string::npos) << run_.last_error_inside;
        EXPECT_NE(run_.last_error_inside.find("from inside"), std::string::npos) << run_.last_error_inside;
        EXPECT_EQ(run_.backend_inside, GRASS_BACKEND_NONE) << "grass_get_context_backend answers inside";
        size_t refusals = 0;
        for (grass_message_id id : run_.ids) refusals += id == GRASS_MSG_REENTRANT_CALL;
        // A refusal inside the log callback is not logged again (no recursion); inside the
        // other callbacks it is.
        EXPECT_EQ(refusals, c == Callback::log ? 0u : 1u);
        expect_state_intact();
    }
}

INSTANTIATE_TEST_SUITE_P(Callbacks, ReentrancyTest,
                         ::testing::Values(Callback::lod_test, Callback::log, Callback::allocator),
                         [](const auto& p) { return callback_name(p.param); });

// A log callback that calls its context on every message (as a careless host might, to
// read more): each refusal is kept as the last error, and nothing recurses.
TEST(Reentrancy, ALogCallbackThatAlwaysCallsBackEndsAfterOneMessage) {
    struct State {
        grass_context* ctx = nullptr;
        int messages = 0;
    } state;
    grass_context_desc d = grass_default_context_desc();
    d.log_user_data = &state;
    d.log_fn = [](void* user, grass_log_level, grass_message_id, const char*) {
        auto* s = static_cast<State*>(user);
        s->messages += 1;
        if (s->messages > 100) std::abort(); // a recursion
        grass_patch_id p{};
        EXPECT_EQ(grass_create_patch(s->ctx, nullptr, &p), GRASS_ERROR_INVALID_STATE);
    };
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &state.ctx), GRASS_SUCCESS);
    grass_patch_id p{};
    EXPECT_EQ(grass_create_patch(state.ctx, nullptr, &p), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(state.messages, 1);
    EXPECT_NE(std::string(grass_get_last_error(state.ctx)).find("log callback"), std::string::npos)
        << grass_get_last_error(state.ctx);
    grass_destroy_context(state.ctx);
}

// Calls on another context from inside a callback are allowed: contexts share nothing.
TEST(Reentrancy, ALodTestCallbackMayCallAnotherContext) {
    struct State {
        grass_context* other = nullptr;
        grass_result result = GRASS_ERROR_BACKEND;
    } state;
    grass_context_desc d = grass_default_context_desc();
    grass_context* ctx = nullptr;
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &ctx), GRASS_SUCCESS);
    ASSERT_EQ(grass_create_context(GRASS_HEADER_VERSION, &d, &state.other), GRASS_SUCCESS);
    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 16;
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS);
    grass_tier_desc tier{};
    tier.kind = GRASS_TIER_GEOMETRY;
    grass_lod_test test{};
    test.kind = GRASS_LOD_TEST_CALLBACK;
    test.user_data = &state;
    test.callback = [](void* user, const grass_lod_node*) {
        auto* s = static_cast<State*>(user);
        grass_patch_desc p = grass_default_patch_desc();
        p.blade_count = 8;
        grass_patch_id id{};
        s->result = grass_create_patch(s->other, &p, &id);
        return GRASS_LOD_DRAW;
    };
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 1;
    fd.tiers = &tier;
    fd.tier_count = 1;
    fd.lod_tests = &test;
    fd.lod_test_count = 1;
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS);
    const double eye[3] = {0.1, 2.0, 0.1}, target[3] = {0.1, 0.0, 0.11};
    const grass_view_desc v = test_view(eye, target);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << grass_get_last_error(ctx);
    EXPECT_EQ(state.result, GRASS_SUCCESS) << grass_get_last_error(state.other);
    EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    grass_destroy_context(state.other);
    grass_destroy_context(ctx);
}

} // namespace
