// grass_set_field_wind_map (grass.h "Responsive grass"): the documented defaults, the plan it
// makes (the wind-map variant and its uniforms, nothing without it), and every refusal:
// null, stale and foreign ids, a single-channel map, NaN and out-of-range speeds, a singular
// transform, a wrong struct header, a call inside a frame; each names the argument and the
// value and leaves the earlier state. A map in use by a wind map cannot be destroyed.
#include "dynamics_fixture.hpp"

#include "context/backend.hpp"

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

class WindMapApiTest : public DynamicsTest {
protected:
    grass_map_id make_map(grass_map_format format) {
        const std::vector<float> texels(4 * 4 * 4, 0.5f);
        const std::vector<uint8_t> bytes(4 * 4 * 4, 128); // RGBA8 at most
        grass_map_desc md = grass_default_map_desc();
        md.width = md.height = 4;
        md.format = format;
        md.pixels = format == GRASS_MAP_FORMAT_RGBA32_FLOAT ? static_cast<const void*>(texels.data()) : bytes.data();
        grass_map_id id{};
        EXPECT_EQ(grass_create_map(ctx, &md, &id), GRASS_SUCCESS) << last_message();
        return id;
    }
    // The draws' feature masks and field uniforms the next frame plans, as bytes.
    std::string planned_draws() {
        EXPECT_EQ(frame(5.0), GRASS_SUCCESS) << last_message();
        std::string s;
        for (const auto& d : plan().draws) {
            s += std::to_string(d.features) + ":";
            s.append(reinterpret_cast<const char*>(&d.uniforms), sizeof(d.uniforms));
        }
        return s;
    }
};

TEST_F(WindMapApiTest, DefaultsAreTheDocumentedValues) {
    const grass_wind_map_desc d = grass_default_wind_map_desc();
    EXPECT_EQ(d.type, GRASS_STRUCT_TYPE_WIND_MAP_DESC);
    EXPECT_EQ(d.next, nullptr);
    EXPECT_TRUE(grass_map_id_is_null(d.map));
    EXPECT_EQ(d.speed, 5.0f);
    for (double v : d.cell_to_map) EXPECT_EQ(v, 0.0);
    // The default (a null map) is accepted: it removes nothing that is not there.
    EXPECT_EQ(grass_set_field_wind_map(ctx, field, &d), GRASS_SUCCESS) << last_message();
}

// A wind map gives every draw of its field the wind-map variant (with kFeatureWind), and its
// transform and speed in the field's uniforms; removing it plans exactly the still frame.
TEST_F(WindMapApiTest, AWindMapPlansItsVariantAndRemovingItPlansStillGrass) {
    const std::string still = planned_draws();
    ASSERT_FALSE(plan().draws.empty());
    for (const auto& d : plan().draws) EXPECT_EQ(d.features & (grass::kFeatureWind | grass::kFeatureWindMap), 0u);
    const grass_map_id wind = make_map(GRASS_MAP_FORMAT_RGBA32_FLOAT);
    grass_wind_map_desc d = grass_default_wind_map_desc();
    d.map = wind;
    d.speed = 7.5f;
    ASSERT_EQ(grass_set_field_wind_map(ctx, field, &d), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(frame(5.0), GRASS_SUCCESS) << last_message();
    for (const auto& draw : plan().draws) {
        EXPECT_EQ(draw.features & (grass::kFeatureWind | grass::kFeatureWindMap),
                  grass::kFeatureWind | grass::kFeatureWindMap);
        EXPECT_EQ(draw.uniforms.wind_map_u[0], 1.0f / 16.0f); // spans the 16-cell field
        EXPECT_EQ(draw.uniforms.wind_map_v[1], 1.0f / 16.0f);
        EXPECT_EQ(draw.uniforms.wind_map_u[3], 7.5f);
    }
    EXPECT_GT(backend->curve_uploads, 0u) << "a wind-map draw bends blades from their curves";
    // Its own transform, as given.
    const double m[6] = {0.5, 0.0, 0.0, 0.25, 0.125, -1.0};
    std::memcpy(d.cell_to_map, m, sizeof m);
    ASSERT_EQ(grass_set_field_wind_map(ctx, field, &d), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(frame(5.0), GRASS_SUCCESS) << last_message();
    ASSERT_FALSE(plan().draws.empty());
    const grass::FieldUniforms& u = plan().draws[0].uniforms;
    EXPECT_EQ(u.wind_map_u[0], 0.5f);
    EXPECT_EQ(u.wind_map_u[2], 0.125f);
    EXPECT_EQ(u.wind_map_v[1], 0.25f);
    EXPECT_EQ(u.wind_map_v[2], -1.0f);
    // In use: the map stays.
    EXPECT_EQ(grass_destroy_map(ctx, wind), GRASS_ERROR_IN_USE);
    EXPECT_EQ(last_id(), GRASS_MSG_MAP_IN_USE);
    EXPECT_NE(last_message().find("still used"), std::string::npos) << last_message();
    // Removed by NULL, and by a null map id: the still plan again, and the map can go.
    ASSERT_EQ(grass_set_field_wind_map(ctx, field, nullptr), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(planned_draws(), still);
    ASSERT_EQ(grass_set_field_wind_map(ctx, field, &d), GRASS_SUCCESS) << last_message();
    grass_wind_map_desc none = grass_default_wind_map_desc();
    ASSERT_EQ(grass_set_field_wind_map(ctx, field, &none), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(planned_draws(), still);
    EXPECT_EQ(grass_destroy_map(ctx, wind), GRASS_SUCCESS) << last_message();
}

// Destroying the field releases its wind map's use.
TEST_F(WindMapApiTest, DestroyingTheFieldReleasesTheMap) {
    const grass_map_id wind = make_map(GRASS_MAP_FORMAT_RGBA8_UNORM);
    grass_wind_map_desc d = grass_default_wind_map_desc();
    d.map = wind;
    ASSERT_EQ(grass_set_field_wind_map(ctx, field, &d), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_destroy_map(ctx, wind), GRASS_ERROR_IN_USE);
    ASSERT_EQ(grass_destroy_field(ctx, field), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_destroy_map(ctx, wind), GRASS_SUCCESS) << last_message();
}

TEST_F(WindMapApiTest, BadInputIsRefusedNamingTheArgumentAndKeepsTheEarlierMap) {
    const grass_map_id wind = make_map(GRASS_MAP_FORMAT_RGBA32_FLOAT);
    const grass_map_id grey = make_map(GRASS_MAP_FORMAT_R8_UNORM);
    const grass_map_id gone = make_map(GRASS_MAP_FORMAT_RGBA32_FLOAT);
    ASSERT_EQ(grass_destroy_map(ctx, gone), GRASS_SUCCESS);
    grass_wind_map_desc good = grass_default_wind_map_desc();
    good.map = wind;
    good.speed = 3.0f;
    ASSERT_EQ(grass_set_field_wind_map(ctx, field, &good), GRASS_SUCCESS) << last_message();
    const std::string before = planned_draws();
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    struct Case {
        const char* name;  // the argument the refusal must name
        const char* value; // and its value
        grass_result result;
        std::function<void(grass_wind_map_desc*)> spoil;
    };
    const Case cases[] = {
        {"desc->map", "", GRASS_ERROR_INVALID_HANDLE, [&](grass_wind_map_desc* d) { d->map = gone; }},
        {"desc->map", "", GRASS_ERROR_INVALID_HANDLE, [&](grass_wind_map_desc* d) { d->map.owner ^= 0x5a5a; }},
        {"desc->map", "1 channel", GRASS_ERROR_INVALID_ARGUMENT, [&](grass_wind_map_desc* d) { d->map = grey; }},
        {"desc->speed", "nan", GRASS_ERROR_INVALID_ARGUMENT, [](grass_wind_map_desc* d) { d->speed = float(kNaN); }},
        {"desc->speed", "-1", GRASS_ERROR_INVALID_ARGUMENT, [](grass_wind_map_desc* d) { d->speed = -1.0f; }},
        {"desc->speed", "1000.5", GRASS_ERROR_INVALID_ARGUMENT, [](grass_wind_map_desc* d) { d->speed = 1000.5f; }},
        {"desc->cell_to_map", "nan", GRASS_ERROR_INVALID_ARGUMENT,
         [](grass_wind_map_desc* d) { d->cell_to_map[4] = kNaN; }},
        {"desc->cell_to_map", "determinant 0", GRASS_ERROR_INVALID_ARGUMENT,
         [](grass_wind_map_desc* d) { d->cell_to_map[0] = d->cell_to_map[2] = 1.0; }},
        {"desc->type", "", GRASS_ERROR_WRONG_STRUCT_TYPE,
         [](grass_wind_map_desc* d) { d->type = GRASS_STRUCT_TYPE_WIND_DESC; }},
        {"desc->next", "", GRASS_ERROR_INVALID_ARGUMENT, [](grass_wind_map_desc* d) { d->next = d; }},
    };
    for (const Case& c : cases) {
        grass_wind_map_desc d = grass_default_wind_map_desc();
        d.map = wind;
        d.speed = 4.0f;
        c.spoil(&d);
        log.clear();
        EXPECT_EQ(grass_set_field_wind_map(ctx, field, &d), c.result) << c.name << " " << c.value;
        EXPECT_NE(last_message().find(c.name), std::string::npos) << last_message();
        EXPECT_NE(last_message().find(c.value), std::string::npos) << last_message();
        EXPECT_EQ(planned_draws(), before) << c.name << " " << c.value;
    }
    // A null or stale field, a null context, and inside a frame.
    log.clear();
    EXPECT_EQ(grass_set_field_wind_map(ctx, grass_field_id{}, &good), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_NE(last_message().find("field"), std::string::npos) << last_message();
    EXPECT_EQ(grass_set_field_wind_map(nullptr, field, &good), GRASS_ERROR_INVALID_ARGUMENT);
    const double eye[3] = {2.0, 3.0, 2.0};
    const grass_view_desc v = view_at(eye, 6.0);
    ASSERT_EQ(grass_begin_frame(ctx, &v), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_set_field_wind_map(ctx, field, nullptr), GRASS_ERROR_INVALID_STATE);
    EXPECT_EQ(last_id(), GRASS_MSG_FRAME_ALREADY_BEGUN);
    ASSERT_EQ(grass_end_frame(ctx), GRASS_SUCCESS);
    EXPECT_EQ(planned_draws(), before);
}

} // namespace
