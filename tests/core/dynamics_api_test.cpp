// The responsive grass calls (grass.h "Responsive grass"): documented defaults, and every
// refusal: NaN and infinity in every float, ranges, enums, NULL arrays, zero vectors, the
// struct header; a refusal names the argument and the value and leaves the earlier state.
#include "dynamics_fixture.hpp"

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// One input to spoil: a name the refusal must carry and how to set it.
struct Input {
    std::string name;
    std::function<void(double)> set;
};

class DynamicsApiTest : public DynamicsTest {
protected:
    // The inputs of every call, on copies made by `reset`.
    void reset() {
        wind = grass_default_wind_desc();
        for (int k = 0; k < 3; ++k) sources[k] = source(static_cast<grass_wind_source_kind>(k));
        wind.sources = sources;
        wind.source_count = 3;
        colliders[0] = sphere(1, 0.1, 1, 0.3f, 1, 0, 0);
        colliders[1] = sphere(2, 0.1, 2, 0.3f);
        colliders[1].shape = GRASS_COLLIDER_CAPSULE;
        colliders[1].end[0] = 3, colliders[1].end[1] = 0.1, colliders[1].end[2] = 2;
        mechanics = grass_default_blade_mechanics();
        interaction = grass_default_interaction_desc();
    }
    static grass_wind_source source(grass_wind_source_kind kind) {
        grass_wind_source s{};
        s.kind = kind;
        s.position[0] = 4, s.position[1] = 10, s.position[2] = 4;
        s.direction[1] = -1.0f;
        s.cone_angle = 0.5f;
        s.speed = 20.0f;
        s.radius = 5.0f;
        s.start_time = 1.0;
        s.duration = 2.0f;
        s.front_speed = 10.0f;
        return s;
    }
    grass_result set_all() {
        grass_result r = grass_set_wind(ctx, &wind);
        if (r == GRASS_SUCCESS) r = grass_set_colliders(ctx, colliders, 2);
        if (r == GRASS_SUCCESS) r = grass_set_blade_mechanics(ctx, patch, &mechanics);
        if (r == GRASS_SUCCESS) r = grass_set_interaction(ctx, &interaction);
        return r;
    }
    // Every float and double the host gives the responsive calls (and the view's time).
    std::vector<Input> float_inputs() {
        std::vector<Input> in;
        auto arr = [&](const std::string& name, float* v, int n) {
            for (int i = 0; i < n; ++i) {
                in.push_back({name + "[" + std::to_string(i) + "]", [v, i](double x) { v[i] = float(x); }});
            }
        };
        auto arrd = [&](const std::string& name, double* v, int n) {
            for (int i = 0; i < n; ++i)
                in.push_back({name + "[" + std::to_string(i) + "]", [v, i](double x) { v[i] = x; }});
        };
        auto one = [&](const std::string& name, float* v) { in.push_back({name, [v](double x) { *v = float(x); }}); };
        arr("wind->direction", wind.direction, 3);
        one("wind->speed", &wind.speed);
        one("wind->gust_strength", &wind.gust_strength);
        one("wind->gust_length", &wind.gust_length);
        one("wind->turbulence", &wind.turbulence);
        arr("wind->gravity", wind.gravity, 3);
        for (int k = 0; k < 3; ++k) {
            const std::string s = "wind->sources[" + std::to_string(k) + "].";
            arrd(s + "position", sources[k].position, 3);
            arr(s + "direction", sources[k].direction, 3);
            one(s + "cone_angle", &sources[k].cone_angle);
            one(s + "speed", &sources[k].speed);
            one(s + "radius", &sources[k].radius);
            double* start = &sources[k].start_time;
            in.push_back({s + "start_time", [start](double x) { *start = x; }});
            one(s + "duration", &sources[k].duration);
            one(s + "front_speed", &sources[k].front_speed);
        }
        for (int k = 0; k < 2; ++k) {
            const std::string s = "colliders[" + std::to_string(k) + "].";
            one(s + "radius", &colliders[k].radius);
            arrd(s + "center", colliders[k].center, 3);
            arrd(s + "end", colliders[k].end, 3);
            arr(s + "velocity", colliders[k].velocity, 3);
        }
        one("mechanics->stiffness", &mechanics.stiffness);
        one("mechanics->mass", &mechanics.mass);
        one("mechanics->wind_response", &mechanics.wind_response);
        one("mechanics->trample_depth", &mechanics.trample_depth);
        one("mechanics->recovery_time", &mechanics.recovery_time);
        one("mechanics->variation", &mechanics.variation);
        arr("desc->up", interaction.up, 3);
        arr("desc->texel_size", interaction.texel_size, 2);
        return in;
    }
    // The state the next frame plans from, as bytes: frame uniforms, collider count, draws.
    std::string planned_state() {
        EXPECT_EQ(frame(5.0), GRASS_SUCCESS) << last_message();
        std::string s(reinterpret_cast<const char*>(&plan().frame), sizeof(plan().frame));
        for (const auto& d : plan().draws) s.append(reinterpret_cast<const char*>(&d.uniforms), sizeof(d.uniforms));
        s += std::to_string(plan().stats.colliders) + "/" + std::to_string(plan().interaction.resolution);
        return s;
    }

public: // spoiled by the cases' lambdas
    grass_wind_desc wind{};
    grass_wind_source sources[3]{};
    grass_collider colliders[2]{};
    grass_blade_mechanics mechanics{};
    grass_interaction_desc interaction{};
};

TEST_F(DynamicsApiTest, DefaultsAreTheDocumentedValues) {
    const grass_blade_mechanics m = grass_default_blade_mechanics();
    EXPECT_EQ(m.type, GRASS_STRUCT_TYPE_BLADE_MECHANICS);
    EXPECT_EQ(m.next, nullptr);
    EXPECT_EQ(m.stiffness, 40.0f);
    EXPECT_EQ(m.mass, 1.0f);
    EXPECT_EQ(m.wind_response, 2.0f);
    EXPECT_EQ(m.trample_depth, 0.5f);
    EXPECT_EQ(m.recovery_time, 4.0f);
    EXPECT_EQ(m.variation, 0.25f);
    const grass_wind_desc w = grass_default_wind_desc();
    EXPECT_EQ(w.type, GRASS_STRUCT_TYPE_WIND_DESC);
    EXPECT_EQ(w.direction[0], 1.0f);
    EXPECT_EQ(w.direction[1], 0.0f);
    EXPECT_EQ(w.direction[2], 0.3f);
    EXPECT_EQ(w.speed, 0.0f);
    EXPECT_EQ(w.gust_strength, 0.6f);
    EXPECT_EQ(w.gust_length, 14.0f);
    EXPECT_EQ(w.turbulence, 0.3f);
    EXPECT_EQ(w.gravity[0], 0.0f);
    EXPECT_EQ(w.gravity[1], -9.81f);
    EXPECT_EQ(w.gravity[2], 0.0f);
    EXPECT_EQ(w.sources, nullptr);
    EXPECT_EQ(w.source_count, 0u);
    const grass_interaction_desc i = grass_default_interaction_desc();
    EXPECT_EQ(i.type, GRASS_STRUCT_TYPE_INTERACTION_DESC);
    EXPECT_EQ(i.up[0], 0.0f);
    EXPECT_EQ(i.up[1], 1.0f);
    EXPECT_EQ(i.up[2], 0.0f);
    EXPECT_EQ(i.resolution, 256u);
    EXPECT_EQ(i.level_count, 2u);
    EXPECT_EQ(i.texel_size[0], 0.05f);
    EXPECT_EQ(i.texel_size[1], 1.0f);
    // Each default is accepted, and so is every input of reset().
    EXPECT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_set_wind(ctx, &w), GRASS_SUCCESS) << last_message();
    EXPECT_EQ(grass_set_interaction(ctx, &i), GRASS_SUCCESS) << last_message();
    reset();
    EXPECT_EQ(set_all(), GRASS_SUCCESS) << last_message();
}

TEST_F(DynamicsApiTest, EveryFloatInputRefusesNaNAndInfinity) {
    reset();
    ASSERT_EQ(set_all(), GRASS_SUCCESS) << last_message();
    const std::string before = planned_state();
    reset();
    const size_t count = float_inputs().size();
    EXPECT_GE(count, 70u); // every field above, three source kinds, both collider shapes
    for (size_t k = 0; k < count; ++k) {
        for (double bad : {kNaN, kInf, -kInf}) {
            reset();
            std::vector<Input> inputs = float_inputs();
            inputs[k].set(bad);
            log.clear();
            EXPECT_EQ(set_all(), GRASS_ERROR_INVALID_ARGUMENT) << inputs[k].name << " = " << bad;
            EXPECT_EQ(last_id(), GRASS_MSG_NOT_FINITE) << inputs[k].name << ": " << last_message();
            EXPECT_NE(last_message().find(inputs[k].name), std::string::npos) << last_message();
            // The refused call changed nothing (the calls before it set the same values).
            EXPECT_EQ(planned_state(), before) << inputs[k].name;
        }
    }
    // The view's time too.
    const double eye[3] = {2, 3, 2};
    grass_view_desc v = view_at(eye, kNaN);
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NOT_FINITE);
    EXPECT_NE(last_message().find("view->time"), std::string::npos) << last_message();
    // Nothing refused changed what the next frame plans (the calls before the refused one
    // succeeded with the same values as before).
    EXPECT_EQ(planned_state(), before);
}

TEST_F(DynamicsApiTest, RangesEnumsNullsAndZeroVectorsAreRefused) {
    struct Case {
        const char* name; // the argument the refusal must name
        grass_message_id id;
        std::function<void(DynamicsApiTest*)> spoil;
    };
    const Case cases[] = {
        {"wind->direction", GRASS_MSG_ZERO_VECTOR, [](DynamicsApiTest* t) { std::memset(t->wind.direction, 0, 12); }},
        {"wind->speed", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->wind.speed = 1000.5f; }},
        {"wind->speed", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->wind.speed = -1.0f; }},
        {"wind->gust_strength", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->wind.gust_strength = 4.5f; }},
        {"wind->gust_length", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->wind.gust_length = 0.05f; }},
        {"wind->turbulence", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->wind.turbulence = 1.5f; }},
        {"wind->gravity[1]", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->wind.gravity[1] = -2e3f; }},
        {"wind->source_count", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->wind.source_count = 17; }},
        {"wind->sources", GRASS_MSG_NULL_ARGUMENT, [](DynamicsApiTest* t) { t->wind.sources = nullptr; }},
        {"wind->sources[0].kind", GRASS_MSG_BAD_ENUM,
         [](DynamicsApiTest* t) { t->sources[0].kind = static_cast<grass_wind_source_kind>(3); }},
        {"wind->sources[0].position[2]", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->sources[0].position[2] = 2e12; }},
        {"wind->sources[0].speed", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->sources[0].speed = 1e4f; }},
        {"wind->sources[0].radius", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->sources[0].radius = 0.0f; }},
        {"wind->sources[1].direction", GRASS_MSG_ZERO_VECTOR,
         [](DynamicsApiTest* t) { std::memset(t->sources[1].direction, 0, 12); }},
        {"wind->sources[1].cone_angle", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->sources[1].cone_angle = 0.0f; }},
        {"wind->sources[1].cone_angle", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->sources[1].cone_angle = 1.6f; }},
        {"wind->sources[2].start_time", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->sources[2].start_time = 2e9; }},
        {"wind->sources[2].duration", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->sources[2].duration = 0; }},
        {"wind->sources[2].front_speed", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->sources[2].front_speed = 2e4f; }},
        {"colliders[0].shape", GRASS_MSG_BAD_ENUM,
         [](DynamicsApiTest* t) { t->colliders[0].shape = static_cast<grass_collider_shape>(7); }},
        {"colliders[0].radius", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->colliders[0].radius = -1.0f; }},
        {"colliders[0].radius", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->colliders[0].radius = 2e6f; }},
        {"colliders[0].center[0]", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->colliders[0].center[0] = -2e12; }},
        {"colliders[1].end[1]", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->colliders[1].end[1] = 2e12; }},
        {"colliders[1].velocity[2]", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->colliders[1].velocity[2] = 2e5f; }},
        {"mechanics->stiffness", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->mechanics.stiffness = 0.05f; }},
        {"mechanics->mass", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->mechanics.mass = 101.0f; }},
        {"mechanics->wind_response", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->mechanics.wind_response = -0.5f; }},
        {"mechanics->trample_depth", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->mechanics.trample_depth = 1.5f; }},
        {"mechanics->recovery_time", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->mechanics.recovery_time = 0.0f; }},
        {"mechanics->variation", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->mechanics.variation = 0.95f; }},
        {"mechanics->type", GRASS_MSG_WRONG_STRUCT_TYPE,
         [](DynamicsApiTest* t) { t->mechanics.type = GRASS_STRUCT_TYPE_WIND_DESC; }},
        {"mechanics->next", GRASS_MSG_NEXT_NOT_NULL, [](DynamicsApiTest* t) { t->mechanics.next = t; }},
        {"desc->up", GRASS_MSG_ZERO_VECTOR, [](DynamicsApiTest* t) { std::memset(t->interaction.up, 0, 12); }},
        {"desc->resolution", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->interaction.resolution = 300; }},
        {"desc->resolution", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->interaction.resolution = 4096; }},
        {"desc->level_count", GRASS_MSG_OUT_OF_RANGE, [](DynamicsApiTest* t) { t->interaction.level_count = 3; }},
        {"desc->texel_size[0]", GRASS_MSG_OUT_OF_RANGE,
         [](DynamicsApiTest* t) { t->interaction.texel_size[0] = 1e-4f; }},
        {"desc->texel_size[1]", GRASS_MSG_RANGE_INVERTED,
         [](DynamicsApiTest* t) { t->interaction.texel_size[1] = 0.01f; }},
        {"desc->type", GRASS_MSG_WRONG_STRUCT_TYPE,
         [](DynamicsApiTest* t) { t->interaction.type = GRASS_STRUCT_TYPE_VIEW_DESC; }},
        {"wind->next", GRASS_MSG_NEXT_NOT_NULL, [](DynamicsApiTest* t) { t->wind.next = t; }},
    };
    reset();
    ASSERT_EQ(set_all(), GRASS_SUCCESS) << last_message();
    const std::string before = planned_state();
    for (const Case& c : cases) {
        reset();
        c.spoil(this);
        log.clear();
        EXPECT_NE(set_all(), GRASS_SUCCESS) << c.name;
        EXPECT_EQ(last_id(), c.id) << c.name << ": " << last_message();
        EXPECT_NE(last_message().find(c.name), std::string::npos) << last_message();
        EXPECT_EQ(planned_state(), before) << c.name;
    }
    // NULL with a count, too many colliders, a stale patch.
    EXPECT_EQ(grass_set_colliders(ctx, nullptr, 1), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NULL_ARGUMENT);
    EXPECT_EQ(grass_set_colliders(ctx, colliders, GRASS_MAX_COLLIDERS + 1), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last_message().find("65537"), std::string::npos) << last_message();
    EXPECT_EQ(grass_set_blade_mechanics(ctx, patch, nullptr), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_NULL_ARGUMENT);
    EXPECT_EQ(grass_set_blade_mechanics(ctx, grass_patch_id{}, &mechanics), GRASS_ERROR_INVALID_HANDLE);
    EXPECT_EQ(planned_state(), before);
}

// docs/responsive.md's ranges as a host writes them in C: each bound of grass_blade_mechanics
// as a float literal is accepted (recovery_time = 0.01f is 0.0099999998, below 0.01: it was
// refused), and the float next beyond it is refused by name with its value.
TEST_F(DynamicsApiTest, MechanicsBoundsAsWrittenInCAreAccepted) {
    struct Bound {
        const char* name;
        float grass_blade_mechanics::*field;
        float lo, hi;
    };
    const Bound bounds[] = {{"mechanics->stiffness", &grass_blade_mechanics::stiffness, 0.1f, 1e5f},
                            {"mechanics->mass", &grass_blade_mechanics::mass, 0.0f, 100.0f},
                            {"mechanics->wind_response", &grass_blade_mechanics::wind_response, 0.0f, 100.0f},
                            {"mechanics->trample_depth", &grass_blade_mechanics::trample_depth, 0.0f, 1.0f},
                            {"mechanics->recovery_time", &grass_blade_mechanics::recovery_time, 0.01f, 1e5f},
                            {"mechanics->variation", &grass_blade_mechanics::variation, 0.0f, 0.9f}};
    for (const Bound& b : bounds) {
        for (int side = 0; side < 2; ++side) {
            const float at = side == 0 ? b.lo : b.hi;
            grass_blade_mechanics m = grass_default_blade_mechanics();
            m.*b.field = at;
            EXPECT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_SUCCESS)
                << b.name << " = " << at << ": " << last_message();
            m.*b.field = std::nextafter(at, side == 0 ? -1e30f : 1e30f);
            log.clear();
            EXPECT_EQ(grass_set_blade_mechanics(ctx, patch, &m), GRASS_ERROR_INVALID_ARGUMENT) << b.name;
            EXPECT_EQ(last_id(), GRASS_MSG_OUT_OF_RANGE) << b.name;
            EXPECT_NE(last_message().find(b.name), std::string::npos) << last_message();
        }
    }
}

TEST_F(DynamicsApiTest, TimeIsBoundedAndGoingBackwardsStepsZeroAndWarnsOnce) {
    const double eye[3] = {2, 3, 2};
    grass_view_desc v = view_at(eye, 1.5e9);
    EXPECT_EQ(grass_begin_frame(ctx, &v), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(last_id(), GRASS_MSG_OUT_OF_RANGE);
    EXPECT_NE(last_message().find("view->time is 1.5e+09"), std::string::npos) << last_message();
    ASSERT_EQ(frame(1e9), GRASS_SUCCESS) << last_message(); // the bound itself
    EXPECT_EQ(plan().stats.time_step, 0.0);                 // the first frame steps 0
    ASSERT_EQ(frame(1e9), GRASS_SUCCESS);
    ASSERT_EQ(frame(10.0), GRASS_SUCCESS); // the clock went back: step 0, one warning
    EXPECT_EQ(plan().stats.time_step, 0.0);
    int warnings = 0;
    for (const LogRecord& r : log) warnings += r.id == GRASS_MSG_TIME_BACKWARDS ? 1 : 0;
    EXPECT_EQ(warnings, 1);
    EXPECT_EQ(log.back().level, GRASS_LOG_WARNING);
    ASSERT_EQ(frame(10.25), GRASS_SUCCESS); // and it goes on from the new time
    EXPECT_EQ(plan().stats.time_step, 0.25);
    ASSERT_EQ(frame(9.0), GRASS_SUCCESS); // a second occurrence warns again
    warnings = 0;
    for (const LogRecord& r : log) warnings += r.id == GRASS_MSG_TIME_BACKWARDS ? 1 : 0;
    EXPECT_EQ(warnings, 2);
    // A refused frame commits no time: the next step is from the last frame that began.
    v = view_at(eye, kNaN);
    EXPECT_NE(grass_begin_frame(ctx, &v), GRASS_SUCCESS);
    ASSERT_EQ(frame(9.5), GRASS_SUCCESS);
    EXPECT_EQ(plan().stats.time_step, 0.5);
}

} // namespace
