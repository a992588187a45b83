// The patch generator (lemme2012 4.1): determinism, blade shape and layout.
#include "core_fixture.hpp"

#include "context/context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace {

const grass::PatchData& patch_data(grass_context* ctx, grass_patch_id id) {
    return ctx->patches.get(id.index - 1)->data;
}

TEST_F(CoreTest, SameDescAndSeedGiveBitIdenticalPatches) {
    grass_patch_info a{}, b{};
    const grass_patch_id pa = make_patch(), pb = make_patch();
    ASSERT_EQ(grass_get_patch_info(ctx, pa, &a), GRASS_SUCCESS);
    ASSERT_EQ(grass_get_patch_info(ctx, pb, &b), GRASS_SUCCESS);
    EXPECT_EQ(a.content_hash, b.content_hash);
    const auto& va = patch_data(ctx, pa).vertices;
    const auto& vb = patch_data(ctx, pb).vertices;
    ASSERT_EQ(va.size(), vb.size());
    EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(va[0])));
}

// Pins the generated default patch. If this fails, the generator's output changed: every
// host's grass changes with it. Update the value only for an intended change, and say so.
TEST_F(CoreTest, DefaultPatchHashIsPinned) {
    grass_patch_info info{};
    ASSERT_EQ(grass_get_patch_info(ctx, make_patch(), &info), GRASS_SUCCESS);
    EXPECT_EQ(info.content_hash, 0xd95241bc6a83daa1ull) << std::hex << "actual 0x" << info.content_hash;
    EXPECT_EQ(info.blade_count, 384u);
    EXPECT_EQ(info.vertex_count, 384u * 10u);
    EXPECT_EQ(info.triangle_count, 384u * 8u);
}

TEST_F(CoreTest, SeedAndShapeParametersChangeThePatch) {
    grass_patch_desc d = grass_default_patch_desc();
    grass_patch_info base{}, other{};
    ASSERT_EQ(grass_get_patch_info(ctx, make_patch(d), &base), GRASS_SUCCESS);
    d.seed = 2;
    ASSERT_EQ(grass_get_patch_info(ctx, make_patch(d), &other), GRASS_SUCCESS);
    EXPECT_NE(base.content_hash, other.content_hash);
    d = grass_default_patch_desc();
    d.tilt_max = 0.9f;
    ASSERT_EQ(grass_get_patch_info(ctx, make_patch(d), &other), GRASS_SUCCESS);
    EXPECT_NE(base.content_hash, other.content_hash);
}

TEST_F(CoreTest, BladesAreRootedInsideTheUnitSquareAndStayInTheirLengthRange) {
    grass_patch_desc d = grass_default_patch_desc();
    d.subdivisions = 8;
    const auto& p = patch_data(ctx, make_patch(d));
    const uint32_t per = p.vertices_per_blade;
    for (uint32_t b = 0; b < p.blade_count; ++b) {
        const grass::BladeVertex* v = &p.vertices[size_t(b) * per];
        const float rx = v[0].root_shape[0], rz = v[0].root_shape[1];
        ASSERT_GE(rx, 0.0f);
        ASSERT_LT(rx, 1.0f);
        ASSERT_GE(rz, 0.0f);
        ASSERT_LT(rz, 1.0f);
        // The root sits on the ground between its two root vertices.
        EXPECT_NEAR(0.5f * (v[0].position[0] + v[1].position[0]), rx, 1e-6f);
        EXPECT_NEAR(v[0].position[1], 0.0f, 1e-7f);
        // Arc length of the centre line ~ blade length (chords underestimate slightly).
        double arc = 0.0;
        for (uint32_t k = 0; k < d.subdivisions; ++k) {
            double dx = 0, dy = 0, dz = 0;
            for (int e = 0; e < 2; ++e) {
                dx += 0.5 * (v[2 * (k + 1) + e].position[0] - v[2 * k + e].position[0]);
                dy += 0.5 * (v[2 * (k + 1) + e].position[1] - v[2 * k + e].position[1]);
                dz += 0.5 * (v[2 * (k + 1) + e].position[2] - v[2 * k + e].position[2]);
            }
            arc += std::sqrt(dx * dx + dy * dy + dz * dz);
        }
        EXPECT_GE(arc, d.length_min * 0.97) << "blade " << b;
        EXPECT_LE(arc, d.length_max * 1.0001) << "blade " << b;
        EXPECT_GT(v[per - 1].position[1], 0.0f) << "a blade grows upwards";
    }
}

TEST_F(CoreTest, NormalsAreUnitAndOrthogonalToTheBladeTangent) {
    grass_patch_desc d = grass_default_patch_desc();
    d.subdivisions = 16; // fine steps: the chord is close to the tangent
    const auto& p = patch_data(ctx, make_patch(d));
    const uint32_t per = p.vertices_per_blade;
    double worst = 0.0;
    for (uint32_t b = 0; b < p.blade_count; ++b) {
        const grass::BladeVertex* v = &p.vertices[size_t(b) * per];
        for (uint32_t k = 1; k < d.subdivisions; ++k) {
            // Central difference of the centre line at sample k.
            float t[3], n[3];
            for (int c = 0; c < 3; ++c) {
                const float next = 0.5f * (v[2 * (k + 1)].position[c] + v[2 * (k + 1) + 1].position[c]);
                const float prev = 0.5f * (v[2 * (k - 1)].position[c] + v[2 * (k - 1) + 1].position[c]);
                t[c] = next - prev;
                n[c] = v[2 * k].normal[c];
            }
            const double tl = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
            const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            ASSERT_NEAR(nl, 1.0, 1e-5);
            worst = std::max(worst, std::fabs((t[0] * n[0] + t[1] * n[1] + t[2] * n[2]) / (tl * nl)));
        }
    }
    EXPECT_LT(worst, 0.01) << "cosine between normal and tangent";
}

TEST_F(CoreTest, ColourVariesPerBladeAndPerVertex) {
    const auto& p = patch_data(ctx, make_patch());
    // Same height (root) on different blades: per-blade modulation.
    int differing_blades = 0;
    for (uint32_t b = 1; b < p.blade_count; ++b) {
        differing_blades +=
            std::memcmp(p.vertices[0].color, p.vertices[size_t(b) * p.vertices_per_blade].color, 3) != 0;
    }
    EXPECT_GT(differing_blades, int(p.blade_count) / 2);
    // Two sides of one blade at the same height: per-vertex modulation.
    int differing_vertices = 0;
    for (size_t k = 0; k + 1 < p.vertices.size(); k += 2) {
        differing_vertices += std::memcmp(p.vertices[k].color, p.vertices[k + 1].color, 3) != 0;
    }
    EXPECT_GT(differing_vertices, int(p.vertices.size() / 2) / 4);
}

// Responsive grass: each blade's rest pose as jahrmann's quadratic Bezier curve (v0 = the
// root): it passes through the blade's centre line at every vertex row, its length is the
// blade's arc length, and its facing angle gives the direction the blade's width runs along.
TEST_F(CoreTest, BladeCurvesAreTheBladesAsBezierCurves) {
    grass_patch_desc d = grass_default_patch_desc();
    d.subdivisions = 16;
    d.bend_max = 1.5f;
    const auto& p = patch_data(ctx, make_patch(d));
    ASSERT_EQ(p.blade_curves.size(), size_t(p.blade_count) * 8);
    const uint32_t per = p.vertices_per_blade, rows = per / 2;
    double worst_point = 0.0, worst_length = 0.0, worst_side = 0.0;
    for (uint32_t b = 0; b < p.blade_count; ++b) {
        const float* c = &p.blade_curves[size_t(b) * 8];
        const grass::BladeVertex* v = &p.vertices[size_t(b) * per];
        const double root[3] = {v[0].root_shape[0], 0.0, v[0].root_shape[1]};
        double length = 0.0, previous[3] = {root[0], root[1], root[2]};
        for (uint32_t k = 0; k < rows; ++k) {
            const double t = v[2 * k].root_shape[3];
            double bezier[3];
            for (int a = 0; a < 3; ++a) {
                // B(t) = 2 t (1 - t) v1 + t^2 v2, relative to the root.
                bezier[a] = root[a] + 2.0 * t * (1.0 - t) * c[a] + t * t * c[4 + a];
                const double centre = 0.5 * (double(v[2 * k].position[a]) + v[2 * k + 1].position[a]);
                worst_point = std::max(worst_point, std::fabs(bezier[a] - centre));
            }
            length += std::sqrt((bezier[0] - previous[0]) * (bezier[0] - previous[0]) +
                                (bezier[1] - previous[1]) * (bezier[1] - previous[1]) +
                                (bezier[2] - previous[2]) * (bezier[2] - previous[2]));
            std::copy(bezier, bezier + 3, previous);
        }
        // The polyline through 17 rows is a little shorter than the curve (0.2 %).
        worst_length = std::max(worst_length, std::fabs(length - c[3]) / c[3]);
        // The width runs from vertex 0 to vertex 1 of the root row, along (-sin, 0, cos).
        const double side[3] = {double(v[1].position[0]) - v[0].position[0], 0.0,
                                double(v[1].position[2]) - v[0].position[2]};
        const double side_len = std::sqrt(side[0] * side[0] + side[2] * side[2]);
        worst_side = std::max(worst_side, std::fabs(side[0] / side_len + std::sin(double(c[7]))) +
                                              std::fabs(side[2] / side_len - std::cos(double(c[7]))));
        ASSERT_GE(c[3], d.length_min * 0.999f);
        ASSERT_LE(c[3], d.length_max * 1.001f);
    }
    EXPECT_LT(worst_point, 1e-6);
    EXPECT_LT(worst_length, 0.004);
    EXPECT_LT(worst_side, 1e-5);
    std::printf("[ curves   ] worst distance to a vertex row %.2g, length %.2g%% off, facing %.2g\n", worst_point,
                100.0 * worst_length, worst_side);
}

} // namespace
