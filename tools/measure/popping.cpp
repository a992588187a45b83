// grass-measure popping: popping, measured (issue 6 item 3). A camera at player height dollies
// forward at walking speed through the football scene; at each step the frame is rendered
// and, inside the screen region of each transition zone (where two tiers' distance bands
// overlap, from the field's lod setup and the camera geometry), the per-pixel luma change
// from the previous frame is measured. The camera moves, so part of that change is motion;
// the same dolly rendered with blades everywhere (one geometry tier to infinity: the
// reference) changes too, and its change is the irreducible flicker. Per zone: mean and 95th
// percentile of |delta luma| for the lod setup and for the reference, and their ratios.
// Then the per-tier mean-colour agreement: a distant 8 x 8 patch of cells drawn by each tier
// of the setup alone (as tests/render/tier_lighting_test.cpp does), mean sRGB over the pixels
// that are grass in every render.
//
// Each zone is rendered in its own window: the rows and columns of the full frame that hold
// it, through an off-centre projection that is exactly that part of the full frame's frustum
// (the pixels are the full frame's pixels). The reference costs ~25k vertices a cell, so far
// zones are measured on a centred range of columns whose reference plan stays within
// --cell-budget geometry cells (planned first on a context without a GPU).
//
// --wind S: under a wind of S m/s (grass_default_wind_desc's direction, gusts and turbulence),
// both the lod setup and the reference, every frame at the same time, --wind-time (default 2 s).
// The measure compares each frame with the previous one while the camera moves: were the wind's
// time to advance too, every pixel would change by the grass's sway as well, in the lod setup
// and the reference alike, and the ratio would measure the sway. With one time for the whole
// dolly the wind is a fixed function of world position: the grass stands bent, gusts and all,
// and what changes from frame to frame is the motion and the transitions, as for still grass.
// Usage: grass-measure popping [--backend gl|vk] [--scene FILE] [--frames N] [--size WxH]
//                              [--samples N] [--canopy M] [--cell-budget N] [--max-reference-cells N]
//                              [--cache DIR] [--no-agreement] [--wind S] [--wind-time T]
//                              [--blade-culling TESTS] [--tessellation PX]
// A zone whose reference needs more than --max-reference-cells cells even in its narrowest
// window (4 columns) is listed but not measured (the far zones: ~1500 cells for 8 pixels).
#include <grass/grass.h>

#include "cli.hpp"
#include "headless_host.hpp"
#include "measure.hpp"
#include "scene.hpp"
#include "stats.hpp"
#include "tool.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace grass_measure {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kWalkSpeed = 1.4; // m/s
constexpr double kFps = 30.0;
constexpr float kNear = 0.05f;

struct Options {
    grass_backend backend = GRASS_BACKEND_GL;
    std::string scene_path = GRASS_SCENE_DIR "/football.json";
    std::string cache_dir;
    int frames = 30;
    uint32_t width = 320, height = 180, samples = 4;
    double canopy = 0.2;                // m: the height where a view ray meets the lawn (see docs/records/popping.md)
    uint64_t cell_budget = 150;         // reference geometry cells per zone window
    uint64_t max_reference_cells = 600; // a zone whose narrowest window needs more is not measured
    bool agreement = true;
    float wind = 0.0f;      // m/s; 0: still grass
    double wind_time = 2.0; // s: grass_view_desc.time of every frame
    // --blade-culling: per-blade culling of the lod setup's geometry tier (not the reference's)
    std::vector<std::string> blade_culling;
    float tessellation = 0.0f; // --tessellation: the lod setup's blades' dynamic tessellation (pixels; 0: off)
};

double luma(const uint8_t* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// The camera of step k: the scene camera moved forward (horizontally) by k steps.
struct Camera {
    double eye[3], target[3];
};

Camera camera_at(const grass_sample::Scene& s, int k) {
    double f[2] = {s.target[0] - s.eye[0], s.target[2] - s.eye[2]};
    const double l = std::sqrt(f[0] * f[0] + f[1] * f[1]);
    const double step = kWalkSpeed / kFps * k;
    Camera c{};
    for (int i = 0; i < 3; ++i) {
        c.eye[i] = s.eye[i];
        c.target[i] = s.target[i];
    }
    c.eye[0] += f[0] / l * step;
    c.eye[2] += f[1] / l * step;
    c.target[0] += f[0] / l * step;
    c.target[2] += f[1] / l * step;
    return c;
}

// The tiers and lod tests of a field.
struct LodSetup {
    std::vector<grass_tier_desc> tiers;
    std::vector<grass_lod_test> tests;
};

// A transition zone: the overlap of two tiers' distance bands (metres from the camera).
struct Zone {
    uint32_t tier_a, tier_b;
    double begin, end;
    // Its pixels in the full frame and the window that holds them.
    std::vector<uint8_t> mask; // full frame, 1 = in the zone
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    uint64_t reference_cells = 0;
    double reference_end = 0.0; // m: the reference's blades end here (beyond, no cell can reach the zone's pixels)
    // Measured.
    std::vector<float> delta_lod, delta_ref; // |delta luma| of every zone pixel of every step
    double luma_lod = 0.0, luma_ref = 0.0;   // mean luma over every frame
    uint64_t luma_samples = 0;
};

const char* kind_name(grass_tier_kind k) {
    return k == GRASS_TIER_GEOMETRY ? "geometry" : k == GRASS_TIER_VOLUME ? "volume" : "image";
}

std::string tier_name(const grass_tier_desc& t) {
    if (t.kind == GRASS_TIER_VOLUME) return "volume " + std::to_string(t.slices);
    return kind_name(t.kind);
}

// The full frame's view ray through the centre of pixel (px, py), top row first.
void pixel_ray(const Camera& c, double fovy_deg, uint32_t w, uint32_t h, double px, double py, double out[3]) {
    double f[3] = {c.target[0] - c.eye[0], c.target[1] - c.eye[1], c.target[2] - c.eye[2]};
    const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (double& x : f) x /= fl;
    double r[3] = {-f[2], 0.0, f[0]}; // f x (0, 1, 0), as grass_host::make_view
    const double rl = std::sqrt(r[0] * r[0] + r[2] * r[2]);
    for (double& x : r) x /= rl;
    const double u[3] = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    const double t = std::tan(fovy_deg * kPi / 360.0);
    const double nx = (2.0 * (px + 0.5) / w - 1.0) * t * double(w) / double(h);
    const double ny = (1.0 - 2.0 * (py + 0.5) / h) * t;
    for (int i = 0; i < 3; ++i) out[i] = f[i] + nx * r[i] + ny * u[i];
}

// The projection of window [x0, x1) x [y0, y1) of the full frame: the full projection with
// its x and y rows remapped so that the window's part of NDC fills [-1, 1].
void window_projection(const grass_host::Host& host, const Options& o, float fovy_deg, float far_m, uint32_t x0,
                       uint32_t y0, uint32_t x1, uint32_t y1, float out[16]) {
    float p[16];
    host.projection(static_cast<float>(fovy_deg * kPi / 180.0), float(o.width) / float(o.height), kNear, far_m, p);
    const double sign = p[5] > 0.0f ? 1.0 : -1.0; // GL: +y up in NDC; Vulkan: y down
    const double left = 2.0 * x0 / o.width - 1.0, right = 2.0 * x1 / o.width - 1.0;
    const double top_up = 1.0 - 2.0 * y0 / o.height, bottom_up = 1.0 - 2.0 * y1 / o.height;
    const double cx = 0.5 * (left + right), sx = 0.5 * (right - left);
    const double cy = sign * 0.5 * (top_up + bottom_up), sy = 0.5 * (top_up - bottom_up);
    for (int col = 0; col < 4; ++col) {
        const double w = p[4 * col + 3];
        out[4 * col + 0] = static_cast<float>((p[4 * col + 0] - cx * w) / sx);
        out[4 * col + 1] = static_cast<float>((p[4 * col + 1] - cy * w) / sy);
        out[4 * col + 2] = p[4 * col + 2];
        out[4 * col + 3] = p[4 * col + 3];
    }
}

grass_view_desc window_view(const grass_host::Host& host, const Options& o, const grass_sample::Scene& s,
                            const Camera& c, const Zone& z, uint32_t x0, uint32_t x1) {
    grass_view_desc v = grass_host::make_view(host, c.eye, c.target, s.fov_degrees, kNear, s.far_m);
    window_projection(host, o, s.fov_degrees, s.far_m, x0, z.y0, x1, z.y1, v.projection);
    v.viewport[2] = static_cast<int32_t>(x1 - x0);
    v.viewport[3] = static_cast<int32_t>(z.y1 - z.y0);
    grass_sample::apply_light(s, &v);
    v.time = o.wind_time;
    return v;
}

// A null host for planning (grass_create_context draws nothing): projections only.
class PlanHost final : public grass_host::Host {
public:
    explicit PlanHost(const grass_host::TargetDesc& t) : Host(t) {}
    grass_backend backend() const override { return GRASS_BACKEND_NONE; }
    std::string device_name() const override { return "none"; }
    grass_result create_context(const grass_context_desc& d, grass_context** out) override {
        return grass_create_context(GRASS_HEADER_VERSION, &d, out);
    }
    void projection(float fovy, float aspect, float n, float f, float out[16]) const override {
        // The GL convention (z -1..1, y up): the frustum is the same.
        const float t = 1.0f / std::tan(fovy * 0.5f);
        std::memset(out, 0, 16 * sizeof(float));
        out[0] = t / aspect;
        out[5] = t;
        out[10] = (f + n) / (n - f);
        out[11] = -1.0f;
        out[14] = 2.0f * f * n / (n - f);
    }
    grass_result render(grass_context*, const grass_view_desc&, const grass_host::Occluder*, grass_host::Image*,
                        std::string*) override {
        return GRASS_ERROR_UNSUPPORTED;
    }
    uint32_t validation_messages() const override { return 0; }
    std::string validation_log() const override { return ""; }
};

// A context's scene: the patch and one field (the scene's lod setup, or blades everywhere).
struct SceneContext {
    grass_context* ctx = nullptr;
    grass_patch_id patch{};
    grass_field_id field{};
    ~SceneContext() {
        if (ctx) grass_destroy_context(ctx);
    }
};

bool make_scene_context(grass_host::Host& host, const Options& o, const grass_sample::Scene& s,
                        const std::vector<grass_tier_desc>& tiers, const std::vector<grass_lod_test>& tests,
                        SceneContext* out, std::string* error) {
    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = grass_sample::log_to_stderr;
    if (!o.cache_dir.empty()) cd.cache_directory = o.cache_dir.c_str();
    grass_result r = host.create_context(cd, &out->ctx);
    if (r == GRASS_SUCCESS) r = grass_create_patch(out->ctx, &s.patch, &out->patch);
    if (r == GRASS_SUCCESS) {
        grass_field_desc f = s.field;
        f.patch = out->patch;
        f.tiers = tiers.data();
        f.tier_count = static_cast<uint32_t>(tiers.size());
        f.lod_tests = tests.data();
        f.lod_test_count = static_cast<uint32_t>(tests.size());
        r = grass_create_field(out->ctx, &f, &out->field);
    }
    if (r == GRASS_SUCCESS && o.wind > 0.0f) {
        grass_wind_desc wind = grass_default_wind_desc();
        wind.speed = o.wind;
        r = grass_set_wind(out->ctx, &wind);
    }
    if (r != GRASS_SUCCESS) {
        *error = std::string("cannot make the scene: ") + grass_result_string(r) +
                 (out->ctx ? std::string(" (") + grass_get_last_error(out->ctx) + ")" : std::string());
        return false;
    }
    return true;
}

// --blade-culling on the lod setup's field: each name switches one of jahrmann2017 6.2's
// tests on at his values (the distance tests over the geometry tier).
bool set_blade_culling(const Options& o, const SceneContext& lod, std::string* error) {
    if (o.blade_culling.empty()) return true;
    const grass_blade_culling_desc c = grass_sample::blade_culling_desc(o.blade_culling);
    const grass_result r = grass_set_blade_culling(lod.ctx, lod.field, &c);
    if (r == GRASS_SUCCESS) return true;
    *error = std::string("grass_set_blade_culling: ") + grass_get_last_error(lod.ctx);
    return false;
}

// ---- Per-tier mean-colour agreement ------------------------------------------------------

struct Agreement {
    std::string name;
    double coverage = 0.0;
    double mean[3] = {0, 0, 0};
};

bool tier_agreement(const Options& o, const grass_sample::Scene& s, const std::vector<grass_tier_desc>& tiers,
                    std::vector<Agreement>* out, std::string* error) {
    grass_host::TargetDesc t;
    t.width = t.height = 128;
    t.samples = 4;
    auto host = grass_host::Host::create(o.backend, t, error);
    if (!host) return false;
    std::vector<grass_host::Image> images;
    for (const grass_tier_desc& tier : tiers) {
        std::vector<grass_tier_desc> solo = {tier};
        std::vector<grass_lod_test> tests(tier.kind == GRASS_TIER_GEOMETRY ? 1 : 2);
        tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
        tests[0].end = INFINITY;
        if (tests.size() > 1) {
            tests[1].kind = GRASS_LOD_TEST_MACRO_CELL;
            tests[1].max_macro_cells = 1;
        }
        grass_sample::Scene cells = s;
        cells.field.cells_x = cells.field.cells_z = 8;
        cells.field.cell_size = 0.25;
        for (int i = 0; i < 16; ++i) cells.field.base_transform[i] = (i % 5 == 0) ? 1.0 : 0.0;
        SceneContext sc;
        if (!make_scene_context(*host, o, cells, solo, tests, &sc, error)) return false;
        // About 9 m away, 1.6 m up (tier_lighting_test.cpp's camera).
        const double eye[3] = {1.0, 1.6, -8.0}, target[3] = {1.0, 0.0, 1.0};
        grass_view_desc v = grass_host::make_view(*host, eye, target, 14.0f, kNear, 100.0f);
        grass_sample::apply_light(s, &v);
        v.time = o.wind_time;
        grass_host::Image image;
        const grass_result r = host->render(sc.ctx, v, nullptr, &image, error);
        if (r != GRASS_SUCCESS) {
            *error = std::string("rendering a tier alone: ") + grass_result_string(r) + " " + *error;
            return false;
        }
        images.push_back(std::move(image));
    }
    if (host->validation_messages() != 0) {
        *error = "validation messages:\n" + host->validation_log();
        return false;
    }
    uint8_t sky[3];
    for (int c = 0; c < 3; ++c) {
        const double l = t.clear_color[c];
        const double e = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
        sky[c] = static_cast<uint8_t>(std::lround(e * 255.0));
    }
    const auto is_grass = [&](const uint8_t* p) {
        for (int c = 0; c < 3; ++c) {
            if (std::abs(int(p[c]) - int(sky[c])) > 6) return true;
        }
        return false;
    };
    out->assign(tiers.size(), Agreement{});
    uint64_t common = 0;
    for (uint32_t y = 0; y < t.height; ++y) {
        for (uint32_t x = 0; x < t.width; ++x) {
            bool all = true;
            for (size_t k = 0; k < tiers.size(); ++k) {
                const bool g = is_grass(images[k].pixel(x, y));
                (*out)[k].coverage += g;
                all = all && g;
            }
            if (!all) continue;
            ++common;
            for (size_t k = 0; k < tiers.size(); ++k) {
                for (int c = 0; c < 3; ++c) (*out)[k].mean[c] += images[k].pixel(x, y)[c];
            }
        }
    }
    for (size_t k = 0; k < tiers.size(); ++k) {
        (*out)[k].name = tier_name(tiers[k]);
        (*out)[k].coverage /= double(t.width) * t.height;
        for (double& m : (*out)[k].mean) m = common ? m / double(common) : 0.0;
    }
    return true;
}

// The scene's lod setup: its own, or the library's default.
LodSetup lod_setup(const grass_sample::Scene& s) {
    LodSetup lod{s.tiers, s.lod_tests};
    std::vector<grass_tier_desc>& tiers = lod.tiers;
    std::vector<grass_lod_test>& tests = lod.tests;
    if (tiers.empty() && tests.empty()) {
        tiers.resize(GRASS_DEFAULT_TIER_COUNT);
        tests.resize(GRASS_DEFAULT_LOD_TEST_COUNT);
        grass_default_lod_setup(s.field.cell_size, tiers.data(), tests.data());
    }
    return lod;
}

// The transition zones: where two tiers' distance bands overlap (hilltop overlays left
// out), nearest first.
std::vector<Zone> find_zones(const LodSetup& lod) {
    const std::vector<grass_tier_desc>& tiers = lod.tiers;
    std::vector<double> band_begin(tiers.size(), -1.0), band_end(tiers.size(), -1.0);
    std::vector<bool> overlay(tiers.size(), false);
    for (const grass_lod_test& t : lod.tests) {
        if (t.tier >= tiers.size()) continue;
        if (t.kind == GRASS_LOD_TEST_DISTANCE_BAND) {
            band_begin[t.tier] = t.begin;
            band_end[t.tier] = t.end;
        }
        if (t.kind == GRASS_LOD_TEST_HILLTOP) overlay[t.tier] = true;
    }
    std::vector<Zone> zones;
    for (uint32_t a = 0; a < tiers.size(); ++a) {
        for (uint32_t b = a + 1; b < tiers.size(); ++b) {
            if (overlay[a] || overlay[b] || band_begin[a] < 0.0 || band_begin[b] < 0.0) continue;
            const double lo = std::max(band_begin[a], band_begin[b]), hi = std::min(band_end[a], band_end[b]);
            if (hi > lo) {
                Zone z;
                z.tier_a = a;
                z.tier_b = b;
                z.begin = lo;
                z.end = hi;
                zones.push_back(z);
            }
        }
    }
    std::sort(zones.begin(), zones.end(), [](const Zone& x, const Zone& y) { return x.begin < y.begin; });
    return zones;
}

// Each zone's pixels in the full frame and the window that holds them; zones off screen are
// dropped.
void mark_zone_pixels(const Options& o, const grass_sample::Scene& s, std::vector<Zone>* zones_out) {
    std::vector<Zone>& zones = *zones_out;
    // Each zone's pixels: the ray of a pixel meets the lawn at the canopy height; the blade
    // roots under that point are at distance d from the camera (what the tiers' bands
    // measure). A pixel is in a zone in the first and the last frame, over the field.
    const double field_w = s.field.cells_x * s.field.cell_size, field_d = s.field.cells_z * s.field.cell_size;
    const double ox = s.field.base_transform[12], oz = s.field.base_transform[14];
    const Camera first = camera_at(s, 0), last = camera_at(s, o.frames - 1);
    for (Zone& z : zones) {
        z.mask.assign(size_t(o.width) * o.height, 0);
        z.x0 = o.width;
        z.y0 = o.height;
        for (uint32_t py = 0; py < o.height; ++py) {
            for (uint32_t px = 0; px < o.width; ++px) {
                bool in = true;
                double ground = 0.0;
                for (const Camera* c : {&first, &last}) {
                    double dir[3];
                    pixel_ray(*c, s.fov_degrees, o.width, o.height, px, py, dir);
                    const double drop = c->eye[1] - o.canopy;
                    if (!(dir[1] < 0.0) || drop <= 0.0) {
                        in = false;
                        break;
                    }
                    const double t = drop / -dir[1];
                    const double x = c->eye[0] + t * dir[0], zz = c->eye[2] + t * dir[2];
                    const double gx = x - c->eye[0], gz = zz - c->eye[2];
                    const double d = std::sqrt(gx * gx + gz * gz + c->eye[1] * c->eye[1]);
                    const bool on_field = x >= ox && x <= ox + field_w && zz >= oz && zz <= oz + field_d;
                    in = in && on_field && d >= z.begin && d <= z.end;
                    if (in) {
                        // Where the ray meets the ground: nothing farther shows in this pixel.
                        const double tg = c->eye[1] / -dir[1];
                        const double g[3] = {tg * dir[0], -c->eye[1], tg * dir[2]};
                        ground = std::max(ground, std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]));
                    }
                }
                if (!in) continue;
                z.reference_end = std::max(z.reference_end, ground + 1.0);
                z.mask[size_t(py) * o.width + px] = 1;
                z.x0 = std::min(z.x0, px);
                z.y0 = std::min(z.y0, py);
                z.x1 = std::max(z.x1, px + 1);
                z.y1 = std::max(z.y1, py + 1);
            }
        }
    }
    zones.erase(std::remove_if(zones.begin(), zones.end(), [](const Zone& z) { return z.x1 <= z.x0; }), zones.end());
    if (zones.empty()) throw grass_sample::Failure("no transition zone is on screen");
}

// The reference: blades everywhere (one geometry tier) out to `end` metres.
LodSetup reference_setup(double end) {
    LodSetup ref;
    ref.tiers = {{GRASS_TIER_GEOMETRY, 0}};
    ref.tests.resize(1);
    ref.tests[0].kind = GRASS_LOD_TEST_DISTANCE_BAND;
    ref.tests[0].end = static_cast<float>(end);
    return ref;
}

// Narrows each zone's window to a centred range of columns whose reference plan (on a
// context without a GPU) stays within the cell budget.
void narrow_windows(const Options& o, const grass_sample::Scene& s, std::vector<Zone>* zones) {
    const Camera first = camera_at(s, 0), last = camera_at(s, o.frames - 1);
    {
        grass_host::TargetDesc t;
        t.width = o.width;
        t.height = o.height;
        PlanHost plan_host(t);
        const auto plan_cells = [&](const Zone& z, uint32_t x0, uint32_t x1) {
            SceneContext plan;
            const LodSetup ref = reference_setup(z.reference_end);
            std::string error;
            if (!make_scene_context(plan_host, o, s, ref.tiers, ref.tests, &plan, &error)) {
                throw grass_sample::Failure(error);
            }
            uint64_t most = 0;
            for (const Camera& c : {first, last}) {
                const grass_view_desc v = window_view(plan_host, o, s, c, z, x0, x1);
                grass_frame_stats st{};
                grass_sample::check(grass_begin_frame(plan.ctx, &v), "grass_begin_frame", plan.ctx);
                grass_sample::check(grass_get_frame_stats(plan.ctx, &st), "grass_get_frame_stats", plan.ctx);
                grass_sample::check(grass_end_frame(plan.ctx), "grass_end_frame", plan.ctx);
                most = std::max(most, st.cells[GRASS_TIER_GEOMETRY]);
            }
            return most;
        };
        for (Zone& z : *zones) {
            const uint32_t centre = (z.x0 + z.x1) / 2;
            uint32_t half = (z.x1 - z.x0 + 1) / 2;
            while (half > 2) {
                const uint32_t x0 = centre > half ? centre - half : 0, x1 = std::min(o.width, centre + half);
                if (plan_cells(z, x0, x1) <= o.cell_budget) break;
                half = half * 3 / 4;
            }
            z.x0 = centre > half ? centre - half : 0;
            z.x1 = std::min(o.width, centre + half);
            z.reference_cells = plan_cells(z, z.x0, z.x1);
        }
    }
}

// Renders the dolly in the zone's window with the lod setup and with the reference, and
// measures the zone's pixels; a zone whose reference needs more than --max-reference-cells
// is reported on stderr and left unmeasured. *device: the host's device name.
void measure_zone(const Options& o, const grass_sample::Scene& s, const LodSetup& setup, Zone* z, std::string* device) {
    std::string error;
    if (z->reference_cells > o.max_reference_cells) {
        std::fprintf(stderr,
                     "grass-measure popping: zone %s/%s not measured: its reference needs %llu cells (raise "
                     "--max-reference-cells)\n",
                     tier_name(setup.tiers[z->tier_a]).c_str(), tier_name(setup.tiers[z->tier_b]).c_str(),
                     static_cast<unsigned long long>(z->reference_cells));
        return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    grass_host::TargetDesc t = grass_sample::target_desc(s);
    t.width = z->x1 - z->x0;
    t.height = z->y1 - z->y0;
    auto host = grass_host::Host::create(o.backend, t, &error);
    if (!host) throw grass_sample::Failure("cannot create the headless host: " + error);
    *device = host->device_name();
    SceneContext lod, ref;
    const LodSetup reference = reference_setup(z->reference_end);
    if (!make_scene_context(*host, o, s, setup.tiers, setup.tests, &lod, &error) ||
        !make_scene_context(*host, o, s, reference.tiers, reference.tests, &ref, &error) ||
        !set_blade_culling(o, lod, &error)) {
        throw grass_sample::Failure(error);
    }
    if (grass_sample::set_tessellation(lod.ctx, lod.field, o.tessellation) != GRASS_SUCCESS) {
        error = std::string("grass_set_blade_tessellation: ") + grass_get_last_error(lod.ctx);
        throw grass_sample::Failure(error);
    }
    std::vector<double> prev_lod, prev_ref;
    uint64_t zone_pixels = 0;
    for (int k = 0; k < o.frames; ++k) {
        const grass_view_desc v = window_view(*host, o, s, camera_at(s, k), *z, z->x0, z->x1);
        grass_host::Image img_lod, img_ref;
        grass_result r = host->render(lod.ctx, v, nullptr, &img_lod, &error);
        if (r == GRASS_SUCCESS) r = host->render(ref.ctx, v, nullptr, &img_ref, &error);
        if (r != GRASS_SUCCESS) {
            throw grass_sample::Failure(std::string("rendering failed: ") + grass_result_string(r) + " " + error);
        }
        std::vector<double> cur_lod, cur_ref;
        for (uint32_t y = z->y0; y < z->y1; ++y) {
            for (uint32_t x = z->x0; x < z->x1; ++x) {
                if (!z->mask[size_t(y) * o.width + x]) continue;
                cur_lod.push_back(luma(img_lod.pixel(x - z->x0, y - z->y0)));
                cur_ref.push_back(luma(img_ref.pixel(x - z->x0, y - z->y0)));
            }
        }
        zone_pixels = cur_lod.size();
        for (size_t i = 0; i < cur_lod.size(); ++i) {
            z->luma_lod += cur_lod[i];
            z->luma_ref += cur_ref[i];
        }
        z->luma_samples += cur_lod.size();
        if (k > 0) {
            for (size_t i = 0; i < cur_lod.size(); ++i) {
                z->delta_lod.push_back(static_cast<float>(std::fabs(cur_lod[i] - prev_lod[i])));
                z->delta_ref.push_back(static_cast<float>(std::fabs(cur_ref[i] - prev_ref[i])));
            }
        }
        prev_lod.swap(cur_lod);
        prev_ref.swap(cur_ref);
    }
    if (host->validation_messages() != 0)
        throw grass_sample::Failure("validation messages:\n" + host->validation_log());
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr,
                 "grass-measure popping: %s zone %s/%s %.1f-%.1f m: window %ux%u at (%u, %u), %llu zone pixels, "
                 "reference %llu cells, %d frames in %.1f s\n",
                 grass_sample::backend_name(o.backend), tier_name(setup.tiers[z->tier_a]).c_str(),
                 tier_name(setup.tiers[z->tier_b]).c_str(), z->begin, z->end, t.width, t.height, z->x0, z->y0,
                 static_cast<unsigned long long>(zone_pixels), static_cast<unsigned long long>(z->reference_cells),
                 o.frames, secs);
}

// The Markdown report on stdout: a row per zone, then the per-tier mean colours.
void print_report(const Options& o, const grass_sample::Scene& s, const LodSetup& lod, const std::vector<Zone>& zones,
                  const std::vector<Agreement>& agreement, const std::string& device, double total) {
    std::printf("## grass-popping: %s (%s)\n\n", grass_sample::backend_name(o.backend), device.c_str());
    std::printf("%s, %ux%u, %ux MSAA, camera %.1f m up dollying %.3f m per frame (%.1f m/s at %.0f fps), %d frames; "
                "zone pixels where the view ray meets the lawn (%.2f m up) over roots in the zone; luma in 8-bit "
                "sRGB levels (Rec. 709 weights); wind %.1f m/s at %.2f s in every frame; run %.0f s\n\n",
                o.scene_path.c_str(), o.width, o.height, o.samples, s.eye[1], kWalkSpeed / kFps, kWalkSpeed, kFps,
                o.frames, o.canopy, double(o.wind), o.wind_time, total);
    std::printf("| zone | distance (m) | rows | columns | pixels | ref. cells (blades to m) | mean dY lod | mean dY "
                "ref | ratio | p95 dY lod | "
                "p95 dY ref | ratio | mean Y lod | mean Y ref |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Zone& z : zones) {
        uint64_t pixels = 0;
        for (uint32_t y = z.y0; y < z.y1; ++y) {
            for (uint32_t x = z.x0; x < z.x1; ++x) pixels += z.mask[size_t(y) * o.width + x];
        }
        if (z.delta_lod.empty()) {
            std::printf(
                "| %s / %s | %.2f-%.2f | %u-%u | %u-%u | %llu | %llu (%.0f) | not measured (--max-reference-cells) "
                "| | | | | | | |\n",
                tier_name(lod.tiers[z.tier_a]).c_str(), tier_name(lod.tiers[z.tier_b]).c_str(), z.begin, z.end, z.y0,
                z.y1 - 1, z.x0, z.x1 - 1, static_cast<unsigned long long>(pixels),
                static_cast<unsigned long long>(z.reference_cells), z.reference_end);
            continue;
        }
        const double ml = grass_sample::mean(z.delta_lod), mr = grass_sample::mean(z.delta_ref);
        const double pl = grass_sample::percentile(z.delta_lod, 0.95), pr = grass_sample::percentile(z.delta_ref, 0.95);
        std::printf("| %s / %s | %.2f-%.2f | %u-%u | %u-%u | %llu | %llu (%.0f) | %.2f | %.2f | %.2f | %.1f | %.1f | "
                    "%.2f | %.1f | %.1f |\n",
                    tier_name(lod.tiers[z.tier_a]).c_str(), tier_name(lod.tiers[z.tier_b]).c_str(), z.begin, z.end,
                    z.y0, z.y1 - 1, z.x0, z.x1 - 1, static_cast<unsigned long long>(pixels),
                    static_cast<unsigned long long>(z.reference_cells), z.reference_end, ml, mr, mr > 0 ? ml / mr : 0.0,
                    pl, pr, pr > 0 ? pl / pr : 0.0, z.luma_samples ? z.luma_lod / double(z.luma_samples) : 0.0,
                    z.luma_samples ? z.luma_ref / double(z.luma_samples) : 0.0);
    }
    if (!agreement.empty()) {
        std::printf(
            "\nPer-tier mean colour: 8 x 8 cells at ~9 m, each tier alone, 128x128, 4x MSAA; mean sRGB over the "
            "pixels that are grass in every render\n\n");
        std::printf(
            "| tier | coverage | mean sRGB | minus geometry | largest channel difference |\n|---|---|---|---|---|\n");
        for (const Agreement& a : agreement) {
            const double* g = agreement[0].mean;
            double largest = 0.0;
            for (int c = 0; c < 3; ++c) largest = std::max(largest, std::fabs(a.mean[c] - g[c]));
            std::printf("| %s | %.3f | (%.1f, %.1f, %.1f) | (%+.1f, %+.1f, %+.1f) | %.1f |\n", a.name.c_str(),
                        a.coverage, a.mean[0], a.mean[1], a.mean[2], a.mean[0] - g[0], a.mean[1] - g[1],
                        a.mean[2] - g[2], largest);
        }
    }
}

int run(const Options& o) {
    const auto t_start = std::chrono::steady_clock::now();
    grass_sample::Scene s;
    std::string error;
    if (!grass_sample::load_scene(o.scene_path, &s, &error)) throw grass_sample::Failure(error);
    s.width = o.width;
    s.height = o.height;
    s.samples = o.samples;
    const LodSetup lod = lod_setup(s);
    std::vector<Zone> zones = find_zones(lod);
    mark_zone_pixels(o, s, &zones);
    narrow_windows(o, s, &zones);
    std::string device;
    for (Zone& z : zones) measure_zone(o, s, lod, &z, &device);
    std::vector<Agreement> agreement;
    if (o.agreement && !tier_agreement(o, s, lod.tiers, &agreement, &error)) throw grass_sample::Failure(error);
    print_report(o, s, lod, zones, agreement, device,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count());
    return 0;
}

} // namespace

Subcommand add_popping(CLI::App& measure) {
    auto o = std::make_shared<Options>();
    CLI::App* app = measure.add_subcommand(
        "popping", "Popping in the transition zones: a camera dollies through the scene; per zone, the frame-to-frame "
                   "luma change of the lod setup against blades everywhere; then the per-tier mean colours "
                   "(docs/records/popping.md).");
    grass_sample::add_backend_option(*app, &o->backend);
    app->add_option("--scene", o->scene_path, "scene file")->capture_default_str();
    app->add_option("--frames", o->frames, "frames of the dolly")->capture_default_str()->check(CLI::Range(2, 10000));
    grass_sample::add_size_option(*app, &o->width, &o->height, 16, 4096, "the full frame's size in pixels");
    app->add_option("--samples", o->samples, "1 or 4")->capture_default_str()->check(CLI::IsMember({1, 4}));
    app->add_option("--canopy", o->canopy, "metres up where a view ray meets the lawn, 0 <= M < 1")
        ->capture_default_str()
        ->check(CLI::Validator(
            [](std::string& text) {
                double m = -1.0;
                return CLI::detail::lexical_cast(text, m) && m >= 0.0 && m < 1.0 ? std::string()
                                                                                 : "\"" + text + "\" is not 0 <= M < 1";
            },
            "[0, 1)"));
    app->add_option("--cell-budget", o->cell_budget, "reference geometry cells per zone window")
        ->capture_default_str()
        ->check(grass_sample::at_least(10));
    app->add_option("--max-reference-cells", o->max_reference_cells,
                    "a zone whose narrowest window's reference needs more cells is not measured")
        ->capture_default_str();
    app->add_option("--cache", o->cache_dir, "baked-slice cache directory");
    app->add_flag_callback(
        "--no-agreement", [o]() { o->agreement = false; }, "leave out the per-tier mean-colour agreement");
    app->add_option("--wind", o->wind, "m/s of wind (default direction, gusts and turbulence); 0: still grass")
        ->capture_default_str()
        ->check(grass_sample::closed_range(0.0, 1000.0));
    grass_sample::add_blade_culling_option(*app, &o->blade_culling, "of the lod setup's geometry tier");
    grass_sample::add_tessellation_option(*app, &o->tessellation, "of the lod setup's geometry tier");
    app->add_option("--wind-time", o->wind_time, "seconds: grass_view_desc.time of every frame")
        ->capture_default_str()
        ->check(grass_sample::closed_range(0.0, 1e6));
    return {app, [o]() { return run(*o); }};
}

} // namespace grass_measure
