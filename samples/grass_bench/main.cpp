// grass-bench: the speed/accuracy trade of the quality presets (docs/quality.md).
//
// For each scene (the football field, the park, the hills; reduced for the bench, see
// kScenes) x camera (high, player height, ant, grazing) x backend, it renders every preset of
// grass_quality_preset(): the REFERENCE first (blades everywhere), then the others, each on a
// target with the preset's MSAA sample count. Per frame it measures the wall time of a
// rendered and read-back frame (median of --frames frames after one warm-up), the plan time
// (grass_frame_stats.plan_ms, median), the GPU time per tier where the driver has timer
// queries (grass_get_tier_gpu_ms), and the image error against the reference of the same
// scene, camera and backend: SSIM on luma (Wang et al. 2004) and PSNR on the sRGB channels.
// It writes each frame and an amplified difference image into --out, and a CSV, a Markdown
// table (also printed) and an SVG plot of cost ratio against 1 - SSIM into --docs (or --out).
//
// --sweep renders, instead of the presets, DEFAULT with one knob of grass_quality_desc changed at a
// time (a few values each around DEFAULT's, the others at DEFAULT's; see sweep_variants), after
// the REFERENCE and DEFAULT presets themselves, for football / player unless --scene/--camera
// say otherwise. Each row is measured as the presets' are (against the reference's image of the
// same frame) and set against DEFAULT's row: cost / DEFAULT and the change of 1 - SSIM. It
// writes sweep.csv and a Markdown table sweep.md (also printed) into --docs (or --out), leaving
// bench.* alone.
#include "image_metrics.hpp"
#include "scene.hpp"

#include <grass/grass.h>

#include "headless_host.hpp"
#include "image_io.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace {

// ---- The bench's scenes ---------------------------------------------------------------

struct Camera {
    const char* name;
    double eye[3];
    double target[3];
};

// A scene file, reduced so that its reference (blades everywhere) renders in seconds on
// llvmpipe: a part of the field (the maps are mapped so that the part keeps its place in
// them), fewer and wider blades per patch. Heights of cameras over a height map are above
// the terrain under the eye (the target moves up by the same amount, so the view direction
// is the flat one).
struct BenchScene {
    const char* name;
    const char* file;
    uint32_t first_x, first_z; // the part of the scene's field, in its cells
    uint32_t cells_x, cells_z;
    uint32_t blade_count;
    float width_min, width_max; // patch units
    Camera cameras[4];
};

// Football: scripts/football-cameras.sh's cameras. The field's centre strip, 20 m wide and
// 60 m deep from the near goal line (80 x 240 of its 380 x 532 cells), so every preset's
// tiers up to the image tier (200 cells = 50 m out for DEFAULT) are in view.
// Park: the whole 40 m x 40 m park (its maps are the scene), fewer blades.
// Hills: 80 m x 100 m of the 200 m x 200 m hills (160 x 200 cells of 0.5 m) around the
// valley camera of docs/design-maps.md, with the host's ground drawn (see main).
const BenchScene kScenes[] = {
    {"football", "football.json", 150, 0, 80, 240, 32, 0.05f, 0.08f,
     {{"high", {47.5, 60, -40}, {47.5, 0, 80}},
      {"player", {47.5, 1.7, 6}, {47.5, 0, 60}},
      {"ant", {47.3, 0.05, 6}, {47.3, 0.04, 20}},
      {"grazing", {47.3, 3, -2}, {47.3, 2.9, 400}}}},
    {"park", "park.json", 0, 0, 160, 160, 24, 0.05f, 0.08f,
     {{"high", {20, 30, -15}, {20, 0, 22}},
      {"player", {20, 1.7, 2}, {20, 0, 30}},
      {"ant", {30, 0.05, 5}, {30, 0.04, 19}},
      {"grazing", {20, 3, -2}, {20, 2.9, 400}}}},
    {"hills", "hills.json", 120, 0, 160, 200, 24, 0.0f, 0.0f,
     {{"high", {100, 40, -30}, {100, 0, 60}},
      {"player", {100, 1.7, 5}, {100, 4, 60}},
      {"ant", {100, 0.05, 5}, {100, 0.04, 19}},
      {"grazing", {100, 3, -2}, {100, 2.9, 400}}}},
};
constexpr int kSceneCount = int(sizeof(kScenes) / sizeof(kScenes[0]));

const char* const kLevelNames[GRASS_QUALITY_LEVEL_COUNT] = {"reference", "high", "default", "low", "fastest"};
const char* const kLevelColors[GRASS_QUALITY_LEVEL_COUNT] = {"#000000", "#1f77b4", "#2ca02c", "#ff7f0e", "#d62728"};

// ---- Options -------------------------------------------------------------------------

struct Options {
    std::vector<grass_backend> backends = {GRASS_BACKEND_GL, GRASS_BACKEND_VULKAN};
    std::vector<int> scenes;   // indices into kScenes; empty = all
    std::vector<int> cameras;  // 0..3; empty = all
    std::string scene_dir = std::string(GRASS_SOURCE_DIR) + "/samples/grass_render/scenes";
    std::string out = "grass-bench-out";
    std::string docs;          // CSV, Markdown and SVG here; empty: into --out
    std::string cache;         // slice cache; empty: <out>/cache
    uint32_t width = 320, height = 180;
    int frames = 3;
    bool sweep = false;        // --sweep: one knob at a time from DEFAULT instead of the presets
};

void usage(FILE* f) {
    std::fprintf(f,
                 "usage: grass-bench [options]\n"
                 "  --backend gl|vk|both   backends (default both)\n"
                 "  --scene NAME           football, park or hills (repeatable; default all)\n"
                 "  --camera NAME          high, player, ant or grazing (repeatable; default all)\n"
                 "  --quick                one scene and one camera (football, player): a smoke run\n"
                 "  --sweep                instead of the presets: DEFAULT with one knob at a time changed (a few\n"
                 "                         values each around DEFAULT's), the REFERENCE and DEFAULT presets as\n"
                 "                         yardsticks; writes sweep.csv and sweep.md (not bench.*). Without\n"
                 "                         --scene/--camera: football, player\n"
                 "  --frames N             timed frames per preset after one warm-up (default 3; median)\n"
                 "  --size WxH             image size (default 320x180)\n"
                 "  --out DIR              every frame and difference image (default grass-bench-out)\n"
                 "  --docs DIR             bench.csv, bench.md and cost-vs-error.svg (default: --out)\n"
                 "  --scenes DIR           the scene files (default the source tree's samples/grass_render/scenes)\n"
                 "  --cache DIR            baked-slice cache (default OUT/cache)\n");
}

int fail(const std::string& m) {
    std::fprintf(stderr, "grass-bench: %s\n", m.c_str());
    return 1;
}

void log_to_stderr(void*, grass_log_level level, grass_message_id id, const char* message) {
    if (level == GRASS_LOG_INFO) return;
    static const char* const names[] = {"error", "warning", "info"};
    std::fprintf(stderr, "grass %s %d: %s\n", names[level], static_cast<int>(id), message);
}

bool make_dirs(const std::string& path) {
    std::string partial;
    std::stringstream ss(path);
    std::string part;
    if (!path.empty() && path[0] == '/') partial = "/";
    while (std::getline(ss, part, '/')) {
        if (part.empty()) continue;
        partial += part + "/";
        if (mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST) return false;
    }
    return true;
}

double median(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---- One row of the results ------------------------------------------------------------

struct Row {
    std::string scene, camera, backend, preset;
    std::string knob, value; // --sweep: the knob changed from DEFAULT and its value ("preset", level name)
    int level = 0;
    uint32_t msaa = 1, blades = 0, subdivisions = 0;
    double field_ms = 0, frame_ms = 0, frame_min_ms = 0, ratio = 1, plan_ms = 0;
    bool gpu_available = false;
    double gpu_ms[GRASS_TIER_KIND_COUNT] = {0, 0, 0};
    double ssim = 1, psnr = std::numeric_limits<double>::infinity();
    uint64_t triangles = 0, instances[GRASS_TIER_KIND_COUNT] = {0, 0, 0};
    double gpu_total() const { return gpu_ms[0] + gpu_ms[1] + gpu_ms[2]; }
};

std::string fmt(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof(b), f, v);
    return b;
}
std::string psnr_text(double p) { return std::isinf(p) ? "inf" : fmt("%.2f", p); }
std::string gpu_text(const Row& r, int tier) {
    if (!r.gpu_available) return "n/a";
    return fmt("%.2f", tier < 0 ? r.gpu_total() : r.gpu_ms[tier]);
}

// ---- Terrain heights for cameras over a height map ---------------------------------------

// The height map's value under world (x, z), bilinear between texel centres like the GPU.
double terrain_height(const grass_render::Scene& s, uint32_t full_cells_x, uint32_t full_cells_z, double x, double z) {
    const auto& m = s.maps[4];
    if (m.pixels.empty()) return 0.0;
    const double cs = s.field.cell_size;
    // The scene's full field starts at its own origin (base_transform before the bench moves it).
    const double u = (x - s.field.base_transform[12]) / (cs * full_cells_x), v = (z - s.field.base_transform[14]) / (cs * full_cells_z);
    auto texel = [&](int64_t tx, int64_t tz) {
        tx = std::clamp<int64_t>(tx, 0, m.width - 1);
        tz = std::clamp<int64_t>(tz, 0, m.height - 1);
        const size_t i = size_t(tz) * m.width + size_t(tx);
        if (m.format == GRASS_MAP_FORMAT_R16_UNORM) {
            uint16_t t;
            std::memcpy(&t, &m.pixels[2 * i], 2);
            return t / 65535.0;
        }
        return m.pixels[i] / 255.0;
    };
    const double fx = u * m.width - 0.5, fz = v * m.height - 0.5;
    const int64_t x0 = int64_t(std::floor(fx)), z0 = int64_t(std::floor(fz));
    const double ax = fx - double(x0), az = fz - double(z0);
    const double h = (1 - az) * ((1 - ax) * texel(x0, z0) + ax * texel(x0 + 1, z0)) +
                     az * ((1 - ax) * texel(x0, z0 + 1) + ax * texel(x0 + 1, z0 + 1));
    return s.field.base_transform[13] + h * s.height_scale;
}

// ---- The lod setup of a preset for a scene --------------------------------------------

// grass_apply_quality's tiers, plus, on a height map, what hills.json adds to Lemme's table:
// an UNPLANARITY test on every tier but the blades, and a hilltop overlay volume tier
// (2 slices times the preset's slice scale, macro-cells up to 8) where the image tier starts.
bool lod_setup(grass_context* ctx, const grass_quality_desc& q, const grass_render::Scene& s, grass_patch_desc* patch,
               std::vector<grass_tier_desc>* tiers, std::vector<grass_lod_test>* tests, std::string* error) {
    tiers->assign(GRASS_MAX_TIERS, grass_tier_desc{});
    tests->assign(GRASS_MAX_LOD_TESTS, grass_lod_test{});
    uint32_t tc = 0, lc = 0;
    if (grass_apply_quality(ctx, &q, s.field.cell_size, patch, tiers->data(), &tc, tests->data(), &lc) != GRASS_SUCCESS) {
        *error = std::string("grass_apply_quality: ") + grass_get_last_error(ctx);
        return false;
    }
    tiers->resize(tc);
    tests->resize(lc);
    if (s.maps[4].pixels.empty() || q.blades_everywhere) return true;
    float image_begin = std::numeric_limits<float>::infinity();
    for (uint32_t t = 0; t < tc; ++t) {
        if ((*tiers)[t].kind == GRASS_TIER_GEOMETRY) continue;
        grass_lod_test u{};
        u.kind = GRASS_LOD_TEST_UNPLANARITY;
        u.tier = t;
        u.max_unplanarity = 0.25f;
        u.unplanarity_ratio = 0.02f;
        tests->push_back(u);
        if ((*tiers)[t].kind == GRASS_TIER_IMAGE) {
            for (const auto& b : *tests)
                if (b.kind == GRASS_LOD_TEST_DISTANCE_BAND && b.tier == t) image_begin = std::min(image_begin, b.begin);
        }
    }
    if (std::isfinite(image_begin) && tiers->size() < GRASS_MAX_TIERS) {
        const uint32_t t = uint32_t(tiers->size());
        grass_tier_desc overlay{};
        overlay.kind = GRASS_TIER_VOLUME;
        overlay.slices = std::max<uint32_t>(1, uint32_t(std::lround(2.0 * q.slice_scale)));
        tiers->push_back(overlay);
        grass_lod_test band{};
        band.kind = GRASS_LOD_TEST_DISTANCE_BAND;
        band.tier = t;
        band.begin = image_begin;
        band.end = std::numeric_limits<float>::infinity();
        grass_lod_test hill{};
        hill.kind = GRASS_LOD_TEST_HILLTOP;
        hill.tier = t;
        grass_lod_test macro{};
        macro.kind = GRASS_LOD_TEST_MACRO_CELL;
        macro.tier = t;
        macro.max_macro_cells = 8;
        tests->insert(tests->end(), {band, hill, macro});
    }
    return true;
}

// ---- Output -----------------------------------------------------------------------------

std::string csv(const std::vector<Row>& rows, const Options& o) {
    std::ostringstream s;
    s << "scene,camera,backend,preset,width,height,msaa,blades_per_patch,subdivisions,frame_ms,frame_min_ms,cost_ratio,"
         "plan_ms,gpu_ms,gpu_geometry_ms,gpu_volume_ms,gpu_image_ms,ssim,psnr_db,triangles,geometry_instances,"
         "volume_instances,image_instances,field_create_ms\n";
    for (const Row& r : rows) {
        s << r.scene << ',' << r.camera << ',' << r.backend << ',' << r.preset << ',' << o.width << ',' << o.height << ','
          << r.msaa << ',' << r.blades << ',' << r.subdivisions << ',' << fmt("%.2f", r.frame_ms) << ','
          << fmt("%.2f", r.frame_min_ms) << ',' << fmt("%.4f", r.ratio) << ',' << fmt("%.3f", r.plan_ms) << ','
          << gpu_text(r, -1) << ',' << gpu_text(r, 0) << ',' << gpu_text(r, 1) << ',' << gpu_text(r, 2) << ','
          << fmt("%.5f", r.ssim) << ',' << psnr_text(r.psnr) << ',' << r.triangles << ',' << r.instances[0] << ','
          << r.instances[1] << ',' << r.instances[2] << ',' << fmt("%.1f", r.field_ms) << '\n';
    }
    return s.str();
}

std::string markdown(const std::vector<Row>& rows, const Options& o, double total_s) {
    std::ostringstream s;
    s << "# grass-bench results\n\n"
      << "Written by `grass-bench` (samples/grass_bench; docs/quality.md explains it). " << o.width << " x " << o.height
      << " pixels, each preset on a target with its own MSAA sample count; frame = wall time of a rendered and read-back "
         "frame, median of "
      << o.frames << " after one warm-up; cost = frame / the reference's frame (same scene, camera, backend); "
         "SSIM (luma, Gaussian window 11, sigma 1.5) and PSNR (sRGB RGB) against the reference's image of the same "
         "backend; GPU = grass_get_tier_gpu_ms summed over the tiers (n/a: no timer result). The run took "
      << fmt("%.0f", total_s) << " s.\n\n";
    // Summary: per backend and preset, the median over scenes and cameras.
    s << "## Summary: median over scenes and cameras\n\n"
      << "| backend | preset | cost / reference | 1 - SSIM | PSNR (dB) | frame (ms) | plan (ms) |\n"
      << "|---|---|---|---|---|---|---|\n";
    for (const char* be : {"gl", "vk"}) {
        for (int l = 0; l < GRASS_QUALITY_LEVEL_COUNT; ++l) {
            std::vector<double> ratio, err, psnr, frame, plan;
            for (const Row& r : rows) {
                if (r.backend != be || r.level != l) continue;
                ratio.push_back(r.ratio);
                err.push_back(1.0 - r.ssim);
                psnr.push_back(r.psnr);
                frame.push_back(r.frame_ms);
                plan.push_back(r.plan_ms);
            }
            if (ratio.empty()) continue;
            s << "| " << be << " | " << kLevelNames[l] << " | " << fmt("%.3f", median(ratio)) << " | "
              << fmt("%.4f", median(err)) << " | " << psnr_text(median(psnr)) << " | " << fmt("%.1f", median(frame))
              << " | " << fmt("%.2f", median(plan)) << " |\n";
        }
    }
    s << "\n## Every frame\n\n"
      << "| scene | camera | backend | preset | MSAA | blades x subdiv | frame (ms) | cost / ref | plan (ms) | GPU (ms) | "
         "SSIM | PSNR (dB) | triangles | instances g / v / i |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        s << "| " << r.scene << " | " << r.camera << " | " << r.backend << " | " << r.preset << " | " << r.msaa << " | "
          << r.blades << " x " << r.subdivisions << " | " << fmt("%.1f", r.frame_ms) << " | " << fmt("%.3f", r.ratio)
          << " | " << fmt("%.2f", r.plan_ms) << " | " << gpu_text(r, -1) << " | " << fmt("%.4f", r.ssim) << " | "
          << psnr_text(r.psnr) << " | " << r.triangles << " | " << r.instances[0] << " / " << r.instances[1] << " / "
          << r.instances[2] << " |\n";
    }
    return s.str();
}

// x: cost relative to the reference, log10; y: 1 - SSIM. A marker per frame: colour per
// preset, circle GL, square Vulkan; hovering shows the frame.
std::string svg(const std::vector<Row>& rows) {
    const double W = 760, H = 480, L = 70, R = 150, T = 40, B = 60;
    double xmin = 0.0, xmax = 0.0, ymax = 0.0;
    for (const Row& r : rows) {
        if (!(r.ratio > 0) || !std::isfinite(r.ratio)) continue;
        xmin = std::min(xmin, std::floor(std::log10(r.ratio)));
        xmax = std::max(xmax, std::ceil(std::log10(r.ratio)));
        ymax = std::max(ymax, 1.0 - r.ssim);
    }
    if (xmax <= xmin) xmax = xmin + 1;
    // A tidy top for the y axis: 1, 2 or 5 times a power of ten.
    double ytop = 0.01;
    if (ymax > 0) {
        const double p = std::pow(10.0, std::floor(std::log10(ymax)));
        ytop = ymax <= p ? p : ymax <= 2 * p ? 2 * p : ymax <= 5 * p ? 5 * p : 10 * p;
    }
    auto px = [&](double ratio) { return L + (std::log10(ratio) - xmin) / (xmax - xmin) * (W - L - R); };
    auto py = [&](double e) { return H - B - e / ytop * (H - T - B); };
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
      << ' ' << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << L << "\" y=\"22\" font-size=\"15\">grass-bench: frame cost against image error, every scene and camera</text>\n";
    // Axes, grid and ticks.
    s << "<g stroke=\"#ddd\">\n";
    for (double d = xmin; d <= xmax + 1e-9; d += 1.0) {
        for (int m = 2; m < 10 && d < xmax; ++m) {
            const double x = px(std::pow(10.0, d) * m);
            s << "<line x1=\"" << fmt("%.1f", x) << "\" y1=\"" << T << "\" x2=\"" << fmt("%.1f", x) << "\" y2=\"" << H - B
              << "\" stroke=\"#f2f2f2\"/>\n";
        }
        s << "<line x1=\"" << fmt("%.1f", px(std::pow(10.0, d))) << "\" y1=\"" << T << "\" x2=\""
          << fmt("%.1f", px(std::pow(10.0, d))) << "\" y2=\"" << H - B << "\"/>\n";
    }
    for (int k = 0; k <= 5; ++k) {
        s << "<line x1=\"" << L << "\" y1=\"" << fmt("%.1f", py(ytop * k / 5)) << "\" x2=\"" << W - R << "\" y2=\""
          << fmt("%.1f", py(ytop * k / 5)) << "\"/>\n";
    }
    s << "</g>\n<g stroke=\"black\"><line x1=\"" << L << "\" y1=\"" << H - B << "\" x2=\"" << W - R << "\" y2=\"" << H - B
      << "\"/><line x1=\"" << L << "\" y1=\"" << T << "\" x2=\"" << L << "\" y2=\"" << H - B << "\"/></g>\n";
    for (double d = xmin; d <= xmax + 1e-9; d += 1.0) {
        s << "<text x=\"" << fmt("%.1f", px(std::pow(10.0, d))) << "\" y=\"" << H - B + 16 << "\" text-anchor=\"middle\">"
          << fmt("%g", std::pow(10.0, d)) << "</text>\n";
    }
    for (int k = 0; k <= 5; ++k) {
        s << "<text x=\"" << L - 6 << "\" y=\"" << fmt("%.1f", py(ytop * k / 5) + 4) << "\" text-anchor=\"end\">"
          << fmt("%g", ytop * k / 5) << "</text>\n";
    }
    s << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 18
      << "\" text-anchor=\"middle\">frame cost / reference's frame cost (log scale)</text>\n"
      << "<text transform=\"translate(18," << (T + H - B) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">1 - SSIM against the reference</text>\n";
    // Markers.
    for (const Row& r : rows) {
        if (!(r.ratio > 0) || !std::isfinite(r.ratio)) continue;
        const double x = px(r.ratio), y = py(1.0 - r.ssim);
        const std::string title = "<title>" + r.scene + ", " + r.camera + ", " + r.backend + ", " + r.preset + ": cost " +
                                  fmt("%.3f", r.ratio) + ", SSIM " + fmt("%.4f", r.ssim) + "</title>";
        const char* c = kLevelColors[r.level];
        if (r.backend == "gl") {
            s << "<circle cx=\"" << fmt("%.1f", x) << "\" cy=\"" << fmt("%.1f", y) << "\" r=\"4\" fill=\"" << c
              << "\" fill-opacity=\"0.75\">" << title << "</circle>\n";
        } else {
            s << "<rect x=\"" << fmt("%.1f", x - 3.5) << "\" y=\"" << fmt("%.1f", y - 3.5)
              << "\" width=\"7\" height=\"7\" fill=\"none\" stroke=\"" << c << "\" stroke-width=\"1.5\">" << title
              << "</rect>\n";
        }
    }
    // Legend.
    double ly = T + 10;
    for (int l = 0; l < GRASS_QUALITY_LEVEL_COUNT; ++l, ly += 20) {
        s << "<circle cx=\"" << W - R + 20 << "\" cy=\"" << ly << "\" r=\"5\" fill=\"" << kLevelColors[l] << "\"/><text x=\""
          << W - R + 32 << "\" y=\"" << ly + 4 << "\">" << kLevelNames[l] << "</text>\n";
    }
    ly += 10;
    s << "<circle cx=\"" << W - R + 20 << "\" cy=\"" << ly << "\" r=\"4\" fill=\"#777\"/><text x=\"" << W - R + 32
      << "\" y=\"" << ly + 4 << "\">GL (llvmpipe)</text>\n";
    ly += 20;
    s << "<rect x=\"" << W - R + 16.5 << "\" y=\"" << ly - 3.5
      << "\" width=\"7\" height=\"7\" fill=\"none\" stroke=\"#777\" stroke-width=\"1.5\"/><text x=\"" << W - R + 32
      << "\" y=\"" << ly + 4 << "\">Vulkan (lavapipe)</text>\n";
    s << "</svg>\n";
    return s.str();
}

bool write_text(const std::string& path, const std::string& text) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    return std::fclose(f) == 0 && ok;
}

// ---- One scene x preset x backend: a host, a context, a field, every camera ---------------

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A scene of kScenes reduced for the bench, and its cameras' eyes and targets (over its
// terrain on a height map).
struct PreparedScene {
    const BenchScene* bench = nullptr;
    grass_render::Scene scene;
    double cams[4][2][3] = {};
};

bool prepare_scene(const Options& opt, const BenchScene& bs, PreparedScene* ps, std::string* error) {
    ps->bench = &bs;
    grass_render::Scene& scene = ps->scene;
    if (!grass_render::load_scene(opt.scene_dir + "/" + bs.file, &scene, error)) return false;
    // The bench's variant: a part of the field, its maps mapped onto that part.
    const uint32_t full_x = scene.field.cells_x, full_z = scene.field.cells_z;
    if (bs.first_x + bs.cells_x > full_x || bs.first_z + bs.cells_z > full_z) {
        *error = std::string(bs.name) + ": the bench's part lies outside the field";
        return false;
    }
    const double cs = scene.field.cell_size;
    for (int c = 0; c < 4; ++c) {
        const Camera& cam = bs.cameras[c];
        const double lift = terrain_height(scene, full_x, full_z, cam.eye[0], cam.eye[2]);
        for (int k = 0; k < 3; ++k) {
            ps->cams[c][0][k] = cam.eye[k] + (k == 1 ? lift : 0.0);
            ps->cams[c][1][k] = cam.target[k] + (k == 1 ? lift : 0.0);
        }
    }
    scene.field.cells_x = bs.cells_x;
    scene.field.cells_z = bs.cells_z;
    scene.field.base_transform[12] += bs.first_x * cs;
    scene.field.base_transform[14] += bs.first_z * cs;
    double* m = scene.field.maps.cell_to_map;
    m[0] = 1.0 / full_x, m[1] = 0.0, m[2] = 0.0, m[3] = 1.0 / full_z;
    m[4] = double(bs.first_x) / full_x, m[5] = double(bs.first_z) / full_z;
    scene.patch.blade_count = bs.blade_count;
    if (bs.width_max > 0.0f) scene.patch.width_min = bs.width_min, scene.patch.width_max = bs.width_max;
    // The hills scene draws no ground (the host's ground is flat); with the bench's
    // sparse blades the sky showed through the grass, so the flat ground at y = 0, under
    // the hills, shows as soil behind it instead.
    scene.ground = true;
    if (!scene.density_texels.empty()) {
        *error = std::string(bs.name) + ": the bench reads density through the map stack only";
        return false;
    }
    return true;
}

// One setup to render: a preset, or (--sweep) DEFAULT with one knob changed.
struct Variant {
    grass_quality_desc q;
    int level = GRASS_QUALITY_DEFAULT; // the preset's level; a sweep's variants: DEFAULT's
    std::string name;                  // Row::preset and the progress line
    std::string file;                  // images: <scene>-<camera>-<backend>-<file>.png
    std::string knob, value;           // the sweep's columns ("preset" and the level's name for a preset)
};

Variant preset_variant(int level) {
    Variant v;
    v.q = grass_quality_preset(grass_quality_level(level));
    v.level = level;
    v.name = v.file = v.value = kLevelNames[level];
    v.knob = "preset";
    return v;
}

// The reference's image and frame time per camera, of one scene and backend: what the
// other frames of that scene and backend are measured against.
struct Reference {
    grass_host::Image image[4];
    double ms[4] = {0, 0, 0, 0};
};

// Renders one variant of one scene on one backend: a host with the variant's sample count,
// a context, a field made with grass_apply_quality, then every selected camera (one
// warm-up and opt.frames timed frames each). The reference preset's frames go into *ref;
// every other frame is measured against them. Appends a row per camera; a failed frame is
// reported and sets *status to 1; false (with *error) when the run cannot go on.
bool render_variant(const Options& opt, grass_backend backend, const PreparedScene& ps, const Variant& v, Reference* ref,
                    std::chrono::steady_clock::time_point t_start, std::vector<Row>* rows, int* status,
                    std::string* error) {
    const char* be = backend == GRASS_BACKEND_GL ? "gl" : "vk";
    const BenchScene& bs = *ps.bench;
    const grass_render::Scene& scene = ps.scene;
    const grass_quality_desc& q = v.q;
    grass_host::TargetDesc td;
    td.width = opt.width;
    td.height = opt.height;
    td.samples = q.msaa_samples;
    td.ground = scene.ground;
    std::memcpy(td.ground_color, scene.ground_color, sizeof(td.ground_color));
    auto host = grass_host::Host::create(backend, td, error);
    if (!host) {
        *error = std::string("cannot create the ") + be + " host: " + *error;
        return false;
    }
    grass_context_desc cd = grass_default_context_desc();
    cd.log_fn = log_to_stderr;
    cd.cache_directory = opt.cache.c_str();
    grass_context* ctx = nullptr;
    if (host->create_context(cd, &ctx) != GRASS_SUCCESS) {
        *error = "cannot create a grass context";
        return false;
    }
    grass_patch_desc pd = scene.patch;
    std::vector<grass_tier_desc> tiers;
    std::vector<grass_lod_test> tests;
    if (!lod_setup(ctx, q, scene, &pd, &tiers, &tests, error)) {
        grass_destroy_context(ctx);
        return false;
    }
    const auto t_field = std::chrono::steady_clock::now();
    grass_patch_id patch{};
    grass_field_desc fd = scene.field;
    grass_result r = grass_create_patch(ctx, &pd, &patch);
    grass_map_id* slots[5] = {&fd.maps.density, &fd.maps.color, &fd.maps.ambient, &fd.maps.diffuse, &fd.maps.height};
    for (int role = 0; role < 5 && r == GRASS_SUCCESS; ++role) {
        const auto& mi = scene.maps[role];
        if (mi.pixels.empty()) continue;
        grass_map_desc md = grass_default_map_desc();
        md.pixels = mi.pixels.data();
        md.width = mi.width;
        md.height = mi.height;
        md.format = mi.format;
        r = grass_create_map(ctx, &md, slots[role]);
    }
    fd.maps.height_scale = scene.height_scale;
    fd.patch = patch;
    fd.tiers = tiers.data();
    fd.tier_count = uint32_t(tiers.size());
    fd.lod_tests = tests.data();
    fd.lod_test_count = uint32_t(tests.size());
    grass_field_id field{};
    if (r == GRASS_SUCCESS) r = grass_create_field(ctx, &fd, &field);
    const double field_ms = seconds_since(t_field) * 1e3;
    if (r != GRASS_SUCCESS) {
        const std::string e = grass_get_last_error(ctx);
        grass_destroy_context(ctx);
        *error = std::string(bs.name) + ", " + v.name + ": the field was refused: " + e;
        return false;
    }
    for (const int ci : opt.cameras) {
        grass_view_desc view = grass_host::make_view(*host, ps.cams[ci][0], ps.cams[ci][1], scene.fov_degrees, 0.05f,
                                                     scene.far_m);
        std::memcpy(view.sun_direction, scene.sun_direction, sizeof(scene.sun_direction));
        std::memcpy(view.sun_color, scene.sun_color, sizeof(scene.sun_color));
        std::memcpy(view.ambient_color, scene.ambient_color, sizeof(scene.ambient_color));
        Row row;
        row.scene = bs.name;
        row.camera = bs.cameras[ci].name;
        row.backend = be;
        row.preset = v.name;
        row.knob = v.knob;
        row.value = v.value;
        row.level = v.level;
        row.msaa = q.msaa_samples;
        row.blades = pd.blade_count;
        row.subdivisions = pd.subdivisions;
        row.field_ms = field_ms;
        grass_host::Image image;
        std::vector<double> wall, plan, gpu[GRASS_TIER_KIND_COUNT];
        grass_frame_stats stats{};
        for (int f = 0; f <= opt.frames && r == GRASS_SUCCESS; ++f) {
            grass_host::Image* dst = f == 0 ? &image : nullptr;
            grass_host::Image scratch;
            const auto f0 = std::chrono::steady_clock::now();
            r = host->render(ctx, view, nullptr, dst ? dst : &scratch, error);
            const double ms = seconds_since(f0) * 1e3;
            grass_get_frame_stats(ctx, &stats);
            if (f == 0) continue; // the warm-up: uploads, first use of the pipelines
            wall.push_back(ms);
            plan.push_back(stats.plan_ms);
            double g[GRASS_TIER_KIND_COUNT] = {0, 0, 0};
            grass_bool available = 0;
            if (grass_get_tier_gpu_ms(ctx, g, &available) == GRASS_SUCCESS && available) {
                for (int t = 0; t < GRASS_TIER_KIND_COUNT; ++t) gpu[t].push_back(g[t]);
            }
        }
        if (r != GRASS_SUCCESS) {
            std::fprintf(stderr, "grass-bench: %s %s %s %s: rendering failed: %s (%s) %s\n", bs.name, row.camera.c_str(), be,
                         row.preset.c_str(), grass_result_string(r), grass_get_last_error(ctx), error->c_str());
            *status = 1;
            r = GRASS_SUCCESS;
            continue;
        }
        row.frame_ms = median(wall);
        row.frame_min_ms = *std::min_element(wall.begin(), wall.end());
        row.plan_ms = median(plan);
        row.gpu_available = !gpu[0].empty();
        for (int t = 0; t < GRASS_TIER_KIND_COUNT && row.gpu_available; ++t) row.gpu_ms[t] = median(gpu[t]);
        row.triangles = stats.triangles;
        for (int t = 0; t < GRASS_TIER_KIND_COUNT; ++t) row.instances[t] = stats.instances[t];
        const std::string stem = opt.out + "/images/" + bs.name + "-" + row.camera + "-" + be + "-" + v.file;
        if (!grass_host::write_png(stem + ".png", image, error)) {
            grass_destroy_context(ctx);
            return false;
        }
        if (v.level == GRASS_QUALITY_REFERENCE) {
            ref->image[ci] = image;
            ref->ms[ci] = row.frame_ms;
        } else if (!ref->image[ci].rgba.empty()) {
            const auto& reference = ref->image[ci];
            row.ratio = row.frame_ms / ref->ms[ci];
            row.ssim = grass_bench::ssim_rgba(reference.rgba.data(), image.rgba.data(), image.width, image.height);
            row.psnr = grass_bench::psnr_rgba(reference.rgba.data(), image.rgba.data(), image.width, image.height);
            grass_host::Image diff;
            diff.width = image.width;
            diff.height = image.height;
            diff.rgba = grass_bench::difference_rgba(reference.rgba.data(), image.rgba.data(), image.width, image.height, 4.0);
            if (!grass_host::write_png(stem + "-error.png", diff, error)) {
                grass_destroy_context(ctx);
                return false;
            }
        }
        std::fprintf(stderr,
                     "[%6.0f s] %-8s %-7s %s %-9s frame %8.1f ms (x%.3f) plan %6.2f ms  gpu %s  SSIM %.4f  PSNR %s  "
                     "%llu triangles\n",
                     seconds_since(t_start), bs.name, row.camera.c_str(), be, row.preset.c_str(), row.frame_ms, row.ratio,
                     row.plan_ms, gpu_text(row, -1).c_str(), row.ssim, psnr_text(row.psnr).c_str(),
                     static_cast<unsigned long long>(row.triangles));
        rows->push_back(row);
    }
    if (host->validation_messages() != 0) {
        std::fprintf(stderr, "grass-bench: %u validation messages:\n%s\n", host->validation_messages(),
                     host->validation_log().c_str());
        *status = 1;
    }
    grass_destroy_context(ctx);
    return true;
}

// ---- --sweep: one knob at a time from DEFAULT ---------------------------------------------

// The sweep's setups: the reference (what every frame is measured against), DEFAULT (the
// baseline), then for each knob of grass_quality_desc but blades_everywhere a few values
// around DEFAULT's within the knob's range (grass.h), the other knobs at DEFAULT's. A value
// equal to DEFAULT's is left out (the baseline row has it).
std::vector<Variant> sweep_variants() {
    const grass_quality_desc base = grass_quality_preset(GRASS_QUALITY_DEFAULT);
    std::vector<Variant> v = {preset_variant(GRASS_QUALITY_REFERENCE), preset_variant(GRASS_QUALITY_DEFAULT)};
    struct Knob {
        const char* name;
        std::vector<double> values;
        double current;
        void (*set)(grass_quality_desc*, double);
    };
    const Knob knobs[] = {
        {"distance_scale", {0.5, 2.0}, base.distance_scale, [](grass_quality_desc* q, double x) { q->distance_scale = float(x); }},
        {"transition_scale", {0.0, 0.5, 1.2}, base.transition_scale,
         [](grass_quality_desc* q, double x) { q->transition_scale = float(x); }},
        {"slice_scale", {0.5, 2.0}, base.slice_scale, [](grass_quality_desc* q, double x) { q->slice_scale = float(x); }},
        {"macro_cell_scale", {0.5, 2.0}, base.macro_cell_scale,
         [](grass_quality_desc* q, double x) { q->macro_cell_scale = float(x); }},
        {"blade_subdivisions", {2, 8}, double(base.blade_subdivisions),
         [](grass_quality_desc* q, double x) { q->blade_subdivisions = uint32_t(x); }},
        {"blade_fraction", {0.5, 0.75}, base.blade_fraction, [](grass_quality_desc* q, double x) { q->blade_fraction = float(x); }},
        // Not 2: the headless hosts are meant for 1 or 4 samples (headless_host.hpp), and on
        // llvmpipe a 2-sample target renders the very image of DEFAULT's 4.
        {"msaa_samples", {1}, double(base.msaa_samples), [](grass_quality_desc* q, double x) { q->msaa_samples = uint32_t(x); }},
    };
    for (const Knob& k : knobs) {
        for (const double x : k.values) {
            if (float(x) == float(k.current)) continue;
            Variant s;
            s.q = base;
            k.set(&s.q, x);
            s.level = GRASS_QUALITY_DEFAULT;
            s.knob = k.name;
            s.value = fmt("%g", x);
            s.name = s.knob + "=" + s.value;
            s.file = "sweep-" + s.knob + "-" + s.value;
            v.push_back(s);
        }
    }
    return v;
}

// The DEFAULT row of r's backend, scene and camera; null when that frame failed.
const Row* sweep_baseline(const std::vector<Row>& rows, const Row& r) {
    for (const Row& b : rows) {
        if (b.backend == r.backend && b.scene == r.scene && b.camera == r.camera && b.knob == "preset" &&
            b.level == GRASS_QUALITY_DEFAULT)
            return &b;
    }
    return nullptr;
}

std::string ratio_text(double num, const Row* base) {
    return base && base->frame_ms > 0 ? fmt("%.3f", num / base->frame_ms) : "n/a";
}
// The change of 1 - SSIM against DEFAULT's: positive = further from the reference.
std::string error_change_text(const Row& r, const Row* base) {
    return base ? fmt("%+.4f", base->ssim - r.ssim) : "n/a";
}

std::string sweep_csv(const std::vector<Row>& rows, const Options& o) {
    std::ostringstream s;
    s << "backend,scene,camera,knob,value,width,height,msaa,blades_per_patch,subdivisions,frame_ms,frame_min_ms,"
         "cost_vs_default,cost_vs_reference,plan_ms,gpu_ms,ssim,psnr_db,one_minus_ssim_change_vs_default,triangles,"
         "geometry_instances,volume_instances,image_instances,field_create_ms\n";
    for (const Row& r : rows) {
        const Row* b = sweep_baseline(rows, r);
        s << r.backend << ',' << r.scene << ',' << r.camera << ',' << r.knob << ',' << r.value << ',' << o.width << ','
          << o.height << ',' << r.msaa << ',' << r.blades << ',' << r.subdivisions << ',' << fmt("%.2f", r.frame_ms) << ','
          << fmt("%.2f", r.frame_min_ms) << ',' << ratio_text(r.frame_ms, b) << ',' << fmt("%.4f", r.ratio) << ','
          << fmt("%.3f", r.plan_ms) << ',' << gpu_text(r, -1) << ',' << fmt("%.5f", r.ssim) << ',' << psnr_text(r.psnr)
          << ',' << error_change_text(r, b) << ',' << r.triangles << ',' << r.instances[0] << ',' << r.instances[1] << ','
          << r.instances[2] << ',' << fmt("%.1f", r.field_ms) << '\n';
    }
    return s.str();
}

std::string sweep_markdown(const std::vector<Row>& rows, const Options& o, double total_s) {
    const grass_quality_desc d = grass_quality_preset(GRASS_QUALITY_DEFAULT);
    std::ostringstream s;
    s << "# grass-bench sweep: one knob at a time from DEFAULT\n\n"
      << "Written by `grass-bench --sweep` (samples/grass_bench; docs/quality.md explains the knobs and the "
         "measures). Each row is DEFAULT with one knob of `grass_quality_desc` changed (the others at DEFAULT's: "
         "distance_scale "
      << fmt("%g", d.distance_scale) << ", transition_scale " << fmt("%g", d.transition_scale) << ", slice_scale "
      << fmt("%g", d.slice_scale) << ", macro_cell_scale " << fmt("%g", d.macro_cell_scale) << ", blade_subdivisions "
      << d.blade_subdivisions << ", blade_fraction " << fmt("%g", d.blade_fraction) << ", msaa_samples " << d.msaa_samples
      << "); the rows `preset` are the REFERENCE and DEFAULT presets themselves. " << o.width << " x " << o.height
      << " pixels, each row on a target with its own MSAA sample count; frame = wall time of a rendered and read-back "
         "frame, median of "
      << o.frames << " after one warm-up; cost = frame / DEFAULT's or the reference's frame (same backend, scene, "
         "camera); SSIM (luma) and PSNR (sRGB RGB) against the reference's image of the same frame; change of 1 - SSIM "
         "= (1 - SSIM) - DEFAULT's (positive: further from the reference). The run took "
      << fmt("%.0f", total_s) << " s.\n\n";
    // With more than one frame per backend, knob and value: the median over scenes and cameras.
    std::vector<std::string> frames;
    for (const Row& r : rows) {
        const std::string f = r.scene + "/" + r.camera;
        if (std::find(frames.begin(), frames.end(), f) == frames.end()) frames.push_back(f);
    }
    if (frames.size() > 1) {
        s << "## Summary: median over scenes and cameras\n\n"
          << "| backend | knob | value | cost / default | cost / reference | SSIM | change of 1 - SSIM vs default |\n"
          << "|---|---|---|---|---|---|---|\n";
        std::vector<std::string> done;
        for (const Row& r : rows) {
            const std::string key = r.backend + "/" + r.knob + "/" + r.value;
            if (std::find(done.begin(), done.end(), key) != done.end()) continue;
            done.push_back(key);
            std::vector<double> to_default, to_reference, ssim, change;
            for (const Row& x : rows) {
                if (x.backend != r.backend || x.knob != r.knob || x.value != r.value) continue;
                const Row* b = sweep_baseline(rows, x);
                if (b && b->frame_ms > 0) to_default.push_back(x.frame_ms / b->frame_ms);
                if (b) change.push_back(b->ssim - x.ssim);
                to_reference.push_back(x.ratio);
                ssim.push_back(x.ssim);
            }
            s << "| " << r.backend << " | " << r.knob << " | " << r.value << " | "
              << (to_default.empty() ? "n/a" : fmt("%.3f", median(to_default))) << " | " << fmt("%.3f", median(to_reference))
              << " | " << fmt("%.4f", median(ssim)) << " | " << (change.empty() ? "n/a" : fmt("%+.4f", median(change)))
              << " |\n";
        }
        s << "\n## Every frame\n\n";
    }
    s << "| backend | scene | camera | knob | value | frame (ms) | cost / default | cost / reference | SSIM | PSNR (dB) | "
         "change of 1 - SSIM vs default | triangles |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        const Row* b = sweep_baseline(rows, r);
        s << "| " << r.backend << " | " << r.scene << " | " << r.camera << " | " << r.knob << " | " << r.value << " | "
          << fmt("%.1f", r.frame_ms) << " | " << ratio_text(r.frame_ms, b) << " | " << fmt("%.3f", r.ratio) << " | "
          << fmt("%.4f", r.ssim) << " | " << psnr_text(r.psnr) << " | " << error_change_text(r, b) << " | " << r.triangles
          << " |\n";
    }
    return s.str();
}

} // namespace

int main(int argc, char** argv) {
    Options opt;
    bool quick = false;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        auto value = [&]() -> std::string {
            if (k + 1 >= argc) {
                std::fprintf(stderr, "grass-bench: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++k];
        };
        if (a == "--help" || a == "-h") {
            usage(stdout);
            return 0;
        } else if (a == "--backend") {
            const std::string b = value();
            if (b == "gl") opt.backends = {GRASS_BACKEND_GL};
            else if (b == "vk" || b == "vulkan") opt.backends = {GRASS_BACKEND_VULKAN};
            else if (b == "both") opt.backends = {GRASS_BACKEND_GL, GRASS_BACKEND_VULKAN};
            else return fail("--backend must be gl, vk or both");
        } else if (a == "--scene") {
            const std::string n = value();
            int found = -1;
            for (int s = 0; s < kSceneCount; ++s)
                if (n == kScenes[s].name) found = s;
            if (found < 0) return fail("unknown scene \"" + n + "\" (football, park, hills)");
            opt.scenes.push_back(found);
        } else if (a == "--camera") {
            const std::string n = value();
            int found = -1;
            for (int c = 0; c < 4; ++c)
                if (n == kScenes[0].cameras[c].name) found = c;
            if (found < 0) return fail("unknown camera \"" + n + "\" (high, player, ant, grazing)");
            opt.cameras.push_back(found);
        } else if (a == "--quick") {
            quick = true;
        } else if (a == "--sweep") {
            opt.sweep = true;
        } else if (a == "--frames") {
            opt.frames = std::atoi(value().c_str());
            if (opt.frames < 1 || opt.frames > 100) return fail("--frames must be 1..100");
        } else if (a == "--size") {
            if (std::sscanf(value().c_str(), "%ux%u", &opt.width, &opt.height) != 2 || opt.width < 16 || opt.height < 16 ||
                opt.width > 4096 || opt.height > 4096)
                return fail("--size must be WxH, 16..4096 each");
        } else if (a == "--out") {
            opt.out = value();
        } else if (a == "--docs") {
            opt.docs = value();
        } else if (a == "--scenes") {
            opt.scene_dir = value();
        } else if (a == "--cache") {
            opt.cache = value();
        } else {
            usage(stderr);
            return fail("unknown option " + a);
        }
    }
    if (quick || opt.sweep) {
        if (opt.scenes.empty()) opt.scenes = {0};
        if (opt.cameras.empty()) opt.cameras = {1};
    }
    if (opt.scenes.empty())
        for (int s = 0; s < kSceneCount; ++s) opt.scenes.push_back(s);
    if (opt.cameras.empty()) opt.cameras = {0, 1, 2, 3};
    if (opt.cache.empty()) opt.cache = opt.out + "/cache";
    const std::string docs = opt.docs.empty() ? opt.out : opt.docs;
    if (!make_dirs(opt.out + "/images") || !make_dirs(opt.cache) || !make_dirs(docs)) {
        return fail("cannot create " + opt.out + ", " + opt.cache + " or " + docs);
    }

    std::vector<Variant> variants;
    if (opt.sweep) {
        variants = sweep_variants();
    } else {
        for (int level = 0; level < GRASS_QUALITY_LEVEL_COUNT; ++level) variants.push_back(preset_variant(level));
    }
    const auto t_start = std::chrono::steady_clock::now();
    std::vector<Row> rows;
    int status = 0;
    for (const grass_backend backend : opt.backends) {
        for (const int si : opt.scenes) {
            PreparedScene ps;
            std::string error;
            if (!prepare_scene(opt, kScenes[si], &ps, &error)) return fail(error);
            // The reference comes first (variants[0]): every other frame is measured against it.
            Reference reference;
            for (const Variant& v : variants) {
                if (!render_variant(opt, backend, ps, v, &reference, t_start, &rows, &status, &error)) return fail(error);
            }
        }
    }
    auto scene_rank = [&](const Row& r) {
        int s = 0, c = 0;
        for (int k = 0; k < kSceneCount; ++k)
            if (r.scene == kScenes[k].name) s = k;
        for (int k = 0; k < 4; ++k)
            if (r.camera == kScenes[0].cameras[k].name) c = k;
        return s * 4 + c;
    };
    if (opt.sweep) {
        // Rows in the order backend, scene, camera, then the sweep's order.
        auto rank = [&](const Row& r) { return (r.backend == "vk") * kSceneCount * 4 + scene_rank(r); };
        std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) { return rank(a) < rank(b); });
        const double total_s = seconds_since(t_start);
        const std::string md = sweep_markdown(rows, opt, total_s);
        if (!write_text(docs + "/sweep.csv", sweep_csv(rows, opt)) || !write_text(docs + "/sweep.md", md)) {
            return fail("cannot write into " + docs);
        }
        std::printf("%s\ngrass-bench: %zu frames in %.0f s; wrote %s/sweep.csv, sweep.md; images in %s/images\n", md.c_str(),
                    rows.size(), total_s, docs.c_str(), opt.out.c_str());
        return status;
    }
    // Rows in the order scene, camera, backend, preset.
    auto rank = [&](const Row& r) {
        return (scene_rank(r) * 2 + (r.backend == "vk")) * GRASS_QUALITY_LEVEL_COUNT + r.level;
    };
    std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) { return rank(a) < rank(b); });
    const double total_s = seconds_since(t_start);
    const std::string md = markdown(rows, opt, total_s);
    if (!write_text(docs + "/bench.csv", csv(rows, opt)) || !write_text(docs + "/bench.md", md) ||
        !write_text(docs + "/cost-vs-error.svg", svg(rows))) {
        return fail("cannot write into " + docs);
    }
    std::printf("%s\ngrass-bench: %zu frames in %.0f s; wrote %s/bench.csv, bench.md, cost-vs-error.svg; images in %s/images\n",
                md.c_str(), rows.size(), total_s, docs.c_str(), opt.out.c_str());
    return status;
}
