// Blades scattered on a host's triangle mesh (jahrmann2017 4, 6.2): the mesh validated by
// name, blades by area on their triangles with interpolated normals, Poisson-disk tufts,
// determinism, patches of equal count with boxes and spread prefixes, a sphere's every face.
#include "mesh/mesh_scatter.hpp"
#include "mesh/mesh_surface.hpp"
#include "mesh/poisson_disk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace {

using grass::MeshBlade;
using grass::MeshScatter;
using grass::MeshScatterParams;
using grass::MeshSeeding;
using grass::MeshSurface;
using grass::MeshSurfaceDesc;

struct Mesh {
    std::vector<float> positions, normals, uvs;
    std::vector<uint32_t> indices;
    uint32_t add(float x, float y, float z, float nx, float ny, float nz, float u = 0, float v = 0) {
        positions.insert(positions.end(), {x, y, z});
        normals.insert(normals.end(), {nx, ny, nz});
        uvs.insert(uvs.end(), {u, v});
        return static_cast<uint32_t>(positions.size() / 3 - 1);
    }
    void triangle(uint32_t a, uint32_t b, uint32_t c) { indices.insert(indices.end(), {a, b, c}); }
    MeshSurfaceDesc desc() const {
        MeshSurfaceDesc d;
        d.positions = positions.data();
        d.normals = normals.data();
        d.uvs = uvs.data();
        d.indices = indices.data();
        d.vertex_count = positions.size() / 3;
        d.index_count = indices.size();
        return d;
    }
};

// Two separate triangles on y = 0 of areas 1 and 3.
Mesh two_triangles() {
    Mesh m;
    m.triangle(m.add(0, 0, 0, 0, 1, 0), m.add(0, 0, 1, 0, 1, 0), m.add(2, 0, 0, 0, 1, 0));
    m.triangle(m.add(5, 0, 0, 0, 1, 0), m.add(5, 0, 2, 0, 1, 0), m.add(8, 0, 0, 0, 1, 0));
    return m;
}

// A flat square of side `size` on y = 0, two triangles, UVs over it.
Mesh square(float size) {
    Mesh m;
    const uint32_t a = m.add(0, 0, 0, 0, 1, 0, 0, 0), b = m.add(size, 0, 0, 0, 1, 0, 1, 0),
                   c = m.add(size, 0, size, 0, 1, 0, 1, 1), d = m.add(0, 0, size, 0, 1, 0, 0, 1);
    m.triangle(a, c, b);
    m.triangle(a, d, c);
    return m;
}

void unit(float v[3]) {
    const float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; ++i) v[i] /= l;
}

// An icosphere of radius 1 ("a planet"), subdivided `levels` times; normals point out.
Mesh icosphere(int levels) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<std::array<float, 3>> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    std::vector<std::array<uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (auto& p : v) unit(p.data());
    for (int l = 0; l < levels; ++l) {
        std::vector<std::array<uint32_t, 3>> g;
        for (const auto& tri : f) {
            uint32_t mid[3];
            for (int e = 0; e < 3; ++e) {
                std::array<float, 3> p;
                for (int i = 0; i < 3; ++i) p[i] = (v[tri[e]][i] + v[tri[(e + 1) % 3]][i]) / 2;
                unit(p.data());
                v.push_back(p);
                mid[e] = static_cast<uint32_t>(v.size() - 1);
            }
            g.push_back({tri[0], mid[0], mid[2]});
            g.push_back({tri[1], mid[1], mid[0]});
            g.push_back({tri[2], mid[2], mid[1]});
            g.push_back({mid[0], mid[1], mid[2]});
        }
        f = g;
    }
    Mesh m;
    for (const auto& p : v) m.add(p[0], p[1], p[2], p[0], p[1], p[2]);
    for (const auto& tri : f) m.triangle(tri[0], tri[1], tri[2]);
    return m;
}

double distance(const float* a, const float* b) {
    double s = 0;
    for (int i = 0; i < 3; ++i) s += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
    return std::sqrt(s);
}

// Mean distance from each of the first `k` blades to its nearest other among them.
double mean_nearest(const MeshBlade* blades, uint32_t k) {
    double sum = 0;
    for (uint32_t a = 0; a < k; ++a) {
        double best = 1e30;
        for (uint32_t b = 0; b < k; ++b)
            if (a != b) best = std::min(best, distance(blades[a].root, blades[b].root));
        sum += best;
    }
    return sum / k;
}

class MeshScatterTest : public ::testing::Test {
protected:
    static grass_context_desc log_desc(std::vector<std::string>* messages) {
        grass_context_desc d = grass_default_context_desc();
        d.log_fn = [](void* user, grass_log_level, grass_message_id, const char* message) {
            static_cast<std::vector<std::string>*>(user)->push_back(message);
        };
        d.log_user_data = messages;
        return d;
    }
    MeshScatterTest() : log_(log_desc(&messages_)), host_(grass_allocator{}) {}

    grass_result build(const MeshSurfaceDesc& d, MeshSurface* s) {
        return grass::build_mesh_surface(&log_, "test", d, s);
    }
    MeshScatter scatter(const Mesh& m, const MeshScatterParams& p) {
        MeshSurface s(&host_);
        EXPECT_EQ(build(m.desc(), &s), GRASS_SUCCESS) << last();
        MeshScatter out(&host_);
        EXPECT_EQ(grass::scatter_mesh_blades(&log_, "test", s, p, &out), GRASS_SUCCESS) << last();
        return out;
    }
    std::string last() const { return messages_.empty() ? std::string() : messages_.back(); }

    std::vector<std::string> messages_;
    grass::Log log_;
    grass::HostAllocator host_;
};

TEST_F(MeshScatterTest, BladeCountFollowsArea) {
    MeshScatterParams p;
    p.density = 4000.0; // 4 m^2: 16000 blades
    p.patch_blades = 1000;
    const MeshScatter out = scatter(two_triangles(), p);
    ASSERT_EQ(out.blades.size(), 16000u);
    size_t on_small = 0;
    for (const MeshBlade& b : out.blades) on_small += b.triangle == 0;
    // Binomial(16000, 1/4): 4000 +- 55 (one sigma); five sigmas.
    EXPECT_NEAR(double(on_small), 4000.0, 5 * std::sqrt(16000 * 0.25 * 0.75)) << on_small;
}

TEST_F(MeshScatterTest, RootsOnTheirTriangleNormalsInterpolatedAndUnit) {
    Mesh m;
    const float s = 1 / std::sqrt(2.0f);
    const uint32_t c0 = m.add(0, 0, 0, 0, 1, 0, 0, 0), c1 = m.add(1, 0.5f, 0, s, s, 0, 1, 0),
                   c2 = m.add(0, 0.3f, 1, 0, s, s, 0, 1); // one declaration: added in this order
    m.triangle(c0, c1, c2);
    MeshScatterParams p;
    p.density = 2000.0;
    p.patch_blades = 256;
    const MeshScatter out = scatter(m, p);
    ASSERT_GE(out.blades.size(), 256u);
    const float* v = m.positions.data();
    const double e1[3] = {v[3] - v[0], v[4] - v[1], v[5] - v[2]}, e2[3] = {v[6] - v[0], v[7] - v[1], v[8] - v[2]};
    const double d11 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2],
                 d22 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2],
                 d12 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
    double widest_turn = 0, outside = 0, off_plane = 0, length_error = 0, normal_error = 0, uv_error = 0;
    for (const MeshBlade& b : out.blades) {
        const double r[3] = {b.root[0] - v[0], b.root[1] - v[1], b.root[2] - v[2]};
        const double r1 = r[0] * e1[0] + r[1] * e1[1] + r[2] * e1[2], r2 = r[0] * e2[0] + r[1] * e2[1] + r[2] * e2[2];
        const double det = d11 * d22 - d12 * d12;
        const double b1 = (d22 * r1 - d12 * r2) / det, b2 = (d11 * r2 - d12 * r1) / det, b0 = 1 - b1 - b2;
        outside = std::max(outside, -std::min({b0, b1, b2})); // a negative barycentric: off the triangle
        for (int i = 0; i < 3; ++i) off_plane = std::max(off_plane, std::fabs(r[i] - b1 * e1[i] - b2 * e2[i]));
        const double bary[3] = {b0, b1, b2};
        double n[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k)
            for (int i = 0; i < 3; ++i) n[i] += bary[k] * m.normals[k * 3 + i];
        const double ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        length_error = std::max(length_error,
                                std::fabs(std::sqrt(b.up[0] * b.up[0] + b.up[1] * b.up[1] + b.up[2] * b.up[2]) - 1.0));
        for (int i = 0; i < 3; ++i) normal_error = std::max(normal_error, std::fabs(b.up[i] - n[i] / ln));
        uv_error = std::max({uv_error, std::fabs(b.uv[0] - b1), std::fabs(b.uv[1] - b2)});
        widest_turn = std::max(widest_turn, 1.0 - b.up[1]);
    }
    EXPECT_LT(outside, 1e-5);
    EXPECT_LT(off_plane, 1e-5);
    EXPECT_LT(length_error, 1e-5);
    EXPECT_LT(normal_error, 1e-4);
    EXPECT_LT(uv_error, 1e-4);
    EXPECT_GT(widest_turn, 0.15); // the normals do turn: the comparison above is not vacuous
}

TEST_F(MeshScatterTest, PoissonTuftsKeepTheirMinimumDistance) {
    MeshScatterParams p;
    p.seeding = MeshSeeding::kTufts;
    p.density = 200.0; // 16 m^2: 3200 blades, 400 tufts of 8
    p.patch_blades = 400;
    p.tuft_min_distance = 0.12;
    p.tuft_radius = 0.05;
    p.blades_per_tuft = 8;
    const MeshScatter out = scatter(square(4), p);
    ASSERT_EQ(out.blades.size(), 3200u);
    const uint32_t tufts = static_cast<uint32_t>(out.tuft_centres.size() / 3);
    ASSERT_EQ(tufts, 400u);
    double closest = 1e30;
    for (uint32_t a = 0; a < tufts; ++a)
        for (uint32_t b = a + 1; b < tufts; ++b)
            closest = std::min(closest, distance(&out.tuft_centres[a * 3], &out.tuft_centres[b * 3]));
    EXPECT_GE(closest, 0.12 - 1e-6);
    EXPECT_LT(closest, 0.15); // the distance binds: tufts are packed up to it
    std::vector<uint32_t> per_tuft(tufts, 0);
    for (const MeshBlade& b : out.blades) {
        ASSERT_LT(b.tuft, tufts);
        ++per_tuft[b.tuft];
        ASSERT_LE(distance(b.root, &out.tuft_centres[b.tuft * 3]), 0.05 + 1e-6);
        ASSERT_NEAR(b.root[1], 0.0f, 1e-6); // in the triangle's plane
    }
    for (uint32_t n : per_tuft) ASSERT_EQ(n, 8u);

    // A distance at which the tufts cannot fit is refused by name, not clamped.
    p.tuft_min_distance = 1.0;
    MeshSurface s(&host_);
    const Mesh sq = square(4);
    ASSERT_EQ(build(sq.desc(), &s), GRASS_SUCCESS);
    MeshScatter refused(&host_);
    EXPECT_EQ(grass::scatter_mesh_blades(&log_, "test", s, p, &refused), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("params->tuft_min_distance 1 m"), std::string::npos) << last();
    EXPECT_TRUE(refused.blades.empty());
}

// Coordinates whose cell index passes int64 (1e300 m, a minimum distance of 1e-300 m):
// fuzz_mesh_field found the cast's undefined behaviour in the dart throwing (clang's UBSan,
// float-cast-overflow; GCC's -fsanitize=undefined of the asan stage leaves that check out,
// and without a sanitizer the answers were the same). The points still keep their distance.
TEST_F(MeshScatterTest, PoissonCellsOfHugeCoordinatesStayDefined) {
    grass::PoissonDiskSet far(1.0, 16, &host_);
    const double a[3] = {1e300, 0.0, 0.0}, b[3] = {-1e300, 1e300, -1e300}, c[3] = {1e300, 0.5, 0.0};
    EXPECT_TRUE(far.try_insert(a));
    EXPECT_TRUE(far.try_insert(b));
    EXPECT_FALSE(far.try_insert(c)); // 0.5 m from a: too close, though its cell index is held at the bound
    EXPECT_FALSE(far.try_insert(a));
    grass::PoissonDiskSet tiny(1e-300, 16, &host_);
    const double d[3] = {1.0, 2.0, 3.0}, e[3] = {1.0, 2.0, 3.5};
    EXPECT_TRUE(tiny.try_insert(d));
    EXPECT_TRUE(tiny.try_insert(e));
    EXPECT_EQ(tiny.size(), 2u);
}

TEST_F(MeshScatterTest, TuftRadiusAndDistanceInWorldMetresUnderAScaledTransform) {
    MeshScatterParams p;
    p.seeding = MeshSeeding::kTufts;
    p.density = 50.0; // 4 x 2 m in the world: 400 blades, 50 tufts of 8
    p.patch_blades = 400;
    p.tuft_min_distance = 0.15;
    p.tuft_radius = 0.1;
    const Mesh sq = square(2);
    MeshSurfaceDesc d = sq.desc();
    d.transform[0] = 2.0; // mesh x is twice as long in the world
    MeshSurface s(&host_);
    ASSERT_EQ(build(d, &s), GRASS_SUCCESS);
    EXPECT_NEAR(s.total_area(), 8.0, 1e-9);
    MeshScatter out(&host_);
    ASSERT_EQ(grass::scatter_mesh_blades(&log_, "test", s, p, &out), GRASS_SUCCESS) << last();
    ASSERT_EQ(out.blades.size(), 400u);
    double farthest = 0, closest = 1e30;
    for (const MeshBlade& b : out.blades) {
        const float* c = &out.tuft_centres[b.tuft * 3];
        const double dx = 2.0 * (b.root[0] - c[0]), dz = b.root[2] - c[2]; // world metres
        farthest = std::max(farthest, std::sqrt(dx * dx + dz * dz));
    }
    const size_t tufts = out.tuft_centres.size() / 3;
    for (size_t a = 0; a < tufts; ++a) {
        for (size_t b = a + 1; b < tufts; ++b) {
            const double dx = 2.0 * (out.tuft_centres[a * 3] - out.tuft_centres[b * 3]),
                         dz = out.tuft_centres[a * 3 + 2] - out.tuft_centres[b * 3 + 2];
            closest = std::min(closest, std::sqrt(dx * dx + dz * dz));
        }
    }
    EXPECT_LE(farthest, 0.1 + 1e-5);
    EXPECT_GT(farthest, 0.09); // the radius is used, in world metres
    EXPECT_GE(closest, 0.15 - 1e-5);
}

TEST_F(MeshScatterTest, SameSeedSameBlades) {
    for (MeshSeeding seeding : {MeshSeeding::kSingleBlades, MeshSeeding::kTufts}) {
        MeshScatterParams p;
        p.seeding = seeding;
        p.patch_blades = 256;
        p.tuft_min_distance = 0.1;
        const Mesh sphere = icosphere(1);
        const MeshScatter a = scatter(sphere, p), b = scatter(sphere, p);
        ASSERT_EQ(a.blades.size(), b.blades.size());
        EXPECT_EQ(std::memcmp(a.blades.data(), b.blades.data(), a.blades.size() * sizeof(MeshBlade)), 0);
        p.seed = 2;
        const MeshScatter c = scatter(sphere, p);
        ASSERT_EQ(a.blades.size(), c.blades.size());
        EXPECT_NE(std::memcmp(a.blades.data(), c.blades.data(), a.blades.size() * sizeof(MeshBlade)), 0);
    }
}

TEST_F(MeshScatterTest, PatchesOfEqualCountWhoseBoxesHoldTheirBlades) {
    MeshScatterParams p;
    p.density = 1000.0; // 12.4 m^2: about 12 patches of 1024
    p.patch_blades = 1024;
    const MeshScatter out = scatter(icosphere(2), p);
    ASSERT_GT(out.patches.size(), 4u);
    ASSERT_EQ(out.blades.size(), out.patches.size() * 1024);
    double box_sum = 0;
    for (size_t k = 0; k < out.patches.size(); ++k) {
        const grass::MeshPatch& patch = out.patches[k];
        ASSERT_EQ(patch.first_blade, k * 1024);
        for (uint32_t j = 0; j < 1024; ++j) {
            const MeshBlade& b = out.blades[patch.first_blade + j];
            for (int i = 0; i < 3; ++i) {
                ASSERT_GE(b.root[i], patch.bounds_min[i]);
                ASSERT_LE(b.root[i], patch.bounds_max[i]);
            }
        }
        box_sum += distance(patch.bounds_min, patch.bounds_max);
    }
    // Nearby blades: a patch's box is a fraction of the planet's (diagonal 3.5).
    EXPECT_LT(box_sum / out.patches.size(), 1.75);
}

TEST_F(MeshScatterTest, APrefixOfAPatchIsSpreadOverIt) {
    MeshScatterParams p;
    p.density = 100.0; // 100 m^2: 10 patches of 1024
    p.patch_blades = 1024;
    const MeshScatter out = scatter(square(10), p);
    ASSERT_EQ(out.patches.size(), 10u);
    double ratio = 0;
    for (const grass::MeshPatch& patch : out.patches) {
        const MeshBlade* blades = &out.blades[patch.first_blade];
        ratio += mean_nearest(blades, 256) / mean_nearest(blades, 1024);
    }
    ratio /= out.patches.size();
    // A quarter of the blades spread over the patch: neighbours about twice as far apart.
    EXPECT_GT(ratio, 1.7) << ratio;
}

TEST_F(MeshScatterTest, DensityThresholdsAsTheFlatPatchs) {
    MeshScatterParams p;
    p.density = 100.0;
    p.patch_blades = 1024;
    const MeshScatter out = scatter(square(10), p);
    std::vector<float> all;
    for (const grass::MeshPatch& patch : out.patches) {
        uint32_t kept = 0;
        for (uint32_t j = 0; j < 1024; ++j) {
            const float t = out.blades[patch.first_blade + j].threshold;
            ASSERT_GT(t, 0.0f);
            ASSERT_LE(t, 1.0f);
            kept += t <= 0.25f;
            all.push_back(t);
        }
        EXPECT_NEAR(kept / 1024.0, 0.25, 0.07); // every patch thinned alike, five sigmas
    }
    std::sort(all.begin(), all.end());
    for (size_t k = 0; k < all.size(); ++k) ASSERT_FLOAT_EQ(all[k], float(double(k + 1) / all.size()));
}

TEST_F(MeshScatterTest, BadInputIsRefusedByNameAndLeavesTheSurface) {
    const Mesh good = two_triangles();
    MeshSurface s(&host_);
    ASSERT_EQ(build(good.desc(), &s), GRASS_SUCCESS);
    const double area = s.total_area();
    EXPECT_NEAR(area, 4.0, 1e-9);

    Mesh nan = good;
    nan.positions[4] = std::nanf("");
    EXPECT_EQ(build(nan.desc(), &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->positions[1] has nan in component 1"), std::string::npos) << last();

    Mesh inf = good;
    inf.normals[0] = INFINITY;
    EXPECT_EQ(build(inf.desc(), &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->normals[0] has inf"), std::string::npos) << last();

    Mesh zero = good;
    zero.normals[3] = zero.normals[4] = zero.normals[5] = 0;
    EXPECT_EQ(build(zero.desc(), &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->normals[1] is (0, 0, 0)"), std::string::npos) << last();

    Mesh out_of_range = good;
    out_of_range.indices[4] = 7;
    EXPECT_EQ(build(out_of_range.desc(), &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->indices[4] is 7; it must be below desc->vertex_count (6)"), std::string::npos)
        << last();

    MeshSurfaceDesc huge = good.desc(); // 2^31 indices over a buffer of 6: refused before reading
    huge.index_count = uint64_t{1} << 31;
    EXPECT_EQ(build(huge, &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->index_count is 2147483648"), std::string::npos) << last();
    huge.index_count = (uint64_t{1} << 31) + 1; // a multiple of 3: refused by the limit alone
    EXPECT_EQ(build(huge, &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->index_count is 2147483649"), std::string::npos) << last();

    MeshSurfaceDesc flat = good.desc();
    flat.transform[5] = 0; // y scaled to nothing
    EXPECT_EQ(build(flat, &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->transform flattens the mesh"), std::string::npos) << last();

    // Every refusal left the surface built first.
    EXPECT_EQ(s.triangle_count(), 2u);
    EXPECT_EQ(s.total_area(), area);

    MeshScatterParams p;
    p.density = std::nan("");
    MeshScatter out(&host_);
    EXPECT_EQ(grass::scatter_mesh_blades(&log_, "test", s, p, &out), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("params->density is nan"), std::string::npos) << last();
    p.density = 100.0;
    p.patch_blades = 10;
    EXPECT_EQ(grass::scatter_mesh_blades(&log_, "test", s, p, &out), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("params->patch_blades is 10"), std::string::npos) << last();
    p.patch_blades = 1024;
    p.density = 1e5;
    Mesh large = square(200); // 4e4 m^2 at 1e5 a square metre: 4e9 blades
    MeshSurface wide(&host_);
    ASSERT_EQ(build(large.desc(), &wide), GRASS_SUCCESS);
    EXPECT_EQ(grass::scatter_mesh_blades(&log_, "test", wide, p, &out), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("params->density 100000 on 40000 m^2"), std::string::npos) << last();
    p.density = 100.0;
    p.thresholds.mode = GRASS_THRESHOLD_CLUSTERED; // clusters over UVs: refused on a mesh without them
    MeshSurfaceDesc bare = good.desc();
    bare.uvs = nullptr;
    MeshSurface no_uvs(&host_);
    ASSERT_EQ(build(bare, &no_uvs), GRASS_SUCCESS);
    EXPECT_EQ(grass::scatter_mesh_blades(&log_, "test", no_uvs, p, &out), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("desc->uvs is NULL"), std::string::npos) << last();
    EXPECT_TRUE(out.blades.empty());
}

TEST_F(MeshScatterTest, DegenerateTrianglesAreSkippedAndCounted) {
    Mesh m = two_triangles();
    const uint32_t a = m.add(10, 0, 0, 0, 1, 0), b = m.add(11, 0, 0, 0, 1, 0), c = m.add(12, 0, 0, 0, 1, 0);
    m.triangle(a, b, c); // collinear
    m.triangle(a, a, b); // a repeated corner
    MeshSurface s(&host_);
    ASSERT_EQ(build(m.desc(), &s), GRASS_SUCCESS) << last();
    EXPECT_EQ(s.triangle_count(), 2u);
    EXPECT_EQ(s.degenerate_count(), 2u);
    MeshScatterParams p;
    p.density = 1000.0;
    p.patch_blades = 1000;
    MeshScatter out(&host_);
    ASSERT_EQ(grass::scatter_mesh_blades(&log_, "test", s, p, &out), GRASS_SUCCESS) << last();
    for (const MeshBlade& blade : out.blades) ASSERT_LT(blade.triangle, 2u);

    Mesh none;
    none.triangle(none.add(0, 0, 0, 0, 1, 0), none.add(1, 0, 0, 0, 1, 0), none.add(2, 0, 0, 0, 1, 0));
    EXPECT_EQ(build(none.desc(), &s), GRASS_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(last().find("all 1 triangles are degenerate"), std::string::npos) << last();
    EXPECT_EQ(s.triangle_count(), 2u);
}

TEST_F(MeshScatterTest, APlanetGetsBladesOnEveryFaceTheUndersideIncluded) {
    const Mesh planet = icosphere(2); // 320 faces, 12.5 m^2
    MeshScatterParams p;
    p.density = 800.0; // about 31 blades a face
    p.patch_blades = 512;
    const MeshScatter out = scatter(planet, p);
    std::vector<uint32_t> per_face(planet.indices.size() / 3, 0);
    uint32_t underside = 0;
    for (const MeshBlade& b : out.blades) {
        ++per_face[b.triangle];
        underside += b.up[1] < -0.95f;
        float radial[3] = {b.root[0], b.root[1], b.root[2]};
        unit(radial);
        ASSERT_GT(radial[0] * b.up[0] + radial[1] * b.up[1] + radial[2] * b.up[2], 0.98f); // up points out
    }
    for (size_t f = 0; f < per_face.size(); ++f) ASSERT_GT(per_face[f], 0u) << "face " << f;
    EXPECT_GT(underside, 50u);

    // The transform's scale counts in the area: twice the radius, four times the blades.
    MeshSurfaceDesc twice = planet.desc();
    twice.transform[0] = twice.transform[5] = twice.transform[10] = 2.0;
    twice.transform[13] = 100.0;
    MeshSurface small(&host_), big(&host_);
    ASSERT_EQ(build(planet.desc(), &small), GRASS_SUCCESS);
    ASSERT_EQ(build(twice, &big), GRASS_SUCCESS);
    EXPECT_NEAR(big.total_area(), 4 * small.total_area(), 1e-9);
    EXPECT_GT(small.total_area(), 12.0); // a sphere of radius 1: at most 4 pi
    EXPECT_LT(small.total_area(), 4 * M_PI);
}

} // namespace
