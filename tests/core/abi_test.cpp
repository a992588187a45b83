// The ABI promise (grass.h, "ABI and versions"): accepted header versions, getters that write
// only the caller's struct size, the fields grown in 0.4, the id helpers and the 0.3 names
// (and the 0.4 names renamed in 0.5).
// The 0.3 names: exported for binaries built against grass.h 0.3, declared (deprecated) to
// sources that define GRASS_ENABLE_DEPRECATED; this test calls them on purpose.
#define GRASS_ENABLE_DEPRECATED 1
#include "core_fixture.hpp"
#include "foundation/abi_sizes.hpp"
#include "view_helpers.hpp"

#include <grass/grass_gl.h>
#include <grass/grass_vk.h>

#include <cstring>

#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

namespace {

constexpr uint32_t header_version(uint32_t major, uint32_t minor, uint32_t patch = 0) {
    return (major << 22) | (minor << 12) | patch;
}

struct Refusal {
    grass_result result = GRASS_SUCCESS;
    grass_message_id id = GRASS_MSG_NONE;
    std::string message;
};

Refusal create_with(uint32_t version, grass_context** out) {
    Refusal r;
    grass_context_desc d = grass_default_context_desc();
    d.log_fn = [](void* user, grass_log_level, grass_message_id id, const char* message) {
        static_cast<Refusal*>(user)->id = id;
        static_cast<Refusal*>(user)->message = message;
    };
    d.log_user_data = &r;
    r.result = grass_create_context(version, &d, out);
    return r;
}

TEST(HeaderVersion, OlderThan03NewerThanTheLibraryOrAnotherMajorIsRefusedNamingBoth) {
    const std::string library = std::to_string(GRASS_VERSION_MAJOR) + "." + std::to_string(GRASS_VERSION_MINOR);
    const uint32_t cases[] = {header_version(0, 2), header_version(0, GRASS_VERSION_MINOR + 1),
                              header_version(1, GRASS_VERSION_MINOR)};
    for (const uint32_t version : cases) {
        grass_context* ctx = nullptr;
        const Refusal r = create_with(version, &ctx);
        EXPECT_EQ(r.result, GRASS_ERROR_VERSION_MISMATCH) << std::hex << version;
        EXPECT_EQ(ctx, nullptr);
        EXPECT_EQ(r.id, GRASS_MSG_VERSION_MISMATCH);
        const uint32_t minor = (version >> 12) & 0x3ff, major = version >> 22;
        const std::string header = "grass.h " + std::to_string(major) + "." + std::to_string(minor);
        EXPECT_NE(r.message.find(header), std::string::npos) << r.message;
        EXPECT_NE(r.message.find("library is " + library), std::string::npos) << r.message;
    }
}

TEST(HeaderVersion, From03ToTheLibrarysOwnIsAccepted) {
    for (uint32_t minor = grass::kOldestHeaderMinor; minor <= GRASS_VERSION_MINOR; ++minor) {
        grass_context* ctx = nullptr;
        const Refusal r = create_with(header_version(0, minor, 7), &ctx);
        EXPECT_EQ(r.result, GRASS_SUCCESS) << "0." << minor << ": " << r.message;
        grass_destroy_context(ctx);
    }
    EXPECT_EQ(grass_get_library_version(), GRASS_HEADER_VERSION);
    EXPECT_EQ(grass_get_library_version() >> 22, 0u);
    EXPECT_EQ((grass_get_library_version() >> 12) & 0x3ffu, 5u);
}

TEST(OutStructSizes, TheCurrentHeaderGetsWholeStructsAnd03GetsItsOwn) {
    using grass::OutStruct;
    EXPECT_EQ(grass::out_struct_size(OutStruct::frame_stats, GRASS_VERSION_MINOR), sizeof(grass_frame_stats));
    EXPECT_EQ(grass::out_struct_size(OutStruct::memory_stats, GRASS_VERSION_MINOR), sizeof(grass_memory_stats));
    EXPECT_EQ(grass::out_struct_size(OutStruct::patch_info, GRASS_VERSION_MINOR), sizeof(grass_patch_info));
    EXPECT_EQ(grass::out_struct_size(OutStruct::frame_stats, 3), offsetof(grass_frame_stats, draws));
    EXPECT_EQ(grass::out_struct_size(OutStruct::memory_stats, 3), offsetof(grass_memory_stats, host_bytes_peak));
    EXPECT_EQ(grass::out_struct_size(OutStruct::patch_info, 3), sizeof(grass_patch_info));
    EXPECT_EQ(grass::out_struct_size(OutStruct::frame_stats, 4), offsetof(grass_frame_stats, colliders));
    EXPECT_EQ(grass::out_struct_size(OutStruct::memory_stats, 4), offsetof(grass_memory_stats, dynamics_gpu_bytes));
}

// A context made with the 0.3 header version: the getters leave every byte past the 0.3
// struct untouched (a 0.3 host has no memory there).
TEST(OutStructSizes, A03ContextsGettersWriteNothingPastThe03Structs) {
    grass_context* ctx = nullptr;
    ASSERT_EQ(create_with(header_version(0, 3), &ctx).result, GRASS_SUCCESS);
    grass_patch_desc pd = grass_default_patch_desc();
    grass_patch_id patch{};
    ASSERT_EQ(grass_create_patch(ctx, &pd, &patch), GRASS_SUCCESS);
    grass_field_desc fd = grass_default_field_desc();
    fd.patch = patch;
    fd.cells_x = fd.cells_z = 32;
    grass_field_id field{};
    ASSERT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS);
    const double eye[3] = {4, 1.7, -2}, target[3] = {4, 0, 4};
    const grass_view_desc view = test_view(eye, target);
    ASSERT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);

    grass_frame_stats fs;
    std::memset(&fs, 0xab, sizeof(fs));
    ASSERT_EQ(grass_get_frame_stats(ctx, &fs), GRASS_SUCCESS);
    EXPECT_EQ(fs.fields_drawn, 1u);
    EXPECT_GT(fs.cells_drawn, 0u);
    EXPECT_EQ(fs.draws, 0xababababababababull); // not written: past the 0.3 struct

    grass_memory_stats ms;
    std::memset(&ms, 0xab, sizeof(ms));
    ASSERT_EQ(grass_get_memory_stats(ctx, &ms), GRASS_SUCCESS);
    EXPECT_GT(ms.host_bytes, 0u);
    EXPECT_EQ(ms.host_bytes_peak, 0xababababababababull);

    grass_patch_info info;
    std::memset(&info, 0xab, sizeof(info));
    ASSERT_EQ(grass_get_patch_info(ctx, patch, &info), GRASS_SUCCESS);
    EXPECT_EQ(info.blade_count, pd.blade_count);
    grass_destroy_context(ctx);
}

class GrownFieldsTest : public CoreTest {
protected:
    grass_field_id make_field(grass_patch_id patch, double x_offset, const grass_tier_desc* tiers, uint32_t tier_count,
                              const grass_lod_test* tests, uint32_t test_count) {
        grass_field_desc fd = grass_default_field_desc();
        fd.patch = patch;
        fd.cells_x = fd.cells_z = 16;
        fd.base_transform[12] = x_offset;
        fd.tiers = tiers;
        fd.tier_count = tier_count;
        fd.lod_tests = tests;
        fd.lod_test_count = test_count;
        grass_field_id field{};
        EXPECT_EQ(grass_create_field(ctx, &fd, &field), GRASS_SUCCESS) << last_message();
        return field;
    }
    grass_frame_stats frame(const double eye[3], const double target[3]) {
        const grass_view_desc view = test_view(eye, target);
        EXPECT_EQ(grass_begin_frame(ctx, &view), GRASS_SUCCESS) << last_message();
        EXPECT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
        grass_frame_stats fs;
        std::memset(&fs, 0xab, sizeof(fs));
        EXPECT_EQ(grass_get_frame_stats(ctx, &fs), GRASS_SUCCESS);
        return fs;
    }
};

// draws: one instanced draw per field and tier that draws at least one instance.
TEST_F(GrownFieldsTest, DrawsCountsOnePerFieldAndTierThatDraws) {
    const grass_patch_id patch = make_patch();
    // One geometry tier at every distance.
    const grass_tier_desc blades[1] = {{GRASS_TIER_GEOMETRY, 0}};
    grass_lod_test everywhere{};
    everywhere.kind = GRASS_LOD_TEST_DISTANCE_BAND;
    everywhere.tier = 0;
    everywhere.begin = 0.0f;
    everywhere.end = INFINITY;
    make_field(patch, 0.0, blades, 1, &everywhere, 1);
    const double eye[3] = {2, 1.7, -2}, target[3] = {2, 0, 2}, away[3] = {2, 1.7, -10};
    const grass_frame_stats one = frame(eye, target);
    EXPECT_EQ(one.draws, 1u);
    EXPECT_EQ(one.fields_drawn, 1u);

    // A second field with a geometry and an image tier, split at 4 m (the field spans 2.6 to
    // 6.5 m from the camera): both tiers draw.
    const grass_tier_desc two[2] = {{GRASS_TIER_GEOMETRY, 0}, {GRASS_TIER_IMAGE, 0}};
    grass_lod_test bands[3] = {};
    bands[0].kind = bands[1].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    bands[0].tier = 0;
    bands[0].begin = 0.0f;
    bands[0].end = 4.0f;
    bands[1].tier = 1;
    bands[1].begin = 4.0f;
    bands[1].end = INFINITY;
    bands[2].kind = GRASS_LOD_TEST_MACRO_CELL;
    bands[2].tier = 1;
    bands[2].max_macro_cells = 4;
    make_field(patch, 0.0, two, 2, bands, 3);
    grass_frame_stats fs = frame(eye, target);
    EXPECT_EQ(fs.fields_drawn, 2u);
    EXPECT_GT(fs.cells_drawn, one.cells_drawn); // the second field's geometry tier draws too
    EXPECT_GT(fs.instances[GRASS_TIER_IMAGE], 0u);
    EXPECT_EQ(fs.draws, 3u);

    // Looking away: nothing is drawn.
    fs = frame(eye, away);
    EXPECT_EQ(fs.fields_drawn, 0u);
    EXPECT_EQ(fs.draws, 0u);
}

TEST_F(GrownFieldsTest, HostBytesPeakKeepsTheHighWaterMark) {
    grass_memory_stats before;
    std::memset(&before, 0xab, sizeof(before));
    ASSERT_EQ(grass_get_memory_stats(ctx, &before), GRASS_SUCCESS);
    EXPECT_GE(before.host_bytes_peak, before.host_bytes);

    grass_patch_desc pd = grass_default_patch_desc();
    pd.blade_count = 4096;
    const grass_patch_id patch = make_patch(pd);
    grass_memory_stats with_patch{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &with_patch), GRASS_SUCCESS);
    EXPECT_GT(with_patch.host_bytes, before.host_bytes);
    EXPECT_GE(with_patch.host_bytes_peak, with_patch.host_bytes);

    ASSERT_EQ(grass_destroy_patch(ctx, patch), GRASS_SUCCESS);
    grass_memory_stats after{};
    ASSERT_EQ(grass_get_memory_stats(ctx, &after), GRASS_SUCCESS);
    EXPECT_LT(after.host_bytes, with_patch.host_bytes);
    EXPECT_GE(after.host_bytes_peak, with_patch.host_bytes); // the peak stays
    EXPECT_GE(after.host_bytes_peak, with_patch.host_bytes_peak);
}

TEST_F(CoreTest, IdHelpersCompareEveryMemberAndKnowTheNullId) {
    const grass_patch_id a = make_patch(), b = make_patch();
    EXPECT_TRUE(grass_patch_id_equal(a, a));
    EXPECT_FALSE(grass_patch_id_equal(a, b));
    grass_patch_id same_slot_other_generation = a;
    same_slot_other_generation.generation += 1;
    EXPECT_FALSE(grass_patch_id_equal(a, same_slot_other_generation));
    grass_patch_id other_owner = a;
    other_owner.owner ^= 1;
    EXPECT_FALSE(grass_patch_id_equal(a, other_owner));
    EXPECT_FALSE(grass_patch_id_is_null(a));
    EXPECT_TRUE(grass_patch_id_is_null(grass_patch_id{}));
    EXPECT_TRUE(grass_patch_id_equal(grass_patch_id{}, grass_patch_id{}));

    const grass_field_id f1{1, 2, 3}, f2{1, 2, 4};
    EXPECT_TRUE(grass_field_id_equal(f1, f1));
    EXPECT_FALSE(grass_field_id_equal(f1, f2));
    EXPECT_TRUE(grass_field_id_is_null(grass_field_id{}));
    EXPECT_FALSE(grass_field_id_is_null(grass_field_id{0, 1, 0}));
    const grass_map_id m1{5, 0, 7}, m2{6, 0, 7};
    EXPECT_TRUE(grass_map_id_equal(m1, m1));
    EXPECT_FALSE(grass_map_id_equal(m1, m2));
    EXPECT_TRUE(grass_map_id_is_null(grass_map_id{}));
    EXPECT_FALSE(grass_map_id_is_null(m1));
}

TEST_F(CoreTest, The03NamesStillAnswer) {
    EXPECT_EQ(grass_context_backend(ctx), GRASS_BACKEND_NONE);
    EXPECT_EQ(grass_get_context_backend(ctx), GRASS_BACKEND_NONE);
    EXPECT_EQ(grass_destroy_patch(ctx, grass_patch_id{}), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_STREQ(grass_last_error(ctx), grass_get_last_error(ctx));
    EXPECT_STRNE(grass_last_error(ctx), "");
    EXPECT_EQ(grass_gl_default_desc().type, GRASS_STRUCT_TYPE_GL_DESC);
    EXPECT_EQ(grass_default_gl_desc().type, GRASS_STRUCT_TYPE_GL_DESC);
    EXPECT_EQ(grass_vk_default_desc().type, GRASS_STRUCT_TYPE_VK_DESC);
    EXPECT_EQ(grass_vk_default_desc().frames_in_flight, grass_default_vk_desc().frames_in_flight);
    EXPECT_EQ(grass_vk_default_record_desc().type, GRASS_STRUCT_TYPE_VK_RECORD_DESC);
    EXPECT_EQ(grass_default_vk_record_desc().type, GRASS_STRUCT_TYPE_VK_RECORD_DESC);
}

// Renamed in 0.5 (the headers' "0.4 names" blocks): the old symbols answer as the new ones.
TEST_F(CoreTest, The04NamesStillAnswer) {
    EXPECT_EQ(grass_library_version(), grass_get_library_version());
    int not_a_command_buffer = 0;
    EXPECT_EQ(grass_vk_prepare_frame(nullptr, &not_a_command_buffer), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(grass_vk_prepare_frame(ctx, &not_a_command_buffer), GRASS_ERROR_INVALID_STATE)
        << "forwarded to grass_vk_prepare, which refuses a context that is not a Vulkan one";
    EXPECT_NE(std::strstr(grass_get_last_error(ctx), "grass_vk_prepare:"), nullptr) << grass_get_last_error(ctx);
    EXPECT_EQ(grass_default_vk_prepare_desc().type, GRASS_STRUCT_TYPE_VK_PREPARE_DESC);
}

} // namespace
